// Unit tests of the validating JSON reader and the case sections (solvers/model).
#include <gtest/gtest.h>

#include "model/case_reader.h"
#include "model/errors.h"
#include "support/test_support.h"

namespace gearbench::model {
namespace {

using nlohmann::json;

using testing_support::input_error_of;

json spur_pair() {
  return json::parse(R"({"teeth": [22, 32], "normal_module_mm": 2.0,
                         "normal_pressure_angle_deg": 25.0, "face_width_mm": 20.0})");
}

TEST(ObjectReader, ReadsUnitsIntoSI) {
  const auto g = read_gear_pair(ObjectReader(spur_pair(), "gear_pair"));
  EXPECT_EQ(g.teeth[1], 32);
  EXPECT_DOUBLE_EQ(g.normal_module, 2e-3);
  EXPECT_NEAR(g.normal_pressure_angle, 25.0 * M_PI / 180.0, 1e-15);
  EXPECT_DOUBLE_EQ(g.dedendum_coef, 1.25);
  EXPECT_DOUBLE_EQ(g.root_radius_coef, 0.38);
  EXPECT_FALSE(g.center_distance.has_value());
}

TEST(ObjectReader, UnknownKeySuggestsNearest) {
  auto j = spur_pair();
  j["face_widht_mm"] = 20.0;
  const auto msg = input_error_of([&] { read_gear_pair(ObjectReader(j, "gear_pair")); });
  EXPECT_NE(msg.find("gear_pair.face_widht_mm: unknown key (did you mean 'face_width_mm'?)"),
                    std::string::npos) << msg;
}

TEST(ObjectReader, MissingKeyIsNamed) {
  auto j = spur_pair();
  j.erase("normal_module_mm");
  EXPECT_EQ(input_error_of([&] { read_gear_pair(ObjectReader(j, "gear_pair")); }),
            "gear_pair.normal_module_mm: missing required key");
}

TEST(ObjectReader, WrongTypeIsNamed) {
  auto j = spur_pair();
  j["teeth"] = json::array({22.5, 32});
  EXPECT_EQ(input_error_of([&] { read_gear_pair(ObjectReader(j, "gear_pair")); }),
            "gear_pair.teeth[0] = 22.5: must be an integer, got a number");
  j = spur_pair();
  j["normal_module_mm"] = "2";
  EXPECT_EQ(input_error_of([&] { read_gear_pair(ObjectReader(j, "gear_pair")); }),
            "gear_pair.normal_module_mm = \"2\": must be a number, got a string");
}

TEST(ObjectReader, RangesAreNamed) {
  auto j = spur_pair();
  j["normal_pressure_angle_deg"] = 40;
  EXPECT_EQ(input_error_of([&] { read_gear_pair(ObjectReader(j, "gear_pair")); }),
            "gear_pair.normal_pressure_angle_deg = 40: allowed range is [10, 35] deg");
  j = spur_pair();
  j["normal_module_mm"] = 0;
  EXPECT_EQ(input_error_of([&] { read_gear_pair(ObjectReader(j, "gear_pair")); }),
            "gear_pair.normal_module_mm = 0: allowed range is [0.01, 1000] mm");
}

TEST(ObjectReader, MaterialsOneObjectOrPair) {
  const auto one = json::parse(R"({"materials": {"youngs_modulus_GPa": 206, "poisson_ratio": 0.3}})");
  ObjectReader r1(one, "");
  const auto m = read_materials(r1);
  EXPECT_DOUBLE_EQ(m[1].youngs_modulus, 206e9);
  const auto two = json::parse(R"({"materials": [{"youngs_modulus_GPa": 206, "poisson_ratio": 0.3},
                                                 {"youngs_modulus_GPa": 70, "poisson_ratio": 0.7}]})");
  ObjectReader r2(two, "");
  EXPECT_EQ(input_error_of([&] { read_materials(r2); }),
            "materials[1].poisson_ratio = 0.7: allowed range is [0, 0.5]");
}

TEST(ObjectReader, LubricantViscosityOrder) {
  const auto j = json::parse(R"({"viscosity_Pa_s": 0.08, "pressure_viscosity_1_per_GPa": 20,
                                 "nu40_mm2_s": 30, "nu100_mm2_s": 320})");
  EXPECT_NE(input_error_of([&] { read_lubricant(ObjectReader(j, "lubricant")); }).find("must be below nu40_mm2_s"),
            std::string::npos);
}

TEST(ParseJson, MalformedGivesLine) {
  const auto msg = input_error_of([] { parse_json("{\n  \"kind\": \"geometry\",\n  \"x\": ]\n}", "case.json"); });
  EXPECT_EQ(msg.rfind("case.json: malformed JSON at line 3", 0), 0u) << msg;
}

TEST(EditDistance, Basics) {
  EXPECT_EQ(edit_distance("teeht", "teeth"), 2u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("abc", "abc"), 0u);
}

}  // namespace
}  // namespace gearbench::model
