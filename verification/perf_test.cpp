// Unit tests of the performance history: the Mann–Whitney U test against hand-computed
// values and a published example, and `report perf` logic on synthetic benchmark records
// (no benchmark is run here, and no wall time is asserted).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>

#include "bench_ratios.h"
#include "bench_section.h"
#include "support/perf_support.h"
#include "mann_whitney.h"
#include "model/errors.h"
#include "perf_history.h"
#include "report.h"
#include "support/temp_dir.h"

namespace gearbench::reports {
namespace {

using nlohmann::json;

// p-values are sums of a few exact fractions or one erfc evaluation: 1e-12 relative is
// far below any decision (alpha = 0.05) and far above double rounding.
constexpr double p_tol = 1e-12;

TEST(MannWhitney, UStatisticCountsPairsWithHalfTies) {
  // Pooled 1 2 2 3 4 -> ranks 1, 2.5, 2.5, 4, 5; R1 = 1 + 2.5 + 4 = 7.5, U1 = 7.5 − 6 = 1.5:
  // pairs x > y: (3, 2); ties: (2, 2) counts 1/2.
  EXPECT_DOUBLE_EQ(u_statistic({1, 2, 3}, {2, 4}), 1.5);
  EXPECT_DOUBLE_EQ(u_statistic({2, 4}, {1, 2, 3}), 6.0 - 1.5);
}

TEST(MannWhitney, PublishedDiabetesExample) {
  // Shier (2004), "Statistics: 2.3 The Mann-Whitney U Test", as reproduced in scipy's
  // mannwhitneyu documentation: ages at diagnosis, U_M = 17, U_F = 3, exact two-sided
  // p = 0.1111 (= 2·7/126: 7 of the C(9,4) = 126 arrangements have U ≤ 3), and with the
  // normal approximation and continuity correction p = 0.11134688653314041.
  const std::vector<double> males{19, 22, 16, 29, 24}, females{20, 11, 17, 12};
  const auto exact = mann_whitney_u(males, females);
  EXPECT_TRUE(exact.exact);  // 4 values, no ties: scipy's 'auto' picks exact
  EXPECT_DOUBLE_EQ(exact.u1, 17.0);
  EXPECT_DOUBLE_EQ(exact.u2, 3.0);
  EXPECT_NEAR(exact.p_value, 14.0 / 126.0, p_tol);
  const auto normal = mann_whitney_u(males, females, UTestMethod::asymptotic);
  EXPECT_FALSE(normal.exact);
  EXPECT_NEAR(normal.p_value, 0.11134688653314041, p_tol);
  // Symmetric in the order of the samples.
  EXPECT_NEAR(mann_whitney_u(females, males).p_value, exact.p_value, p_tol);
}

TEST(MannWhitney, ExactSmallSamplesByHand) {
  // Fully separated samples: only 1 of C(n1+n2, n1) arrangements is as extreme each way.
  EXPECT_NEAR(mann_whitney_u({1, 2, 3}, {4, 5, 6}).p_value, 2.0 / 20.0, p_tol);
  // Two repetitions each can never reach p < 0.05: 2/6.
  EXPECT_NEAR(mann_whitney_u({1, 2}, {3, 4}).p_value, 2.0 / 6.0, p_tol);
  // Interleaved x y x y: U1 = 1, U = max(U1, U2) = 3. The 6 arrangements of 2 + 2 have
  // U = 0, 1, 2, 2, 3, 4, so P(U ≥ 3) = 2/6 and p = 4/6.
  EXPECT_NEAR(mann_whitney_u({1, 3}, {2, 4}).p_value, 4.0 / 6.0, p_tol);
  // Identical location: p = 1 (clamped from 2·P(U ≥ n1n2/2) > 1).
  EXPECT_DOUBLE_EQ(mann_whitney_u({1, 4}, {2, 3}).p_value, 1.0);
}

TEST(MannWhitney, NormalApproximationWithTiesByHand) {
  // x = 1 2 2 3 5, y = 2 4 4 6 7 8 9 9 10 (ties: asymptotic). U1 = 0 + ½ + ½ + 1 + 3 = 5,
  // U = 40, tie groups of 3, 2, 2: Σ(t³ − t) = 36, σ² = 45/12·(15 − 36/182) = 55.5082;
  // z = (40 − 22.5 − 0.5)/σ = 2.28176, p = 2·Q(z) = 0.0225034442530469.
  const auto r = mann_whitney_u({1, 2, 2, 3, 5}, {2, 4, 4, 6, 7, 8, 9, 9, 10});
  EXPECT_FALSE(r.exact);
  EXPECT_DOUBLE_EQ(r.u1, 5.0);
  EXPECT_NEAR(r.p_value, 0.022503444253046942, p_tol);
  // 10 vs 10 separated (n > 8: asymptotic): U = 100, σ² = 100·21/12,
  // z = 49.5/13.2288 = 3.74185, p = 1.826717911095504e-4.
  std::vector<double> low, high;
  for (int i = 0; i < 10; ++i) {
    low.push_back(i);
    high.push_back(10 + i);
  }
  EXPECT_NEAR(mann_whitney_u(high, low).p_value, 1.826717911095504e-4, 1e-15);
}

TEST(MannWhitney, TooFewRepetitionsThrow) {
  EXPECT_THROW(mann_whitney_u({1.0}, {2.0, 3.0}), std::invalid_argument);
}

const PerfChange* find_change(const PerfHistory& h, const std::string& name, bool ratio, std::size_t after) {
  for (const auto& c : h.changes)
    if (c.name == name && c.ratio == ratio && c.after == after) return &c;
  return nullptr;
}

TEST(PerfHistory, FlagsSlowdownOnlyAboveThresholdAndSignificance) {
  std::vector<PerfRun> runs;
  // Given out of order: the history is ordered by commit time.
  runs.push_back(parse_perf_record(record("ccc", "2026-11-03T00:00:00Z", "A", {{"BM_X", reps(1.3)}, {"BM_Y", reps(1.02)}}), "c.json"));
  runs.push_back(parse_perf_record(record("aaa", "2026-11-01T00:00:00Z", "A", {{"BM_X", reps(1.0)}, {"BM_Y", reps(1.0)}}), "a.json"));
  runs.push_back(parse_perf_record(record("bbb", "2026-11-02T00:00:00Z", "A", {{"BM_X", reps(1.0)}, {"BM_Y", reps(1.0)}}), "b.json"));
  const auto h = analyse_perf_history(runs, {});
  ASSERT_EQ(h.runs.size(), 3u);
  EXPECT_EQ(h.runs[0].sha, "aaa");
  EXPECT_EQ(h.runs[2].sha, "ccc");

  const auto* same = find_change(h, "BM_X", false, 1);
  ASSERT_NE(same, nullptr);
  EXPECT_EQ(same->verdict, "unchanged");  // identical samples: p = 1
  const auto* slow = find_change(h, "BM_X", false, 2);
  ASSERT_NE(slow, nullptr);
  EXPECT_EQ(slow->verdict, "regression");
  EXPECT_NEAR(slow->change, 0.3, 1e-12);  // medians scale exactly with the centre
  EXPECT_LT(slow->p_value, 1e-3);         // 10 vs 10 fully separated: 1.83e-4
  // +2 %: just as significant, but below the 5 % threshold.
  const auto* small = find_change(h, "BM_Y", false, 2);
  ASSERT_NE(small, nullptr);
  EXPECT_LT(small->p_value, 0.05);
  EXPECT_EQ(small->verdict, "unchanged");
  ASSERT_EQ(h.latest_regressions().size(), 1u);
  EXPECT_EQ(h.latest_regressions()[0]->name, "BM_X");
  // A faster run is an improvement, never a regression.
  runs.push_back(parse_perf_record(record("ddd", "2026-11-04T00:00:00Z", "A", {{"BM_X", reps(1.0)}}), "d.json"));
  const auto later = analyse_perf_history(runs, {});
  EXPECT_EQ(find_change(later, "BM_X", false, 3)->verdict, "improvement");
  EXPECT_TRUE(later.latest_regressions().empty());
}

TEST(PerfHistory, TimesOnlyOnTheSameMachineRatiosAcross) {
  std::vector<PerfRun> runs;
  runs.push_back(parse_perf_record(record("aaa", "2026-11-01T00:00:00Z", "fast CPU",
                                          {{"BM_S", reps(1.0)}, {"BM_S_baseline", reps(2.0)}}), "a.json"));
  // Another machine, three times slower in absolute terms, and the solver lost ground
  // against its baseline: ratio 0.5 -> 0.8.
  runs.push_back(parse_perf_record(record("bbb", "2026-11-02T00:00:00Z", "slow CPU",
                                          {{"BM_S", reps(4.8)}, {"BM_S_baseline", reps(6.0)}}), "b.json"));
  const auto h = analyse_perf_history(runs, {});
  EXPECT_EQ(find_change(h, "BM_S", false, 1), nullptr);  // no time comparison across machines
  const auto* ratio = find_change(h, "BM_S", true, 1);
  ASSERT_NE(ratio, nullptr);
  EXPECT_NEAR(ratio->median_before, 0.5, 1e-12);
  EXPECT_NEAR(ratio->median_after, 0.8, 1e-12);
  EXPECT_EQ(ratio->verdict, "regression");
  // One figure per benchmark and per ratio, its series per machine, commits on the x axis.
  ASSERT_EQ(h.figures.size(), 3u);
  EXPECT_EQ(h.figures[0].series.size(), 6u);  // per machine: median, fastest, slowest
  EXPECT_EQ(h.figures[0].xtic_labels, (std::vector<std::string>{"aaa", "bbb"}));
  const std::string md = h.markdown({});
  EXPECT_NE(md.find("**regression**"), std::string::npos);
  EXPECT_EQ(md.find("nan"), std::string::npos);
}

TEST(PerfHistory, SingleRepetitionsAreNotTested) {
  std::vector<PerfRun> runs;
  runs.push_back(parse_perf_record(record("aaa", "2026-11-01T00:00:00Z", "A", {{"BM_X", {1.0}}}), "a.json"));
  runs.push_back(parse_perf_record(record("bbb", "2026-11-02T00:00:00Z", "A", {{"BM_X", {2.0}}}), "b.json"));
  const auto h = analyse_perf_history(runs, {});
  ASSERT_EQ(h.changes.size(), 1u);
  EXPECT_EQ(h.changes[0].verdict, "untested");
  EXPECT_TRUE(h.latest_regressions().empty());
}

TEST(PerfHistory, ClockSelectsCpuOrRealTime) {
  json r = record("aaa", "2026-11-01T00:00:00Z", "A", {{"BM_X", {1.0, 1.0}}});
  for (auto& b : r["benchmarks"]) b["cpu_time"] = 0.5;  // ms, as real_time
  EXPECT_DOUBLE_EQ(parse_perf_record(r, "a.json").seconds["BM_X"][0], 0.5e-3);  // CPU by default
  EXPECT_DOUBLE_EQ(parse_perf_record(r, "a.json", PerfClock::real).seconds["BM_X"][0], 1.0e-3);
  EXPECT_THROW(parse_perf_clock("wall"), gearbench::InputError);
}

TEST(PerfHistory, RejectsWhatIsNotARecordAndBadOptions) {
  EXPECT_THROW(parse_perf_record(json{{"benchmarks", json::array()}}, "x.json"), gearbench::InputError);
  EXPECT_THROW(analyse_perf_history({}, {.alpha = 1.5}), gearbench::InputError);
  EXPECT_THROW(analyse_perf_history({}, {.threshold = -0.1}), gearbench::InputError);
}

TEST(FigureCsv, DataNextToTheFigureWithoutNaN) {
  const auto path = gearbench::testing_support::temp_path("fig.csv");
  Figure f{.id = "f", .section = "s", .title = "t", .xlabel = "commit", .ylabel = "time, ms",
           .series = {{"machine \"A\"", {0.0, 1.0}, {1.5, std::nan("")}}}};
  f.xtic_labels = {"aaa", "bbb"};
  write_figure_csv(f, path.string());
  std::ifstream in(path);
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  EXPECT_EQ(text, "series,commit,label,\"time, ms\"\n\"machine \"\"A\"\"\",0,aaa,1.5\n\"machine \"\"A\"\"\",1,bbb,\n");
  std::filesystem::remove(path);
}

TEST(Provenance, HardwareFingerprintIsStableAndRecorded) {
  EXPECT_EQ(hardware_fingerprint(), hardware_fingerprint());
  EXPECT_EQ(hardware_fingerprint().size(), 16u);
  const auto p = provenance();
  EXPECT_EQ(p["machine"]["hardware_fingerprint"], hardware_fingerprint());
  EXPECT_GT(p["machine"]["memory_GiB"].get<long>(), 0);
}

TEST(PerfCli, ReportPerfFlagsTheNewestRegressionAndWritesFigures) {
  namespace fs = std::filesystem;
  const auto dir = gearbench::testing_support::temp_path("perf_cli");
  fs::remove_all(dir);
  fs::create_directories(dir / "records");
  std::ofstream(dir / "records" / "a.json")
      << record("aaa", "2026-11-01T00:00:00Z", "A", {{"BM_S", reps(1.0)}, {"BM_S_baseline", reps(2.0)}}).dump();
  std::ofstream(dir / "records" / "b.json")
      << record("bbb", "2026-11-02T00:00:00Z", "A", {{"BM_S", reps(1.5)}, {"BM_S_baseline", reps(2.0)}}).dump();
  std::ofstream(dir / "records" / "report.json") << json{{"schema_version", 1}}.dump();  // not a record: passed over
  const std::string args = "report perf --dir '" + (dir / "records").string() + "' --out '" + (dir / "out").string() + "'";
  EXPECT_EQ(run_gearbench(args, dir / "log"), 1) << slurp(dir / "log");  // +50 %: exit 1
  EXPECT_NE(slurp(dir / "log").find("REGRESSION time BM_S: +50.0 %"), std::string::npos) << slurp(dir / "log");
  for (const char* f : {"perf.md", "perf.json", "figures/time_BM_S.csv", "figures/ratio_BM_S.csv"})
    EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  // A looser threshold lets the same history pass.
  EXPECT_EQ(run_gearbench(args + " --threshold 0.6", dir / "log"), 0) << slurp(dir / "log");
  EXPECT_EQ(run_gearbench("report perf --dir '" + (dir / "nothing").string() + "'", dir / "log"), 2);
  fs::remove_all(dir);
}

TEST(PerfCli, BenchRejectsBadRepetitionsBeforeRunningAnything) {
  const auto log = gearbench::testing_support::temp_path("bench_bad");
  EXPECT_EQ(run_gearbench("bench --record --repetitions 0 --out '" + log.string() + "_dir'", log), 2);
  EXPECT_NE(slurp(log).find("--repetitions = 0"), std::string::npos) << slurp(log);
  EXPECT_FALSE(std::filesystem::exists(log.string() + "_dir"));
  std::filesystem::remove(log);
}

TEST(PerfCli, ReportPdfDrawsEveryFigureOfAReport) {
  namespace fs = std::filesystem;
  const auto dir = gearbench::testing_support::temp_path("pdf_cli");
  fs::remove_all(dir);
  fs::create_directories(dir);
  Report r;
  r.tier = "fast";
  r.figures.push_back({"line", "s", "a line", "x [m]", "y [Pa]", {{"l", {0.0, 1.0, 2.0}, {1.0, 2.0, 1.5}}}});
  std::ofstream(dir / "report.json") << to_json(r).dump();
  EXPECT_EQ(run_gearbench("report pdf '" + dir.string() + "'", dir / "log"), 0) << slurp(dir / "log");
  EXPECT_EQ(slurp(dir / "figures" / "line.pdf").substr(0, 5), "%PDF-");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gearbench::reports

// Ratios compare times in seconds whatever unit each benchmark reports in (a regression:
// BM_ContactFriction in µs against its baseline in ms came out 1000 times too large).
TEST(BenchRatios, UseSecondsAcrossTimeUnits) {
  const auto runs = nlohmann::json::parse(R"([
    {"run_name": "BM_X", "run_type": "iteration", "real_time": 2.0, "time_unit": "us"},
    {"run_name": "BM_X_baseline", "run_type": "iteration", "real_time": 4.0, "time_unit": "ms"},
    {"run_name": "BM_Y/8", "run_type": "iteration", "real_time": 3.0, "time_unit": "ns"},
    {"run_name": "BM_Y_baseline/8", "run_type": "iteration", "real_time": 6.0, "time_unit": "ns"}])");
  const auto r = gearbench::reports::side_by_side_ratios(runs);
  EXPECT_DOUBLE_EQ(r["BM_X"]["ratio"].get<double>(), 2e-6 / 4e-3);
  EXPECT_DOUBLE_EQ(r["BM_Y/8"]["ratio"].get<double>(), 0.5);
  EXPECT_FALSE(r.contains("BM_X_baseline"));
  EXPECT_FALSE(r["BM_X"].contains("baseline_converged"));
}

// A baseline stopped at its cap (counter converged = 0) marks the ratio as a bound.
TEST(BenchRatios, MarksAnUnconvergedBaseline) {
  const auto runs = nlohmann::json::parse(R"([
    {"run_name": "BM_S/4097", "run_type": "iteration", "real_time": 0.2, "time_unit": "s"},
    {"run_name": "BM_S_baseline/4097", "run_type": "iteration", "real_time": 20.0, "time_unit": "s",
     "converged": 0, "residual": 0.012}])");
  const auto r = gearbench::reports::side_by_side_ratios(runs);
  EXPECT_DOUBLE_EQ(r["BM_S/4097"]["ratio"].get<double>(), 0.01);
  EXPECT_FALSE(r["BM_S/4097"]["baseline_converged"].get<bool>());
  EXPECT_DOUBLE_EQ(r["BM_S/4097"]["baseline_residual"].get<double>(), 0.012);
}

// A baseline timed to an accuracy (the single-grid pair's counters error and accuracy) keeps
// both beside its residual, and the report's table prints the bound with its error, the figure
// that says how far it got (its residual, 0.21 at the cap, said nothing of its films' 6.0).
TEST(BenchRatios, AnUnconvergedBaselineKeepsItsErrorAndTheAccuracyAsked) {
  const auto runs = nlohmann::json::parse(R"([
    {"name": "BM_S/1025", "run_name": "BM_S/1025", "run_type": "iteration", "real_time": 0.01, "time_unit": "s"},
    {"name": "BM_S_baseline/1025", "run_name": "BM_S_baseline/1025", "run_type": "iteration", "real_time": 1.2,
     "time_unit": "s", "converged": 0, "residual": 0.21, "error": 6.0, "accuracy": 4.2e-5}])");
  const auto r = gearbench::reports::side_by_side_ratios(runs);
  EXPECT_DOUBLE_EQ(r["BM_S/1025"]["baseline_error"].get<double>(), 6.0);
  EXPECT_DOUBLE_EQ(r["BM_S/1025"]["baseline_accuracy"].get<double>(), 4.2e-5);
  EXPECT_DOUBLE_EQ(r["BM_S/1025"]["baseline_residual"].get<double>(), 0.21);
  const nlohmann::json record = {
      {"benchmarks", runs},
      {"ratios", r},
      {"gearbench",
       {{"code", {{"git_sha", "abc"}}}, {"machine", {{"cpu_model", "cpu"}, {"cores", 2}}}, {"build", {{"build_type", "Release"}}}}}};
  const std::string text = gearbench::reports::benchmark_note(record).text;
  EXPECT_NE(text.find("< 0.00833 (the baseline stopped unconverged, its error 6 against the 4.2e-05 asked)"),
            std::string::npos)
      << text;
}

