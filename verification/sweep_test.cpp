// Unit tests of `gearbench sweep`: grid order, key paths, validation, a failed case that is
// recorded while the sweep goes on, and the CSV/JSON table and figures.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include "model/errors.h"
#include "model/json_reader.h"
#include "sweep_command.h"
#include "support/temp_dir.h"

namespace gearbench::app {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;
namespace fs = std::filesystem;

ordered_json efficiency_sweep() {
  return ordered_json::parse(R"({
    "base": ")" GEARBENCH_SOURCE_DIR R"(/cases/seed004_spur_efficiency.json",
    "vary": { "operating.pinion_torque_Nm": [50, -5, 200], "operating.pinion_speed_rpm": [500, 1000] },
    "outputs": ["efficiency_mean", "power_loss_mean_W"] })");
}

TEST(SweepKeys, DottedPathsAndPointers) {
  EXPECT_EQ(key_pointer("operating.pinion_torque_Nm").to_string(), "/operating/pinion_torque_Nm");
  EXPECT_EQ(key_pointer("/gear_pair/teeth/0").to_string(), "/gear_pair/teeth/0");
  EXPECT_EQ(key_pointer("a~b.c").to_string(), "/a~0b/c");
  EXPECT_THROW(key_pointer(""), InputError);
  EXPECT_THROW(key_pointer("operating..speed"), InputError);
  EXPECT_THROW(key_pointer("/a/~2"), InputError);  // not a valid pointer escape
}

TEST(SweepGrid, LastAxisVariesFastestAndKeysAreSet) {
  const auto spec = parse_sweep_spec(efficiency_sweep(), ".", "eff");
  ASSERT_EQ(spec.axes.size(), 2u);
  EXPECT_EQ(spec.axes[0].key, "operating.pinion_torque_Nm");  // order as written
  EXPECT_EQ(spec.size(), 6u);
  EXPECT_EQ(json(spec.values_at(0)), json::parse("[50, 500]"));
  EXPECT_EQ(json(spec.values_at(1)), json::parse("[50, 1000]"));
  EXPECT_EQ(json(spec.values_at(5)), json::parse("[200, 1000]"));
  const auto c = spec.case_at(3);
  EXPECT_EQ(c["operating"]["pinion_torque_Nm"], -5);
  EXPECT_EQ(c["operating"]["pinion_speed_rpm"], 1000);
  EXPECT_EQ(c["kind"], "efficiency");  // the rest of the base case is kept
  // Array elements by index.
  auto teeth = efficiency_sweep();
  teeth["vary"] = ordered_json::parse(R"({"gear_pair.teeth.1": [30, 40]})");
  EXPECT_EQ(parse_sweep_spec(teeth, ".", "t").case_at(1)["gear_pair"]["teeth"], json::parse("[22, 40]"));
}

