// Unit tests of the validating JSON reader and the case sections (solvers/model).
#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_log.h>
#include <gtest/gtest.h>

#include <cmath>

#include "model/case_reader.h"
#include "model/errors.h"
#include "model/gsl_status.h"
#include "support/test_support.h"

namespace gearbench::model {
namespace {

using nlohmann::json;

using testing_support::input_error_of;

json spur_pair() {
  return json::parse(R"({"teeth": [22, 32], "normal_module_mm": 2.0,
                         "normal_pressure_angle_deg": 25.0, "face_width_mm": 20.0})");
}

// GSL's failures come back as statuses and errors, never through its default handler, which
// would abort() the process: ln(−1) is a domain error.
TEST(GslStatus, FailuresAreStatusesAndErrorsNotAborts) {
  gsl_use_status_codes();
  gsl_sf_result r;
  const int status = gsl_sf_log_e(-1.0, &r);
  EXPECT_EQ(status, GSL_EDOM);
  try {
    gsl_check(status, "log");
    ADD_FAILURE() << "no error for GSL_EDOM";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), std::string("GSL log: ") + gsl_strerror(GSL_EDOM));
  }
  EXPECT_NO_THROW(gsl_check(GSL_SUCCESS, "log"));
}

TEST(ObjectReader, ReadsUnitsIntoSI) {
  const auto g = read_gear_pair(ObjectReader(spur_pair(), "gear_pair"));
  EXPECT_EQ(g.teeth[1], 32);
  EXPECT_DOUBLE_EQ(g.normal_module, 2e-3);
  EXPECT_NEAR(g.normal_pressure_angle, 25.0 * M_PI / 180.0, 1e-15);
  EXPECT_DOUBLE_EQ(g.dedendum_coef, 1.25);
  // 25°: the rack tooth is too narrow for ISO 53's ρ_fP 0.38; the default is the full-round
  // tip radius, (π/4 − h_fP tan α)/(1/cos α − tan α).
  const double a = 25.0 * M_PI / 180.0;
  EXPECT_NEAR(g.root_radius_coef, (M_PI / 4 - 1.25 * std::tan(a)) / (1 / std::cos(a) - std::tan(a)), 1e-15);
  EXPECT_FALSE(g.center_distance.has_value());
}

