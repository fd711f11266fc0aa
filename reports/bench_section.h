#pragma once
// The benchmark record of `gearbench bench` as a report section: every benchmark's time and
// counters, and the side-by-side ratios against the baselines measured in the same run.
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "perf_history.h"
#include "report.h"

namespace gearbench::reports {

/// Throws InputError when the record is not a `gearbench bench` record.
Note benchmark_note(const nlohmann::json& record);

/// The work–precision diagrams of the integrator study (benchmarks/dynamics_benchmark.cpp:
/// BM_WorkPrecision/<model>/<method>/<rtol exponent>, BM_WorkPrecision_RK4/<model>/<steps a
/// cycle>) for the Benchmarks section: per model a figure of the transmission-error error and
/// one of the mesh-force error against CPU time per run, log–log, one series per method (RK4
/// included), its points from loose to tight (median CPU time over repetitions). Runs that
/// stopped with an error are left out; none when the record holds no such runs.
std::vector<Figure> work_precision_figures(const nlohmann::json& record);

/// Which record is this commit's and which machine it ran on, for the Performance section.
struct PerformanceQuery {
  std::string sha;          ///< this build's commit
  std::string fingerprint;  ///< this machine's hardware fingerprint
  std::string build_type;
};

/// The Performance section of a verification report: this commit's benchmarks (`current`,
/// else the newest record of the commit among `history` on this machine and build type)
/// against the previous record of the history on the same machine and build type, with the
/// U test of `gearbench report perf`. Says so when either record is missing.
Note performance_note(const std::vector<PerfRun>& history, const std::optional<PerfRun>& current,
                      const PerformanceQuery& query, const PerfOptions& options = {});

}  // namespace gearbench::reports
