#include "case_reader.h"

#include "errors.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace gearbench::model {

namespace {
constexpr double mm = 1e-3;
constexpr double um = 1e-6;
constexpr double deg = std::numbers::pi / 180.0;
constexpr double GPa = 1e9;
}  // namespace

namespace {
/// Negative shifts bring the pair closer: inv α_wt = inv α_t + 2 tan α_n (x1 + x2)/(z1 + z2)
/// (ISO 21771:2007) must stay positive, or no working pressure angle, and no centre
/// distance, exists for the pair (x = −1 on both gears of 22/32 teeth, for one).
void check_shift_sum(const GearPair& g, const std::string& key) {
  const double tan_alpha_n = std::tan(g.normal_pressure_angle);
  const double alpha_t = std::atan(tan_alpha_n / std::cos(g.helix_angle));
  const double z_sum = g.teeth[0] + g.teeth[1];
  const double lowest = -(std::tan(alpha_t) - alpha_t) * z_sum / (2.0 * tan_alpha_n);
  const double sum = g.profile_shift[0] + g.profile_shift[1];
  if (sum <= lowest)
    throw InputError(fmt::format("{} = [{}, {}]: the sum {} leaves no working pressure angle for {} + {} teeth; "
                                 "the sum must exceed {:.4g}",
                                 key, format_value(g.profile_shift[0]), format_value(g.profile_shift[1]),
                                 format_value(sum), g.teeth[0], g.teeth[1], lowest));
}
}  // namespace

// A full-round rack's two tip rounds meet on the tooth's centre line, tangent to the flanks:
// π/4 − h_fP tan α = ρ(1/cos α − tan α), the largest tip radius that fits.
double default_root_radius_coef(double dedendum_coef, double normal_pressure_angle) {
  const double full_round = std::max(0.0, std::numbers::pi / 4.0 - dedendum_coef * std::tan(normal_pressure_angle)) /
                            (1.0 / std::cos(normal_pressure_angle) - std::tan(normal_pressure_angle));
  return std::min(0.38, full_round);
}

namespace {

/// ISO 53:1998 basic rack profiles (h_aP 1, α 20°): dedendum h_fP and tip radius ρ_fP in m_n.
struct RackProfile {
  double dedendum, tip_radius;
};
RackProfile iso53_profile(const std::string& name) {
  if (name == "B") return {1.25, 0.30};
  if (name == "C") return {1.25, 0.25};
  if (name == "D") return {1.40, 0.39};
  return {1.25, 0.38};  // A
}

/// "basic_rack": "ISO53_A" … "ISO53_D", or "dedendum_coef" and "root_radius_coef" given
/// singly. Without either, profile A's 1.25 and 0.38, but for racks too narrow for ρ 0.38
/// (pressure angles above about 22°, which ISO 53 does not cover) the full-round tip radius.
void read_basic_rack(ObjectReader& s, GearPair& g) {
  const auto rack = s.optional_string("basic_rack", {"ISO53_A", "ISO53_B", "ISO53_C", "ISO53_D"});
  const auto dedendum = s.optional_number("dedendum_coef", Range::positive(2.5));
  const auto tip_radius = s.optional_number("root_radius_coef", {0.0, 1.0, false, true});
  if (rack && (dedendum || tip_radius))
    throw InputError(s.key_path("basic_rack") + " = \"" + *rack +
                     "\": sets dedendum_coef and root_radius_coef; give either the profile or the two values");
  if (rack) {
    if (std::abs(g.normal_pressure_angle - 20.0 * deg) > 1e-12)
      throw InputError(s.key_path("basic_rack") + " = \"" + *rack + "\": ISO 53 profiles have a 20 deg pressure angle");
    const auto p = iso53_profile(rack->substr(6));
    g.dedendum_coef = p.dedendum;
    g.root_radius_coef = p.tip_radius;
    return;
  }
  g.dedendum_coef = dedendum.value_or(1.25);
  g.root_radius_coef = tip_radius.value_or(default_root_radius_coef(g.dedendum_coef, g.normal_pressure_angle));
}
}  // namespace

