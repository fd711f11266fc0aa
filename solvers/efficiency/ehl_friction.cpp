#include "ehl_friction.h"

#include <cmath>
#include <fmt/format.h>

#include "ehl/traction.h"
#include "lubricant/rheology.h"
#include "lubricant/thermal_rheology.h"
#include "lubricant/viscosity_temperature.h"
#include "model/errors.h"

namespace gearbench::efficiency {

namespace {

void require(bool present, const std::string& key) {
  if (!present) throw InputError(fmt::format("{}: missing, required by friction.model = \"ehl_thermal\"", key));
}

}  // namespace

ThermalFrictionMedia thermal_friction_media(const std::array<model::Material, 2>& materials,
                                            const model::Lubricant& lubricant, double oil_temperature) {
  ThermalFrictionMedia m;
  m.inlet_temperature = oil_temperature;
  auto& l = m.lubricant;
  require(lubricant.eyring_stress.has_value(), "lubricant.eyring_stress_MPa");
  require(lubricant.density.has_value(), "lubricant.density_kg_m3");
  require(lubricant.thermal_conductivity.has_value(), "lubricant.thermal_conductivity_W_per_mK");
  require(lubricant.specific_heat.has_value(), "lubricant.specific_heat_J_per_kgK");
  l.eyring_stress = lubricant.eyring_stress;
  l.pressure_viscosity = lubricant.pressure_viscosity;
  l.thermal_conductivity = *lubricant.thermal_conductivity;
  l.specific_heat = *lubricant.specific_heat;
  // The thermal solver's density law is ISO/TR 15144-1's, ρ(T) = ρ15 − 0.7·(T − 15 °C): ρ15
  // from the density the case gives at its oil temperature.
  l.density_15C = *lubricant.density +
                  lubricant::iso15144_density_slope * (oil_temperature - (lubricant::celsius_zero + 15.0));
  if (lubricant.temperature_viscosity) {  // Roelands with β, η0 at the oil temperature
    l.viscosity = lubricant.viscosity;
    l.temperature_viscosity = *lubricant.temperature_viscosity;
  } else if (lubricant.nu40 && lubricant.nu100) {  // Ubbelohde–Walther
    l.nu40 = lubricant.nu40;
    l.nu100 = lubricant.nu100;
  } else {
    throw InputError("lubricant.temperature_viscosity_1_per_K: missing, required by friction.model = "
                     "\"ehl_thermal\" (or nu40_mm2_s with nu100_mm2_s for the Ubbelohde-Walther law)");
  }
  for (std::size_t g = 0; g < 2; ++g) {
    const auto key = [&](const char* name) { return fmt::format("materials.{} (gear {})", name, g + 1); };
    require(materials[g].thermal_conductivity.has_value(), key("thermal_conductivity_W_per_mK"));
    require(materials[g].specific_heat.has_value(), key("specific_heat_J_per_kgK"));
    m.solids.conductivity[g] = *materials[g].thermal_conductivity;
    m.solids.specific_heat[g] = *materials[g].specific_heat;
    m.solids.density[g] = materials[g].density;
  }
  // The thermal solver derives Roelands' z from η0 and α; a different z given for the
  // isothermal laws would be silently dropped here.
  if (lubricant.roelands_z) {
    const lubricant::ThermalRheology rheology(l, oil_temperature);
    const double z = rheology.roelands_z();
    if (std::abs(*lubricant.roelands_z / z - 1.0) > 0.01)
      throw InputError(fmt::format("lubricant.roelands_z = {}: friction.model = \"ehl_thermal\" takes z from eta0 and "
                                   "alpha (z = {:.4f} here); allowed is that value within 1 % or no roelands_z",
                                   model::format_value(*lubricant.roelands_z), z));
  }
  return m;
}

ehl::EhlOptions EhlFriction::default_grid() {
  ehl::EhlOptions o;
  o.nodes = 161;
  return o;
}

ehl::ThermalEhlOptions EhlFriction::default_thermal_options() {
  // The solver's defaults on 81 nodes. Measured on seed 004's path
  // (cases/efficiency_seed004_ehl_thermal.json, fourteenth session): mean μ 0.05795 on 81
  // nodes, 0.05753 on 161 and 0.05737 on 641 (the mean efficiency 99.099, 99.105, 99.107 %),
  // at 2.8 s, 11 s and 90 s (641 nodes: 40.5 s after the fifteenth session's V-cycles and single
  // sweeps, μ 0.057372). Until the coupling stopped at its discretisation error and the
  // temperature sweeps held each column's flow, this law needed Anderson's β 0.3, h_min
  // settled to 1e-3 only and 300 iterations: β 0.15 left a contact of the dynamics test
  // (M 11.6, L 19) with a non-finite temperature on 81 nodes. It does not now.
  ehl::ThermalEhlOptions o;
  o.grid.nodes = 81;
  return o;
}

double EhlFriction::isothermal_coefficient(const ehl::LineContactData& contact, double eyring_stress,
                                           const ehl::EhlOptions& grid) {
  const ehl::LineContactProblem problem(contact);
  const auto r = ehl::LineContactSolver(problem, grid).solve();
  return ehl::eyring_traction(problem, r, eyring_stress).coefficient;
}

double EhlFriction::thermal_coefficient(const ehl::LineContactData& contact, const lubricant::ThermalRheology& rheology,
                                        const model::ThermalSolids& solids, const ehl::ThermalEhlOptions& options) {
  return ehl::ThermalLineContact(contact, rheology, solids, options).solve().friction_coefficient;
}

EhlFriction::EhlFriction(const ehl::LineContactData& fluid, double eyring_stress, ehl::EhlOptions grid)
    : law_(lubricant::FrictionModel::ehl), fluid_(fluid) {
  if (!eyring_stress_range().contains(eyring_stress * 1e-6))
    throw InputError(model::range_message("friction.eyring_stress_MPa", eyring_stress * 1e-6, eyring_stress_range(), "MPa"));
  grid.validate();
  solve_ = [eyring_stress, grid = std::move(grid)](const ehl::LineContactData& d) {
    return isothermal_coefficient(d, eyring_stress, grid);
  };
}

EhlFriction::EhlFriction(const ehl::LineContactData& fluid, ThermalFrictionMedia media, ehl::ThermalEhlOptions options)
    : law_(lubricant::FrictionModel::ehl_thermal), fluid_(fluid) {
  if (!media.lubricant.eyring_stress)
    throw InputError("lubricant.eyring_stress_MPa: missing, required by friction.model = \"ehl_thermal\"");
  options.film.rheology = lubricant::ShearRheology::eyring;
  options.validate();
  auto rheology = std::make_shared<const lubricant::ThermalRheology>(media.lubricant, media.inlet_temperature);
  solve_ = [rheology, solids = media.solids, options = std::move(options)](const ehl::LineContactData& d) {
    return thermal_coefficient(d, *rheology, solids, options);
  };
}

int EhlFriction::solves() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return static_cast<int>(cache_.size());
}

