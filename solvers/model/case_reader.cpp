#include "case_reader.h"

#include "errors.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace gearbench::model {

namespace {
constexpr double GPa = 1e9;
}  // namespace

// A full-round rack's two tip rounds meet on the tooth's centre line, tangent to the flanks:
// π/4 − h_fP tan α = ρ(1/cos α − tan α), the largest tip radius that fits.
double default_root_radius_coef(double dedendum_coef, double normal_pressure_angle) {
  const double full_round = std::max(0.0, std::numbers::pi / 4.0 - dedendum_coef * std::tan(normal_pressure_angle)) /
                            (1.0 / std::cos(normal_pressure_angle) - std::tan(normal_pressure_angle));
  return std::min(0.38, full_round);
}

GearPair read_gear_pair(ObjectReader s) {
  GearPair g;
  gear_pair_table().read(s, g);
  s.finish();
  return g;
}

namespace {
Material read_material(ObjectReader s) {
  Material m;
  material_table().read(s, m);
  s.finish();
  return m;
}
}  // namespace

std::array<Material, 2> read_materials(ObjectReader& root) {
  const auto pair = root.object_or_pair("materials");
  return {read_material(ObjectReader(pair.objects[0], pair.paths[0])),
          read_material(ObjectReader(pair.objects[1], pair.paths[1]))};
}

OperatingPoint read_operating(ObjectReader s) {
  OperatingPoint op;
  operating_table().read(s, op);
  s.finish();
  return op;
}

Lubricant read_lubricant(ObjectReader s) {
  Lubricant l;
  lubricant_table().read(s, l);
  s.finish();
  return l;
}

ThermalLubricant read_thermal_lubricant(ObjectReader l) {
  ThermalLubricant d;
  d.pressure_viscosity = l.number("pressure_viscosity_1_per_GPa", Range::positive(100.0), "1/GPa") / GPa;
  d.density_15C = l.number("density_kg_m3", {500.0, 2000.0}, "kg/m3");
  d.thermal_conductivity = l.number("thermal_conductivity_W_per_mK", {0.01, 10.0}, "W/(m*K)");
  d.specific_heat = l.number("specific_heat_J_per_kgK", {100.0, 1e5}, "J/(kg*K)");
  const bool walther = l.has("nu40_mm2_s") || l.has("nu100_mm2_s");
  if (walther && (l.has("viscosity_Pa_s") || l.has("temperature_viscosity_1_per_K")))
    throw InputError(l.key_path("viscosity_Pa_s") + ": give either viscosity_Pa_s with "
                     "temperature_viscosity_1_per_K (Roelands) or nu40_mm2_s with nu100_mm2_s "
                     "(Ubbelohde–Walther), not both");
  if (walther) {
    d.nu40 = l.number("nu40_mm2_s", {2.0, 1e6}, "mm2/s") * 1e-6;
    d.nu100 = l.number("nu100_mm2_s", {2.0, 1e6}, "mm2/s") * 1e-6;
  } else {
    d.viscosity = l.number("viscosity_Pa_s", {1e-4, 1e4}, "Pa*s");
    d.temperature_viscosity = l.number("temperature_viscosity_1_per_K", {0.0, 1.0}, "1/K");
  }
  if (auto tau = l.optional_number("eyring_stress_MPa", Range::positive(1e3), "MPa")) d.eyring_stress = *tau * 1e6;
  l.finish();
  return d;
}

ThermalSolids read_thermal_solids(ObjectReader s) {
  ThermalSolids d;
  d.conductivity = s.number_pair("thermal_conductivity_W_per_mK", {0.1, 1e4}, "W/(m*K)");
  d.specific_heat = s.number_pair("specific_heat_J_per_kgK", {10.0, 1e5}, "J/(kg*K)");
  d.density = s.number_pair("density_kg_m3", {100.0, 1e5}, "kg/m3");
  s.finish();
  return d;
}

LoadFactors read_load_factors(ObjectReader f) {
  LoadFactors k;
  k.K_A = f.optional_number("K_A", {1.0, 10.0}).value_or(1.0);
  k.K_v = f.optional_number("K_v", {1.0, 10.0}).value_or(1.0);
  k.K_H_alpha = f.optional_number("K_H_alpha", {1.0, 10.0}).value_or(1.0);
  k.K_H_beta = f.optional_number("K_H_beta", {1.0, 10.0}).value_or(1.0);
  f.finish();
  return k;
}

double read_inlet_temperature(ObjectReader& root) { return root.number("inlet_temperature_K", {200.0, 600.0}, "K"); }

ThermalPathCase read_thermal_path_case(ObjectReader& root) {
  ThermalPathCase c;
  c.gear_pair = read_gear_pair(root.object("gear_pair"));
  if (!root.has("materials")) throw InputError("materials: missing required key");
  c.materials = read_materials(root);
  if (!root.has("operating")) throw InputError("operating: missing required key");
  c.operating = read_operating(root.object("operating"));
  if (root.has("load_factors")) c.load_factors = read_load_factors(root.object("load_factors"));
  c.lubricant = read_thermal_lubricant(root.object("lubricant"));
  c.solids = read_thermal_solids(root.object("solids"));
  c.inlet_temperature = read_inlet_temperature(root);
  c.load_sharing = root.optional_string("load_sharing", {"iso", "equal"}).value_or("iso");
  return c;
}

GearCase read_gear_case(ObjectReader& root) {
  GearCase c;
  c.gear_pair = read_gear_pair(root.object("gear_pair"));
  if (root.has("materials")) c.materials = read_materials(root);
  if (root.has("operating")) c.operating = read_operating(root.object("operating"));
  if (root.has("lubricant")) c.lubricant = read_lubricant(root.object("lubricant"));
  return c;
}

}  // namespace gearbench::model