GearPair read_gear_pair(ObjectReader s) {
  GearPair g;
  // Tooth counts: the undercut-free minimum depends on the shift and is checked by the
  // geometry; 5 is a hard floor for any involute gear.
  g.teeth = s.integer_pair("teeth", 5, 10000);
  g.normal_module = s.number("normal_module_mm", Range::closed(0.01, 1000.0), "mm") * mm;
  g.normal_pressure_angle =
      s.number("normal_pressure_angle_deg", Range::closed(10.0, 35.0), "deg") * deg;
  g.helix_angle = s.optional_number("helix_angle_deg", Range::closed(0.0, 45.0), "deg")
                      .value_or(0.0) * deg;
  g.face_width = s.number("face_width_mm", Range::closed(0.01, 1e5), "mm") * mm;
  g.profile_shift =
      s.optional_number_pair("profile_shift", Range::closed(-1.0, 2.0)).value_or(
          std::array<double, 2>{0.0, 0.0});
  g.addendum_coef = s.optional_number("addendum_coef", Range::positive(2.0)).value_or(1.0);
  read_basic_rack(s, g);
  check_shift_sum(g, s.key_path("profile_shift"));
  if (auto a = s.optional_number("center_distance_mm", Range::positive(1e6), "mm"))
    g.center_distance = *a * mm;
  if (auto da = s.optional_number_pair("tip_diameter_mm", Range::positive(1e7), "mm"))
    g.tip_diameter = std::array<double, 2>{(*da)[0] * mm, (*da)[1] * mm};
  if (s.has("herringbone")) {
    auto h = s.object("herringbone");
    g.herringbone = Herringbone{h.number("groove_width_mm", Range::closed(0.0, 1e5), "mm") * mm};
    h.finish();
    if (g.helix_angle == 0.0)
      throw InputError(s.key_path("helix_angle_deg") +
                       " = 0: a herringbone pair needs a helix angle in (0, 45] deg");
  }
  s.finish();
  return g;
}

namespace {
Material read_material(ObjectReader s) {
  Material m;
  m.youngs_modulus = s.number("youngs_modulus_GPa", Range::closed(1e-3, 1e4), "GPa") * GPa;
  m.poisson_ratio = s.number("poisson_ratio", Range::closed(0.0, 0.5));
  m.density = s.optional_number("density_kg_m3", Range::closed(100.0, 1e5), "kg/m3").value_or(7850.0);
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
  op.pinion_speed =
      s.number("pinion_speed_rpm", Range::positive(1e6), "rpm") * 2.0 * std::numbers::pi / 60.0;
  // At least 1e-6 N·m: the static tooth deflection T/(r_b·k) is then ~1e-14 m or more, well
  // above what double precision resolves in a rotation times a base radius (~1e-18 m); a
  // torque of 5e-324 N·m once returned a dynamic factor of 0 (issue 20).
  op.pinion_torque = s.number("pinion_torque_Nm", Range::closed(1e-6, 1e9), "N*m");
  op.oil_temperature =
      s.optional_number("oil_temperature_C", Range::closed(-60.0, 400.0), "degC").value_or(40.0) +
      273.15;
  const auto ra = s.optional_number_pair("roughness_Ra_um", Range::closed(0.0, 100.0), "um")
                      .value_or(std::array<double, 2>{0.0, 0.0});
  op.roughness_Ra = {ra[0] * um, ra[1] * um};
  s.finish();
  return op;
}

Lubricant read_lubricant(ObjectReader s) {
  Lubricant l;
  l.viscosity = s.number("viscosity_Pa_s", Range::positive(1e4), "Pa*s");
  l.pressure_viscosity =
      s.number("pressure_viscosity_1_per_GPa", Range::closed(0.0, 100.0), "1/GPa") / GPa;
  l.roelands_z = s.optional_number("roelands_z", Range::positive(2.0));
  l.density = s.optional_number("density_kg_m3", Range::positive(1e4), "kg/m3");
  if (auto v = s.optional_number("nu40_mm2_s", Range::positive(1e7), "mm2/s")) l.nu40 = *v * 1e-6;
  if (auto v = s.optional_number("nu100_mm2_s", Range::positive(1e7), "mm2/s")) l.nu100 = *v * 1e-6;
  if (l.nu40 && l.nu100 && *l.nu100 >= *l.nu40)
    throw InputError(s.key_path("nu100_mm2_s") + " = " + format_value(*l.nu100 * 1e6) +
                     ": must be below nu40_mm2_s = " + format_value(*l.nu40 * 1e6) +
                     " (viscosity falls with temperature)");
  l.thermal_conductivity =
      s.optional_number("thermal_conductivity_W_per_mK", Range::positive(1e3), "W/(m*K)");
  l.specific_heat = s.optional_number("specific_heat_J_per_kgK", Range::positive(1e6), "J/(kg*K)");
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
