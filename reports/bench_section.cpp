#include "bench_section.h"

#include <algorithm>
#include <fmt/format.h>
#include <set>
#include <string>

#include "model/errors.h"

namespace gearbench::reports {

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
    text += r.value("baseline_converged", true)
                ? fmt::format("| `{}` | `{}` | {:.3g} |\n", name, r["baseline"].get<std::string>(), r["ratio"].get<double>())
                : fmt::format("| `{}` | `{}` | < {:.3g} (the baseline stopped unconverged at residual {:.2g}) |\n", name,
                              r["baseline"].get<std::string>(), r["ratio"].get<double>(),
                              r["baseline_residual"].get<double>());
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
/// The newest run (in commit order) of `runs` for which `pick` holds.
template <class Pred>
std::optional<PerfRun> newest(std::vector<PerfRun> runs, Pred pick) {
  std::stable_sort(runs.begin(), runs.end(), [](const PerfRun& a, const PerfRun& b) { return a.order_key < b.order_key; });
  for (auto it = runs.rbegin(); it != runs.rend(); ++it)
    if (pick(*it)) return *it;
  return std::nullopt;
}
}  // namespace

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
