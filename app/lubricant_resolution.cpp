#include "lubricant_resolution.h"

#include <string>

#include "lubricant/lubricant_section.h"
#include "lubricant/viscosity_temperature.h"
#include "model/errors.h"
#include "model/json_reader.h"

namespace gearbench::app {
namespace {

using nlohmann::json;
using lubricant::CaseTemperature;
using lubricant::SectionForm;

bool thermal_kind(const std::string& kind) { return kind == "tehl_point" || kind == "tehl_path"; }

/// Which reader the kind's "lubricant" section feeds.
SectionForm lubricant_form(const std::string& kind) {
  if (kind == "ehl_line") return SectionForm::ehl_line;
  return thermal_kind(kind) ? SectionForm::thermal : SectionForm::gear;
}

/// The case's own temperature: the inlet of the thermal kinds, else the operating oil
/// temperature; numbers only (their ranges are the catalogue's to judge).
std::optional<CaseTemperature> case_temperature(const json& c, const std::string& kind) {
  if (thermal_kind(kind)) {
    if (const auto it = c.find("inlet_temperature_K"); it != c.end() && it->is_number())
      return CaseTemperature{"inlet_temperature_K", it->get<double>()};
    return std::nullopt;
  }
  if (const auto op = c.find("operating"); op != c.end() && op->is_object())
    if (const auto it = op->find("oil_temperature_C"); it != op->end() && it->is_number())
      return CaseTemperature{"operating.oil_temperature_C", it->get<double>() + lubricant::celsius_zero};
  return std::nullopt;
}

void resolve_at(json& section, const std::string& path, SectionForm form, const std::optional<CaseTemperature>& T,
                json& echo) {
  if (!lubricant::names_oil(section)) return;
  auto resolved = lubricant::resolve_section(section, path, form, T);
  section = std::move(resolved.section);
  echo[path] = std::move(resolved.echo);
}

}  // namespace

json resolve_named_lubricants(const json& case_json, json& echo) {
  echo = json::object();
  const auto kind_it = case_json.find("kind");
  if (kind_it == case_json.end() || !kind_it->is_string()) return case_json;
  const std::string kind = kind_it->get<std::string>();
  json c = case_json;
  if (const auto it = c.find("lubricant"); it != c.end())
    resolve_at(*it, "lubricant", lubricant_form(kind), case_temperature(case_json, kind), echo);
  if (const auto m = c.find("micropitting"); m != c.end() && m->is_object())
    if (const auto oil = m->find("oil"); oil != m->end())
      resolve_at(*oil, "micropitting.oil", SectionForm::micropitting_oil, std::nullopt, echo);
  return c;
}

}  // namespace gearbench::app
