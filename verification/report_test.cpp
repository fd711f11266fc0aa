// Unit tests of reports/: no NaN reaches a report, pass/fail and comparison logic, and
// the atomic, never-overwriting report folder.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "compare.h"
#include "report.h"

namespace gearbench::reports {
namespace {

CheckRecord record(const std::string& id, double value, double reference, double rel) {
  CheckRecord c;
  c.id = id;
  c.section = "s";
  c.value = value;
  c.reference_value = reference;
  c.tolerance = {0.0, rel};
  return c;
}

TEST(CheckRecord, ToleranceDecides) {
  EXPECT_TRUE(record("a", 1.0005, 1.0, 1e-3).passed());
  EXPECT_FALSE(record("a", 1.002, 1.0, 1e-3).passed());
  EXPECT_FALSE(record("a", std::nan(""), 1.0, 1e-3).passed());
  auto thrown = record("a", 1.0, 1.0, 1e-3);
  thrown.error = "solver threw";
  EXPECT_FALSE(thrown.passed());
}

TEST(CheckRecord, ReproductionMissIsRecordedNotFailed) {
  auto r = record("seed", 30.0, 14.3, 0.05);  // paper 14.3, reached 30
  r.reproduction = true;
  r.recorded = 30.0;
  r.recorded_tolerance = 0.01;
  EXPECT_FALSE(r.passed());
  EXPECT_FALSE(r.failed());
  EXPECT_EQ(r.status(), "missed");
  r.value = 31.0;  // drifted from the recorded figure: a regression
  EXPECT_TRUE(r.failed());
  EXPECT_EQ(r.status(), "fail");
  r.value = r.recorded = 14.5;  // within 5 % of the paper
  EXPECT_EQ(r.status(), "reproduced");
}

TEST(ReportJson, NonFiniteBecomesNull) {
  Report r;
  r.tier = "fast";
  r.checks.push_back(record("nan", std::nan(""), 1.0, 1e-3));
  r.figures.push_back({"f", "s", "t", "x", "y", {{"l", {0.0, 1.0}, {1.0, INFINITY}}}});
  const auto j = to_json(r);
  EXPECT_TRUE(j["checks"][0]["value"].is_null());
  EXPECT_EQ(j["checks"][0]["status"], "fail");
  EXPECT_TRUE(j["figures"][0]["series"][0]["y"][1].is_null());
  EXPECT_EQ(j["summary"]["failed"], 1);
  EXPECT_EQ(j.dump().find("NaN"), std::string::npos);
}

TEST(Compare, FlagsRegressionsChangesAndTimings) {
  Report before, after;
  before.checks = {record("x", 1.0, 1.0, 1e-6), record("y", 2.0, 2.0, 1e-6)};
  after.checks = {record("x", 1.5, 1.0, 1e-6), record("z", 2.0, 2.0, 1e-6)};
  before.checks[0].seconds = 1.0;
  after.checks[0].seconds = 1.5;
  const auto c = compare_reports(to_json(before), to_json(after));
  ASSERT_EQ(c.regressions.size(), 1u);
  EXPECT_EQ(c.regressions[0], "x");
  EXPECT_EQ(c.changed.size(), 1u);
  EXPECT_EQ(c.added, std::vector<std::string>{"z"});
  EXPECT_EQ(c.removed, std::vector<std::string>{"y"});
  EXPECT_TRUE(c.same_machine);  // same process: same fingerprint
  EXPECT_EQ(c.slower.size(), 1u);
}

TEST(WriteReport, NeverOverwritesAndLeavesNoTemporary) {
  const auto dir = std::filesystem::temp_directory_path() / ("gearbench_report_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  Report r;
  r.tier = "fast";
  r.checks.push_back(record("x", 1.0, 1.0, 1e-6));
  const auto first = write_report(r, dir.string());
  const auto second = write_report(r, dir.string());
  EXPECT_NE(first, second);
  EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(first) / "report.json"));
  EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(second) / "report.md"));
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_NE(entry.path().filename().string().rfind(".tmp", 0), 0u) << entry.path();
  std::filesystem::remove_all(dir);
}

// A colour-map figure (a field sampled on points) keeps its colour values through the CSV
// and the report JSON: the third column is z, and figure_from_json restores it exactly
// (values chosen binary-exact); a non-finite z becomes an empty cell, never "nan".
TEST(Figure, ColourMapKeepsItsValues) {
  Figure f{.id = "field", .section = "s", .title = "t", .xlabel = "x [mm]", .ylabel = "y [mm]",
           .series = {{"field", {0.0, 0.5, 1.0}, {0.0, 0.25, 1.0}, {2.0, std::nan(""), 3.5}}},
           .colour_label = "von Mises [MPa]"};
  const auto csv = std::filesystem::temp_directory_path() / ("gearbench_colour_" + std::to_string(::getpid()) + ".csv");
  write_figure_csv(f, csv.string());
  std::ifstream in(csv);
  std::string header, row0, row1;
  std::getline(in, header);
  std::getline(in, row0);
  std::getline(in, row1);
  EXPECT_EQ(header, "series,x [mm],y [mm],von Mises [MPa]");
  EXPECT_EQ(row0, "field,0,0,2");
  EXPECT_EQ(row1, "field,0.5,0.25,");
  std::filesystem::remove(csv);
  const nlohmann::json j = {{"id", "field"}, {"colour_label", "von Mises [MPa]"},
                            {"series", {{{"label", "field"}, {"x", {0.0, 1.0}}, {"y", {0.0, 1.0}}, {"z", {2.0, 3.5}}}}}};
  const auto back = figure_from_json(j);
  EXPECT_EQ(back.colour_label, "von Mises [MPa]");
  ASSERT_EQ(back.series.at(0).z.size(), 2u);
  EXPECT_EQ(back.series[0].z[1], 3.5);
}

}  // namespace
}  // namespace gearbench::reports