// A baseline that converged in every repetition is not a bound because of its aggregates: the
// standard deviation of converged = 1 is 0 (a regression: BM_EhlMultigridVsSingleGrid/257 read
// "< 0.07 x baseline" with --repetitions 3).
TEST(BenchRatios, AggregatesDoNotMarkAConvergedBaseline) {
  const auto runs = nlohmann::json::parse(R"([
    {"run_name": "BM_S/257", "run_type": "iteration", "real_time": 1.0, "time_unit": "ms"},
    {"run_name": "BM_S_baseline/257", "run_type": "iteration", "real_time": 20.0, "time_unit": "ms", "converged": 1},
    {"run_name": "BM_S_baseline/257", "run_type": "aggregate", "aggregate_name": "stddev", "real_time": 0.1,
     "time_unit": "ms", "converged": 0}])");
  const auto r = gearbench::reports::side_by_side_ratios(runs);
  EXPECT_DOUBLE_EQ(r["BM_S/257"]["ratio"].get<double>(), 0.05);
  EXPECT_FALSE(r["BM_S/257"].contains("baseline_converged"));
}

// The scaling fit recovers the exponent of time ∝ nodes^p across time units, ignores
// families without a nodes counter or with fewer than three sizes.
TEST(BenchScaling, FitsTheExponentOfTimeAgainstNodes) {
  auto runs = nlohmann::json::array();
  for (double n : {257.0, 1025.0, 4097.0})
    runs.push_back({{"run_name", "BM_S/" + std::to_string(static_cast<int>(n))}, {"run_type", "iteration"},
                    {"real_time", 3.0 * std::pow(n, 1.2) * (n > 1000 ? 1e-3 : 1.0)},
                    {"time_unit", n > 1000 ? "ms" : "us"}, {"nodes", n}});
  runs.push_back({{"run_name", "BM_S/16385"}, {"run_type", "iteration"}, {"real_time", 1.0}, {"time_unit", "s"},
                  {"nodes", 16385.0}, {"converged", 0.0}});  // stopped at a cap: not a point of the fit
  runs.push_back({{"run_name", "BM_T/1"}, {"run_type", "iteration"}, {"real_time", 1.0}, {"time_unit", "ms"}, {"nodes", 9.0}});
  runs.push_back({{"run_name", "BM_T/2"}, {"run_type", "iteration"}, {"real_time", 2.0}, {"time_unit", "ms"}, {"nodes", 17.0}});
  const auto s = gearbench::reports::scaling_exponents(runs);
  ASSERT_TRUE(s.contains("BM_S"));
  EXPECT_NEAR(s["BM_S"]["exponent"].get<double>(), 1.2, 1e-12);
  EXPECT_EQ(s["BM_S"]["points"].get<int>(), 3);
  EXPECT_FALSE(s.contains("BM_T"));
}