double EhlFriction::coefficient(const lubricant::ContactState& c) const {
  const auto key = std::make_tuple(c.load_per_length, c.reduced_radius, c.u1, c.u2);
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
  }
  ehl::LineContactData d = fluid_;
  d.load_per_length = c.load_per_length;
  d.reduced_radius = c.reduced_radius;
  d.u1 = c.u1;
  d.u2 = c.u2;
  const auto failed = [&](const std::string& why) {
    return ConvergenceError(fmt::format("friction.model = \"{}\": the {}EHL solve at w {:.4g} N/m, R {:.4g} m, "
                                        "u [{:.4g}, {:.4g}] m/s (Moes M {:.3g}, L {:.3g}) failed: {}",
                                        lubricant::friction_model_name(law_),
                                        law_ == lubricant::FrictionModel::ehl_thermal ? "thermal " : "",
                                        d.load_per_length, d.reduced_radius, d.u1, d.u2, d.moes_M(), d.moes_L(), why));
  };
  double mu = 0.0;
  try {
    mu = std::abs(solve_(d));
  } catch (const ConvergenceError& e) {
    throw failed(e.what());
  }
  if (!std::isfinite(mu)) throw failed(fmt::format("no finite friction coefficient ({})", mu));
  const std::lock_guard<std::mutex> lock(mutex_);
  cache_.emplace(key, mu);
  return mu;
}

}  // namespace gearbench::efficiency
