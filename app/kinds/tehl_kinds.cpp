// Case kinds "tehl_point" (one dimensional thermal line contact) and "tehl_path" (thermal
// EHL at A, AB, B, C, D, DE, E of a gear pair's path of contact, seed 001).
#include <algorithm>
#include <fmt/format.h>

#include "ehl/thermal_mesh_path.h"
#include "ehl_sections.h"
#include "geometry/gear_pair_geometry.h"
#include "kind_registry.h"
#include "model/case_reader.h"
#include "model/errors.h"
#include "model/json_reader.h"
#include "tehl_sections.h"

namespace gearbench::app {
namespace {

using model::Range;
using nlohmann::json;

double read_inlet_temperature(model::ObjectReader& root) {
  return root.number("inlet_temperature_K", {200.0, 600.0}, "K");
}

ehl::LineContactData read_contact(model::ObjectReader& root) {
  ehl::LineContactData d;
  auto c = root.object("contact");
  d.reduced_radius = c.number("reduced_radius_m", Range::positive(10.0), "m");
  d.load_per_length = c.number("load_per_length_N_per_m", Range::positive(1e10), "N/m");
  const auto u = c.number_pair("surface_speeds_m_per_s", Range::closed(0.0, 1e3), "m/s");
  d.u1 = u[0];
  d.u2 = u[1];
  if (d.u1 + d.u2 <= 0.0)
    throw InputError("contact.surface_speeds_m_per_s = [0, 0]: the entrainment speed must be positive");
  d.reduced_modulus = c.number("reduced_modulus_Pa", {1e6, 1e16}, "Pa");
  c.finish();
  return d;
}

ConvergenceError not_converged(const ehl::ThermalEhlResult& r, const json& out) {
  return ConvergenceError(fmt::format("thermal EHL did not converge: {}", r.summary()), out.dump(2));
}

json run_tehl_point(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  const auto contact = read_contact(root);
  const double T0 = read_inlet_temperature(root);
  const auto options = read_thermal_options(root);
  const auto lubricant = model::read_thermal_lubricant(root.object("lubricant"));
  const auto solids = model::read_thermal_solids(root.object("solids"));
  root.finish();

  const lubricant::ThermalRheology rheology(lubricant, T0);
  const auto r = ehl::ThermalLineContact(contact, rheology, solids, options).try_solve();
  json out = thermal_result_json(r, true);
  out["kind"] = "tehl_point";
  out["inlet_temperature_K"] = T0;
  out["inlet_viscosity_Pa_s"] = rheology.inlet_viscosity();
  out["roelands_z"] = rheology.roelands_z();
  if (!r.converged) throw not_converged(r, out);
  return out;
}

ehl::LoadFactors read_load_factors(model::ObjectReader& root) {
  ehl::LoadFactors k;
  if (!root.has("load_factors")) return k;
  auto f = root.object("load_factors");
  k.K_A = f.optional_number("K_A", {1.0, 10.0}).value_or(1.0);
  k.K_v = f.optional_number("K_v", {1.0, 10.0}).value_or(1.0);
  k.K_H_alpha = f.optional_number("K_H_alpha", {1.0, 10.0}).value_or(1.0);
  k.K_H_beta = f.optional_number("K_H_beta", {1.0, 10.0}).value_or(1.0);
  f.finish();
  return k;
}

json run_tehl_path(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  const auto pair = model::read_gear_pair(root.object("gear_pair"));
  if (!root.has("materials")) throw InputError("materials: missing required key (kind tehl_path)");
  const auto materials = model::read_materials(root);
  if (!root.has("operating")) throw InputError("operating: missing required key (kind tehl_path)");
  const auto operating = model::read_operating(root.object("operating"));
  const double T0 = read_inlet_temperature(root);
  const auto options = read_thermal_options(root);
  const auto lubricant = model::read_thermal_lubricant(root.object("lubricant"));
  const auto solids = model::read_thermal_solids(root.object("solids"));
  const auto factors = read_load_factors(root);
  const auto sharing = root.optional_string("load_sharing", {"iso", "equal"}).value_or("iso");
  root.finish();

  const geometry::GearPairGeometry geometry(pair);
  const lubricant::ThermalRheology rheology(lubricant, T0);
  const ehl::ThermalMeshPath path(geometry, operating, materials, rheology, solids, factors, sharing, options);
  const auto result = path.run();
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
  return {{"kind", "tehl_path"},
          {"inlet_temperature_K", T0},
          {"inlet_viscosity_Pa_s", rheology.inlet_viscosity()},
          {"roelands_z", rheology.roelands_z()},
          {"load_sharing", sharing},
          {"load_factor_product", factors.product()},
          {"minimum_film_point", result.points[static_cast<std::size_t>(result.minimum_film_point)].name},
          {"points", points},
          {"seconds", result.seconds}};
}

const RegisterKind tehl_point_kind({"tehl_point", "steady thermal line-contact EHL (generalized Reynolds, energy "
                                    "equation in film and solids)", run_tehl_point});
const RegisterKind tehl_path_kind({"tehl_path", "thermal EHL at A, AB, B, C, D, DE, E of a gear pair's path of "
                                   "contact", run_tehl_path});

}  // namespace
}  // namespace gearbench::app
