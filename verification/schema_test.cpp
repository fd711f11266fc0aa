// `gearbench schema` (issue 21): every key of every case file in cases/ is held against its
// kind's schema, so a key the tables do not declare (or a value outside a declared range)
// fails here. Every kind has a schema.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/cli_support.h"

namespace {

using gearbench::testing_support::cases_dir;
using gearbench::testing_support::read_case;
using gearbench::testing_support::read_json_file;
using gearbench::testing_support::run_gearbench;
using nlohmann::json;
namespace fs = std::filesystem;

/// The part of JSON Schema 2020-12 that `gearbench schema` writes: type, properties,
/// required, additionalProperties false, items, min/maxItems, enum, const, the four bounds,
/// anyOf/oneOf (one branch must hold), allOf with if/then, and $ref into $defs. Returns what does not hold.
class SchemaCheck {
 public:
  explicit SchemaCheck(json root) : root_(std::move(root)) {}

  std::vector<std::string> errors(const json& value) const {
    std::vector<std::string> out;
    check(value, root_, "case", out);
    return out;
  }

 private:
  void check(const json& v, const json& s, const std::string& at, std::vector<std::string>& out) const {
    if (s.contains("$ref")) return check(v, root_["$defs"][s["$ref"].get<std::string>().substr(8)], at, out);
    for (const char* any : {"anyOf", "oneOf"})
      if (s.contains(any)) {
        const bool one_holds = std::any_of(s[any].begin(), s[any].end(), [&](const json& branch) {
          std::vector<std::string> e;
          check(v, branch, at, e);
          return e.empty();
        });
        if (!one_holds) out.push_back(at + ": matches none of " + any);
      }
    for (const auto& part : s.value("allOf", json::array())) {
      std::vector<std::string> condition;
      if (part.contains("if")) check(v, part["if"], at, condition);
      if (condition.empty()) check(v, part.contains("then") ? part["then"] : part, at, out);
    }
    if (s.contains("type") && !has_type(v, s["type"].get<std::string>()))
      return out.push_back(at + ": not of type " + s["type"].get<std::string>());
    if (s.contains("enum") && std::find(s["enum"].begin(), s["enum"].end(), v) == s["enum"].end())
      out.push_back(at + " = " + v.dump() + ": not in enum");
    if (s.contains("const") && v != s["const"]) out.push_back(at + " = " + v.dump() + ": not the const");
    if (v.is_number()) bounds(v.get<double>(), s, at, out);
    if (v.is_object()) object(v, s, at, out);
    if (v.is_array()) {
      if (s.contains("minItems") && v.size() < s["minItems"].get<std::size_t>()) out.push_back(at + ": too few items");
      if (s.contains("maxItems") && v.size() > s["maxItems"].get<std::size_t>()) out.push_back(at + ": too many items");
      if (s.contains("items"))
        for (std::size_t i = 0; i < v.size(); ++i) check(v[i], s["items"], at + "[" + std::to_string(i) + "]", out);
    }
  }

  static bool has_type(const json& v, const std::string& type) {
    if (type == "object") return v.is_object();
    if (type == "array") return v.is_array();
    if (type == "number") return v.is_number();
    if (type == "integer") return v.is_number_integer();
    if (type == "string") return v.is_string();
    if (type == "boolean") return v.is_boolean();
    return false;
  }

  static void bounds(double x, const json& s, const std::string& at, std::vector<std::string>& out) {
    if ((s.contains("minimum") && x < s["minimum"].get<double>()) ||
        (s.contains("maximum") && x > s["maximum"].get<double>()) ||
        (s.contains("exclusiveMinimum") && x <= s["exclusiveMinimum"].get<double>()) ||
        (s.contains("exclusiveMaximum") && x >= s["exclusiveMaximum"].get<double>()))
      out.push_back(at + " = " + json(x).dump() + ": out of bounds");
  }

  void object(const json& v, const json& s, const std::string& at, std::vector<std::string>& out) const {
    const json properties = s.value("properties", json::object());
    for (const auto& key : s.value("required", json::array()))
      if (!v.contains(key)) out.push_back(at + "." + key.get<std::string>() + ": required, missing");
    for (const auto& [key, value] : v.items()) {
      if (properties.contains(key)) check(value, properties[key], at + "." + key, out);
      else if (s.value("additionalProperties", true) == false) out.push_back(at + "." + key + ": unknown key");
    }
  }

