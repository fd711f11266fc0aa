// Unit tests of reports/: no NaN reaches a report, pass/fail and comparison logic, and
// the atomic, never-overwriting report folder.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "compare.h"
#include "report.h"
#include "support/temp_dir.h"

namespace gearbench::reports {
namespace {

using nlohmann::json;

/// A record as verification::classify would leave it (the rules are tested in outcome_test).
CheckRecord record(const std::string& id, double value, double reference, Outcome outcome) {
  CheckRecord c;
  c.id = id;
  c.section = "s";
  c.value = value;
  c.reference_value = reference;
  c.tolerance = {0.0, 1e-6};
  c.outcome = outcome;
  return c;
}

TEST(ReportJson, NonFiniteBecomesNull) {
  Report r;
  r.tier = "fast";
  r.checks.push_back(record("nan", std::nan(""), 1.0, Outcome::fail));
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
  before.checks = {record("x", 1.0, 1.0, Outcome::pass), record("y", 2.0, 2.0, Outcome::pass)};
  after.checks = {record("x", 1.5, 1.0, Outcome::fail), record("z", 2.0, 2.0, Outcome::pass)};
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

TEST(Compare, FingerprintsOfDifferentDigestsNeverMatch) {
  Report r;
  json legacy = to_json(r);  // a schema-1 report: std::hash fingerprint, no digest recorded
  legacy["machine"].erase("fingerprint_digest");
  json now = to_json(r);
  legacy["machine"]["fingerprint"] = now["machine"]["fingerprint"];
  EXPECT_FALSE(compare_reports(legacy, now).same_machine);
  EXPECT_TRUE(compare_reports(legacy, legacy).same_machine);  // old against old: as before
  EXPECT_TRUE(compare_reports(now, now).same_machine);
}

TEST(Fingerprint, Fnv1a64KnownVectors) {
  // The FNV test suite (draft-eastlake-fnv, test vectors for FNV-1a 64).
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ull);
}

TEST(Fingerprint, RecordedWithItsDigest) {
  const auto machine = provenance()["machine"];
  EXPECT_EQ(machine["fingerprint_digest"], "fnv1a64");
  EXPECT_EQ(machine["fingerprint"].get<std::string>().size(), 16u);
  EXPECT_EQ(machine["fingerprint"], machine_fingerprint());
}

/// One check of every outcome and one section that could not be built.
Report every_outcome() {
  Report r;
  r.tier = "fast";
  r.checks = {record("p", 1.0, 1.0, Outcome::pass), record("r", 1.0, 1.0, Outcome::reproduced),
              record("m", 2.0, 1.0, Outcome::missed), record("f", 3.0, 1.0, Outcome::fail)};
  r.section_failures.push_back({"broken_section", "figure data missing"});
  return r;
}

TEST(Headline, CountsEveryOutcomeSeparately) {
  const auto n = every_outcome().counts();
  EXPECT_EQ(n.checks, 4);
  EXPECT_EQ(n.pass, 1);
  EXPECT_EQ(n.reproduced, 1);
  EXPECT_EQ(n.missed, 1);
  EXPECT_EQ(n.failed, 1);
  EXPECT_EQ(n.sections_failed, 1);
  EXPECT_EQ(headline(n),
            "4 checks: 1 pass, 1 reproduced, 1 missed, 1 failed; 1 report section(s) could not be built");
}

TEST(Headline, JsonAndMarkdownCarryTheCounts) {
  const auto report = every_outcome();
  const auto j = to_json(report);
  EXPECT_EQ(j["summary"]["pass"], 1);
  EXPECT_EQ(j["summary"]["reproduced"], 1);
  EXPECT_EQ(j["summary"]["missed"], 1);
  EXPECT_EQ(j["summary"]["failed"], 1);
  EXPECT_EQ(j["summary"]["sections_failed"], 1);
  EXPECT_EQ(j["section_failures"][0]["section"], "broken_section");
  const auto md = to_markdown(report, j);
  EXPECT_NE(md.find(headline(report.counts())), std::string::npos);
  EXPECT_NE(md.find("| missed | 1 |"), std::string::npos);
  EXPECT_NE(md.find("**FAIL** `broken_section`: figure data missing"), std::string::npos);
  EXPECT_EQ(md.find(" of 4 checks pass"), std::string::npos);
}

TEST(WriteReport, NeverOverwritesAndLeavesNoTemporary) {
  const auto dir = gearbench::testing_support::temp_path("report_test");
  std::filesystem::remove_all(dir);
  Report r;
  r.tier = "fast";
  r.checks.push_back(record("x", 1.0, 1.0, Outcome::pass));
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
  const auto csv = gearbench::testing_support::temp_path("colour.csv");
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
