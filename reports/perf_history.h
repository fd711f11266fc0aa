#pragma once
// Performance history across commits (`gearbench report perf`): benchmark records of
// `gearbench bench --record` in commit order, one figure per benchmark, and regressions
// flagged by a two-sided Mann–Whitney U test over repetitions, as Google Benchmark's
// compare.py does. Timings are compared only between runs with the same hardware
// fingerprint and build type; the dimensionless solver/baseline ratios across machines.
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "report.h"

namespace gearbench::reports {

/// One benchmark record.
struct PerfRun {
  std::string file;
  std::string sha;
  bool dirty = false;
  std::string order_key;    ///< commit time (else recording time), then recording time
  std::string fingerprint;  ///< hardware: CPU model, cores, memory
  std::string machine;      ///< human-readable machine description
  std::string build_type;
  std::string status = "ok";          ///< "build_failed" or "run_failed" for a commit of a range
  std::vector<std::string> missing;   ///< benchmarks other commits of its range ran and it did not
  /// Time per repetition on the chosen clock [s], by run name ("BM_X/101").
  std::map<std::string, std::vector<double>> seconds;
  /// Solver run -> baseline run measured in the same record.
  std::map<std::string, std::string> baseline_of;

  /// Solver over baseline per repetition pair (pairs by repetition index).
  [[nodiscard]] std::vector<double> ratio_samples(const std::string& run) const;
  [[nodiscard]] std::string commit_label() const { return sha + (dirty ? "+" : ""); }
};

/// Which of Google Benchmark's times is compared. CPU time (of the benchmark's thread) is
/// the default: the benchmarks are single-threaded, and on a shared machine it is far less
/// disturbed by other load than wall-clock time (measured on a loaded 2-core VM: coefficient
/// of variation over 10 repetitions 7–29 % for CPU time against 20–63 % for real time).
enum class PerfClock { cpu, real };
PerfClock parse_perf_clock(const std::string& name);  ///< "cpu" or "real"; InputError otherwise

struct PerfOptions {
  double alpha = 0.05;      ///< significance level of the U test (compare.py's default)
  double threshold = 0.05;  ///< relative change of the median below which nothing is flagged
  PerfClock clock = PerfClock::cpu;  ///< named in the report
  void validate() const;    ///< InputError when out of range
};

/// One comparison of a benchmark (or a ratio) between two runs.
struct PerfChange {
  std::string name;
  bool ratio = false;        ///< solver/baseline ratio rather than a time
  std::size_t before = 0, after = 0;  ///< indices into the runs
  double median_before = 0.0, median_after = 0.0;
  double change = 0.0;       ///< median_after / median_before − 1
  double p_value = 1.0;      ///< 1 when untested
  bool tested = false;       ///< both sides had ≥ 2 repetitions
  std::string verdict;       ///< "regression", "improvement", "unchanged", "untested"
};

struct PerfHistory {
  std::vector<PerfRun> runs;        ///< in commit order
  std::vector<PerfChange> changes;  ///< each run against the latest earlier comparable run with the benchmark
  std::vector<Figure> figures;

  /// Regressions whose later run is the newest run with this benchmark of its machine (time)
  /// or overall (ratio).
  [[nodiscard]] std::vector<const PerfChange*> latest_regressions() const;
  /// The `count` tested changes of largest size, either way, largest first.
  [[nodiscard]] std::vector<const PerfChange*> largest_changes(std::size_t count) const;
  [[nodiscard]] std::string markdown(const PerfOptions& options) const;
  [[nodiscard]] nlohmann::json to_json(const PerfOptions& options) const;
};

/// Reads one record (InputError when it is not a `gearbench bench` record).
PerfRun parse_perf_record(const nlohmann::json& record, const std::string& file, PerfClock clock = PerfClock::cpu);
/// Every *.json `gearbench bench` record in `dir` (other JSON files are passed over).
std::vector<PerfRun> load_perf_records(const std::string& dir, PerfClock clock = PerfClock::cpu);
/// Sorts the runs into commit order, compares and draws.
PerfHistory analyse_perf_history(std::vector<PerfRun> runs, const PerfOptions& options);

/// Median of a non-empty sample.
double median(std::vector<double> values);

/// Seconds per Google Benchmark time_unit ("ns", "us", "ms", "s"); InputError naming `file`
/// for any other.
double unit_seconds(const std::string& unit, const std::string& file);

}  // namespace gearbench::reports
