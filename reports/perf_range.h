#pragma once
// Benchmarking a range of commits (`gearbench bench --commits`, issue 25), the parts that
// need no git, no build and no process: which commits of a range are taken, in which order
// the repetitions run, and how one commit's repetitions become one record of the
// performance history. The runner in app/bench_range.cpp does the building and running.
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace gearbench::reports {

/// Regular expression (Google Benchmark's --benchmark_filter) of a named benchmark set.
/// "short": benchmarks whose names have not changed since the first commits and that take
/// well under 2 minutes for 5 repetitions (the backfill's set); "full": every benchmark.
/// InputError for any other name.
std::string benchmark_set_filter(const std::string& set);

/// Every `every`-th commit of `commits` (oldest first), counted back from the newest, which
/// is always taken: extending a history by one new commit then always benchmarks it.
std::vector<std::string> every_kth(const std::vector<std::string>& commits, int every);

/// The order of the runs: repetition r of every commit before repetition r + 1 of any, so
/// that a drift of a shared machine (other jobs starting, thermal throttling) falls on
/// every commit alike; odd rounds go newest to oldest, so no commit always runs first.
/// Pairs (repetition, index into the commits).
std::vector<std::pair<int, std::size_t>> interleaved_schedule(std::size_t commits, int repetitions);

/// The note stored in every record of a range run, saying how its repetitions were taken.
std::string interleaving_note(std::size_t commits, int repetitions);

/// Google Benchmark outputs of one commit, one per repetition, as one output: every
/// iteration run with its repetition_index (and repetitions) set, the context of the first.
nlohmann::json join_repetitions(const std::vector<nlohmann::json>& outputs);

/// What happened to one commit of a range.
struct CommitOutcome {
  std::string sha;                ///< full sha
  std::string commit_time_utc;    ///< "YYYY-MM-DDTHH:MM:SSZ"
  std::string status = "ok";      ///< "ok", "build_failed" or "run_failed"
  std::string log_tail;           ///< the end of the build or run log when not ok
  std::vector<nlohmann::json> outputs;  ///< Google Benchmark JSON, one per repetition that ran
};

/// The range a record belongs to: what was asked for and how it ran.
struct RangeContext {
  std::string set;                ///< "short", "full" or "custom"
  std::string filter;             ///< the regular expression that ran
  int repetitions = 0;
  std::vector<std::string> commits;  ///< full shas, oldest first
};

/// Run names ("BM_X/101") of the iteration runs of a joined output.
std::vector<std::string> run_names(const nlohmann::json& joined);

/// One record of the performance history for one commit: the joined benchmarks, their
/// ratios and scaling, and under "gearbench" the runner's provenance (machine, compiler,
/// build type) with "code" set to the benchmarked commit, "status", "missing" (names that
/// other commits of the range ran and this one did not) and "range". `provenance` is
/// reports::provenance() of the runner.
nlohmann::json range_record(const CommitOutcome& outcome, const RangeContext& range,
                            const std::vector<std::string>& missing, const nlohmann::json& provenance);

/// Per commit, the run names that another commit of the range ran and this one did not (a
/// commit that did not build lacks them all).
std::vector<std::vector<std::string>> missing_benchmarks(const std::vector<CommitOutcome>& outcomes);

}  // namespace gearbench::reports
