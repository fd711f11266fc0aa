// `gearbench bench`: runs the Google Benchmark suite and stores its JSON together with the
// git, build and machine context (Google Benchmark records none of these itself) and the
// side-by-side ratios: a benchmark named X_baseline pairs with X in the same run.
// With --record the run has repetitions (for the U test of `gearbench report perf`) and
// lands in reports/perf/<date>_<sha>.json, the performance history of the checkout.
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <iostream>
#include <unistd.h>

#include "bench_support.h"
#include "build_info.h"
#include "commands.h"
#include "model/errors.h"
#include "model/json_reader.h"
#include "perf_history.h"
#include "bench_ratios.h"
#include "report.h"

namespace gearbench::app {

namespace fs = std::filesystem;
using nlohmann::json;

void BenchRequest::validate() const {
  if (!(min_time > 0.0)) throw InputError(fmt::format("--min-time = {}: must be > 0 s", min_time));
  if (repetitions < 1 || repetitions > 1000)
    throw InputError(fmt::format("--repetitions = {}: must lie in [1, 1000]", repetitions));
}

int bench_command(const BenchRequest& request) {
  request.validate();
  const std::string exe = build::benchmark_executable();
  if (!fs::exists(exe))
    throw InputError(fmt::format("benchmark executable {} not built (configure with "
                                 "GEARBENCH_BUILD_BENCHMARKS=ON)", exe));
  fs::create_directories(request.out_dir);
  const auto raw = fs::path(request.out_dir) / fmt::format(".bench-{}.json", ::getpid());
  // Every repetition goes into the file (the U test needs them); the console shows only
  // the aggregates. Interleaving the repetitions of all benchmarks keeps a slow drift of
  // the machine from landing on one benchmark.
  const std::string repetitions =
      request.repetitions > 1
          ? fmt::format("--benchmark_repetitions={} --benchmark_display_aggregates_only=true "
                        "--benchmark_enable_random_interleaving=true ", request.repetitions)
          : std::string();
  const std::string command = fmt::format(
      "'{}' --benchmark_format=console --benchmark_out='{}' --benchmark_out_format=json "
      "--benchmark_min_time={} {}{} 1>&2",
      exe, raw.string(), request.min_time, repetitions,
      request.filter.empty() ? "" : fmt::format("--benchmark_filter='{}'", request.filter));
  std::cerr << "running " << exe << "\n";
  if (std::system(command.c_str()) != 0) {
    fs::remove(raw);
    throw std::runtime_error("the benchmark executable failed");
  }
  json record = reports::parse_benchmark_output(model::read_text_file(raw.string(), "benchmark output"), raw.string());
  fs::remove(raw);
  record["gearbench"] = reports::provenance();
  if (const auto t = commit_time_utc(build::source_dir(), build::git_sha()); !t.empty())
    record["gearbench"]["code"]["commit_time_utc"] = t;
  record["gearbench"]["repetitions"] = request.repetitions;
  record["ratios"] = reports::side_by_side_ratios(record["benchmarks"]);
  record["scaling"] = reports::scaling_exponents(record["benchmarks"]);
  const auto name = reports::report_folder_name();
  const auto target = free_path(request.out_dir, request.record ? name : "bench_" + name);
  write_record(target, record);
  for (const auto& [run, r] : record["ratios"].items())
    std::cerr << fmt::format("{}: {}{:.3g} x baseline\n", run, r.value("baseline_converged", true) ? "" : "< ",
                             r["ratio"].get<double>());
  for (const auto& [family, s] : record["scaling"].items())
    std::cerr << fmt::format("{}: time ∝ nodes^{:.3g}\n", family, s["exponent"].get<double>());
  std::cout << target.string() << "\n";
  return exit_ok;
}

}  // namespace gearbench::app
