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

json side_by_side_ratios(const json& benchmarks) {
  std::map<std::string, std::pair<std::string, double>> times;  // family -> (run name, time)
  for (const auto& b : benchmarks)
    if (b.value("run_type", "iteration") == "iteration" || b.value("aggregate_name", "") == "median") {
      const auto name = b["run_name"].get<std::string>();
      times.try_emplace(family(name), name, b["real_time"].get<double>());
    }
  json ratios = json::object();
  const std::string suffix = "_baseline";
  for (const auto& [fam, baseline] : times) {
    if (fam.size() <= suffix.size() || fam.compare(fam.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    const auto it = times.find(fam.substr(0, fam.size() - suffix.size()));
    if (it == times.end() || baseline.second <= 0.0) continue;
    ratios[it->second.first] = {{"baseline", baseline.first},
                                {"solver_time", it->second.second},
                                {"baseline_time", baseline.second},
                                {"ratio", it->second.second / baseline.second}};
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
