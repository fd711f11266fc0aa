// Unit tests of the Benchmarks section's work–precision diagrams (issue 22) on a synthetic
// `gearbench bench` record: which runs become points, of which series, in which order.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_ratios.h"
#include "bench_section.h"
#include "report.h"

namespace gearbench::reports {
namespace {

using nlohmann::json;

/// One run as Google Benchmark writes it in JSON, with the study's error counters.
json run(const std::string& name, double cpu_time, double te_error, double force_error, const std::string& unit = "ms") {
  return {{"name", name},           {"run_name", name},         {"run_type", "iteration"},
          {"iterations", 1},        {"real_time", cpu_time},    {"cpu_time", cpu_time},
          {"time_unit", unit},      {"te_error", te_error},     {"force_error", force_error}};
}

json study_record() {
  json failed = {{"name", "BM_WorkPrecision/spur6/verner/6/iterations:1"}, {"run_type", "iteration"},
                 {"error_occurred", true}, {"error_message", "the error test failed repeatedly"},
                 {"cpu_time", 0.0}, {"time_unit", "ms"}};
  json aggregate = run("BM_WorkPrecision/spur6/dormand_prince/7/iterations:1_median", 1.0, 1.0, 1.0);
  aggregate["run_type"] = "aggregate";
  return {{"benchmarks",
           {run("BM_WorkPrecision/spur6/dormand_prince/7/iterations:1", 150.0, 1.7e-7, 1.8e-7),
            run("BM_WorkPrecision/spur6/dormand_prince/6/iterations:1", 102.0, 1.6e-6, 1.5e-6),
            run("BM_WorkPrecision/spur6/dormand_prince/7/iterations:1", 164.0, 1.7e-7, 1.8e-7),  // a repetition
            failed, aggregate,
            run("BM_WorkPrecision_RK4/spur6/4096/iterations:1", 84000.0, 5.0e-7, 8.3e-7, "us"),
            run("BM_WorkPrecision_RK4/spur6/2048/iterations:1", 42.0, 7.7e-6, 1.3e-5),
            run("BM_WorkPrecision/herringbone12/adams/7/iterations:1", 180.0, 7.3e-8, 7.7e-8),
            run("BM_DefaultVsRK4/spur6", 300.0, 1.0, 1.0)}}};
}

/// CPU times pass through a unit conversion: equal to a few ulp.
void expect_times(const std::vector<double>& x, const std::vector<double>& expected) {
  ASSERT_EQ(x.size(), expected.size());
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_DOUBLE_EQ(x[i], expected[i]);
}

const Figure& find(const std::vector<Figure>& figures, const std::string& id) {
  const auto it = std::find_if(figures.begin(), figures.end(), [&](const Figure& f) { return f.id == id; });
  if (it == figures.end()) throw std::runtime_error("no figure " + id);
  return *it;
}

// Per model one TE and one force figure, log–log; a series per method with RK4 among them;
// points from loose to tight whatever the record's order, CPU time the median of the
// repetitions in ms; failed runs, aggregates and other benchmarks left out.
TEST(WorkPrecision, OneSeriesPerMethodInToleranceOrder) {
  const auto figures = work_precision_figures(study_record());
  ASSERT_EQ(figures.size(), 4u);
  const auto& te = find(figures, "work_precision_spur6_te");
  EXPECT_EQ(te.section, "Benchmarks");
  EXPECT_TRUE(te.log_x);
  EXPECT_TRUE(te.log_y);
  ASSERT_EQ(te.series.size(), 2u);  // verner failed: no series
  EXPECT_EQ(te.series[0].label, "RK4");
  expect_times(te.series[0].x, {42.0, 84.0});
  EXPECT_EQ(te.series[0].y, (std::vector<double>{7.7e-6, 5.0e-7}));
  EXPECT_EQ(te.series[1].label, "dormand_prince");
  expect_times(te.series[1].x, {102.0, 157.0});
  EXPECT_EQ(te.series[1].y, (std::vector<double>{1.6e-6, 1.7e-7}));
  const auto& force = find(figures, "work_precision_spur6_force");
  ASSERT_EQ(force.series.size(), 2u);
  EXPECT_EQ(force.series[0].y, (std::vector<double>{1.3e-5, 8.3e-7}));
  EXPECT_EQ(force.series[1].y, (std::vector<double>{1.5e-6, 1.8e-7}));
  const auto& herringbone = find(figures, "work_precision_herringbone12_te");
  ASSERT_EQ(herringbone.series.size(), 1u);
  EXPECT_EQ(herringbone.series[0].label, "adams");
  expect_times(herringbone.series[0].x, {180.0});
  EXPECT_NO_THROW(find(figures, "work_precision_herringbone12_force"));
}

TEST(WorkPrecision, NoStudyNoFigure) {
  const json record = {{"benchmarks", {run("BM_DefaultVsRK4/spur6", 300.0, 1.0, 1.0),
                                       run("BM_Spur6Dynamics", 170.0, 0.0, 0.0)}}};
  EXPECT_TRUE(work_precision_figures(record).empty());
}

// The report keeps the logarithmic x axis and the marks, so `report pdf` draws the same.
TEST(WorkPrecision, AxesSurviveTheReportJson) {
  Report report;
  report.figures = work_precision_figures(study_record());
  const auto back = figure_from_json(to_json(report)["figures"][0]);
  EXPECT_TRUE(back.log_x);
  EXPECT_TRUE(back.log_y);
  EXPECT_TRUE(back.points);
}

// Google Benchmark writes a non-finite aggregate as a bare NaN (the fourteenth session's record
// stopped on one: the stddev of a counter equal in all repetitions); the record reads it as
// null, which the report's counter columns skip, and keeps every finite number.
TEST(BenchmarkOutput, NonFiniteNumbersReadAsNull) {
  const auto j = parse_benchmark_output(
      R"({"benchmarks": [{"name": "BM_X_stddev", "real_time": 1.5e+02, "k": NaN, "m": -nan, "q": inf,
          "label": "NaN inside a string stays"}]})",
      "test");
  const auto& b = j["benchmarks"][0];
  EXPECT_TRUE(b["k"].is_null());
  EXPECT_TRUE(b["m"].is_null());
  EXPECT_TRUE(b["q"].is_null());
  EXPECT_DOUBLE_EQ(b["real_time"].get<double>(), 150.0);
  EXPECT_EQ(b["label"], "NaN inside a string stays");
}

}  // namespace
}  // namespace gearbench::reports
