#pragma once
// JSON Schemas (draft 2020-12) of case files, made from the Options tables that the kinds'
// readers read (issue 21): `gearbench schema [KIND]` prints them, and an editor can check a
// case against them while it is written.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "kind_registry.h"

namespace gearbench::app {

/// The sections model::read_gear_case reads: "gear_pair" (always required) and "materials",
/// "operating", "lubricant", of which `required` names those the kind needs.
nlohmann::json gear_case_schema(const std::vector<std::string>& required);

/// An object schema holding one section read by `section_schema`; `required` if it must be given.
nlohmann::json section_part(const std::string& key, nlohmann::json section_schema, bool required);

/// The schema of a case of this kind.
nlohmann::json kind_schema(const KindSpec& kind);

/// One schema for every kind: the kind's own schema chosen by "kind".
nlohmann::json all_kinds_schema();

}  // namespace gearbench::app