TEST(ObjectReader, BasicRackProfilesOfIso53) {
  auto j = spur_pair();
  j["normal_pressure_angle_deg"] = 20.0;
  EXPECT_DOUBLE_EQ(read_gear_pair(ObjectReader(j, "gear_pair")).root_radius_coef, 0.38);
  j["basic_rack"] = "ISO53_D";
  const auto d = read_gear_pair(ObjectReader(j, "gear_pair"));
  EXPECT_DOUBLE_EQ(d.dedendum_coef, 1.4);
  EXPECT_DOUBLE_EQ(d.root_radius_coef, 0.39);
  j["root_radius_coef"] = 0.3;
  EXPECT_NE(input_error_of([&] { read_gear_pair(ObjectReader(j, "gear_pair")); })
                .find("gear_pair.basic_rack = \"ISO53_D\": sets dedendum_coef and root_radius_coef"),
            std::string::npos);
  j.erase("root_radius_coef");
  j["normal_pressure_angle_deg"] = 25.0;
  EXPECT_NE(input_error_of([&] { read_gear_pair(ObjectReader(j, "gear_pair")); }).find("20 deg pressure angle"),
            std::string::npos);
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

// Issue 20: what a hostile file can do to the parser. Nesting is bounded (60,000 levels
// once overflowed the stack), a number beyond double range and a duplicate key name their
// key, and nothing from the input reaches a message unescaped or whole.
TEST(ParseJson, DeepNestingIsRefusedWithoutRecursion) {
  const std::string deep = std::string(60000, '[') + std::string(60000, ']');
  const auto doc = parse_json(R"({"kind":"geometry","description":)" + deep + "}", "case.json");
  ObjectReader root(doc, "");
  EXPECT_EQ(input_error_of([&] { root.string("description"); }), "description: nested deeper than 64 levels");
  const std::string limit = std::string(max_json_depth, '[') + std::string(max_json_depth, ']');
  EXPECT_NO_THROW(parse_json(limit, "case.json"));
  // With no key to hold the excess, the cap is the error, where it is passed.
  const auto msg = input_error_of([&] { parse_ordered_json("[" + limit + "]", "sweep.json"); });
  EXPECT_EQ(msg.rfind("[0][0]", 0), 0u) << msg;
  EXPECT_NE(msg.find("]: nested deeper than 64 levels"), std::string::npos) << msg;
}

std::string array_of(std::size_t n) {
  std::string a = "[0";
  for (std::size_t i = 1; i < n; ++i) a += ",0";
  return a + "]";
}

// A value under a key that passes a cap is skipped to its end, not read into memory (once
// 7.6 GB and 21 s for 1e8 elements under an unknown key), and kept as a placeholder: an
// unknown key is then refused as unknown, a known one by the cap; what follows is read.
TEST(ParseJson, AValueUnderAKeyPastACapIsNotRead) {
  const auto doc = parse_json(R"({"kind": "geometry", "bogus": )" + array_of(max_json_values) +
                                  R"(, "deep": {"x": )" + std::string(100, '[') + std::string(100, ']') +
                                  R"(}, "gear_pair": {"teeth": [22, 32]}})",
                              "case.json");
  const std::string too_many = fmt::format("more than {} values in one file, the most gearbench reads (a case "
                                           "holds a few hundred)", max_json_values);
  EXPECT_EQ(unread(doc["bogus"]), too_many);
  EXPECT_EQ(unread(doc["deep"]["x"]), "nested deeper than 64 levels");
  EXPECT_EQ(shown_value(doc["bogus"]), fmt::format("(more than {} values)", max_json_values));
  EXPECT_EQ(doc["gear_pair"]["teeth"], json({22, 32}));
  EXPECT_EQ(unread(doc["kind"]), std::nullopt);

  ObjectReader unknown(doc, "");
  unknown.string("kind");
  unknown.accept("deep");
  unknown.accept("gear_pair");
  EXPECT_EQ(input_error_of([&] { unknown.finish(); }), "bogus: unknown key (known keys: deep, gear_pair, kind)");
  ObjectReader known(doc, "");
  EXPECT_EQ(input_error_of([&] { known.number("bogus", Range::positive()); }), "bogus: " + too_many);
  EXPECT_EQ(input_error_of([&] { known.object("deep").number_pair("x", Range::positive()); }),
            "deep.x: nested deeper than 64 levels");

  // With no key to hold the excess, the cap is the error, where it is passed: the top array
  // is the first value, its element n − 2 the last one read.
  const auto msg = input_error_of([&] { parse_json(array_of(max_json_values), "case.json"); });
  EXPECT_EQ(msg, fmt::format("[{}]: {}", max_json_values - 1, too_many));
  EXPECT_EQ(unread(parse_json(R"({"bogus":)" + array_of(max_json_values - 2) + "}", "case.json")["bogus"]),
            std::nullopt);
}

TEST(ParseJson, NumberBeyondDoubleNamesItsKey) {
  EXPECT_EQ(input_error_of([] { parse_json(R"({"gear_pair": {"teeth": [22, 1e400]}})", "case.json"); }),
            "gear_pair.teeth[1] = 1e400: beyond the range of a double (about ±1.8e308)");
  EXPECT_EQ(input_error_of([] { parse_ordered_json(R"({"vary": {"a": [1, 2, -1e999]}})", "sweep.json"); }),
            "vary.a[2] = -1e999: beyond the range of a double (about ±1.8e308)");
  EXPECT_EQ(input_error_of([] { parse_json("1e999", "case.json"); }),
            "case.json = 1e999: beyond the range of a double (about ±1.8e308)");
}

TEST(ParseJson, DuplicateKeyIsRefused) {
  EXPECT_EQ(input_error_of([] { parse_json(R"({"a": {"b": 1, "c": [{"b": 1}], "b": 2}})", "case.json"); }),
            "a.b: duplicate key; give each key once");
  EXPECT_NE(input_error_of([] { parse_ordered_json(R"({"kind": "x", "kind": "y"})", "sweep.json"); }), "");
  EXPECT_NO_THROW(parse_json(R"([{"b": 1}, {"b": 2}])", "case.json"));  // one key per object
}

TEST(ShownText, EscapesControlCharactersAndCutsLongText) {
  EXPECT_EQ(shown_text(std::string("a\0b\r\nc\t\x7f", 8)), "a\\u0000b\\r\\nc\\t\\u007f");
  const auto long_key = shown_text(std::string(1 << 20, 'k'));
  EXPECT_LE(long_key.size(), 200u);
  EXPECT_EQ(long_key.substr(long_key.size() - 3), "...");
  EXPECT_EQ(shown_text("äöü"), "äöü");
  EXPECT_EQ(shown_text(std::string(196, 'a') + "äöü"), std::string(196, 'a') + "...");  // never half a character
}

TEST(ShownValue, NeverDumpsAWholeValue) {
  json deep = json::array();
  for (int i = 0; i < 1000; ++i) deep = json::array({deep, std::string(1000, 'x')});
  const auto shown = shown_value(deep);
  EXPECT_LE(shown.size(), 40u);
  EXPECT_EQ(shown_value(json::parse(R"({"k\n": "v\r"})")), R"({"k\n":"v\r"})");
}

TEST(ObjectReader, KeysAndValuesAreShownEscaped) {
  auto j = spur_pair();
  j[std::string("teeth\0x", 7)] = 1;
  EXPECT_EQ(input_error_of([&] { read_gear_pair(ObjectReader(j, "gear_pair")); }),
            "gear_pair.teeth\\u0000x: unknown key (did you mean 'teeth'?)");
  const auto c = json::parse(R"({"load_sharing": "iso\r\nerror: forged"})");
  ObjectReader root(c, "");
  const auto msg = input_error_of([&] { root.string("load_sharing", {"iso", "equal"}); });
  EXPECT_EQ(msg, R"(load_sharing = "iso\r\nerror: forged": allowed values are iso, equal)");
}

TEST(ObjectReader, LargeIntegersDoNotWrap) {
  auto j = spur_pair();
  j["teeth"] = json::parse("[18446744073709551615, 32]");
  EXPECT_EQ(input_error_of([&] { read_gear_pair(ObjectReader(j, "gear_pair")); }),
            "gear_pair.teeth[0] = 18446744073709551615: allowed range is [5, 10000]");
  j["teeth"] = json::parse("[22, 9223372036854775808]");
  EXPECT_EQ(input_error_of([&] { read_gear_pair(ObjectReader(j, "gear_pair")); }),
            "gear_pair.teeth[1] = 9223372036854775808: allowed range is [5, 10000]");
  j["teeth"] = json::parse("[4294967318, 32]");  // 2^32 + 22 must not read as 22
  EXPECT_EQ(input_error_of([&] { read_gear_pair(ObjectReader(j, "gear_pair")); }),
            "gear_pair.teeth[0] = 4294967318: allowed range is [5, 10000]");
}

// Shifts whose sum leaves inv α_wt ≤ 0 have no working pressure angle: once an internal
// error (inverse_involute) in 7 of 9 kinds, now the key is named with the limit.
TEST(ObjectReader, ShiftSumWithoutWorkingPressureAngle) {
  auto j = spur_pair();
  j["profile_shift"] = {-1.0, -1.0};
  EXPECT_EQ(input_error_of([&] { read_gear_pair(ObjectReader(j, "gear_pair")); }),
            "gear_pair.profile_shift = [-1, -1]: the sum -2 leaves no working pressure angle for 22 + 32 "
            "teeth; the sum must exceed -1.736");
  j["profile_shift"] = {-0.5, -1.0};
  EXPECT_NO_THROW(read_gear_pair(ObjectReader(j, "gear_pair")));
}

TEST(ReadTextFile, DirectoryAndSizeCap) {
  EXPECT_EQ(input_error_of([] { read_text_file("/tmp"); }), "/tmp: is a directory, not a case file");
  EXPECT_EQ(input_error_of([] { read_text_file("/dev/zero", "sweep file"); }),
            "/dev/zero: larger than 64 MiB, the most gearbench reads in a sweep file");
}

TEST(EditDistance, Basics) {
  EXPECT_EQ(edit_distance("teeht", "teeth"), 2u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("abc", "abc"), 0u);
}

}  // namespace
}  // namespace gearbench::model
