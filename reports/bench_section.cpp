#include "bench_section.h"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "model/errors.h"

namespace gearbench::reports {

namespace {
/// A side-by-side ratio as the table prints it: a bound where the baseline stopped at its cap
/// unconverged, with how far it had got (its error against the accuracy asked where the pair
/// is timed to one, else its residual).
std::string ratio_text(const nlohmann::json& r) {
  const double ratio = r["ratio"].get<double>();
  if (r.value("baseline_converged", true)) return fmt::format("{:.3g}", ratio);
  if (r.contains("baseline_error") && r.contains("baseline_accuracy"))
    return fmt::format("< {:.3g} (the baseline stopped unconverged, its error {:.2g} against the {:.2g} asked)", ratio,
                       r["baseline_error"].get<double>(), r["baseline_accuracy"].get<double>());
  return fmt::format("< {:.3g} (the baseline stopped unconverged at residual {:.2g})", ratio,
                     r["baseline_residual"].get<double>());
}
}  // namespace

Note benchmark_note(const nlohmann::json& record) {
  if (!record.contains("benchmarks") || !record.contains("gearbench"))
    throw InputError("--bench: not a gearbench bench record (no benchmarks/gearbench keys)");
  const auto& context = record["gearbench"];
  std::string text = fmt::format(
      "Recorded by `gearbench bench` at commit `{}` on {} ({} cores), {} build. Times are wall "
      "clock per iteration; ratios are solver time over the baseline of the same run (below 1: "
      "the solver is faster).\n\n| benchmark | time | counters |\n|---|---|---|\n",
      context["code"]["git_sha"].get<std::string>(), context["machine"]["cpu_model"].get<std::string>(),
      context["machine"]["cores"].get<unsigned>(), context["build"]["build_type"].get<std::string>());
  static const std::set<std::string> standard{"name", "run_name", "run_type", "repetitions", "repetition_index",
                                              "threads", "iterations", "real_time", "cpu_time", "time_unit",
                                              "family_index", "per_family_instance_index", "aggregate_name",
                                              "aggregate_unit"};
  for (const auto& b : record["benchmarks"]) {
    std::string counters;
    for (const auto& [key, value] : b.items())
      if (!standard.count(key) && value.is_number())
        counters += fmt::format("{}{} = {:.4g}", counters.empty() ? "" : ", ", key, value.get<double>());
    text += fmt::format("| `{}` | {:.4g} {} | {} |\n", b["name"].get<std::string>(), b["real_time"].get<double>(),
                        b["time_unit"].get<std::string>(), counters);
  }
  text += "\n| solver | baseline | ratio |\n|---|---|---|\n";
  for (const auto& [name, r] : record["ratios"].items())
    text += fmt::format("| `{}` | `{}` | {} |\n", name, r["baseline"].get<std::string>(), ratio_text(r));
  // Records from before the scaling fit have no "scaling" key.
  if (record.contains("scaling") && !record["scaling"].empty()) {
    text += "\n| family | time ∝ nodes^p, fitted p | sizes | nodes |\n|---|---|---|---|\n";
    for (const auto& [family, s] : record["scaling"].items())
      text += fmt::format("| `{}` | {:.3g} | {} | {:.0f} … {:.0f} |\n", family, s["exponent"].get<double>(),
                          s["points"].get<int>(), s["nodes_min"].get<double>(), s["nodes_max"].get<double>());
  }
  return {"Benchmarks", text};
}

namespace {
/// One point of the work–precision study over its repetitions.
struct WorkPoint {
  std::vector<double> cpu_ms;
  double te_error = 0.0;
  double force_error = 0.0;
};
/// model -> method -> tolerance order (rtol exponent or steps a cycle: larger is tighter) -> point.
using WorkStudy = std::map<std::string, std::map<std::string, std::map<double, WorkPoint>>>;

/// The parts of a run name between '/', without Google Benchmark's settings such as
/// "iterations:1".
std::vector<std::string> split_name(const std::string& name) {
  std::vector<std::string> parts;
  std::istringstream in(name);
  for (std::string part; std::getline(in, part, '/');)
    if (part.find(':') == std::string::npos) parts.push_back(part);
  return parts;
}

/// Adds one run of the record to the study if it is a completed work–precision run.
void add_work_point(WorkStudy& study, const nlohmann::json& run) {
  if (run.value("run_type", "iteration") != "iteration" || run.value("error_occurred", false) ||
      !run.contains("te_error") || !run.contains("force_error"))
    return;
  const auto parts = split_name(run["name"].get<std::string>());
  const bool method = parts.size() == 4 && parts[0] == "BM_WorkPrecision";
  const bool rk4 = parts.size() == 3 && parts[0] == "BM_WorkPrecision_RK4";
  if (!method && !rk4) return;
  auto& point = study[parts[1]][method ? parts[2] : "RK4"][std::stod(parts.back())];
  point.cpu_ms.push_back(run["cpu_time"].get<double>() * 1e3 *
                         unit_seconds(run["time_unit"].get<std::string>(), "--bench"));
  point.te_error = run["te_error"].get<double>();
  point.force_error = run["force_error"].get<double>();
}

Figure work_precision_figure(const std::string& model, const std::map<std::string, std::map<double, WorkPoint>>& methods,
                             bool force) {
  Figure f{.id = fmt::format("work_precision_{}_{}", model, force ? "force" : "te"),
           .section = "Benchmarks",
           .title = fmt::format("Work–precision, {}: {} error against CPU time", model,
                                force ? "mesh-force" : "transmission-error"),
           .xlabel = "CPU time per run [ms]",
           .ylabel = force ? "max |F - F_ref| / p2p(F_ref)" : "max |TE - TE_ref| / p2p(TE_ref)",
           .log_y = true,
           .points = true,
           .log_x = true};
  for (const auto& [method, points] : methods) {
    Series s{.label = method};
    for (const auto& [order, p] : points) {
      s.x.push_back(median(p.cpu_ms));
      s.y.push_back(force ? p.force_error : p.te_error);
    }
    f.series.push_back(std::move(s));
  }
  return f;
}

/// The newest run (in commit order) of `runs` for which `pick` holds.
template <class Pred>
std::optional<PerfRun> newest(std::vector<PerfRun> runs, Pred pick) {
  std::stable_sort(runs.begin(), runs.end(), [](const PerfRun& a, const PerfRun& b) { return a.order_key < b.order_key; });
  for (auto it = runs.rbegin(); it != runs.rend(); ++it)
    if (pick(*it)) return *it;
  return std::nullopt;
}
}  // namespace

std::vector<Figure> work_precision_figures(const nlohmann::json& record) {
  WorkStudy study;
  for (const auto& run : record.value("benchmarks", nlohmann::json::array())) add_work_point(study, run);
  std::vector<Figure> figures;
  for (const auto& [model, methods] : study)
    for (const bool force : {false, true}) figures.push_back(work_precision_figure(model, methods, force));
  return figures;
}

Note performance_note(const std::vector<PerfRun>& history, const std::optional<PerfRun>& current,
                      const PerformanceQuery& query, const PerfOptions& options) {
  const auto same_machine = [&](const PerfRun& r) {
    return r.fingerprint == query.fingerprint && r.build_type == query.build_type && r.status == "ok";
  };
  const auto now = current ? current : newest(history, [&](const PerfRun& r) { return same_machine(r) && r.sha == query.sha; });
  if (!now)
    return {"Performance", fmt::format("No benchmark record of commit `{}` on this machine (`{}`, {} build): run "
                                       "`gearbench bench --record` (or pass `verify --bench RECORD`) to compare it "
                                       "with the previous record.\n",
                                       query.sha, query.fingerprint, query.build_type)};
  const auto before = newest(history, [&](const PerfRun& r) {
    return same_machine(r) && r.sha != now->sha && r.order_key < now->order_key;
  });
  if (!before)
    return {"Performance", fmt::format("Record {} of commit `{}` has no earlier record on the same machine (`{}`) and "
                                       "build type to compare with.\n",
                                       now->file, now->commit_label(), query.fingerprint)};
  const auto pair = analyse_perf_history({*before, *now}, options);
  std::string text = fmt::format(
      "This commit's benchmarks (`{}`, {}) against the previous record on the same machine (`{}`, {}), {}. A change "
      "is flagged when the two-sided Mann–Whitney U test over the repetitions gives p < {} and the median moved by "
      "more than {:.0f} %.\n\n| benchmark | compared | median before | median now | change | p | verdict |\n"
      "|---|---|---|---|---|---|---|\n",
      now->commit_label(), now->file, before->commit_label(), before->file, now->machine, options.alpha,
      100.0 * options.threshold);
  for (const auto& c : pair.changes)
    text += fmt::format("| `{}` | {} | {:.4g} | {:.4g} | {:+.1f} % | {} | {} |\n", c.name, c.ratio ? "ratio" : "time [s]",
                        c.median_before, c.median_after, 100.0 * c.change,
                        c.tested ? fmt::format("{:.3g}", c.p_value) : std::string("—"),
                        c.verdict == "regression" ? std::string("**regression**") : c.verdict);
  return {"Performance", text};
}

}  // namespace gearbench::reports
