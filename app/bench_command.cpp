// `gearbench bench`: runs the Google Benchmark suite and stores its JSON together with the
// git, build and machine context (Google Benchmark records none of these itself) and the
// side-by-side ratios: a benchmark named X_baseline pairs with X in the same run.
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <map>
#include <unistd.h>

#include "build_info.h"
#include "commands.h"
#include "model/errors.h"
#include "model/json_reader.h"
#include "report.h"

namespace gearbench::app {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {
/// Benchmark family: the name without its arguments ("BM_X/101" -> "BM_X").
std::string family(const std::string& run_name) { return run_name.substr(0, run_name.find('/')); }

/// Solver over baseline for every run X[/args] that has a run X_baseline[/args] with the same
/// arguments, or a baseline without arguments for its whole family.
json side_by_side_ratios(const json& benchmarks) {
  std::map<std::string, double> times;  // run name -> time
  for (const auto& b : benchmarks)
    if (b.value("run_type", "iteration") == "iteration" || b.value("aggregate_name", "") == "median")
      times.try_emplace(b["run_name"].get<std::string>(), b["real_time"].get<double>());
  const std::string suffix = "_baseline";
  json ratios = json::object();
  for (const auto& [name, time] : times) {
    const std::string fam = family(name);
    if (fam.size() > suffix.size() && fam.compare(fam.size() - suffix.size(), suffix.size(), suffix) == 0) continue;
    const std::string args = name.substr(fam.size());
    for (const std::string& baseline : {fam + suffix + args, fam + suffix}) {
      const auto it = times.find(baseline);
      if (it == times.end() || it->second <= 0.0) continue;
      ratios[name] = {{"baseline", baseline}, {"solver_time", time}, {"baseline_time", it->second},
                      {"ratio", time / it->second}};
      break;
    }
  }
  return ratios;
}
}  // namespace

int bench_command(const std::string& out_dir, const std::string& filter, double min_time) {
  const std::string exe = build::benchmark_executable();
  if (!fs::exists(exe))
    throw InputError(fmt::format("benchmark executable {} not built (configure with "
                                 "GEARBENCH_BUILD_BENCHMARKS=ON)", exe));
  fs::create_directories(out_dir);
  const auto raw = fs::path(out_dir) / fmt::format(".bench-{}.json", ::getpid());
  const std::string command = fmt::format(
      "'{}' --benchmark_format=console --benchmark_out='{}' --benchmark_out_format=json "
      "--benchmark_min_time={} {} 1>&2",
      exe, raw.string(), min_time, filter.empty() ? "" : fmt::format("--benchmark_filter='{}'", filter));
  std::cerr << "running " << exe << "\n";
  if (std::system(command.c_str()) != 0) {
    fs::remove(raw);
    throw std::runtime_error("the benchmark executable failed");
  }
  json record = model::read_json_file(raw.string());
  fs::remove(raw);
  record["gearbench"] = reports::provenance();
  record["ratios"] = side_by_side_ratios(record["benchmarks"]);
  const auto target = fs::path(out_dir) / fmt::format("bench_{}.json", reports::report_folder_name());
  const auto temp = fs::path(target.string() + ".tmp");
  std::ofstream(temp) << record.dump(2) << "\n";
  fs::rename(temp, target);
  for (const auto& [name, r] : record["ratios"].items())
    std::cerr << fmt::format("{}: {:.3g} x baseline\n", name, r["ratio"].get<double>());
  std::cout << target.string() << "\n";
  return exit_ok;
}

}  // namespace gearbench::app
