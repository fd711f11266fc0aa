#include "option_table.h"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "errors.h"

namespace gearbench::model {

using nlohmann::json;

void throw_option_range(const std::string& key, double value, const KeyInfo& info) {
  throw InputError(range_message(key, value, *info.range, info.spec.unit));
}

void throw_option_choice(const std::string& key, const KeyInfo& info) {
  throw InputError(fmt::format("{}: holds none of the allowed values {}", key, fmt::join(info.choices, ", ")));
}

namespace {

/// minimum/maximum, or their exclusive forms for an open end; no upper bound for "> lo".
void add_bounds(json& s, const Range& r, bool integer) {
  const auto bound = [integer](double v) { return integer ? json(static_cast<long long>(v)) : json(v); };
  s[r.lo_open ? "exclusiveMinimum" : "minimum"] = bound(r.lo);
  if (r.hi < 1e299) s[r.hi_open ? "exclusiveMaximum" : "maximum"] = bound(r.hi);
}

json value_schema(const KeyInfo& info) {
  switch (info.type) {
    case KeyType::number:
    case KeyType::integer: {
      json s = {{"type", info.type == KeyType::number ? "number" : "integer"}};
      add_bounds(s, *info.range, info.type == KeyType::integer);
      return s;
    }
    case KeyType::boolean: return {{"type", "boolean"}};
    case KeyType::choice: return {{"type", "string"}, {"enum", info.choices}};
    case KeyType::text: return {{"type", "string"}};
    case KeyType::section:
    case KeyType::external: return info.schema;
  }
  return json::object();
}

}  // namespace

json key_schema(const KeyInfo& info, const json& default_value) {
  json s = value_schema(info);
  if (info.shape == Shape::pair) s = {{"type", "array"}, {"items", s}, {"minItems", 2}, {"maxItems", 2}};
  if (info.shape == Shape::list) s = {{"type", "array"}, {"items", s}};
  std::string description = info.spec.description;
  if (!info.spec.default_text.empty())
    description += fmt::format("{}default: {}", description.empty() ? "" : "; ", info.spec.default_text);
  if (!description.empty()) s["description"] = description;
  if (!info.spec.unit.empty()) s["unit"] = info.spec.unit;
  if (!default_value.is_null()) s["default"] = default_value;
  return s;
}

json merge_object_schemas(const std::vector<json>& parts, const std::string& description) {
  json out = {{"type", "object"}};
  if (!description.empty()) out["description"] = description;
  json properties = json::object();
  json required = json::array();
  for (const auto& p : parts) {
    const json part_properties = p.value("properties", json::object());  // items() must not outlive it
    const json part_required = p.value("required", json::array());
    for (const auto& [key, value] : part_properties.items()) properties[key] = value;
    for (const auto& key : part_required)
      if (std::find(required.begin(), required.end(), key) == required.end()) required.push_back(key);
  }
  out["properties"] = properties;
  if (!required.empty()) out["required"] = required;
  // Every reader ends with ObjectReader::finish(), which refuses a key it was not asked about.
  out["additionalProperties"] = false;
  return out;
}

}  // namespace gearbench::model
