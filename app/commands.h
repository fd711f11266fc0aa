#pragma once
// The subcommands of the gearbench CLI. Each returns the process exit code.
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gearbench::app {

/// Exit codes of the CLI contract.
enum ExitCode : int {
  exit_ok = 0,
  exit_failed = 1,         ///< a verification check failed / a regression was found
  exit_bad_input = 2,      ///< InputError
  exit_not_converged = 3,  ///< ConvergenceError
};

/// A result that could not be written (a full disk, a closed stdout): exit code 1, but not
/// reported as an internal error.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

int run_command(const std::string& case_path, const std::string& output_path);
int verify_command(const std::string& tier, const std::string& out_dir, const std::string& cases_dir,
                   const std::string& bench_record, const std::string& only);
int report_compare_command(const std::string& before, const std::string& after);

/// What `gearbench bench` runs and where the record goes.
struct BenchRequest {
  std::string out_dir;
  std::string filter;       ///< regular expression selecting benchmarks ("" = all)
  double min_time = 0.2;    ///< minimum seconds per benchmark (and per repetition)
  int repetitions = 1;
  bool record = false;      ///< a performance-history record: <date>_<sha>.json
  void validate() const;    ///< InputError when out of range
};
int bench_command(const BenchRequest& request);

/// `gearbench bench --commits`: a performance history of past commits, each built in its
/// own git worktree by `build_script`, one record per commit.
struct BenchRangeRequest {
  std::vector<std::string> commits;  ///< "A..B" (git's range: after A up to B) or one commit each
  int every = 1;                     ///< every K-th commit of a range, counted from its newest
  std::string set = "short";         ///< named benchmark set (reports::benchmark_set_filter)
  std::string filter;                ///< a regular expression instead of the set
  int repetitions = 5;
  double min_time = 0.2;
  std::string out_dir;               ///< where the records go (reports/perf)
  std::string repo;                  ///< the git checkout whose commits are built
  std::string workdir;               ///< the worktrees and their builds
  std::string build_script;          ///< `SCRIPT SHA WORKDIR` prints the benchmark executable;
                                     ///< `SCRIPT --clean WORKDIR` removes the builds
  bool keep_worktrees = false;
  void validate() const;             ///< InputError when out of range
};
int bench_range_command(const BenchRangeRequest& request);

/// `gearbench report perf`: the performance history of the records in `dir`.
struct PerfReportRequest {
  std::string dir;
  std::string out_dir;
  double alpha = 0.05;
  double threshold = 0.05;
  std::string clock = "cpu";  ///< "cpu" or "real": which benchmark time is compared
  bool pdf = false;
};
int report_perf_command(const PerfReportRequest& request);

/// `gearbench report pdf`: PDF figures of a written report (from its report.json).
int report_pdf_command(const std::string& report_dir);

/// `gearbench sweep SWEEP.json`: a grid of cases through the kind registry, over MPI ranks
/// when started with mpirun.
int sweep_command(const std::string& sweep_path, const std::string& out_dir, bool pdf);

/// `gearbench lubricants [NAME --temperature-C T]`: the catalogue, or one oil's properties
/// at T with their sources.
int lubricants_command(const std::string& name, std::optional<double> temperature_C);

/// `gearbench schema [KIND]`: the JSON Schema of a kind's case files, or of every kind;
/// InputError for a kind that has none yet.
int schema_command(const std::string& kind);

/// Where `bench --record` writes and `report perf` reads: the checkout's reports/perf.
std::string default_perf_dir();

/// Where `verify` and `bench` write unless told otherwise: an ignored folder of the checkout.
std::string default_output_dir();
std::string default_cases_dir();

}  // namespace gearbench::app
