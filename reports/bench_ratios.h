#pragma once
// Side-by-side ratios of a Google Benchmark run: each benchmark X[/args] over X_baseline
// measured in the same run; and the scaling exponent of a family measured over sizes.
#include <nlohmann/json.hpp>
#include <string>

namespace gearbench::reports {

/// Google Benchmark's JSON output (`text`, from `source`), its non-finite numbers read as null:
/// its reporter prints them as bare NaN / inf, for which JSON has no token (the standard
/// deviation of a counter equal in every repetition can come out NaN from rounding).
nlohmann::json parse_benchmark_output(const std::string& text, const std::string& source);

/// A run's real time in seconds (Google Benchmark reports it in the run's own time_unit).
double real_seconds(const nlohmann::json& run);

/// Solver over baseline for every run X[/args] that has a run X_baseline[/args] with the same
/// arguments, or a baseline without arguments for its whole family; medians over
/// repetitions, times in seconds: {name: {baseline, solver_time, baseline_time, ratio}}.
/// A baseline whose run has the counter converged = 0 stopped at a cap: the entry adds
/// baseline_converged = false and baseline_residual, and the ratio is an upper bound.
nlohmann::json side_by_side_ratios(const nlohmann::json& benchmarks);

/// The fitted exponent p of time ∝ nodes^p for every benchmark family whose runs carry a
/// `nodes` counter at three or more sizes (least squares on the logarithms of the median
/// times; runs with the counter converged = 0 left out): {family: {exponent, points,
/// nodes_min, nodes_max}}.
nlohmann::json scaling_exponents(const nlohmann::json& benchmarks);

}  // namespace gearbench::reports
