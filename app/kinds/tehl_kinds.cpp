// Case kinds "tehl_point" (one dimensional thermal line contact) and "tehl_path" (thermal
// EHL at A, AB, B, C, D, DE, E of a gear pair's path of contact, seed 001).
#include <algorithm>
#include <iostream>
#include <optional>
#include <fmt/format.h>

#include "case_schema.h"
#include "ehl/ehl_tables.h"
#include "ehl/thermal_mesh_path.h"
#include "ehl_sections.h"
#include "geometry/gear_pair_geometry.h"
#include "kind_registry.h"
#include "lubricant/lubricant_section.h"
#include "model/case_reader.h"
#include "model/errors.h"
#include "model/json_reader.h"
#include "micropitting/tehl_micropitting.h"
#include "tehl_sections.h"

namespace gearbench::app {
namespace {

using nlohmann::json;
using micropitting::compare_with_iso;
using micropitting::micropitting_json;
using micropitting::MicropittingCase;
using micropitting::read_micropitting;

/// The keys of a tehl_point case: the contact, the inlet temperature, lubricant and solids, and
/// the solver's options.
struct TehlPointCase {
  ehl::ContactInput contact;
  double inlet_temperature = 0.0;
  model::ThermalLubricant lubricant;
  model::ThermalSolids solids;
  ehl::ThermalEhlOptions options;

  static const model::OptionTable<TehlPointCase>& table() {
    static const auto table = [] {
      model::OptionTable<TehlPointCase> t;
      t.section("contact", &TehlPointCase::contact, ehl::ContactInput::table(),
                {.description = "the dimensional contact", .required = true});
      model::add_thermal_media(t);
      t.include(&TehlPointCase::options, ehl::ThermalEhlOptions::table());
      return t;
    }();
    return table;
  }
};

/// The thermal kinds' lubricant may name an oil from the catalogue.
json with_named_lubricant(json schema) {
  auto& lubricant = schema["properties"]["lubricant"];
  lubricant = lubricant::named_or_explicit_schema(lubricant);
  return schema;
}

/// Options record, convergence and summary of one thermal contact.
void add_run_record(json& out, const ehl::ThermalEhlOptions& options, const ehl::ThermalEhlResult& r) {
  add_solve_status(out, r);
  add_options_record(out, ehl::ThermalEhlOptions::table(), options, options);
}

json run_tehl_point(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  TehlPointCase k;
  TehlPointCase::table().read(root, k);
  root.finish();
  TehlPointCase::table().validate(k);
  ehl::LineContactData contact;
  k.contact.apply(contact);
  const double T0 = k.inlet_temperature;
  const auto& options = k.options;
  const auto& lubricant = k.lubricant;
  const auto& solids = k.solids;

  const lubricant::ThermalRheology rheology(lubricant, T0);
  const auto r = ehl::ThermalLineContact(contact, rheology, solids, options).try_solve();
  json out = thermal_result_json(r, true);
  out["kind"] = "tehl_point";
  out["inlet_temperature_K"] = T0;
  out["inlet_viscosity_Pa_s"] = rheology.inlet_viscosity();
  out["roelands_z"] = rheology.roelands_z();
  add_run_record(out, options, r);
  throw_unless_converged(r, out);
  return out;
}

json run_tehl_path(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  const auto c = model::read_thermal_path_case(root);
  ehl::ThermalEhlOptions options;
  ehl::ThermalEhlOptions::table().read(root, options);
  std::optional<MicropittingCase> micropitting;
  if (root.has("micropitting"))
    micropitting = read_micropitting(root, model::GearCase{c.gear_pair, c.materials, c.operating, std::nullopt},
                                     "tehl_path");
  root.finish();
  ehl::ThermalEhlOptions::table().validate(options);

  const geometry::GearPairGeometry geometry(c.gear_pair);
  const lubricant::ThermalRheology rheology(c.lubricant, c.inlet_temperature);
  const ehl::ThermalMeshPath path(geometry, c.operating, c.materials, rheology, c.solids, c.load_factors,
                                  c.load_sharing, options);
  const auto result = path.try_run([](const std::string& line) { std::cerr << "gearbench: " << line << std::endl; });
  json points = json::array();
  for (const auto& pt : result.points) {
    json p = thermal_result_json(pt.result, pt.name == "A" || pt.name == "C");
    p["point"] = pt.name;
    p["position_m"] = pt.position;
    p["reduced_radius_m"] = pt.contact.reduced_radius;
    p["load_per_length_N_per_m"] = pt.contact.load_per_length;
    p["load_share"] = pt.load_share;
    p["surface_speeds_m_per_s"] = {pt.contact.u1, pt.contact.u2};
    p["slide_to_roll"] = pt.slide_to_roll;
    p["hertz_pressure_Pa"] = pt.hertz_pressure;
    points.push_back(std::move(p));
  }
  json out = {{"kind", "tehl_path"},
          {"inlet_temperature_K", c.inlet_temperature},
          {"inlet_viscosity_Pa_s", rheology.inlet_viscosity()},
          {"roelands_z", rheology.roelands_z()},
          {"load_sharing", c.load_sharing},
          {"load_factor_product", c.load_factors.product()},
          {"minimum_film_point", result.points[static_cast<std::size_t>(result.minimum_film_point)].name},
          {"points", points},
          {"seconds", result.seconds}};
  add_solve_status(out, result);
  add_options_record(out, ehl::ThermalEhlOptions::table(), options, options);
  throw_unless_converged(result, out);
  if (micropitting) out["micropitting"] = micropitting_json(compare_with_iso(result, c, *micropitting, options));
  return out;
}

std::vector<json> tehl_point_schema() { return {with_named_lubricant(TehlPointCase::table().schema())}; }

std::vector<json> tehl_path_schema() {
  // The gear case's sections first: the thermal lubricant replaces its "lubricant".
  return {gear_case_schema({"materials", "operating"}), with_named_lubricant(model::ThermalPathCase::table().schema()),
          ehl::ThermalEhlOptions::table().schema(),
          section_part("micropitting",
                       MicropittingCase::table().schema("ISO/TR 15144-1 method B beside the thermal EHL"), false)};
}

const RegisterKind tehl_point_kind({"tehl_point", "steady thermal line-contact EHL (generalized Reynolds, energy "
                                    "equation in film and solids)", run_tehl_point, tehl_point_schema});
const RegisterKind tehl_path_kind({"tehl_path", "thermal EHL at A, AB, B, C, D, DE, E of a gear pair's path of "
                                   "contact", run_tehl_path, tehl_path_schema});

}  // namespace
}  // namespace gearbench::app
