// Unit tests of benchmarking a commit range (issue 25): the choice and order of the runs,
// the records written for each commit (built, not built, lacking a benchmark), how
// `report perf` joins and flags them, and the verification report's Performance section,
// all on synthetic records; and the runner itself on a tiny git range with a fake build
// script and a fake benchmark executable (no compiler, no benchmark, no wall time asserted).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "bench_section.h"
#include "model/errors.h"
#include "model/json_reader.h"
#include "perf_history.h"
#include "perf_range.h"
#include "support/perf_support.h"
#include "support/temp_dir.h"

namespace gearbench::reports {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

TEST(PerfRange, EveryKthCountsBackFromTheNewest) {
  const std::vector<std::string> c{"a", "b", "c", "d", "e", "f", "g", "h", "i", "j"};
  EXPECT_EQ(every_kth(c, 1), c);
  EXPECT_EQ(every_kth(c, 3), (std::vector<std::string>{"a", "d", "g", "j"}));
  EXPECT_EQ(every_kth(c, 4), (std::vector<std::string>{"b", "f", "j"}));
  EXPECT_EQ(every_kth(c, 20), (std::vector<std::string>{"j"}));
  EXPECT_THROW(every_kth(c, 0), InputError);
}

TEST(PerfRange, RepetitionsInterleaveAcrossCommits) {
  // Every commit's repetition r before any commit's r + 1; odd rounds run backwards.
  const auto s = interleaved_schedule(3, 2);
  const std::vector<std::pair<int, std::size_t>> expected{{0, 0}, {0, 1}, {0, 2}, {1, 2}, {1, 1}, {1, 0}};
  EXPECT_EQ(s, expected);
  EXPECT_NE(interleaving_note(3, 2).find("interleaved"), std::string::npos);
}

TEST(PerfRange, SetsAreNamedAndTheShortOneIsAFilter) {
  EXPECT_FALSE(benchmark_set_filter("short").empty());
  EXPECT_TRUE(benchmark_set_filter("full").empty());
  EXPECT_THROW(benchmark_set_filter("tiny"), InputError);
}

/// One Google Benchmark output of one repetition: `ms` per run name, plus an aggregate.
json output(const std::map<std::string, double>& ms) {
  json out{{"context", {{"executable", "fake"}}}, {"benchmarks", json::array()}};
  for (const auto& [name, t] : ms) {
    out["benchmarks"].push_back({{"name", name}, {"run_name", name}, {"run_type", "iteration"}, {"repetitions", 1},
                                 {"repetition_index", 0}, {"iterations", 10}, {"real_time", t}, {"cpu_time", t},
                                 {"time_unit", "ms"}});
    out["benchmarks"].push_back({{"name", name + "_mean"}, {"run_name", name}, {"run_type", "aggregate"},
                                 {"aggregate_name", "mean"}, {"real_time", t}, {"cpu_time", t}, {"time_unit", "ms"}});
  }
  return out;
}

/// A commit of a range with `repetitions` outputs of `ms` each (±1 % deterministic spread).
CommitOutcome commit(const std::string& sha, const std::string& time, const std::map<std::string, double>& ms,
                     int repetitions = 10) {
  CommitOutcome o{.sha = sha + std::string(40 - sha.size(), '0'), .commit_time_utc = time};
  for (int r = 0; r < repetitions; ++r) {
    auto spread = ms;
    for (auto& [name, t] : spread) t *= 1.0 + 0.002 * ((r * 7) % 10 - 4.5);
    o.outputs.push_back(output(spread));
  }
  return o;
}

const json machine_provenance{{"code", {{"git_sha", "runner0000"}}},
                              {"build", {{"build_type", "Release"}}},
                              {"machine", {{"cpu_model", "CPU A"}, {"cores", 2}, {"hardware_fingerprint", "fpA"}}},
                              {"created_utc", "2026-11-25T15:00:00Z"}};

/// The records of a range as `gearbench bench --commits` writes them, read back.
std::vector<PerfRun> records_of(const std::vector<CommitOutcome>& outcomes) {
  RangeContext range{.set = "custom", .filter = "BM_", .repetitions = 10};
  for (const auto& o : outcomes) range.commits.push_back(o.sha);
  const auto missing = missing_benchmarks(outcomes);
  std::vector<PerfRun> runs;
  for (std::size_t k = 0; k < outcomes.size(); ++k)
    runs.push_back(parse_perf_record(range_record(outcomes[k], range, missing[k], machine_provenance),
                                     "r" + std::to_string(k) + ".json"));
  return runs;
}

TEST(PerfRange, JoinsRepetitionsAndDropsAggregates) {
  const auto joined = join_repetitions(commit("a", "t", {{"BM_X", 1.0}, {"BM_Y", 2.0}}, 3).outputs);
  ASSERT_EQ(joined["benchmarks"].size(), 6u);
  EXPECT_EQ(joined["benchmarks"][4]["repetition_index"], 2);
  EXPECT_EQ(joined["benchmarks"][4]["repetitions"], 3);
  EXPECT_EQ(run_names(joined), (std::vector<std::string>{"BM_X", "BM_Y"}));
  EXPECT_TRUE(join_repetitions({})["benchmarks"].empty());
}

TEST(PerfRange, RecordsSayWhatWasNotBuiltOrNotRun) {
  auto broken = commit("ccc", "2026-11-03T00:00:00Z", {}, 0);
  broken.status = "build_failed";
  broken.log_tail = "error: no such file\n";
  const auto runs = records_of({commit("aaa", "2026-11-01T00:00:00Z", {{"BM_X", 1.0}, {"BM_Y", 1.0}}),
                                commit("bbb", "2026-11-02T00:00:00Z", {{"BM_X", 1.0}}), broken});
  EXPECT_EQ(runs[0].sha, "aaa0000000");  // the short sha, as `bench --record` names a commit
  EXPECT_EQ(runs[0].seconds.at("BM_X").size(), 10u);
  EXPECT_TRUE(runs[0].missing.empty());
  EXPECT_EQ(runs[1].missing, (std::vector<std::string>{"BM_Y"}));
  EXPECT_EQ(runs[2].status, "build_failed");
  EXPECT_EQ(runs[2].missing, (std::vector<std::string>{"BM_X", "BM_Y"}));
  EXPECT_TRUE(runs[2].seconds.empty());
  // The record keeps the commit apart from the runner that measured it, and says how.
  RangeContext range{.set = "short", .filter = "BM_", .repetitions = 10, .commits = {broken.sha}};
  const auto r = range_record(broken, range, {}, machine_provenance);
  EXPECT_EQ(r["gearbench"]["runner_code"]["git_sha"], "runner0000");
  EXPECT_EQ(r["gearbench"]["code"]["git_sha_full"], broken.sha);
  EXPECT_EQ(r["gearbench"]["log_tail"], "error: no such file\n");
  EXPECT_NE(r["gearbench"]["range"]["interleaving"].get<std::string>().find("interleaved"), std::string::npos);
  EXPECT_EQ(r["gearbench"]["machine"]["hardware_fingerprint"], "fpA");
}

TEST(PerfRange, RegressionFlaggedAtTheCommitWhereItAppearsAcrossAFailedBuild) {
  auto broken = commit("ccc", "2026-11-03T00:00:00Z", {}, 0);
  broken.status = "build_failed";
  // BM_X slows by 30 % at bbb and stays there; BM_Y, missing at bbb, is compared with aaa.
  const auto h = analyse_perf_history(
      records_of({commit("aaa", "2026-11-01T00:00:00Z", {{"BM_X", 1.0}, {"BM_Y", 1.0}}),
                  commit("bbb", "2026-11-02T00:00:00Z", {{"BM_X", 1.3}}), broken,
                  commit("ddd", "2026-11-04T00:00:00Z", {{"BM_X", 1.3}, {"BM_Y", 1.0}})}),
      {});
  std::vector<std::string> flagged;
  for (const auto& c : h.changes)
    if (c.verdict == "regression") flagged.push_back(h.runs[c.after].sha);
  EXPECT_EQ(flagged, (std::vector<std::string>{"bbb0000000"}));
  bool y_joined = false, x_joined = false;
  for (const auto& c : h.changes) {
    y_joined |= c.name == "BM_Y" && c.before == 0 && c.after == 3 && c.verdict == "unchanged";
    x_joined |= c.name == "BM_X" && c.before == 1 && c.after == 3 && c.verdict == "unchanged";
  }
  EXPECT_TRUE(y_joined);
  EXPECT_TRUE(x_joined);
  EXPECT_TRUE(h.latest_regressions().empty());  // ddd, newer, has BM_X too
  ASSERT_FALSE(h.largest_changes(1).empty());
  EXPECT_EQ(h.largest_changes(1)[0]->name, "BM_X");
  EXPECT_NEAR(h.largest_changes(1)[0]->change, 0.3, 1e-12);
  // The figure of BM_X: median, fastest, slowest, and the flag at bbb (x = 1).
  const auto& f = h.figures.front();
  ASSERT_EQ(f.id, "time_BM_X");
  ASSERT_EQ(f.series.size(), 4u);
  EXPECT_EQ(f.series[3].label, "regression flagged (U test)");
  EXPECT_EQ(f.series[3].x, (std::vector<double>{1.0}));
  EXPECT_LT(f.series[1].y[0], f.series[0].y[0]);
  EXPECT_GT(f.series[2].y[0], f.series[0].y[0]);
  const auto md = h.markdown({});
  EXPECT_NE(md.find("**build_failed**"), std::string::npos);
  EXPECT_NE(md.find("lacks 1 benchmark(s): `BM_Y`"), std::string::npos);
  EXPECT_NE(md.find("## Largest changes"), std::string::npos);
}

// A benchmark run still writing (or killed while writing) its raw output, .bench-<pid>.json in
// the records' folder, is not a record and must not stop `verify` or `report perf`.
TEST(PerfHistory, HalfWrittenBenchOutputIsNotARecord) {
  const auto dir = gearbench::testing_support::temp_path("perf_hidden");
  fs::create_directories(dir);
  std::ofstream(dir / ".bench-1880.json") << "{\"benchmarks\": [";
  std::vector<PerfRun> runs;
  EXPECT_NO_THROW(runs = load_perf_records(dir.string()));
  EXPECT_TRUE(runs.empty());
  fs::remove_all(dir);
}

TEST(PerformanceSection, ThisCommitAgainstThePreviousRecordOfThisMachine) {
  std::vector<PerfRun> history;
  history.push_back(parse_perf_record(record("aaa", "2026-11-01T00:00:00Z", "A", {{"BM_X", reps(1.0)}}), "a.json"));
  history.push_back(parse_perf_record(record("bbb", "2026-11-02T00:00:00Z", "B", {{"BM_X", reps(5.0)}}), "b.json"));
  history.push_back(parse_perf_record(record("ccc", "2026-11-03T00:00:00Z", "A", {{"BM_X", reps(1.5)}}), "c.json"));
  const PerformanceQuery on_a{.sha = "ccc", .fingerprint = "fp-A", .build_type = "Release"};
  const auto note = performance_note(history, std::nullopt, on_a);
  EXPECT_EQ(note.section, "Performance");
  // Compared with aaa (the same machine), not bbb (the one just before, on another).
  EXPECT_NE(note.text.find("(`aaa`, a.json)"), std::string::npos) << note.text;
  EXPECT_NE(note.text.find("+50.0 %"), std::string::npos) << note.text;
  EXPECT_NE(note.text.find("**regression**"), std::string::npos) << note.text;
  // No record of this commit, or none before it on this machine: the section says so.
  EXPECT_NE(performance_note(history, std::nullopt, {.sha = "ddd", .fingerprint = "fp-A", .build_type = "Release"})
                .text.find("No benchmark record of commit `ddd`"),
            std::string::npos);
  EXPECT_NE(performance_note(history, std::nullopt, {.sha = "bbb", .fingerprint = "fp-B", .build_type = "Release"})
                .text.find("no earlier record"),
            std::string::npos);
}

/// Runs `command` in the shell and fails the test when it fails.
void shell(const std::string& command) { ASSERT_EQ(std::system(command.c_str()), 0) << command; }

TEST(PerfRangeCli, TinyRangeWithAFakeBuildWritesJoinsAndFlags) {
  // A git repository of five commits: a base, then a "benchmark" of 1 ms, 2 ms, one whose
  // benchmarks crash and one that does not build. The fake build script "builds" a commit into
  // an executable that writes Google Benchmark JSON with the commit's time; the runner sees
  // only the script's contract.
  const auto dir = gearbench::testing_support::temp_path("perf_range");
  fs::remove_all(dir);
  fs::create_directories(dir / "repo");
  const auto repo = (dir / "repo").string();
  const std::string git = "git -C '" + repo + "' -c user.name=t -c user.email=t@t ";
  shell(git + "init -q");
  int day = 1;
  for (const char* ms : {"base", "1.0", "2.0", "crash", "broken"}) {
    std::ofstream(dir / "repo" / "ms.txt") << ms << "\n";
    shell(git + "add ms.txt");
    shell("GIT_COMMITTER_DATE='2026-11-0" + std::to_string(day) + "T00:00:00Z' " + git + "commit -q -m " + ms);
    ++day;
  }
  std::ofstream(dir / "build.sh") << R"(#!/bin/sh
set -eu
[ "$1" != --clean ] || exit 0
ms=$(git -C ')" << repo << R"(' show "$1:ms.txt")
[ "$ms" != broken ] || { echo "ms.txt: broken" >&2; exit 1; }
mkdir -p "$2"
exe="$2/bench-$1"
cat > "$exe" <<EOS
#!/bin/sh
[ "$ms" != crash ] || { echo "BM_Fast: crashed" >&2; exit 3; }
for a in "\$@"; do case "\$a" in --benchmark_out=*) out="\${a#--benchmark_out=}";; esac; done
printf '{"context":{},"benchmarks":[{"name":"BM_Fast","run_name":"BM_Fast","run_type":"iteration","repetitions":1,"repetition_index":0,"iterations":1,"real_time":$ms,"cpu_time":$ms,"time_unit":"ms"}]}' > "\$out"
EOS
chmod +x "$exe"
echo "$exe"
)";
  fs::permissions(dir / "build.sh", fs::perms::owner_all);
  const std::string args = "bench --commits HEAD~4..HEAD --repetitions 4 --filter BM_Fast --repo '" + repo +
                           "' --workdir '" + (dir / "work").string() + "' --build-script '" +
                           (dir / "build.sh").string() + "' --out '" + (dir / "records").string() + "'";
  // Every record is written, but a range with a failed commit is not a success: exit 1, and
  // stderr names exactly the failed commits, each with why.
  ASSERT_EQ(run_gearbench(args, dir / "log"), 1) << slurp(dir / "log");
  const auto log = slurp(dir / "log");
  const auto runs = load_perf_records((dir / "records").string());
  ASSERT_EQ(runs.size(), 4u) << log;
  std::map<std::string, const PerfRun*> by_status;
  for (const auto& r : runs) by_status[r.status + (r.seconds.count("BM_Fast") ? "" : "-")] = &r;
  ASSERT_TRUE(by_status.count("build_failed-")) << log;
  ASSERT_TRUE(by_status.count("run_failed-")) << log;
  const auto failures_at = log.find("error: 2 of 4 commits failed");
  ASSERT_NE(failures_at, std::string::npos) << log;
  const auto broken_at = log.find(by_status["build_failed-"]->sha + " (2026-11-05T00:00:00Z) does not build");
  const auto crash_at = log.find(by_status["run_failed-"]->sha + " (2026-11-04T00:00:00Z) its benchmarks failed");
  ASSERT_NE(broken_at, std::string::npos) << log;
  ASSERT_NE(crash_at, std::string::npos) << log;
  EXPECT_GT(std::min(broken_at, crash_at), failures_at) << log;
  EXPECT_NE(log.find("| ms.txt: broken", broken_at), std::string::npos) << log;
  EXPECT_NE(log.find("| BM_Fast: crashed", crash_at), std::string::npos) << log;
  EXPECT_NE(log.find("exited with code 3 at repetition 1", crash_at), std::string::npos) << log;
  for (const auto& r : runs)
    if (r.status == "ok") {
      EXPECT_EQ(log.find(r.sha, failures_at), std::string::npos) << r.sha << " ran\n" << log;
      EXPECT_EQ(r.seconds.at("BM_Fast").size(), 4u);
    }
  const json broken = model::read_json_file(by_status["build_failed-"]->file);
  EXPECT_NE(broken["gearbench"]["log_tail"].get<std::string>().find("ms.txt: broken"), std::string::npos);
  // report perf joins them in commit order and flags the doubling at the second commit.
  const std::string report = "report perf --dir '" + (dir / "records").string() + "' --out '" + (dir / "out").string() + "'";
  EXPECT_EQ(run_gearbench(report, dir / "log"), 1) << slurp(dir / "log");
  EXPECT_NE(slurp(dir / "log").find("REGRESSION time BM_Fast: +100.0 %"), std::string::npos) << slurp(dir / "log");
  EXPECT_TRUE(fs::exists(dir / "out" / "figures" / "time_BM_Fast.csv"));
  fs::remove_all(dir);
}

