#include "case_schema.h"

#include <fmt/format.h>
#include <stdexcept>

#include "lubricant/lubricant_section.h"
#include "model/case_reader.h"

namespace gearbench::app {

using nlohmann::json;

namespace {

constexpr const char* draft = "https://json-schema.org/draft/2020-12/schema";

/// One closed schema per value of the kind's variant key, each applied (if/then) where the case
/// holds that value, the default value's also where the key is absent. The top level names
/// only "kind" and the variant key: the chosen branch checks every key, once.
json variant_schema(const KindSpec& kind, const std::vector<json>& common) {
  const json merged = model::merge_object_schemas(common, kind.summary);
  const json& key = merged["properties"].at(kind.variant_key);
  json branches = json::array();
  for (const auto& variant : kind.schema_variants) {
    auto parts = common;
    for (auto& part : variant.parts()) parts.push_back(std::move(part));
    json when = {{"properties", {{kind.variant_key, {{"const", variant.value}}}}}};
    if (key.value("default", json()) != variant.value) when["required"] = {kind.variant_key};
    branches.push_back({{"if", when}, {"then", model::merge_object_schemas(parts)}});
  }
  return {{"type", "object"},
          {"description", kind.summary},
          {"properties", {{"kind", merged["properties"]["kind"]}, {kind.variant_key, key}}},
          {"required", {"kind"}},
          {"allOf", branches}};
}

}  // namespace

json section_part(const std::string& key, json section_schema, bool required) {
  json part = {{"properties", {{key, std::move(section_schema)}}}};
  if (required) part["required"] = {key};
  return part;
}

json gear_case_schema(const std::vector<std::string>& required) {
  const json material = model::material_table().schema("the material of both gears");
  const json materials = {
      {"description", "one material for both gears, or [pinion, wheel]"},
      {"oneOf", json::array({material, {{"type", "array"}, {"items", material}, {"minItems", 2}, {"maxItems", 2}}})}};
  const json properties = {
      {"gear_pair", model::gear_pair_table().schema("the gear pair (ISO 21771 notation; index 0 the pinion)")},
      {"materials", materials},
      {"operating", model::operating_table().schema("the operating point")},
      {"lubricant", lubricant::named_or_explicit_schema(
                        model::lubricant_table().schema("the lubricant at the oil temperature"))}};
  json needed = json::array({"gear_pair"});
  for (const auto& key : required) needed.push_back(key);
  return {{"properties", properties}, {"required", needed}};
}

json kind_schema(const KindSpec& kind) {
  // Every kind reads its keys from tables (issue 21); a kind registered without them is a
  // programming error, not a case without a schema.
  if (!kind.schema_parts) throw std::logic_error("kind " + kind.name + " registers no schema_parts");
  std::vector<json> parts = {{{"properties",
                               {{"kind", {{"const", kind.name}}},
                                {"description", {{"type", "string"}, {"description", "free text about the case"}}}}},
                              {"required", {"kind"}}}};
  for (auto& part : kind.schema_parts()) parts.push_back(std::move(part));
  json schema = kind.schema_variants.empty() ? model::merge_object_schemas(parts, kind.summary)
                                             : variant_schema(kind, parts);
  schema["$schema"] = draft;
  schema["title"] = fmt::format("gearbench case, kind {}", kind.name);
  return schema;
}

json all_kinds_schema() {
  json names = json::array(), chosen = json::array(), defs = json::object();
  for (const auto& [name, kind] : KindRegistry::instance().kinds()) {
    names.push_back(name);
    auto schema = kind_schema(kind);
    schema.erase("$schema");
    defs[name] = std::move(schema);
    chosen.push_back({{"if", {{"properties", {{"kind", {{"const", name}}}}}, {"required", {"kind"}}}},
                      {"then", {{"$ref", "#/$defs/" + name}}}});
  }
  return {{"$schema", draft},
              {"title", "gearbench case"},
              {"type", "object"},
              {"properties", {{"kind", {{"enum", names}, {"description", "picks the solver"}}}}},
              {"required", {"kind"}},
              {"allOf", chosen},
              {"$defs", defs}};
}

}  // namespace gearbench::app
