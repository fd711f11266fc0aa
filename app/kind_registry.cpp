#include "kind_registry.h"

#include <cmath>
#include <fmt/format.h>
#include <stdexcept>
#include <vector>

#include "model/errors.h"
#include "lubricant_resolution.h"
#include "model/json_reader.h"

namespace gearbench::app {

KindRegistry& KindRegistry::instance() {
  static KindRegistry registry;
  return registry;
}

void KindRegistry::add(KindSpec kind) {
  const std::string name = kind.name;
  kinds_.emplace(name, std::move(kind));
}

const KindSpec& KindRegistry::find(const std::string& name) const {
  const auto it = kinds_.find(name);
  if (it != kinds_.end()) return it->second;
  std::vector<std::string> names;
  std::string nearest;
  std::size_t best = std::string::npos;
  for (const auto& [n, spec] : kinds_) {
    names.push_back(n);
    if (const auto d = model::edit_distance(name, n); d < best) {
      best = d;
      nearest = n;
    }
  }
  throw InputError(fmt::format("kind = {}: unknown kind{}; allowed values are {}", model::shown_value(name),
                               best <= 3 ? fmt::format(" (did you mean '{}'?)", nearest) : "",
                               fmt::join(names, ", ")));
}

nlohmann::json run_case(const nlohmann::json& case_json) {
  if (!case_json.is_object()) throw InputError("case: must be a JSON object with a \"kind\" key");
  const auto it = case_json.find("kind");
  if (it == case_json.end()) throw InputError("kind: missing required key");
  if (!it->is_string())
    throw InputError(fmt::format("kind = {}: must be a string", model::shown_value(*it)));
  const auto& kind = KindRegistry::instance().find(it->get<std::string>());
  nlohmann::json lubricants;
  auto result = kind.run(resolve_named_lubricants(case_json, lubricants));
  if (!lubricants.empty() && result.is_object()) result["lubricant_resolved"] = lubricants;
  ensure_finite(result);
  return result;
}

void ensure_finite(const nlohmann::json& j, const std::string& path) {
  if (j.is_number_float() && !std::isfinite(j.get<double>()))
    throw std::logic_error(fmt::format("{} is not finite: refusing to write it", path));
  if (j.is_array())
    for (std::size_t i = 0; i < j.size(); ++i) ensure_finite(j[i], fmt::format("{}[{}]", path, i));
  if (j.is_object())
    for (const auto& item : j.items()) ensure_finite(item.value(), path + "." + item.key());
}

}  // namespace gearbench::app
