#pragma once
// Synthetic benchmark records and the CLI runner shared by the performance tests
// (perf_test.cpp, perf_range_test.cpp): no benchmark is run to make them.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace gearbench::reports {

/// A `gearbench bench` record: `times` are per-repetition real times in ms.
inline nlohmann::json record(const std::string& sha, const std::string& commit_time, const std::string& cpu,
                                   const std::map<std::string, std::vector<double>>& times) {
  using nlohmann::json;
  json benchmarks = json::array();
  for (const auto& [name, reps] : times)
    for (std::size_t i = 0; i < reps.size(); ++i)
      benchmarks.push_back({{"name", name}, {"run_name", name}, {"run_type", "iteration"},
                            {"repetitions", reps.size()}, {"repetition_index", i}, {"real_time", reps[i]},
                            {"cpu_time", reps[i]}, {"time_unit", "ms"}});
  json ratios = json::object();
  for (const auto& [name, reps] : times)
    if (times.count(name + "_baseline")) ratios[name] = {{"baseline", name + "_baseline"}};
  return {{"benchmarks", benchmarks},
          {"ratios", ratios},
          {"gearbench",
           {{"code", {{"git_sha", sha}, {"dirty", false}, {"commit_time_utc", commit_time}}},
            {"build", {{"build_type", "Release"}}},
            {"machine", {{"cpu_model", cpu}, {"cores", 2}, {"memory_GiB", 24}, {"hardware_fingerprint", "fp-" + cpu}}},
            {"created_utc", "2026-11-22T12:00:00Z"}}}};
}

/// Ten repetitions around `centre` with a fixed ±1 % spread (deterministic "noise").
inline std::vector<double> reps(double centre) {
  std::vector<double> v;
  for (int i = 0; i < 10; ++i) v.push_back(centre * (1.0 + 0.002 * ((i * 7) % 10 - 4.5)));
  return v;
}

inline int run_gearbench(const std::string& args, const std::filesystem::path& log) {
  const std::string command = std::string("'") + GEARBENCH_EXE + "' " + args + " >'" + log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace gearbench::reports