TEST(PerfRangeCli, EachCommitRunsOnItsOwnFilesAndBuild) {
  // scripts/build-commit itself, on a tiny CMake project with no compiler: its "benchmark"
  // is a shell script with the source folder configured in (as GEARBENCH_SOURCE_DIR is
  // compiled into the real ones). BM_Case reads cases/ms.txt from there at run time, as
  // BM_TehlPath reads its case; BM_Built starts the project's app/gearbench, a build product
  // made from the same file, as BM_Startup starts gearbench. Two commits, 1 ms and 2 ms, are
  // built one after the other in the same worktree: each must report its own time, not the
  // last-built commit's.
  const auto dir = gearbench::testing_support::temp_path("perf_tree");
  fs::remove_all(dir);
  fs::create_directories(dir / "repo" / "scripts");
  fs::create_directories(dir / "repo" / "cases");
  const auto repo = (dir / "repo").string();
  fs::copy_file(fs::path(GEARBENCH_SOURCE_DIR) / "scripts" / "build-commit", dir / "repo" / "scripts" / "build-commit");
  std::ofstream(dir / "repo" / "CMakeLists.txt") << R"(cmake_minimum_required(VERSION 3.20)
project(tiny LANGUAGES NONE)
file(STRINGS cases/ms.txt MS)
configure_file(app.in app/gearbench @ONLY FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
configure_file(bench.in benchmarks/gearbench_benchmarks @ONLY FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
add_custom_target(gearbench_benchmarks)
)";
  std::ofstream(dir / "repo" / "app.in") << "#!/bin/sh\necho @MS@\n";
  std::ofstream(dir / "repo" / "bench.in") << R"SH(#!/bin/sh
case_ms=$(cat '@PROJECT_SOURCE_DIR@/cases/ms.txt')
built_ms=$('@PROJECT_BINARY_DIR@/app/gearbench')
for a in "$@"; do case "$a" in --benchmark_out=*) out="${a#--benchmark_out=}";; esac; done
run() { printf '{"name":"%s","run_name":"%s","run_type":"iteration","repetitions":1,"repetition_index":0,"iterations":1,"real_time":%s,"cpu_time":%s,"time_unit":"ms"}' "$1" "$1" "$2" "$2"; }
printf '{"context":{},"benchmarks":[%s,%s]}' "$(run BM_Case "$case_ms")" "$(run BM_Built "$built_ms")" > "$out"
)SH";
  const std::string git = "git -C '" + repo + "' -c user.name=t -c user.email=t@t ";
  shell(git + "init -q");
  int day = 1;
  for (const char* ms : {"0.5", "1.0", "2.0"}) {
    std::ofstream(dir / "repo" / "cases" / "ms.txt") << ms << "\n";
    shell(git + "add -A");
    shell("GIT_COMMITTER_DATE='2026-11-0" + std::to_string(day) + "T00:00:00Z' " + git + "commit -q -m " + ms);
    ++day;
  }
  const std::string args = "bench --commits HEAD~2..HEAD --repetitions 2 --filter BM_ --repo '" + repo +
                           "' --workdir '" + (dir / "work").string() + "' --build-script '" + repo +
                           "/scripts/build-commit' --out '" + (dir / "records").string() + "'";
  ASSERT_EQ(run_gearbench(args, dir / "log"), 0) << slurp(dir / "log");
  auto runs = load_perf_records((dir / "records").string());
  ASSERT_EQ(runs.size(), 2u) << slurp(dir / "log");
  std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.order_key < b.order_key; });
  for (const auto& [k, seconds] : {std::pair{0, 1e-3}, std::pair{1, 2e-3}})
    for (const char* name : {"BM_Case", "BM_Built"}) {
      ASSERT_EQ(runs[k].seconds.count(name), 1u) << name << "\n" << slurp(dir / "log");
      EXPECT_EQ(runs[k].seconds.at(name), (std::vector<double>{seconds, seconds})) << runs[k].sha << " " << name;
    }
  // The builds are removed at the end, the worktree with them.
  EXPECT_FALSE(fs::exists(dir / "work" / "tree"));
  EXPECT_FALSE(fs::exists(dir / "work" / "checkout"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gearbench::reports
