// Start-up of the gearbench executable (issue 27): `gearbench --version` and a `geometry`
// case, side by side with /bin/true started the same way in the same run, so that the
// ratio BM_Startup/<what> / BM_Startup_baseline is the start-up cost over a trivial process
// on whatever machine. Targets: under 20 ms and 20 MiB for every kind but fe_stiffness.
// The time is wall clock from spawn to exit; the counters add the child's own CPU time
// (user + system) and its peak resident memory, which cannot read below this process's own
// (~6 MiB, the baseline's figure): Linux carries the spawning process's peak into the child
// across exec. Google Benchmark's cpu_time is this process's time spent spawning and
// waiting, not the child's: compare these runs by real time (`report perf --clock real`) or
// by child_cpu_ms.
#include <benchmark/benchmark.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <fcntl.h>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace {

struct ChildRun {
  double seconds = 0.0;      ///< wall clock, spawn to exit
  double cpu_seconds = 0.0;  ///< the child's user + system time
  double max_rss_MiB = 0.0;  ///< the child's peak resident set
};

double seconds(const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); }

/// Runs `argv` with stdout and stderr on /dev/null; std::runtime_error unless it exits 0.
ChildRun run_child(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error("cannot start " + argv[0]);
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(argv[0] + " did not exit with 0");
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
          seconds(usage.ru_utime) + seconds(usage.ru_stime), static_cast<double>(usage.ru_maxrss) / 1024.0};
}

void BM_Startup(benchmark::State& state, const std::vector<std::string>& argv) {
  double cpu = 0.0, rss = 0.0;
  for (auto _ : state) {
    try {
      const auto run = run_child(argv);
      state.SetIterationTime(run.seconds);
      cpu += run.cpu_seconds;
      rss = std::max(rss, run.max_rss_MiB);
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      return;
    }
  }
  state.counters["child_cpu_ms"] = benchmark::Counter(1e3 * cpu, benchmark::Counter::kAvgIterations);
  state.counters["max_rss_MiB"] = rss;
}

const std::string case_dir = GEARBENCH_SOURCE_DIR "/cases/";

const bool registered = [] {
  const auto add = [](const std::string& name, std::vector<std::string> argv) {
    benchmark::RegisterBenchmark(name.c_str(), BM_Startup, std::move(argv))
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  };
  add("BM_Startup_baseline", {"/bin/true"});
  add("BM_Startup/version", {GEARBENCH_EXE, "--version"});
  add("BM_Startup/geometry", {GEARBENCH_EXE, "run", case_dir + "seed004_spur_geometry.json"});
  return true;
}();

}  // namespace
