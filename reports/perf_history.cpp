#include "perf_history.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <set>

#include "mann_whitney.h"
#include "model/errors.h"
#include "model/json_reader.h"

namespace gearbench::reports {

namespace fs = std::filesystem;
using nlohmann::json;

double median(std::vector<double> values) {
  if (values.empty()) throw std::invalid_argument("median of an empty sample");
  const auto mid = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  if (values.size() % 2 == 1) return *mid;
  return 0.5 * (*mid + *std::max_element(values.begin(), mid));
}

std::vector<double> PerfRun::ratio_samples(const std::string& run) const {
  const auto b = baseline_of.find(run);
  if (b == baseline_of.end()) return {};
  const auto& solver = seconds.at(run);
  const auto& baseline = seconds.at(b->second);
  std::vector<double> out;
  for (std::size_t i = 0; i < std::min(solver.size(), baseline.size()); ++i)
    if (baseline[i] > 0.0) out.push_back(solver[i] / baseline[i]);
  return out;
}

void PerfOptions::validate() const {
  if (!(alpha > 0.0 && alpha < 1.0))
    throw InputError(fmt::format("--alpha = {}: must lie in (0, 1)", alpha));
  if (!(threshold >= 0.0 && threshold < 10.0))
    throw InputError(fmt::format("--threshold = {}: must lie in [0, 10) (a relative change)", threshold));
}

double unit_seconds(const std::string& unit, const std::string& file) {
  if (unit == "ns") return 1e-9;
  if (unit == "us") return 1e-6;
  if (unit == "ms") return 1e-3;
  if (unit == "s") return 1.0;
  throw InputError(fmt::format("{}: time_unit = \"{}\": expected ns, us, ms or s", file, unit));
}

namespace {

std::string text_or(const json& j, const char* key, const std::string& fallback) {
  return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : fallback;
}

}  // namespace

PerfClock parse_perf_clock(const std::string& name) {
  if (name == "cpu") return PerfClock::cpu;
  if (name == "real") return PerfClock::real;
  throw InputError(fmt::format("--clock = {}: expected cpu or real", name));
}

PerfRun parse_perf_record(const json& record, const std::string& file, PerfClock clock) {
  if (!record.is_object() || !record.contains("benchmarks") || !record.contains("gearbench"))
    throw InputError(fmt::format("{}: not a gearbench bench record (no benchmarks/gearbench keys)", file));
  const json& g = record["gearbench"];
  const json code = g.value("code", json::object()), m = g.value("machine", json::object());
  PerfRun run;
  run.file = file;
  run.sha = code.value("git_sha", "unknown");
  run.dirty = code.value("dirty", false);
  const std::string created = text_or(g, "created_utc", "");
  run.order_key = text_or(code, "commit_time_utc", created) + "|" + created;
  run.fingerprint = text_or(m, "hardware_fingerprint", text_or(m, "fingerprint", "unknown"));
  run.machine = fmt::format("{}, {} cores{}", text_or(m, "cpu_model", "unknown CPU"), m.value("cores", 0u),
                            m.contains("memory_GiB") ? fmt::format(", {} GiB", m["memory_GiB"].dump()) : "");
  run.build_type = g.value("build", json::object()).value("build_type", "unknown");
  run.status = text_or(g, "status", "ok");
  if (g.contains("missing") && g["missing"].is_array()) run.missing = g["missing"].get<std::vector<std::string>>();
  for (const auto& b : record["benchmarks"]) {
    if (b.value("run_type", "iteration") != "iteration") continue;  // aggregates are recomputed
    const char* key = clock == PerfClock::cpu ? "cpu_time" : "real_time";
    const double t = b.at(key).get<double>() * unit_seconds(b.value("time_unit", "ns"), file);
    run.seconds[b.at("run_name").get<std::string>()].push_back(t);
  }
  if (record.contains("ratios"))
    for (const auto& [name, r] : record["ratios"].items()) {
      const std::string baseline = r.value("baseline", "");
      if (run.seconds.count(name) && run.seconds.count(baseline)) run.baseline_of[name] = baseline;
    }
  return run;
}

std::vector<PerfRun> load_perf_records(const std::string& dir, PerfClock clock) {
  if (!fs::is_directory(dir)) throw InputError(fmt::format("--dir {}: not a directory", dir));
  std::vector<PerfRun> runs;
  std::vector<fs::path> files;
  // Hidden files are not records: `bench` writes its raw output to .bench-<pid>.json while it
  // runs, and leaves it half-written when killed (a `verify` meanwhile failed on it).
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".json" &&
        !entry.path().filename().string().starts_with("."))
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    const json j = model::read_json_file(f.string());
    // Other JSON beside the records (a report.json in a milestone folder) is not a record.
    if (j.is_object() && j.contains("benchmarks") && j.contains("gearbench"))
      runs.push_back(parse_perf_record(j, f.string(), clock));
  }
  return runs;
}

