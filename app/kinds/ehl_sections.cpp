// The "grid" section of the EHL kinds and NaN-free JSON output.
#include "ehl_sections.h"

#include <cmath>
#include <fmt/format.h>

#include "model/errors.h"

namespace gearbench::app {

using model::Range;

ehl::EhlOptions read_ehl_grid(model::ObjectReader& root, ehl::EhlOptions defaults) {
  ehl::EhlOptions o = defaults;
  if (!root.has("grid")) return o;
  auto g = root.object("grid");
  if (g.has("nodes") && g.has("levels"))
    throw InputError("grid.nodes: give either nodes or levels (with coarsest_nodes), not both");
  if (auto levels = g.optional_integer("levels", 1, 14)) {
    o.levels = *levels;
    o.nodes = 0;
  }
  o.coarsest_nodes = g.optional_integer("coarsest_nodes", 9, 1025).value_or(o.coarsest_nodes);
  if (o.levels > 0 && o.coarsest_nodes == 0)
    throw InputError("grid.levels: give coarsest_nodes with levels (or give nodes)");
  if (auto nodes = g.optional_integer("nodes", 9, (1 << 20) + 1)) {
    o.nodes = *nodes;
    o.levels = 0;
  }
  if (auto x = g.optional_number("x_in", {-1e3, 0.0, false, true})) o.x_in = *x;
  if (auto x = g.optional_number("x_out", {0.0, 1e3, true, false})) o.x_out = *x;
  if ((o.x_in == 0.0) != (o.x_out == 0.0))
    throw InputError("grid.x_in, grid.x_out: give both or neither");
  if (auto cycle = g.optional_string("cycle", {"V", "W"}))
    o.cycle = *cycle == "V" ? ehl::CycleType::V : ehl::CycleType::W;
  o.max_cycles = g.optional_integer("max_cycles", 1, 100000).value_or(o.max_cycles);
  o.max_levels = g.optional_integer("max_levels", 2, 14).value_or(o.max_levels);
  o.target_error = g.optional_number("target_error", {0.0, 0.5, true, false}).value_or(o.target_error);
  if (auto stop = g.optional_string("stop", {"discretisation_error", "residual"}))
    o.stop = *stop == "residual" ? ehl::StopRule::residual : ehl::StopRule::discretisation_error;
  o.error_fraction = g.optional_number("error_fraction", {0.0, 1.0, true, false}).value_or(o.error_fraction);
  if (auto tolerance = g.optional_number("tolerance", {0.0, 1.0, true, true})) {
    o.tolerance = *tolerance;
    if (!g.has("stop")) o.stop = ehl::StopRule::residual;  // a tolerance given asks for the residual rule
  }
  g.finish();
  o.validate();
  return o;
}

/// Non-finite numbers become null: diagnostics of a failed solve may hold them.
nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
bool newtonian_friction_in_range(double mu) { return std::abs(mu) <= 1.0; }

std::string withheld_friction_note(double mu, const std::string& whose) {
  return fmt::format("{}Newtonian traction would exceed the normal load (friction coefficient {:.3g}): outside "
                     "the Newtonian model, so no friction is given; the film figures stand (a lubricant's shear "
                     "stress is limited: the efficiency kind's \"ehl\" law and the thermal kinds' "
                     "lubricant.eyring_stress_MPa limit it by an Eyring stress)",
                     whose.empty() ? "the " : whose + " ", mu);
}

nlohmann::json finite_vector(const std::vector<double>& v, double scale) {
  nlohmann::json out = nlohmann::json::array();
  for (double x : v) out.push_back(finite_or_null(x * scale));
  return out;
}

ehl::LineContactData read_line_contact(model::ObjectReader& root) {
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

/// The lubricant and solids of the contact; radius, load and speeds come from the mesh.
ehl::LineContactData read_gear_fluid(model::ObjectReader& root, const model::GearCase& c, const std::string& kind) {
  if (!c.operating) throw InputError("operating: missing required key (kind " + kind + ")");
  if (!c.materials) throw InputError("materials: missing required key (kind " + kind + ")");
  if (!c.lubricant) throw InputError("lubricant: missing required key (kind " + kind + ")");
  auto d = ehl::LineContactData::from_gear_media(*c.materials, *c.lubricant);
  if (root.has("rheology")) {
    auto r = root.object("rheology");
    if (r.optional_string("viscosity_model", {"roelands", "barus"}).value_or("roelands") == "barus")
      d.viscosity_model = ehl::ViscosityModel::barus;
    if (r.optional_string("density_model", {"dowson_higginson", "incompressible"}).value_or("dowson_higginson") ==
        "incompressible")
      d.density_model = ehl::DensityModel::incompressible;
    r.finish();
  }
  return d;
}

}  // namespace gearbench::app
