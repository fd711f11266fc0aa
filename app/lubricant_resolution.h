#pragma once
// Named lubricants in case files (issue 24): every "lubricant" section (and the ISO/TR
// 15144-1 "micropitting.oil") that names an oil becomes explicit numbers before the kind
// reads the case. The one place where case parsing meets the lubricant catalogue.
#include <nlohmann/json.hpp>

namespace gearbench::app {

/// The case with its named oils resolved; `echo` gets one entry per resolved section (key
/// path → name, temperature, values, sources), empty when the case names none.
nlohmann::json resolve_named_lubricants(const nlohmann::json& case_json, nlohmann::json& echo);

}  // namespace gearbench::app