namespace {

PerfChange compare_samples(const std::string& name, bool ratio, std::size_t before, std::size_t after,
                           const std::vector<double>& a, const std::vector<double>& b,
                           const PerfOptions& options) {
  PerfChange c{.name = name, .ratio = ratio, .before = before, .after = after};
  c.median_before = median(a);
  c.median_after = median(b);
  c.change = c.median_before > 0.0 ? c.median_after / c.median_before - 1.0 : 0.0;
  c.tested = a.size() >= utest_min_repetitions && b.size() >= utest_min_repetitions;
  if (!c.tested) {
    c.verdict = "untested";
    return c;
  }
  c.p_value = mann_whitney_u(a, b).p_value;
  if (c.p_value < options.alpha && c.change > options.threshold) c.verdict = "regression";
  else if (c.p_value < options.alpha && c.change < -options.threshold) c.verdict = "improvement";
  else c.verdict = "unchanged";
  return c;
}

/// Index of the latest run before `j` for which `comparable(i)` holds, or j when none.
template <class Pred>
std::size_t previous(std::size_t j, Pred comparable) {
  for (std::size_t i = j; i-- > 0;)
    if (comparable(i)) return i;
  return j;
}

/// Display unit for times whose largest value is `largest` seconds.
std::pair<std::string, double> time_unit(double largest) {
  if (largest < 1e-6) return {"ns", 1e9};
  if (largest < 1e-3) return {"µs", 1e6};
  if (largest < 1.0) return {"ms", 1e3};
  return {"s", 1.0};
}

std::string figure_id(const std::string& prefix, const std::string& name) {
  std::string id = prefix;
  for (char ch : name) id.push_back(std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_');
  return id;
}

std::string clock_name(PerfClock clock) { return clock == PerfClock::cpu ? "CPU" : "real"; }

/// The samples of `name` in `run`: its times, or its solver/baseline ratios.
std::vector<double> samples_of(const PerfRun& run, const std::string& name, bool ratio) {
  if (ratio) return run.ratio_samples(name);
  const auto it = run.seconds.find(name);
  return it == run.seconds.end() ? std::vector<double>{} : it->second;
}

/// Per machine the median over the repetitions at each commit, with the fastest and slowest
/// repetition as the spread; and the commits where a regression of `name` was flagged.
Figure history_figure(const std::vector<PerfRun>& runs, const std::vector<PerfChange>& changes,
                      const std::vector<double>& x_of_run, const std::string& name, bool ratio, PerfClock clock) {
  struct Lines {
    Series median, fastest, slowest;
  };
  std::map<std::string, Lines> by_machine;
  Series flagged{.label = "regression flagged (U test)", .style = "points pt 6 ps 2.5 lc rgb 'red'"};
  double largest = 0.0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto samples = samples_of(runs[i], name, ratio);
    if (samples.empty()) continue;
    auto [it, first] = by_machine.try_emplace(runs[i].fingerprint);
    auto& lines = it->second;
    if (first) {
      lines.median.label = fmt::format("median, {} [{}] {}", runs[i].machine, runs[i].fingerprint.substr(0, 8),
                                       runs[i].build_type);
      lines.fastest = {.label = "fastest repetition", .style = "points pt 2 ps 0.8 lc rgb 'gray40'"};
      lines.slowest = {.label = "slowest repetition", .style = "points pt 1 ps 0.8 lc rgb 'gray40'"};
    }
    const auto [low, high] = std::minmax_element(samples.begin(), samples.end());
    for (auto* s : {&lines.median, &lines.fastest, &lines.slowest}) s->x.push_back(x_of_run[i]);
    lines.median.y.push_back(median(samples));
    lines.fastest.y.push_back(*low);
    lines.slowest.y.push_back(*high);
    largest = std::max(largest, *high);
    const bool regression = std::any_of(changes.begin(), changes.end(), [&](const PerfChange& c) {
      return c.after == i && c.ratio == ratio && c.name == name && c.verdict == "regression";
    });
    if (regression) {
      flagged.x.push_back(x_of_run[i]);
      flagged.y.push_back(lines.median.y.back());
    }
  }
  const auto [unit, scale] = ratio ? std::pair<std::string, double>{"-", 1.0} : time_unit(largest);
  Figure f{.id = figure_id(ratio ? "ratio_" : "time_", name), .section = "Performance history",
           .title = ratio ? name + " over its baseline" : name,
           .xlabel = "commit",
           .ylabel = ratio ? fmt::format("{} time ratio solver/baseline [-]", clock_name(clock))
                           : fmt::format("{} time per iteration [{}]", clock_name(clock), unit)};
  for (auto& [fp, lines] : by_machine) {
    for (auto* s : {&lines.median, &lines.fastest, &lines.slowest}) {
      for (double& y : s->y) y *= scale;
      f.series.push_back(std::move(*s));
    }
  }
  for (double& y : flagged.y) y *= scale;
  if (!flagged.x.empty()) f.series.push_back(std::move(flagged));
  f.points = true;
  return f;
}

std::vector<Figure> history_figures(const std::vector<PerfRun>& runs, const std::vector<PerfChange>& changes,
                                    PerfClock clock) {
  std::vector<std::string> commits;  // distinct, in order
  std::vector<double> x_of_run;
  for (const auto& r : runs) {
    if (commits.empty() || commits.back() != r.commit_label()) commits.push_back(r.commit_label());
    x_of_run.push_back(static_cast<double>(commits.size() - 1));
  }
  std::set<std::string> names, ratio_names;
  for (const auto& r : runs) {
    for (const auto& [n, s] : r.seconds) names.insert(n);
    for (const auto& [n, b] : r.baseline_of) ratio_names.insert(n);
  }
  std::vector<Figure> out;
  for (const auto& n : names) out.push_back(history_figure(runs, changes, x_of_run, n, false, clock));
  for (const auto& n : ratio_names) out.push_back(history_figure(runs, changes, x_of_run, n, true, clock));
  for (auto& f : out) f.xtic_labels = commits;
  return out;
}

}  // namespace

