#include "lubricant_section.h"

#include <map>

#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <vector>

#include "catalogue.h"
#include "model/errors.h"
#include "model/json_reader.h"
#include "rheology.h"
#include "viscosity_temperature.h"

namespace gearbench::lubricant {
namespace {

using nlohmann::json;

/// One key a form writes and where its value comes from in an OilState (in the key's unit).
struct FormKey {
  const char* key;
  std::function<std::optional<Sourced>(const OilState&)> value;
  bool required = false;
};

std::vector<FormKey> form_keys(SectionForm form) {
  const auto eta = [](const OilState& s) { return s.viscosity; };
  const auto alpha = [](const OilState& s) { return s.pressure_viscosity; };
  const auto z = [](const OilState& s) { return s.roelands_z; };
  const auto nu40 = [](const OilState& s) { return s.nu40; };
  const auto nu100 = [](const OilState& s) { return s.nu100; };
  const auto k = [](const OilState& s) { return s.thermal_conductivity; };
  const auto c = [](const OilState& s) { return s.specific_heat; };
  const auto rho15 = [](const OilState& s) { return s.density_15C; };
  switch (form) {
    case SectionForm::ehl_line:
      return {{"viscosity_Pa_s", eta, true}, {"pressure_viscosity_1_per_GPa", alpha, true},
              {"roelands_z", z}};
    case SectionForm::thermal:
      return {{"nu40_mm2_s", nu40, true}, {"nu100_mm2_s", nu100, true},
              {"density_kg_m3", rho15, true}, {"pressure_viscosity_1_per_GPa", alpha, true},
              {"thermal_conductivity_W_per_mK", k, true}, {"specific_heat_J_per_kgK", c, true}};
    case SectionForm::micropitting_oil:
      return {{"nu40_mm2_s", nu40, true}, {"nu100_mm2_s", nu100, true},
              {"density_15C_kg_m3", rho15, true}};
    case SectionForm::gear: break;
  }
  return {{"viscosity_Pa_s", eta, true}, {"pressure_viscosity_1_per_GPa", alpha, true},
          {"roelands_z", z}, {"density_kg_m3", [](const OilState& s) { return s.density; }},
          {"nu40_mm2_s", nu40}, {"nu100_mm2_s", nu100}, {"thermal_conductivity_W_per_mK", k},
          {"specific_heat_J_per_kgK", c}};
}

/// The keys of the library in a section (removed before the kind's reader sees it).
constexpr const char* library_keys[] = {"name", "grade", "base", "viscosity_index", "temperature_C"};

/// ν40, ν100 and ρ15 a section gives replace the catalogue's before the oil's state is
/// computed, so that what follows from them (η(T) by ASTM D341, ρ(T) and α by ISO/TR 15144-1,
/// the VI) is the case's oil's, not the grade's (a grade 100 with ν40 95 mm²/s had kept the
/// grade's α and VI). ρ15 is "density_kg_m3" in the thermal form, "density_15C_kg_m3" in the
/// micropitting one (elsewhere "density_kg_m3" is ρ at the temperature: not ρ15).
void use_case_data(model::ObjectReader& r, SectionForm form, OilData& oil) {
  if (const auto nu40 = r.optional_number("nu40_mm2_s", model::Range::positive(1e6), "mm2/s"))
    oil.nu40 = Sourced{*nu40, "case"};
  if (const auto nu100 = r.optional_number("nu100_mm2_s", model::Range::positive(1e6), "mm2/s"))
    oil.nu100 = Sourced{*nu100, "case"};
  const char* rho15 = form == SectionForm::thermal           ? "density_kg_m3"
                      : form == SectionForm::micropitting_oil ? "density_15C_kg_m3"
                                                              : nullptr;
  if (rho15)
    if (const auto rho = r.optional_number(rho15, model::Range::positive(1e5), "kg/m3"))
      oil.density_15C = Sourced{*rho, "case"};
}

/// The oil the section names: by "name", or by "grade" + "base" (+ "nu100_mm2_s" or "viscosity_index").
OilData named_oil(const json& section, const std::string& path, SectionForm form, const Catalogue& catalogue) {
  model::ObjectReader r(section, path);
  if (r.has("name")) {
    if (r.has("grade") || r.has("base") || r.has("viscosity_index"))
      throw InputError(fmt::format("{}.name: give either \"name\" or \"grade\" with \"base\" (and \"viscosity_index\"), "
                                   "not both", path));
    auto oil = catalogue.find(r.string("name"), r.key_path("name"));
    if (!oil.at_temperature) use_case_data(r, form, oil);  // a single-point oil has no ν line
    Catalogue::require_data(oil, r.key_path("name"));
    return oil;
  }
  const int grade = r.integer("grade", 1, 100000);
  const auto base = parse_base_oil(r.string("base"), r.key_path("base"));
  const auto nu100 = r.optional_number("nu100_mm2_s", model::Range::positive(1e6), "mm2/s");
  auto oil = catalogue.grade(grade, base, nu100, r.key_path("grade"));
  // A stated viscosity index (ASTM D2270 / ISO 2909) gives ν100 from the grade's ν40.
  if (r.has("viscosity_index")) {
    if (nu100)
      throw InputError(fmt::format("{}.viscosity_index: give nu100_mm2_s or viscosity_index, not both", path));
    // Any number here: the VIs allowed depend on ν40 (Catalogue::nu100_from_viscosity_index says which).
    const double vi = r.number("viscosity_index", model::Range::closed(-1e300, 1e300));
    oil.nu100 = Sourced{catalogue.nu100_from_viscosity_index(oil.nu40->value, vi, r.key_path("viscosity_index")),
                        "astm_d2270(case)"};
  }
  use_case_data(r, form, oil);
  Catalogue::require_data(oil, r.key_path("grade"));
  return oil;
}

/// The section's own "temperature_C" or the case's temperature (one of them, never both).
std::optional<CaseTemperature> section_temperature(const json& section, const std::string& path,
                                                   const std::optional<CaseTemperature>& case_temperature) {
  if (!section.contains("temperature_C")) return case_temperature;
  if (case_temperature)
    throw InputError(fmt::format("{}.temperature_C: the case gives its temperature in {}: give it once", path,
                                 case_temperature->key));
  model::ObjectReader r(section, path);
  const double theta = r.number("temperature_C", model::Range::closed(-273.15, 1e4), "degC");
  return CaseTemperature{path + ".temperature_C", theta + celsius_zero};
}

/// The state of a two-point oil for the micropitting form, which needs no temperature.
OilState temperature_free_state(const OilData& oil, const std::string& path) {
  if (oil.at_temperature || !oil.base)
    throw InputError(fmt::format("{}.name = '{}': ISO/TR 15144-1 needs a base oil with nu40 and nu100; this oil is "
                                 "given at one temperature only", path, oil.name));
  if (*oil.base == BaseOil::ester)
    throw InputError(fmt::format("{}.name = '{}': ISO/TR 15144-1 has pressure-viscosity formulas for mineral, PAO and "
                                 "PAG oils only", path, oil.name));
  OilState s;
  s.name = oil.name;
  s.base = oil.base;
  s.nu40 = oil.nu40;
  s.nu100 = oil.nu100;
  s.density_15C = oil.density_15C;
  return s;
}

std::string iso15144_base(BaseOil base) {
  switch (base) {
    case BaseOil::pao: return "polyalphaolefin";
    case BaseOil::pag: return "polyglycol";
    default: return "mineral";
  }
}

/// Source texts of every catalogue source named in the echo's sources.
json source_texts(const json& sources, const Catalogue& catalogue) {
  json texts = json::object();
  for (const auto& [key, text] : catalogue.sources().items())
    for (const auto& s : sources)
      if (s.get<std::string>().find(key) != std::string::npos) texts[key] = text;
  return texts;
}

/// The form's keys: the section's own where given, else the state's; `echo` gets the values,
/// their sources and the explicit keys.
json fill_form_keys(const json& section, const std::string& path, SectionForm form, const OilState& state,
                    json& echo) {
  json out = section;
  for (const char* key : library_keys) out.erase(key);
  json values = json::object(), sources = json::object(), explicit_keys = json::array();
  for (const auto& k : form_keys(form)) {
    if (section.contains(k.key)) {
      explicit_keys.push_back(k.key);
      sources[k.key] = "case";
    } else if (const auto v = k.value(state)) {
      out[k.key] = v->value;
      sources[k.key] = v->source;
    } else if (k.required) {
      const bool ester_alpha = state.base == BaseOil::ester && std::string(k.key) == "pressure_viscosity_1_per_GPa";
      throw InputError(fmt::format("{}.{}: missing: the catalogue has no sourced value for '{}'{}; give it", path, k.key,
                                   state.name,
                                   ester_alpha ? " (ISO/TR 15144-1 gives no pressure-viscosity formula for esters)" : ""));
    }
    if (out.contains(k.key)) values[k.key] = out[k.key];
  }
  echo["values"] = values;
  echo["sources"] = sources;
  echo["explicit"] = explicit_keys;
  return out;
}

/// z follows η and α: recomputed (z = α·p0/(ln η0 + 9.67)) when the case gave either but not
/// z. Values that are not positive numbers are left for the kind's reader to refuse.
void follow_roelands_z(const json& section, json& out, json& echo) {
  if (section.contains("roelands_z") ||
      !(section.contains("viscosity_Pa_s") || section.contains("pressure_viscosity_1_per_GPa")))
    return;
  const auto& eta = out.at("viscosity_Pa_s");
  const auto& alpha = out.at("pressure_viscosity_1_per_GPa");
  if (!eta.is_number() || !alpha.is_number() || !(eta.get<double>() > 0.0) || !(alpha.get<double>() >= 0.0)) return;
  out["roelands_z"] = roelands_z_from_alpha(eta.get<double>(), alpha.get<double>() * 1e-9);
  echo["values"]["roelands_z"] = out["roelands_z"];
  echo["sources"]["roelands_z"] = "roelands_z_from_alpha(case)";
}

}  // namespace

json named_or_explicit_schema(json explicit_schema) {
  json named = {{"type", "object"},
                {"description", "an oil named from the catalogue (gearbench lubricants), by name or by grade and base; "
                                "explicit keys beside them override the catalogue's figures"},
                {"properties", explicit_schema.value("properties", json::object())},
                {"anyOf", json::array({{{"required", {"name"}}}, {{"required", {"grade", "base"}}}})},
                {"additionalProperties", false}};
  const std::map<std::string, json> naming = {
      {"name", {{"type", "string"}, {"description", "an oil of the catalogue"}}},
      {"grade", {{"type", "integer"}, {"minimum", 1}, {"maximum", 100000}, {"description", "ISO VG grade"}}},
      {"base", {{"type", "string"}, {"enum", {"mineral", "pao", "ester", "pag"}}, {"description", "base oil of the grade"}}},
      {"viscosity_index", {{"type", "number"}, {"description", "nu100 of the grade by ASTM D2270 / ISO 2909"}}},
      {"temperature_C", {{"type", "number"}, {"minimum", -273.15}, {"unit", "degC"},
                         {"description", "temperature to resolve at, where the case has none of its own"}}}};
  for (const char* key : library_keys) named["properties"][key] = naming.at(key);
  const std::string description = explicit_schema.value("description", "");
  json out = {{"anyOf", json::array({std::move(explicit_schema), std::move(named)})}};
  if (!description.empty()) out["description"] = description;
  return out;
}

bool names_oil(const json& section) {
  return section.is_object() && (section.contains("name") || section.contains("grade"));
}

ResolvedSection resolve_section(const json& section, const std::string& path, SectionForm form,
                                const std::optional<CaseTemperature>& case_temperature) {
  const auto& catalogue = Catalogue::builtin();
  const OilData oil = named_oil(section, path, form, catalogue);
  OilState state;
  json echo = {{"name", oil.name}};
  if (form == SectionForm::micropitting_oil) {
    state = temperature_free_state(oil, path);
  } else {
    const auto T = section_temperature(section, path, case_temperature);
    if (!T)
      throw InputError(fmt::format("{}.temperature_C: missing: a named oil needs a temperature (the case's operating "
                                   "or inlet temperature, or {}.temperature_C)", path, path));
    state = catalogue.at(oil, T->value, T->key);
    echo["temperature_C"] = std::round((T->value - celsius_zero) * 1e9) / 1e9;  // no 89.85000000000002
    echo["temperature_from"] = T->key;
  }
  if (state.base) echo["base"] = base_oil_name(*state.base);
  json out = fill_form_keys(section, path, form, state, echo);
  // The VI the oil has (not a key any kind reads): the case's own, else D2270's from ν40 and ν100.
  if (section.contains("viscosity_index")) {
    echo["viscosity_index"] = section.at("viscosity_index");
    echo["sources"]["viscosity_index"] = "case";
  } else if (state.viscosity_index) {
    echo["viscosity_index"] = state.viscosity_index->value;
    echo["sources"]["viscosity_index"] = state.viscosity_index->source;
  }
  if (form == SectionForm::gear || form == SectionForm::ehl_line) follow_roelands_z(section, out, echo);
  if (form == SectionForm::micropitting_oil) {
    out["base"] = iso15144_base(*state.base);
    echo["values"]["base"] = out["base"];
  }
  echo["source_texts"] = source_texts(echo["sources"], catalogue);
  if (!state.warnings.empty()) echo["warnings"] = state.warnings;
  return {out, echo};
}

}  // namespace gearbench::lubricant
