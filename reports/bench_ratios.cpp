#include "bench_ratios.h"

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "model/json_reader.h"
#include "perf_history.h"

namespace gearbench::reports {

namespace {
/// Benchmark family: the name without its arguments ("BM_X/101" -> "BM_X").
std::string family(const std::string& run_name) { return run_name.substr(0, run_name.find('/')); }

/// A run that stopped at a cap before converging says so with the counter converged = 0.
bool stopped_unconverged(const nlohmann::json& run) {
  return run.contains("converged") && run["converged"].is_number() && run["converged"].get<double>() == 0.0;
}
}  // namespace

nlohmann::json parse_benchmark_output(const std::string& text, const std::string& source) {
  static const std::regex non_finite(R"((:\s*)-?(nan|NaN|inf|Inf|infinity|Infinity)\b)");
  return model::parse_json(std::regex_replace(text, non_finite, "$1null"), source);
}

double real_seconds(const nlohmann::json& run) {
  return run.at("real_time").get<double>() * unit_seconds(run.value("time_unit", "ns"), "benchmark output");
}

/// Solver over baseline for every run X[/args] that has a run X_baseline[/args] with the same
/// arguments, or a baseline without arguments for its whole family; medians over repetitions.
nlohmann::json side_by_side_ratios(const nlohmann::json& benchmarks) {
  std::map<std::string, std::vector<double>> samples;  // run name -> time per repetition
  for (const auto& b : benchmarks)
    if (b.value("run_type", "iteration") == "iteration")
      samples[b["run_name"].get<std::string>()].push_back(real_seconds(b));
  std::map<std::string, double> times;
  for (const auto& [name, s] : samples) times[name] = reports::median(s);
  std::map<std::string, nlohmann::json> unconverged;  // baseline run -> a repetition that stopped unconverged
  // Repetitions only: an aggregate's counters are statistics (the standard deviation of
  // converged = 1 is 0, which read as a run stopped unconverged).
  for (const auto& b : benchmarks)
    if (b.value("run_type", "iteration") == "iteration" && stopped_unconverged(b))
      unconverged[b["run_name"].get<std::string>()] = b;
  const std::string suffix = "_baseline";
  nlohmann::json ratios = nlohmann::json::object();
  for (const auto& [name, time] : times) {
    const std::string fam = family(name);
    if (fam.size() > suffix.size() && fam.compare(fam.size() - suffix.size(), suffix.size(), suffix) == 0) continue;
    const std::string args = name.substr(fam.size());
    for (const std::string& baseline : {fam + suffix + args, fam + suffix}) {
      const auto it = times.find(baseline);
      if (it == times.end() || it->second <= 0.0) continue;
      ratios[name] = {{"baseline", baseline}, {"solver_time", time}, {"baseline_time", it->second},
                      {"ratio", time / it->second}};
      if (const auto u = unconverged.find(baseline); u != unconverged.end()) {
        // Where it stopped: its residual, and where the pair is timed to an accuracy (counters
        // error and accuracy) the error it had reached, which says more than a residual.
        ratios[name]["baseline_converged"] = false;
        ratios[name]["baseline_residual"] = u->second.value("residual", 0.0);
        for (const char* key : {"error", "accuracy"})
          if (u->second.contains(key) && u->second[key].is_number()) ratios[name][std::string("baseline_") + key] = u->second[key];
      }
      break;
    }
  }
  return ratios;
}

nlohmann::json scaling_exponents(const nlohmann::json& benchmarks) {
  std::map<std::string, std::map<double, std::vector<double>>> samples;  // family -> nodes -> times
  for (const auto& b : benchmarks)
    if (b.value("run_type", "iteration") == "iteration" && b.contains("nodes") && b["nodes"].is_number() &&
        b["nodes"].get<double>() > 0.0 && !stopped_unconverged(b))
      samples[family(b["run_name"].get<std::string>())][b["nodes"].get<double>()].push_back(real_seconds(b));
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [fam, by_nodes] : samples) {
    if (by_nodes.size() < 3) continue;
    std::vector<double> x, y;
    for (const auto& [nodes, times] : by_nodes) {
      x.push_back(std::log(nodes));
      y.push_back(std::log(reports::median(times)));
    }
    double intercept = 0.0, slope = 0.0, cov00 = 0.0, cov01 = 0.0, cov11 = 0.0, sumsq = 0.0;
    gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &intercept, &slope, &cov00, &cov01, &cov11, &sumsq);
    out[fam] = {{"exponent", slope}, {"points", x.size()}, {"nodes_min", by_nodes.begin()->first},
                {"nodes_max", by_nodes.rbegin()->first}};
  }
  return out;
}

}  // namespace gearbench::reports