PerfHistory analyse_perf_history(std::vector<PerfRun> runs, const PerfOptions& options) {
  options.validate();
  std::stable_sort(runs.begin(), runs.end(), [](const PerfRun& a, const PerfRun& b) { return a.order_key < b.order_key; });
  PerfHistory h;
  // Each benchmark is compared with the latest earlier run that has it: a commit that did
  // not build, or lacked the benchmark, is passed over rather than breaking the chain.
  for (std::size_t j = 0; j < runs.size(); ++j) {
    const auto& now = runs[j];
    for (const auto& [name, samples] : now.seconds) {
      const std::size_t i = previous(j, [&](std::size_t k) {
        return runs[k].fingerprint == now.fingerprint && runs[k].build_type == now.build_type && runs[k].seconds.count(name);
      });
      if (i != j) h.changes.push_back(compare_samples(name, false, i, j, runs[i].seconds.at(name), samples, options));
    }
    for (const auto& [name, baseline] : now.baseline_of) {
      const std::size_t i = previous(j, [&](std::size_t k) {
        return runs[k].build_type == now.build_type && !runs[k].ratio_samples(name).empty();
      });
      if (i != j)
        h.changes.push_back(compare_samples(name, true, i, j, runs[i].ratio_samples(name), now.ratio_samples(name), options));
    }
  }
  h.figures = history_figures(runs, h.changes, options.clock);
  h.runs = std::move(runs);
  return h;
}

std::vector<const PerfChange*> PerfHistory::largest_changes(std::size_t count) const {
  std::vector<const PerfChange*> out;
  for (const auto& c : changes)
    if (c.tested) out.push_back(&c);
  std::stable_sort(out.begin(), out.end(),
                   [](const PerfChange* a, const PerfChange* b) { return std::abs(a->change) > std::abs(b->change); });
  if (out.size() > count) out.resize(count);
  return out;
}

std::vector<const PerfChange*> PerfHistory::latest_regressions() const {
  std::vector<const PerfChange*> out;
  for (const auto& c : changes) {
    if (c.verdict != "regression") continue;
    bool newest = true;
    for (std::size_t k = c.after + 1; k < runs.size(); ++k)
      if (c.ratio ? runs[k].build_type == runs[c.after].build_type && !runs[k].ratio_samples(c.name).empty()
                  : runs[k].fingerprint == runs[c.after].fingerprint && runs[k].build_type == runs[c.after].build_type &&
                        runs[k].seconds.count(c.name))
        newest = false;
    if (newest) out.push_back(&c);
  }
  return out;
}

