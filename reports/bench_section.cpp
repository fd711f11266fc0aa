#include "bench_section.h"

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

}  // namespace gearbench::reports