TEST(SweepGrid, BadSpecsNameTheKey) {
  auto expect_error = [](ordered_json spec, const std::string& fragment) {
    try {
      parse_sweep_spec(spec, ".", "bad");
      ADD_FAILURE() << "no error for " << spec.dump();
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  auto s = efficiency_sweep();
  s.erase("outputs");
  expect_error(s, "outputs: missing");
  s = efficiency_sweep();
  s["vary"]["operating.pinion_speed_rpm"] = ordered_json::array();
  expect_error(s, "vary.\"operating.pinion_speed_rpm\"");
  s = efficiency_sweep();
  s["varry"] = 1;
  expect_error(s, "varry: unknown key");
  s = efficiency_sweep();
  s["base"] = "no/such/case.json";
  expect_error(s, "no/such/case.json");
  s = efficiency_sweep();
  s["vary"] = ordered_json::parse(R"({"gear_pair.teeth.x": [1]})");  // not an array index
  expect_error(s, "gear_pair.teeth.x");
}

// A value past the value cap is not read (issue 20): under an unknown key the key is
// refused as unknown, as a vary axis the axis names the cap.
TEST(SweepGrid, AValuePastTheCapIsNotRead) {
  std::string long_array = "[0";
  for (std::size_t i = 0; i < model::max_json_values; ++i) long_array += ",0";
  long_array += "]";
  const auto error_of = [](const std::string& text) {
    try {
      parse_sweep_spec(model::parse_ordered_json(text, "sweep.json"), ".", "long");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string base = R"("base": ")" GEARBENCH_SOURCE_DIR R"(/cases/seed004_spur_efficiency.json")";
  EXPECT_EQ(error_of("{" + base + R"(, "vary": {"operating.pinion_speed_rpm": [500]}, "outputs": ["efficiency_mean"],
                     "bogus": )" + long_array + "}"),
            "bogus: unknown key; allowed keys are base, vary, outputs, description");
  EXPECT_EQ(error_of("{" + base + R"(, "vary": {"operating.pinion_speed_rpm": )" + long_array +
                     R"(}, "outputs": ["efficiency_mean"]})"),
            R"(vary."operating.pinion_speed_rpm": more than 1000000 values in one file, the most gearbench reads )"
            "(a case holds a few hundred)");
}

TEST(SweepRun, FailedCaseIsRecordedAndTheRestRuns) {
  const auto spec = parse_sweep_spec(efficiency_sweep(), ".", "eff");
  std::vector<SweepRow> rows;
  for (std::size_t i = 0; i < spec.size(); ++i) rows.push_back(run_sweep_case(spec, i));
  EXPECT_TRUE(rows[0].error.empty()) << rows[0].error;
  EXPECT_EQ(rows[2].error_kind, "bad_input");  // torque −5
  EXPECT_NE(rows[2].error.find("pinion_torque_Nm"), std::string::npos);
  EXPECT_TRUE(rows[5].error.empty());
  // Loss scales with power at constant μ and load sharing: 200 N·m·1000 rpm is 8 times
  // 50 N·m·500 rpm (exact up to rounding of the same loss integral).
  EXPECT_NEAR(rows[5].outputs["power_loss_mean_W"].get<double>() / rows[0].outputs["power_loss_mean_W"].get<double>(),
              8.0, 1e-9);
  const std::string csv = sweep_csv(spec, rows);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "index,operating.pinion_torque_Nm,operating.pinion_speed_rpm,efficiency_mean,power_loss_mean_W,error");
  EXPECT_NE(csv.find("\n2,-5,500,,,\"operating.pinion_torque_Nm = -5"), std::string::npos) << csv;
  const auto table = sweep_json(spec, rows, 1);
  EXPECT_EQ(table["summary"]["failed"], 2);
  EXPECT_EQ(table["rows"][2]["values"]["operating.pinion_torque_Nm"], -5);
  EXPECT_EQ(table.dump().find("NaN"), std::string::npos);
  // One figure per output, one series per speed; the failed case is a gap (NaN, never drawn).
  const auto figures = sweep_figures(spec, rows);
  ASSERT_EQ(figures.size(), 2u);
  EXPECT_EQ(figures[0].series.size(), 2u);
  EXPECT_TRUE(std::isnan(figures[0].series[0].y[1]));
}

TEST(SweepRun, MissingOutputAndUnknownKindAreCaseErrors) {
  auto s = efficiency_sweep();
  s["outputs"] = ordered_json::array({"efficiency_meen"});
  const auto spec = parse_sweep_spec(s, ".", "eff");
  const auto row = run_sweep_case(spec, 0);
  EXPECT_EQ(row.error_kind, "bad_input");
  EXPECT_NE(row.error.find("efficiency_meen"), std::string::npos);
  EXPECT_NE(row.error.find("efficiency_mean"), std::string::npos);  // the result's keys are listed
  s = efficiency_sweep();
  s["vary"] = ordered_json::parse(R"({"kind": ["efficiency", "efficency"]})");
  const auto kinds = parse_sweep_spec(s, ".", "k");
  EXPECT_TRUE(run_sweep_case(kinds, 0).error.empty());
  EXPECT_NE(run_sweep_case(kinds, 1).error.find("unknown kind"), std::string::npos);
}

TEST(SweepCli, WritesTableAndFiguresAndExitsOneOnFailedCases) {
  const auto dir = gearbench::testing_support::temp_path("sweep_cli");
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "eff.json") << efficiency_sweep().dump();
  const std::string command = std::string("'") + GEARBENCH_EXE + "' sweep '" + (dir / "eff.json").string() +
                              "' --out '" + (dir / "out").string() + "' >'" + (dir / "stdout").string() +
                              "' 2>'" + (dir / "stderr").string() + "'";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);  // two cases failed; the table is still written
  for (const char* f : {"sweep.csv", "sweep.json", "figures/sweep_efficiency_mean.csv"})
    EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  std::ifstream err(dir / "stderr");
  const std::string progress{std::istreambuf_iterator<char>(err), {}};
  EXPECT_NE(progress.find("case 6/6 ok"), std::string::npos) << progress;  // progress per case
  EXPECT_NE(progress.find("case 3/6 FAILED"), std::string::npos) << progress;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gearbench::app