namespace {
std::string describe(const PerfChange& c, const std::vector<PerfRun>& runs) {
  // A plain pair, not a structured binding: clang 14 (the fuzz preset) cannot capture those.
  const auto unit_scale = time_unit(std::max(c.median_before, c.median_after));
  auto value = [&](double v) {
    return c.ratio ? fmt::format("{:.4g}", v) : fmt::format("{:.4g} {}", v * unit_scale.second, unit_scale.first);
  };
  return fmt::format("| `{}` | {} | {} → {} | {} → {} | {:+.1f} % | {} | {} |\n", c.name,
                     c.ratio ? "ratio" : "time", runs[c.before].commit_label(), runs[c.after].commit_label(),
                     value(c.median_before), value(c.median_after), 100.0 * c.change,
                     c.tested ? fmt::format("{:.3g}", c.p_value) : std::string("—"),
                     c.verdict == "regression" ? std::string("**regression**") : c.verdict);
}
/// "ok", or why the commit has no times, and the benchmarks its range's other commits ran
/// and it did not.
std::string run_status(const PerfRun& run) {
  std::string text = run.status == "ok" ? "ok" : "**" + run.status + "**";
  if (!run.missing.empty()) text += fmt::format("; lacks {} benchmark(s): `{}`", run.missing.size(), fmt::join(run.missing, "`, `"));
  return text;
}
constexpr const char* change_header =
    "| benchmark | compared | commits | median | change | p (U test) | verdict |\n|---|---|---|---|---|---|---|\n";
}  // namespace

std::string PerfHistory::markdown(const PerfOptions& options) const {
  std::string md = "# gearbench performance history\n\n";
  md += fmt::format(
      "{} benchmark records in commit order; {} time per iteration. Times are compared only between runs on the same "
      "hardware (fingerprint of CPU model, cores and memory) and build type; solver/baseline ratios "
      "across machines. A change is flagged when the two-sided Mann–Whitney U test over the "
      "repetitions gives p < {} and the median moved by more than {:.0f} %; runs with fewer than {} "
      "repetitions are not tested.\n\n",
      runs.size(), clock_name(options.clock), options.alpha, 100.0 * options.threshold, utest_min_repetitions);
  md += "| # | commit | record | machine | fingerprint | build | status |\n|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < runs.size(); ++i)
    md += fmt::format("| {} | `{}` | {} | {} | `{}` | {} | {} |\n", i, runs[i].commit_label(),
                      fs::path(runs[i].file).filename().string(), runs[i].machine, runs[i].fingerprint,
                      runs[i].build_type, run_status(runs[i]));
  const auto latest = latest_regressions();
  md += fmt::format("\n## Regressions at the newest runs: {}\n\n", latest.size());
  if (!latest.empty()) {
    md += change_header;
    for (const auto* c : latest) md += describe(*c, runs);
  }
  md += "\n## Regressions, each at the commit where it appears\n\n";
  md += change_header;
  for (const auto& c : changes)
    if (c.verdict == "regression") md += describe(c, runs);
  md += "\n## Largest changes\n\nThe ten tested comparisons whose median moved most, either way.\n\n";
  md += change_header;
  for (const auto* c : largest_changes(10)) md += describe(*c, runs);
  md += "\n## Every comparison\n\n";
  md += change_header;
  for (const auto& c : changes) md += describe(c, runs);
  md += "\n## Figures\n\n";
  for (const auto& f : figures)
    md += fmt::format("![{}](figures/{}.svg) ([data](figures/{}.csv))\n\n", f.title, f.id, f.id);
  return md;
}

json PerfHistory::to_json(const PerfOptions& options) const {
  json j{{"alpha", options.alpha}, {"threshold", options.threshold},
         {"clock", options.clock == PerfClock::cpu ? "cpu" : "real"}};
  j["runs"] = json::array();
  for (const auto& r : runs)
    j["runs"].push_back({{"file", r.file}, {"commit", r.sha}, {"dirty", r.dirty}, {"machine", r.machine},
                         {"fingerprint", r.fingerprint}, {"build_type", r.build_type}, {"status", r.status},
                         {"missing", r.missing}});
  j["changes"] = json::array();
  for (const auto& c : changes) {
    j["changes"].push_back({{"name", c.name}, {"kind", c.ratio ? "ratio" : "time"}, {"before", c.before},
                            {"after", c.after}, {"median_before", c.median_before},
                            {"median_after", c.median_after}, {"change", c.change}, {"verdict", c.verdict}});
    if (c.tested) j["changes"].back()["p_value"] = c.p_value;
  }
  j["latest_regressions"] = json::array();
  for (const auto* c : latest_regressions()) j["latest_regressions"].push_back(c->name);
  return j;
}

}  // namespace gearbench::reports
