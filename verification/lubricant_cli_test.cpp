// The lubricant catalogue through the CLI: `gearbench lubricants`, named oils in case files,
// and the round trip of issue 24: a case given by name and the same case given by the
// resolved numbers (as echoed under lubricant_resolved) give bit-identical results.
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "support/cli_support.h"

namespace gearbench {
namespace {

using nlohmann::json;
using testing_support::run_gearbench;
using testing_support::write_case;

/// The result without what legitimately differs between two runs (timings, and the summary
/// line that quotes them) and the echo.
json comparable(json r) {
  if (r.is_object()) {
    r.erase("lubricant_resolved");
    r.erase("summary");
    for (auto it = r.begin(); it != r.end();) {
      if (it.key().find("seconds") != std::string::npos) {
        it = r.erase(it);
      } else {
        *it = comparable(*it);
        ++it;
      }
    }
  } else if (r.is_array()) {
    for (auto& e : r) e = comparable(e);
  }
  return r;
}

/// Runs the named case, then the case with its resolved numbers typed, and compares.
void expect_round_trip(const std::string& file) {
  const auto named = run_gearbench("run '" + (testing_support::cases_dir() / file).string() + "'");
  ASSERT_EQ(named.exit_code, 0) << named.err;
  const auto named_result = json::parse(named.out);
  json typed = testing_support::read_json_file(testing_support::cases_dir() / file);
  const auto& echo = named_result.at("lubricant_resolved");
  for (const auto& [path, resolved] : echo.items()) {
    json& section = path == "lubricant" ? typed["lubricant"] : typed["micropitting"]["oil"];
    for (const char* key : {"name", "grade", "base", "viscosity_index", "temperature_C"}) section.erase(key);
    for (const auto& [key, value] : resolved.at("values").items()) section[key] = value;
  }
  const auto explicit_run = run_gearbench("run '" + write_case("round_trip", typed.dump()) + "'");
  ASSERT_EQ(explicit_run.exit_code, 0) << explicit_run.err;
  const auto explicit_result = json::parse(explicit_run.out);
  EXPECT_FALSE(explicit_result.contains("lubricant_resolved"));
  EXPECT_EQ(comparable(named_result).dump(), comparable(explicit_result).dump()) << file;
}

TEST(LubricantCli, ByNameAndByResolvedNumbersGiveIdenticalResults) {
  expect_round_trip("efficiency_iso_vg220_mineral_70C.json");  // grade, by ASTM D341 at 70 °C
  expect_round_trip("efficiency_iso_vg100_mineral_vi97_70C.json");  // grade and VI: ν100 by ASTM D2270
  expect_round_trip("seed004_pitch_point_ehl_named_oil.json");  // one-temperature seed oil, ehl_line
  expect_round_trip("tehl_point_fva3.json");                    // thermal form, an explicit conductivity
  expect_round_trip("seed001_micropitting_named_oil.json");     // the ISO/TR 15144-1 oil section
}

/// A lubricant section that names its oil from the catalogue ({"name"} or {"grade", "base"}).
bool names_oil(const json& section) {
  return section.is_object() && (section.contains("name") || section.contains("grade"));
}

// Issue 24, "done when": at least one case of every lubricated kind in cases/ names its oil.
// A kind is lubricated when any of its cases has a "lubricant" section (or the ISO/TR 15144-1
// "micropitting": {"oil"}); a new lubricated kind without a named case fails here.
TEST(LubricantCli, EveryLubricatedKindHasACaseThatNamesItsOil) {
  std::map<std::string, bool> lubricated;  // kind -> some case names its oil
  for (const auto& entry : std::filesystem::directory_iterator(testing_support::cases_dir())) {
    if (entry.path().extension() != ".json") continue;
    const json c = testing_support::read_json_file(entry.path());
    if (!c.is_object() || !c.contains("kind")) continue;
    const bool has_lubricant = c.contains("lubricant") || (c.contains("micropitting") && c["micropitting"].contains("oil"));
    if (!has_lubricant) continue;
    const bool named = (c.contains("lubricant") && names_oil(c["lubricant"])) ||
                       (c.contains("micropitting") && c["micropitting"].contains("oil") && names_oil(c["micropitting"]["oil"]));
    auto& any_named = lubricated[c["kind"].get<std::string>()];
    any_named = any_named || named;
  }
  // The lubricated kinds as of issue 24 must all be found (a renamed case directory or kind
  // would otherwise make this test vacuous).
  for (const char* kind : {"efficiency", "ehl_line", "ehl_transient", "tehl_point", "tehl_path", "oil_film_stiffness",
                           "dynamics", "micropitting_iso"})
    EXPECT_TRUE(lubricated.count(kind)) << kind << ": no case in cases/ with a lubricant";
  for (const auto& [kind, named] : lubricated) EXPECT_TRUE(named) << kind << ": no case in cases/ names its oil";
}

TEST(LubricantCli, ListsAndResolves) {
  const auto list = run_gearbench("lubricants");
  ASSERT_EQ(list.exit_code, 0) << list.err;
  EXPECT_NE(list.out.find("ISO VG 1500 PAG"), std::string::npos);
  EXPECT_NE(list.out.find("FVA 3"), std::string::npos);
  const auto one = run_gearbench("lubricants 'ISO VG 320 mineral' --temperature-C 80");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const auto j = json::parse(one.out);
  EXPECT_EQ(j.at("values").at("nu40_mm2_s").get<double>(), 320.0);
  EXPECT_EQ(j.at("sources").at("pressure_viscosity_1_per_GPa").get<std::string>(), "iso15144(mineral)");
}

TEST(LubricantCli, BadNamesAndTemperaturesExitTwo) {
  const auto unknown = run_gearbench("lubricants 'ISO VG 330 minral' --temperature-C 80");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(unknown.err.rfind("error: oil.name = \"ISO VG 330 minral\": unknown oil (nearest known: 'ISO VG 320 "
                              "mineral')", 0), 0u) << unknown.err;
  json c = testing_support::read_case("efficiency_iso_vg220_mineral_70C");
  c["operating"]["oil_temperature_C"] = 160;
  const auto hot = run_gearbench("run '" + write_case("hot", c.dump()) + "'");
  EXPECT_EQ(hot.exit_code, 2);
  EXPECT_EQ(hot.err, "error: operating.oil_temperature_C = 160: allowed range is [-20, 150] degC (the catalogue's "
                     "range for two-point oils)\n");
  c["operating"].erase("oil_temperature_C");
  const auto none = run_gearbench("run '" + write_case("none", c.dump()) + "'");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("lubricant.temperature_C: missing"), std::string::npos) << none.err;
}

}  // namespace
}  // namespace gearbench
