// The keys of the sections every gear-pair case shares ("gear_pair", "materials", "operating",
// "lubricant"), one table each (issue 21): the readers in case_reader.cpp, the options record
// and `gearbench schema` come from them.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <tuple>

#include "case_reader.h"
#include "errors.h"

namespace gearbench::model {
namespace {

constexpr double mm = 1e-3;
constexpr double um = 1e-6;
constexpr double deg = std::numbers::pi / 180.0;

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
const std::vector<std::string> racks = {"ISO53_A", "ISO53_B", "ISO53_C", "ISO53_D"};

/// "basic_rack": "ISO53_A" … "ISO53_D", or "dedendum_coef" and "root_radius_coef" given
/// singly (read by the table). Without either, profile A's 1.25 and 0.38, but for racks too
/// narrow for ρ 0.38 (pressure angles above about 22°, which ISO 53 does not cover) the
/// full-round tip radius.
void apply_basic_rack(ObjectReader& s, GearPair& g) {
  const auto rack = s.optional_string("basic_rack", racks);
  if (rack && (s.has("dedendum_coef") || s.has("root_radius_coef")))
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
  if (!s.has("root_radius_coef")) g.root_radius_coef = default_root_radius_coef(g.dedendum_coef, g.normal_pressure_angle);
}

OptionTable<Herringbone> make_herringbone_table() {
  OptionTable<Herringbone> t;
  t.number("groove_width_mm", &Herringbone::groove_width, Range::closed(0.0, 1e5),
           {.description = "axial gap between the two helical halves", .unit = "mm", .scale = mm, .required = true});
  return t;
}

OptionTable<GearPair> make_gear_pair_table() {
  OptionTable<GearPair> t;
  // Tooth counts: the undercut-free minimum depends on the shift and is checked by the
  // geometry; 5 is a hard floor for any involute gear.
  t.integer("teeth", &GearPair::teeth, 5, 10000, {.description = "tooth counts [pinion, wheel]", .required = true});
  t.number("normal_module_mm", &GearPair::normal_module, Range::closed(0.01, 1000.0),
           {.description = "normal module m_n", .unit = "mm", .scale = mm, .required = true});
  t.number("normal_pressure_angle_deg", &GearPair::normal_pressure_angle, Range::closed(10.0, 35.0),
           {.description = "normal pressure angle alpha_n", .unit = "deg", .scale = deg, .required = true});
  t.number("helix_angle_deg", &GearPair::helix_angle, Range::closed(0.0, 45.0),
           {.description = "helix angle beta at the reference cylinder (herringbone: of each half)", .unit = "deg",
            .scale = deg});
  t.number("face_width_mm", &GearPair::face_width, Range::closed(0.01, 1e5),
           {.description = "face width b (herringbone: of each half)", .unit = "mm", .scale = mm, .required = true});
  t.number("profile_shift", &GearPair::profile_shift, Range::closed(-1.0, 2.0),
           {.description = "profile shift coefficients x [pinion, wheel]"});
  t.number("addendum_coef", &GearPair::addendum_coef, Range::positive(2.0), {.description = "addendum h_a* in m_n"});
  t.external("basic_rack", {{"type", "string"}, {"enum", racks}},
             {.description = "an ISO 53:1998 basic rack profile (20 deg only); sets dedendum_coef and root_radius_coef"});
  t.number("dedendum_coef", &GearPair::dedendum_coef, Range::positive(2.5),
           {.description = "dedendum h_f* in m_n (the addendum of the cutting rack)"});
  t.number("root_radius_coef", &GearPair::root_radius_coef, Range{0.0, 1.0, false, true},
           {.description = "tip radius rho_fP* of the rack in m_n",
            .default_text = "0.38 (ISO 53 A), or the full-round tip radius for racks too narrow for it"});
  t.number("center_distance_mm", &GearPair::center_distance, Range::positive(1e6),
           {.description = "centre distance a", .unit = "mm", .scale = mm, .default_text = "from the shifts"});
  t.number("tip_diameter_mm", &GearPair::tip_diameter, Range::positive(1e7),
           {.description = "tip diameters d_a [pinion, wheel]", .unit = "mm", .scale = mm,
            .default_text = "d + 2 m_n (h_a* + x)"});
  static const auto herringbone = make_herringbone_table();
  t.section("herringbone", &GearPair::herringbone, herringbone,
            {.description = "a herringbone pair: two helical halves of opposite hand (needs a helix angle)"});
  t.after_read([](ObjectReader& s, GearPair& g) {
    apply_basic_rack(s, g);
    check_shift_sum(g, s.key_path("profile_shift"));
    if (g.herringbone && g.helix_angle == 0.0)
      throw InputError(s.key_path("helix_angle_deg") + " = 0: a herringbone pair needs a helix angle in (0, 45] deg");
  });
  return t;
}

OptionTable<Material> make_material_table() {
  OptionTable<Material> t;
  t.number("youngs_modulus_GPa", &Material::youngs_modulus, Range::closed(1e-3, 1e4),
           {.description = "Young's modulus E", .unit = "GPa", .scale = 1e9, .required = true});
  t.number("poisson_ratio", &Material::poisson_ratio, Range::closed(0.0, 0.5),
           {.description = "Poisson's ratio nu", .required = true});
  t.number("density_kg_m3", &Material::density, Range::closed(100.0, 1e5),
           {.description = "density (mass of the gear bodies)", .unit = "kg/m3"});
  // The ranges of the thermal EHL kinds' "solids" (read_thermal_solids).
  t.number("thermal_conductivity_W_per_mK", &Material::thermal_conductivity, Range::closed(0.1, 1e4),
           {.description = "thermal conductivity of the gear body (friction.model \"ehl_thermal\")", .unit = "W/(m*K)"});
  t.number("specific_heat_J_per_kgK", &Material::specific_heat, Range::closed(10.0, 1e5),
           {.description = "specific heat of the gear body (friction.model \"ehl_thermal\")", .unit = "J/(kg*K)"});
  return t;
}

OptionTable<OperatingPoint> make_operating_table() {
  OptionTable<OperatingPoint> t;
  t.number("pinion_speed_rpm", &OperatingPoint::pinion_speed, Range::positive(1e6),
           {.description = "pinion speed", .unit = "rpm", .scale = 2.0 * std::numbers::pi / 60.0, .required = true});
  // At least 1e-6 N·m: the static tooth deflection T/(r_b·k) is then ~1e-14 m or more, well
  // above what double precision resolves in a rotation times a base radius (~1e-18 m); a
  // torque of 5e-324 N·m once returned a dynamic factor of 0 (issue 20).
  t.number("pinion_torque_Nm", &OperatingPoint::pinion_torque, Range::closed(1e-6, 1e9),
           {.description = "pinion torque", .unit = "N*m", .required = true});
  t.number("oil_temperature_C", &OperatingPoint::oil_temperature, Range::closed(-60.0, 400.0),
           {.description = "oil temperature", .unit = "degC", .offset = 273.15});
  t.number("roughness_Ra_um", &OperatingPoint::roughness_Ra, Range::closed(0.0, 100.0),
           {.description = "arithmetic mean roughness Ra per flank [pinion, wheel]", .unit = "um", .scale = um});
  return t;
}

OptionTable<Lubricant> make_lubricant_table() {
  OptionTable<Lubricant> t;
  t.number("viscosity_Pa_s", &Lubricant::viscosity, Range::positive(1e4),
           {.description = "dynamic viscosity eta0 at the oil temperature", .unit = "Pa*s", .required = true});
  t.number("pressure_viscosity_1_per_GPa", &Lubricant::pressure_viscosity, Range::closed(0.0, 100.0),
           {.description = "pressure-viscosity coefficient alpha", .unit = "1/GPa", .scale = 1e-9, .required = true});
  t.number("roelands_z", &Lubricant::roelands_z, Range::positive(2.0), {.description = "Roelands pressure index z"});
  t.number("density_kg_m3", &Lubricant::density, Range::positive(1e4),
           {.description = "density rho0 at the oil temperature", .unit = "kg/m3"});
  t.number("nu40_mm2_s", &Lubricant::nu40, Range::positive(1e7),
           {.description = "kinematic viscosity at 40 degC", .unit = "mm2/s", .scale = 1e-6});
  t.number("nu100_mm2_s", &Lubricant::nu100, Range::positive(1e7),
           {.description = "kinematic viscosity at 100 degC, below nu40", .unit = "mm2/s", .scale = 1e-6});
  t.number("thermal_conductivity_W_per_mK", &Lubricant::thermal_conductivity, Range::positive(1e3),
           {.description = "thermal conductivity", .unit = "W/(m*K)"});
  t.number("specific_heat_J_per_kgK", &Lubricant::specific_heat, Range::positive(1e6),
           {.description = "specific heat", .unit = "J/(kg*K)"});
  // As the thermal EHL kinds' lubricant (read_thermal_lubricant).
  t.number("temperature_viscosity_1_per_K", &Lubricant::temperature_viscosity, Range::closed(0.0, 1.0),
           {.description = "viscosity-temperature coefficient beta of Roelands' temperature term (friction.model "
                           "\"ehl_thermal\"; without it nu40_mm2_s and nu100_mm2_s give the Ubbelohde-Walther law)",
            .unit = "1/K"});
  t.number("eyring_stress_MPa", &Lubricant::eyring_stress, Range::positive(1e3),
           {.description = "Eyring stress tau0 of the Ree-Eyring film (friction.model \"ehl_thermal\")", .unit = "MPa",
            .scale = 1e6});
  t.after_read([](ObjectReader& s, const Lubricant& l) {
    if (l.nu40 && l.nu100 && *l.nu100 >= *l.nu40)
      throw InputError(s.key_path("nu100_mm2_s") + " = " + format_value(*l.nu100 * 1e6) +
                       ": must be below nu40_mm2_s = " + format_value(*l.nu40 * 1e6) +
                       " (viscosity falls with temperature)");
  });
  return t;
}

/// Give either the Roelands form (η0 and β at the inlet) or the Walther form (ν40 and ν100).
void check_viscosity_form(ObjectReader& l, const ThermalLubricant&) {
  const bool walther = l.has("nu40_mm2_s") || l.has("nu100_mm2_s");
  if (walther && (l.has("viscosity_Pa_s") || l.has("temperature_viscosity_1_per_K")))
    throw InputError(l.key_path("viscosity_Pa_s") + ": give either viscosity_Pa_s with "
                     "temperature_viscosity_1_per_K (Roelands) or nu40_mm2_s with nu100_mm2_s "
                     "(Ubbelohde–Walther), not both");
  const auto both = [&l](const char* a, const char* b) {
    for (const auto* key : {a, b})
      if (!l.has(key)) throw InputError(fmt::format("{}: missing required key", l.key_path(key)));
  };
  if (walther) both("nu40_mm2_s", "nu100_mm2_s");
  else both("viscosity_Pa_s", "temperature_viscosity_1_per_K");
}

OptionTable<ThermalLubricant> make_thermal_lubricant_table() {
  OptionTable<ThermalLubricant> t;
  t.number("pressure_viscosity_1_per_GPa", &ThermalLubricant::pressure_viscosity, Range::positive(100.0),
           {.description = "pressure-viscosity coefficient alpha at the inlet temperature", .unit = "1/GPa",
            .required = true, .divisor = 1e9});
  t.number("density_kg_m3", &ThermalLubricant::density_15C, Range::closed(500.0, 2000.0),
           {.description = "density rho15 at 15 degC (ISO/TR 15144-1 density law)", .unit = "kg/m3", .required = true});
  t.number("thermal_conductivity_W_per_mK", &ThermalLubricant::thermal_conductivity, Range::closed(0.01, 10.0),
           {.description = "thermal conductivity", .unit = "W/(m*K)", .required = true});
  t.number("specific_heat_J_per_kgK", &ThermalLubricant::specific_heat, Range::closed(100.0, 1e5),
           {.description = "specific heat", .unit = "J/(kg*K)", .required = true});
  t.number("viscosity_Pa_s", &ThermalLubricant::viscosity, Range::closed(1e-4, 1e4),
           {.description = "Roelands form: dynamic viscosity eta0 at the inlet temperature (with "
                           "temperature_viscosity_1_per_K; not with nu40_mm2_s, nu100_mm2_s)",
            .unit = "Pa*s", .unset = 0.0});
  t.number("temperature_viscosity_1_per_K", &ThermalLubricant::temperature_viscosity, Range::closed(0.0, 1.0),
           {.description = "Roelands form: temperature-viscosity coefficient beta", .unit = "1/K"});
  t.number("nu40_mm2_s", &ThermalLubricant::nu40, Range::closed(2.0, 1e6),
           {.description = "Walther form: kinematic viscosity at 40 degC (with nu100_mm2_s)", .unit = "mm2/s",
            .scale = 1e-6});
  t.number("nu100_mm2_s", &ThermalLubricant::nu100, Range::closed(2.0, 1e6),
           {.description = "Walther form: kinematic viscosity at 100 degC", .unit = "mm2/s", .scale = 1e-6});
  t.number("eyring_stress_MPa", &ThermalLubricant::eyring_stress, Range::positive(1e3),
           {.description = "Eyring stress tau0 (the Eyring film, and the Eyring friction beside the Newtonian)",
            .unit = "MPa", .scale = 1e6});
  t.after_read(check_viscosity_form);
  return t;
}

OptionTable<ThermalSolids> make_thermal_solids_table() {
  OptionTable<ThermalSolids> t;
  t.number("thermal_conductivity_W_per_mK", &ThermalSolids::conductivity, Range::closed(0.1, 1e4),
           {.description = "thermal conductivity [1, 2]", .unit = "W/(m*K)", .required = true});
  t.number("specific_heat_J_per_kgK", &ThermalSolids::specific_heat, Range::closed(10.0, 1e5),
           {.description = "specific heat [1, 2]", .unit = "J/(kg*K)", .required = true});
  t.number("density_kg_m3", &ThermalSolids::density, Range::closed(100.0, 1e5),
           {.description = "density [1, 2]", .unit = "kg/m3", .required = true});
  return t;
}

OptionTable<LoadFactors> make_load_factors_table() {
  OptionTable<LoadFactors> t;
  for (const auto& [key, member, what] :
       {std::tuple{"K_A", &LoadFactors::K_A, "application factor"}, std::tuple{"K_v", &LoadFactors::K_v, "dynamic factor"},
        std::tuple{"K_H_alpha", &LoadFactors::K_H_alpha, "transverse load factor"},
        std::tuple{"K_H_beta", &LoadFactors::K_H_beta, "face load factor"}})
    t.number(key, member, Range::closed(1.0, 10.0), {.description = what});
  return t;
}

OptionTable<ThermalPathCase> make_thermal_path_table() {
  OptionTable<ThermalPathCase> t;
  t.section("load_factors", &ThermalPathCase::load_factors, load_factors_table(),
            {.description = "load factors of the normal load (ISO 6336)"});
  add_thermal_media(t);
  add_load_sharing(t, &ThermalPathCase::load_sharing);
  return t;
}

}  // namespace

const OptionTable<GearPair>& gear_pair_table() { return built_once<make_gear_pair_table>(); }
const OptionTable<Material>& material_table() { return built_once<make_material_table>(); }
const OptionTable<OperatingPoint>& operating_table() { return built_once<make_operating_table>(); }
const OptionTable<Lubricant>& lubricant_table() { return built_once<make_lubricant_table>(); }
const OptionTable<ThermalLubricant>& thermal_lubricant_table() { return built_once<make_thermal_lubricant_table>(); }
const OptionTable<ThermalSolids>& thermal_solids_table() { return built_once<make_thermal_solids_table>(); }
const OptionTable<LoadFactors>& load_factors_table() { return built_once<make_load_factors_table>(); }
const OptionTable<ThermalPathCase>& ThermalPathCase::table() { return built_once<make_thermal_path_table>(); }

}  // namespace gearbench::model