  json root_;
};

/// The case files of cases/, each with its kind's schema.
struct SchemaCase {
  fs::path path;
  json value;
  json schema;
};

std::vector<SchemaCase> cases_with_schema() {
  std::vector<SchemaCase> out;
  for (const auto& entry : fs::directory_iterator(cases_dir())) {
    if (entry.path().extension() != ".json") continue;
    auto value = read_json_file(entry.path());
    const auto o = run_gearbench("schema " + value["kind"].get<std::string>());
    EXPECT_EQ(o.exit_code, 0) << entry.path() << ": " << o.err;
    out.push_back({entry.path(), std::move(value), json::parse(o.out)});
  }
  return out;
}

TEST(Schema, EveryKeyOfEveryCaseIsInItsKindsSchema) {
  const auto cases = cases_with_schema();
  // cases/ holds 32 case files today; fewer means the test checks less than it claims (the
  // cases moved).
  EXPECT_GE(cases.size(), 32u);
  for (const char* kind : {"dynamics", "fe_stiffness", "ehl_line", "ehl_transient", "oil_film_stiffness", "tehl_point",
                           "tehl_path"})
    EXPECT_TRUE(std::any_of(cases.begin(), cases.end(), [&](const SchemaCase& c) { return c.value["kind"] == kind; }))
        << kind;
  for (const auto& c : cases)
    for (const auto& e : SchemaCheck(c.schema).errors(c.value)) ADD_FAILURE() << c.path << ": " << e;
}

// The check above must be able to fail: an unknown key at the root and in every section
// that refuses one, and a value outside its range, are each reported.
TEST(Schema, AnUnknownKeyOrAValueOutOfRangeFailsTheCheck) {
  const auto cases = cases_with_schema();
  ASSERT_FALSE(cases.empty());
  for (const auto& c : cases) {
    const SchemaCheck check(c.schema);
    auto extra = c.value;
    extra["not_a_key"] = 1;
    EXPECT_EQ(check.errors(extra).size(), 1u) << c.path;
    for (const auto& [key, section] : c.value.items()) {
      if (!section.is_object() || section.contains("name") || section.contains("grade")) continue;
      auto nested = c.value;
      nested[key]["not_a_key"] = 1;
      EXPECT_FALSE(check.errors(nested).empty()) << c.path << ": " << key << ".not_a_key passed";
    }
    auto out_of_range = c.value;
    out_of_range["gear_pair"]["teeth"] = json::array({4, 30});
    EXPECT_FALSE(check.errors(out_of_range).empty()) << c.path;
  }
}

// A default in the schema is the one the solver gets: the stiffness case gives no
// "positions", so the run records the schema's default as given.
TEST(Schema, DefaultsAreTheOnesTheSolverGets) {
  const auto schema = json::parse(run_gearbench("schema stiffness").out);
  const auto o = run_gearbench("run " GEARBENCH_SOURCE_DIR "/cases/seed003_spur_stiffness.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto result = json::parse(o.out);
  for (const char* key : {"positions", "path_points", "beam_start", "foundation"})
    EXPECT_EQ(result["options_given"][key], schema["properties"][key]["default"]) << key;
  // A spur pair is one slice whatever was given: the record says so.
  EXPECT_EQ(result["options_given"]["slices"], 50);
  EXPECT_EQ(result["options_used"]["slices"], 1);
}

/// A kind's schema and two case files of its two variants, each checked to pass it.
struct TwoVariants {
  SchemaCheck check;
  json first, second;
};
TwoVariants two_variants(const std::string& kind, const std::string& first, const std::string& second) {
  TwoVariants v{SchemaCheck(json::parse(run_gearbench("schema " + kind).out)),
                read_json_file(cases_dir() / first),
                read_json_file(cases_dir() / second)};
  EXPECT_TRUE(v.check.errors(v.first).empty()) << first;
  EXPECT_TRUE(v.check.errors(v.second).empty()) << second;
  return v;
}

// The dynamics kind's keys depend on "model": each model's branch holds its own keys (an
// absent "model" is spur6), so a key of the other model is refused as unknown.
TEST(Schema, DynamicsChoosesTheModelsKeys) {
  auto [check, spur, herringbone] =
      two_variants("dynamics", "seed003_spur_dynamics.json", "seed000_herringbone_dynamics.json");
  spur["mesh_in_impact"] = true;
  EXPECT_EQ(check.errors(spur), std::vector<std::string>{"case.mesh_in_impact: unknown key"});
  spur.erase("mesh_in_impact");
  spur.erase("model");  // spur6 is the default
  spur["crack"] = {{"type", "pitch"}, {"length_mm", 1.0}, {"angle_deg", 45}, {"gear", 2}};
  EXPECT_EQ(check.errors(spur), std::vector<std::string>{"case.crack.gear = 2.0: out of bounds"});
  herringbone.erase("model");  // read as spur6: the herringbone's own keys are unknown there
  EXPECT_FALSE(check.errors(herringbone).empty());
  herringbone["model"] = "herringbone12";
  herringbone["integrator"] = {{"method", "verner"}};  // a study-only method is not offered
  EXPECT_EQ(check.errors(herringbone), std::vector<std::string>{"case.integrator.method = \"verner\": not in enum"});
}

// A default in the dynamics schema is the one the solver gets, read back from the
// options_given of a short run of the spur6 seed case without its friction section.
TEST(Schema, DynamicsDefaultsAreTheOnesTheSolverGets) {
  const auto schema = json::parse(run_gearbench("schema dynamics").out);
  const auto& spur6 = schema["allOf"][0]["then"]["properties"];
  auto c = read_case("seed003_spur_dynamics");
  c["runup_cycles"] = 2;
  c["record_cycles"] = 2;
  c.erase("friction");
  const auto o = run_gearbench("run " + gearbench::testing_support::write_case("schema_spur6_defaults", c.dump()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto given = json::parse(o.out)["options_given"];
  EXPECT_EQ(given["friction"]["mu"], spur6["friction"]["properties"]["mu"]["default"]);
  for (const char* key : {"method", "rtol", "atol", "max_steps"})
    EXPECT_EQ(given["integrator"][key], spur6["integrator"]["properties"][key]["default"]) << key;
  EXPECT_EQ(given["samples_per_cycle"], spur6["samples_per_cycle"]["default"]);
}

// The EHL kinds' "grid" is one table, its defaults its holder's: the steady line contact
// chooses its grid by the error target (no nodes default), the transient and thermal kinds
// run a fixed 641-node grid. The record of a Moes run gives the schema's defaults and the
// grid the error target chose.
TEST(Schema, EhlGridDefaultsAreTheHoldersOwn) {
  const auto line = json::parse(run_gearbench("schema ehl_line").out)["properties"]["grid"]["properties"];
  EXPECT_FALSE(line["nodes"].contains("default"));
  EXPECT_EQ(line["target_error"]["default"], 0.005);
  EXPECT_EQ(line["stop"]["default"], "discretisation_error");
  const auto transient = json::parse(run_gearbench("schema ehl_transient").out)["properties"]["grid"]["properties"];
  EXPECT_EQ(transient["nodes"]["default"], 641);
  EXPECT_EQ(transient["tolerance"]["default"], 1e-6);
  const auto point = json::parse(run_gearbench("schema tehl_point").out)["properties"];
  EXPECT_EQ(point["grid"]["properties"]["stop"]["default"], "residual");
  EXPECT_EQ(point["rheology"]["enum"], json::array({"newtonian", "eyring"}));
  EXPECT_EQ(point["thermal"]["properties"]["heat_sources"]["default"], "shear_and_compression");

  const auto o = run_gearbench("run " GEARBENCH_SOURCE_DIR "/cases/ehl_moes_M20_L10.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  for (const char* key : {"target_error", "max_levels", "cycle", "stop", "error_fraction", "max_cycles"})
    EXPECT_EQ(r["options_given"][key], line[key]["default"]) << key;
  EXPECT_FALSE(r["options_given"].contains("nodes"));
  EXPECT_EQ(r["options_used"]["nodes"], r["diagnostics"]["nodes"]);
  EXPECT_EQ(r["converged"], true);
}

// The oil-film kind's keys depend on "tooth_form": the rack only with the double involute,
// which requires it.
TEST(Schema, OilFilmChoosesTheToothFormsKeys) {
  auto [check, involute, stepped] =
      two_variants("oil_film_stiffness", "oil_film_stiffness_spur.json", "seed002_double_involute_oil_film.json");
  involute["double_involute"] = stepped["double_involute"];
  EXPECT_EQ(check.errors(involute), std::vector<std::string>{"case.double_involute: unknown key"});
  stepped.erase("double_involute");
  EXPECT_EQ(check.errors(stepped), std::vector<std::string>{"case.double_involute: required, missing"});
}

TEST(Schema, EveryKindHasASchema) {
  for (const char* kind : {"ehl_line", "ehl_transient", "oil_film_stiffness", "tehl_point", "tehl_path"}) {
    const auto o = run_gearbench(std::string("schema ") + kind);
    EXPECT_EQ(o.exit_code, 0) << kind << ": " << o.err;
  }
  EXPECT_EQ(run_gearbench("schema no_such_kind").exit_code, 2);
}

TEST(Schema, AllKindsSchemaChoosesEachKindsOwn) {
  const auto o = run_gearbench("schema");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto all = json::parse(o.out);
  for (const auto& kind : all["properties"]["kind"]["enum"]) EXPECT_TRUE(all["$defs"].contains(kind)) << kind;
  EXPECT_EQ(all["properties"]["kind"]["enum"].size(), 11u);
  EXPECT_FALSE(all.contains("$comment"));
  const SchemaCheck check(all);
  auto geometry = read_case("seed004_spur_geometry");
  EXPECT_TRUE(check.errors(geometry).empty());
  geometry["gear_pair"]["not_a_key"] = 1;  // the geometry kind's own schema is the one applied
  EXPECT_EQ(check.errors(geometry), std::vector<std::string>{"case.gear_pair.not_a_key: unknown key"});
  auto herringbone = read_case("seed000_herringbone_dynamics");
  EXPECT_TRUE(check.errors(herringbone).empty());
  herringbone["mesh"]["not_a_key"] = 1;  // through $ref and the model's branch
  EXPECT_EQ(check.errors(herringbone), std::vector<std::string>{"case.mesh.not_a_key: unknown key"});
}

}  // namespace
