// ISO/TR 15144-1 method B (see the header for the sources and what is unconfirmed).
// Formula numbers "(n)" are those of ISO/TR 15144-1:2014 as cited by the public port named in
// the header; the TR's mixed units are converted at each formula and said so.
#include "micropitting/iso15144_micropitting.h"

#include "micropitting/iso15144_case.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "model/errors.h"

namespace gearbench::micropitting::iso15144 {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double to_mm = 1e3;
constexpr double to_um = 1e6;
/// The TR writes absolute temperatures as θ + 273 (e.g. 311 = 38 °C in (8)); T here is that
/// absolute temperature, so θ = T − 273 in the TR's formulas. (Not 273.15: unconfirmed which
/// the TR means; the difference is 0.15 K.)
constexpr double tr_kelvin_offset = 273.0;

[[noreturn]] void fail(const std::string& key, double value, const std::string& allowed) {
  throw InputError(fmt::format("{} = {:.6g}: {}", key, value, allowed));
}

void require(bool ok, const std::string& key, double value, const std::string& allowed) {
  if (!ok) fail(key, value, allowed);
}

double involute(double x) { return std::tan(x) - x; }

/// Inverse involute by Newton's method on f(x) = tan x − x − t, f' = tan² x, from the
/// small-angle start x = (3t)^(1/3). Converges in a handful of steps for gear angles.
double inverse_involute(double t) {
  double x = std::cbrt(3.0 * t);
  for (int i = 0; i < 60; ++i) {
    const double dx = (involute(x) - t) / (std::tan(x) * std::tan(x));
    x -= dx;
    if (std::abs(dx) < 1e-15) break;
  }
  return x;
}

/// Involute geometry of the pair and its path of contact, derived here from the model data
/// (ISO 21771 relations; no code shared with solvers/geometry). Positions are distances from
/// T1, the tangent point on the pinion base circle, along the line of action.
struct PathGeometry {
  double alpha_t = 0.0, beta_b = 0.0, alpha_wt = 0.0, a = 0.0;
  std::array<double, 2> d{}, rb{}, ra{};
  double T1T2 = 0.0, pbt = 0.0;
  double A = 0.0, B = 0.0, C = 0.0, D = 0.0, E = 0.0;
  double eps_alpha = 0.0, eps_beta = 0.0, eps1 = 0.0, eps2 = 0.0;
};

PathGeometry path_geometry(const model::GearPair& p) {
  PathGeometry g;
  const double mn = p.normal_module;
  g.alpha_t = std::atan(std::tan(p.normal_pressure_angle) / std::cos(p.helix_angle));
  g.beta_b = std::atan(std::tan(p.helix_angle) * std::cos(g.alpha_t));
  for (int i = 0; i < 2; ++i) {
    g.d[i] = p.teeth[i] * mn / std::cos(p.helix_angle);
    g.rb[i] = 0.5 * g.d[i] * std::cos(g.alpha_t);
    g.ra[i] = p.tip_diameter ? 0.5 * (*p.tip_diameter)[i]
                             : 0.5 * g.d[i] + mn * (p.addendum_coef + p.profile_shift[i]);
  }
  if (p.center_distance) {
    g.a = *p.center_distance;
    require(g.a > g.rb[0] + g.rb[1], "gear_pair.center_distance_mm", g.a * to_mm,
            "must exceed the sum of the base radii");
    g.alpha_wt = std::acos((g.rb[0] + g.rb[1]) / g.a);
  } else {
    const double inv_wt = involute(g.alpha_t) + 2.0 * std::tan(p.normal_pressure_angle) *
                                                    (p.profile_shift[0] + p.profile_shift[1]) /
                                                    (p.teeth[0] + p.teeth[1]);
    g.alpha_wt = inverse_involute(inv_wt);
    g.a = (g.rb[0] + g.rb[1]) / std::cos(g.alpha_wt);
  }
  g.T1T2 = g.a * std::sin(g.alpha_wt);
  g.pbt = 2.0 * pi * g.rb[0] / p.teeth[0];
  g.E = std::sqrt(g.ra[0] * g.ra[0] - g.rb[0] * g.rb[0]);
  g.A = g.T1T2 - std::sqrt(g.ra[1] * g.ra[1] - g.rb[1] * g.rb[1]);
  g.C = g.rb[0] * std::tan(g.alpha_wt);
  g.B = g.E - g.pbt;
  g.D = g.A + g.pbt;
  g.eps_alpha = (g.E - g.A) / g.pbt;
  g.eps1 = (g.E - g.C) / g.pbt;  // = z1/(2π)·(tan α_a1 − tan α_wt)
  g.eps2 = (g.C - g.A) / g.pbt;
  g.eps_beta = p.face_width * std::sin(p.helix_angle) / (pi * mn);
  require(g.A > 0.0, "gear_pair.tip_diameter_mm[1]", 2.0 * g.ra[1] * to_mm,
          "the wheel tip reaches below the pinion base circle (interference)");
  require(g.E < g.T1T2, "gear_pair.tip_diameter_mm[0]", 2.0 * g.ra[0] * to_mm,
          "the pinion tip reaches below the wheel base circle (interference)");
  require(g.eps_alpha >= 1.0 && g.eps_alpha < 2.0, "transverse contact ratio eps_alpha",
          g.eps_alpha, "method B needs 1 <= eps_alpha < 2 (ε_α > 2 only by method A, clause 8.2)");
  return g;
}

/// X_but of helical gears, ISO/TR 13989-1 (49)–(56) as reproduced by the port (which says
/// ISO/TR 15144-1:2014 clause 11.3 has a buttressing factor; its exact form there is
/// unconfirmed): 1 + 0.3·ε_β (1.3 for ε_β ≥ 1) at A and E, falling linearly to 1 over
/// ΔΓ = 0.2·sin β_b in Γ = s/T1C − 1.
double buttressing_factor(double s, const PathGeometry& g) {
  const double width = 0.2 * std::sin(g.beta_b);
  if (width <= 0.0) return 1.0;
  const double peak = g.eps_beta >= 1.0 ? 1.3 : 1.0 + 0.3 * g.eps_beta;
  const double gamma = s / g.C - 1.0;
  const double from_A = gamma - (g.A / g.C - 1.0);
  const double to_E = (g.E / g.C - 1.0) - gamma;
  if (from_A < width) return peak - from_A / width * (peak - 1.0);
  if (to_E < width) return peak - to_E / width * (peak - 1.0);
  return 1.0;
}

/// H_V of the bulk temperature, (91) for ε_α < 2 (Ohlendorf's loss factor).
double loss_factor(const PathGeometry& g, const model::GearPair& p) {
  return (g.eps1 * g.eps1 + g.eps2 * g.eps2 + 1.0 - g.eps_alpha) * pi *
         (1.0 / p.teeth[0] + 1.0 / p.teeth[1]) / std::cos(g.beta_b);
}

/// Normal relative radius ρ_n = ρ1ρ2/((ρ1 + ρ2)·cos β_b) (43)–(45).
double normal_relative_radius(double rho1, double rho2, double beta_b) {
  return rho1 * rho2 / ((rho1 + rho2) * std::cos(beta_b));
}

const std::array<const char*, 7> point_names = {"A", "AB", "B", "C", "D", "DE", "E"};

}  // namespace

// ---- Lubricant (clause 7 of the TR) ------------------------------------------------------

double kinematic_viscosity(const Oil& oil, double temperature) {
  // (17)–(19); seed 001 §1.3 quotes the same law from TR:2010. ν in mm²/s inside.
  auto walther = [](double nu) { return std::log10(std::log10(nu * to_um + 0.7)); };
  const double A = (walther(oil.nu40) - walther(oil.nu100)) /
                   (std::log10(40.0 + tr_kelvin_offset) - std::log10(100.0 + tr_kelvin_offset));
  const double B = walther(oil.nu40) - A * std::log10(40.0 + tr_kelvin_offset);
  const double w = A * std::log10(temperature) + B;
  return (std::pow(10.0, std::pow(10.0, w)) - 0.7) / to_um;
}

double density(const Oil& oil, double temperature) {
  // (20) in seed 001's form ρ15·[1 − 0.7(T − 15)/ρ15], T in °C, i.e. θ + 273 − 288. The port
  // writes (θ + 273) − 289 for the 2014 edition: 0.7 kg/m³ apart, unconfirmed which is right.
  const double theta = temperature - tr_kelvin_offset;
  return oil.rho15 * (1.0 - 0.7 * (theta - 15.0) / oil.rho15);
}

double dynamic_viscosity(const Oil& oil, double temperature) {
  return kinematic_viscosity(oil, temperature) * density(oil, temperature);  // (16)
}

double pressure_viscosity_38(const Oil& oil) {
  // (9)–(11), η_38 in N·s/m² (= Pa·s; the magnitudes, 1.4–2.3e-8 m²/N for gear oils, fit
  // that unit and not mPa·s). 38 °C = 311 in the TR's absolute temperature.
  const double eta38 = dynamic_viscosity(oil, 38.0 + tr_kelvin_offset);
  switch (oil.base) {
    case OilBase::polyalphaolefin: return 1.466e-8 * std::pow(eta38, 0.0507);
    case OilBase::polyglycol: return 1.392e-8 * std::pow(eta38, 0.1572);
    case OilBase::mineral: break;
  }
  return 2.657e-8 * std::pow(eta38, 0.1348);
}

double pressure_viscosity(const Oil& oil, double temperature) {
  // (8) at θ_M, (28) at θ_B,Y.
  return pressure_viscosity_38(oil) *
         (1.0 + 516.0 * (1.0 / temperature - 1.0 / (38.0 + tr_kelvin_offset)));
}

// ---- Factors ------------------------------------------------------------------------------

double thermal_contact_coefficient(const Solid& s) {
  return std::sqrt(s.conductivity * s.density * s.specific_heat);  // (82)–(83)
}

double helical_load_factor(double eps_gamma) {
  // (88)–(90), the curve of ISO/TR 13989-2 (port and ISO/TR 13989-2 agree).
  if (eps_gamma <= 2.0) return 1.0;
  if (eps_gamma >= 3.5) return 1.3;
  return 1.0 + 0.2 * std::sqrt((eps_gamma - 2.0) * (5.0 - eps_gamma));
}

double lubrication_method_factor(LubricationMethod m) {
  switch (m) {  // X_S of (84)
    case LubricationMethod::spray: return 1.2;
    case LubricationMethod::submerged: return 0.2;
    case LubricationMethod::dip: break;
  }
  return 1.0;
}

double load_sharing_spur(double s, double A, double B, double D, double E, int accuracy_grade) {
  // (46)–(48): X_A = X_E = (Q − 2)/15 with Q ≥ 7, rising by 1/3 over each double-contact
  // zone; 1 in single contact. For Q ≤ 7 the two pairs in contact carry exactly 1 together.
  const double q = std::max(accuracy_grade, 7);
  const double end = (q - 2.0) / 15.0;
  if (s < B) return end + (s - A) / (B - A) / 3.0;
  if (s <= D) return 1.0;
  return end + (E - s) / (E - D) / 3.0;
}

double flash_temperature(double mu, double p_dyn, double v_g, double v_r1, double v_r2,
                         double rho_n, double reduced_modulus, double B_M1, double B_M2) {
  // (80) in SI. √(8ρ_n·p/E_r) is the root of the Hertzian band width 2b_H (b_H = 4ρ_n·p/E_r),
  // so this is Jaeger's uniform band source (width 2b_H, high Péclet number, maximum at the
  // trailing edge) θ = 2q·√(2b_H)/(√π·ΣB_M√v_r), with the mean Hertzian flux q = μ·(π/4)·p·v_g:
  // θ = (√π/2)·μ·p·v_g·√(2b_H)/ΣB_M√v_r, the formula as printed. A consistency check, not a
  // confirmation of the TR's constant.
  return 0.5 * std::sqrt(pi) * mu * p_dyn * std::abs(v_g) *
         std::sqrt(8.0 * rho_n * p_dyn / reduced_modulus) /
         (B_M1 * std::sqrt(v_r1) + B_M2 * std::sqrt(v_r2));
}

double film_thickness(double rho_n, double G, double U, double W, double S_GF) {
  // (4): h_Y[µm] = 1600·ρ_n[mm]·G^0.6·U^0.7·W^−0.13·S_GF^0.22, i.e. h = 1.6·ρ_n·(...) in
  // metres: the Dowson–Higginson (1966) fit with the TR's sliding parameter.
  return 1.6 * rho_n * std::pow(G, 0.6) * std::pow(U, 0.7) * std::pow(W, -0.13) *
         std::pow(S_GF, 0.22);
}

// ---- Inputs ---------------------------------------------------------------------------------

void Inputs::validate() const {
  const std::string m = "micropitting.";
  // The keys of the "micropitting" section: ranges from the tables the case reader reads.
  table().validate(*this, m);
  model::ThermalSolids keys;
  for (std::size_t i = 0; i < 2; ++i) {
    keys.conductivity[i] = solids[i].conductivity;
    keys.specific_heat[i] = solids[i].specific_heat;
    keys.density[i] = solids[i].density;
  }
  solids_table().validate(keys, m + "solids.");
  // What the method needs of the other sections, where their own readers allow more.
  require(pair.normal_module > 0.0, "gear_pair.normal_module_mm", pair.normal_module * to_mm, "must be > 0");
  require(pair.face_width > 0.0, "gear_pair.face_width_mm", pair.face_width * to_mm, "must be > 0");
  for (int i = 0; i < 2; ++i) {
    const auto idx = fmt::format("[{}]", i);
    require(materials[i].youngs_modulus > 0.0, "materials" + idx + ".youngs_modulus_GPa",
            materials[i].youngs_modulus * 1e-9, "must be > 0");
    require(materials[i].poisson_ratio >= 0.0 && materials[i].poisson_ratio < 0.5,
            "materials" + idx + ".poisson_ratio", materials[i].poisson_ratio, "allowed [0, 0.5)");
    require(roughness_Ra[i] > 0.0 && roughness_Ra[i] <= 10e-6, operating_section + ".roughness_Ra_um" + idx,
            roughness_Ra[i] * to_um, "allowed (0, 10] (λ_GF = h/Ra needs a rough surface)");
  }
  require(pinion_speed > 0.0, operating_section + ".pinion_speed_rpm", pinion_speed * 30.0 / pi, "must be > 0");
  require(pinion_torque > 0.0, operating_section + ".pinion_torque_Nm", pinion_torque, "must be > 0");
  require(oil_temperature >= 253.15 && oil_temperature <= 473.15, operating_section + ".oil_temperature_C",
          oil_temperature - 273.15, "allowed [-20, 200] (the Walther law's range of use)");
  require(oil.nu100 < oil.nu40, m + "oil.nu100_mm2_s", oil.nu100 * to_um,
          fmt::format("allowed (0, nu40_mm2_s = {}) (viscosity falls with temperature)", oil.nu40 * to_um));
}

// ---- Method B ---------------------------------------------------------------------------------

Result evaluate(const Inputs& in) {
  in.validate();
  const auto& p = in.pair;
  const auto g = path_geometry(p);
  const bool helical = p.helix_angle > 0.0;
  if (helical && g.eps_beta < 1.0)
    fail("gear_pair.face_width_mm", p.face_width * to_mm,
         fmt::format("gives eps_beta = {:.3f}; helical gears with 0 < eps_beta < 1 are not "
                     "implemented (their load sharing clause is unconfirmed here)", g.eps_beta));

  Result r;
  r.transverse_pressure_angle = g.alpha_t;
  r.working_pressure_angle = g.alpha_wt;
  r.base_helix_angle = g.beta_b;
  r.center_distance = g.a;
  r.contact_ratio_transverse = g.eps_alpha;
  r.contact_ratio_overlap = g.eps_beta;
  r.addendum_contact_ratio = {g.eps1, g.eps2};
  r.reduced_modulus = model::reduced_modulus(in.materials);  // E_r (6)
  r.Ra = 0.5 * (in.roughness_Ra[0] + in.roughness_Ra[1]);   // (3)
  r.tangential_force = 2.0 * in.pinion_torque / g.d[0];
  r.power = in.pinion_torque * in.pinion_speed;
  const double omega2 = in.pinion_speed * p.teeth[0] / p.teeth[1];
  const double K = in.K_A * in.K_v * in.K_Halpha * in.K_Hbeta;

  // Mean friction coefficient (86)–(87), in the TR's units: F_bt/b in N/mm, v in m/s, ρ in
  // mm, η_oil in mPa·s, Ra in µm.
  const double rho_nC = normal_relative_radius(g.C, g.T1T2 - g.C, g.beta_b);
  const double v_sumC = in.pinion_speed * g.C + omega2 * (g.T1T2 - g.C);
  r.helical_load_factor = helical_load_factor(g.eps_alpha + g.eps_beta);
  r.roughness_factor = 2.2 * std::pow(r.Ra * to_um / (rho_nC * to_mm), 0.25);
  r.eta_oil = dynamic_viscosity(in.oil, in.oil_temperature);
  const double w_bt = K * r.tangential_force / std::cos(g.alpha_t) * r.helical_load_factor /
                      (p.face_width * to_mm);
  r.friction_coefficient = 0.045 * std::pow(w_bt / (v_sumC * rho_nC * to_mm), 0.2) *
                           std::pow(r.eta_oil * 1e3, -0.05) * r.roughness_factor *
                           in.oil.lubricant_factor;

  // Bulk temperature (84)–(85): P in kW, a and b in mm.
  r.loss_factor = loss_factor(g, p);
  r.bulk_temperature =
      in.oil_temperature +
      7400.0 * std::pow(r.power * 1e-3 * r.friction_coefficient * r.loss_factor /
                            (g.a * to_mm * p.face_width * to_mm), 0.72) *
          lubrication_method_factor(in.method) / (1.2 * in.tip_relief_factor);

  // Lubricant at the bulk temperature and the materials parameter (5), (8), (16).
  r.nu_M = kinematic_viscosity(in.oil, r.bulk_temperature);
  r.rho_M = density(in.oil, r.bulk_temperature);
  r.eta_M = r.nu_M * r.rho_M;
  r.alpha_38 = pressure_viscosity_38(in.oil);
  r.alpha_M = pressure_viscosity(in.oil, r.bulk_temperature);
  r.materials_parameter = r.alpha_M * r.reduced_modulus;
  r.thermal_contact_coefficient = {thermal_contact_coefficient(in.solids[0]),
                                   thermal_contact_coefficient(in.solids[1])};
  const double Z_E = std::sqrt(r.reduced_modulus / (2.0 * pi));  // (26)

  const std::array<double, 7> at = {g.A, 0.5 * (g.A + g.B), g.B, g.C, g.D, 0.5 * (g.D + g.E), g.E};
  r.lambda_min = 1e300;
  for (std::size_t i = 0; i < at.size(); ++i) {
    auto& y = r.points[i];
    y.name = point_names[i];
    y.position = at[i];
    y.rho1 = at[i];
    y.rho2 = g.T1T2 - at[i];
    y.rho_n = normal_relative_radius(y.rho1, y.rho2, g.beta_b);
    y.buttressing = helical && in.buttressing ? buttressing_factor(at[i], g) : 1.0;
    y.load_share = helical ? y.buttressing / g.eps_alpha
                           : load_sharing_spur(at[i], g.A, g.B, g.D, g.E, in.accuracy_grade);
    // (24)–(25); the cos β_b under the root is the port's (unconfirmed; a load per contact-line
    // length derivation has none: 0.7 % in p for seed 001's β_b = 9.4°).
    y.p_dyn = Z_E * std::sqrt(r.tangential_force * y.load_share /
                              (p.face_width * y.rho_n * std::cos(g.alpha_t) * std::cos(g.beta_b))) *
              std::sqrt(K);
    y.v_r1 = in.pinion_speed * y.rho1;  // (14)–(15): ω·(distance from the base tangent point)
    y.v_r2 = omega2 * y.rho2;
    y.v_sum = y.v_r1 + y.v_r2;          // (13)
    y.v_g = std::abs(y.v_r1 - y.v_r2);  // (81)
    y.flash_temperature = flash_temperature(r.friction_coefficient, y.p_dyn, y.v_g, y.v_r1, y.v_r2,
                                            y.rho_n, r.reduced_modulus,
                                            r.thermal_contact_coefficient[0],
                                            r.thermal_contact_coefficient[1]);
    y.contact_temperature = r.bulk_temperature + y.flash_temperature;  // (79)
    y.nu_B = kinematic_viscosity(in.oil, y.contact_temperature);
    y.rho_B = density(in.oil, y.contact_temperature);
    y.eta_B = y.nu_B * y.rho_B;                                        // (29)
    y.alpha_B = pressure_viscosity(in.oil, y.contact_temperature);     // (28)
    y.sliding_parameter = y.alpha_B * y.eta_B / (r.alpha_M * r.eta_M); // (27)
    y.U = r.eta_M * y.v_sum / (2.0 * r.reduced_modulus * y.rho_n);     // (12), mean speed
    y.W = 2.0 * pi * y.p_dyn * y.p_dyn / (r.reduced_modulus * r.reduced_modulus);  // (22)
    y.h = film_thickness(y.rho_n, r.materials_parameter, y.U, y.W, y.sliding_parameter);
    y.lambda = y.h / r.Ra;                                             // (2)
    if (y.lambda < r.lambda_min) {
      r.lambda_min = y.lambda;
      r.lambda_min_at = y.name;
    }
  }
  return r;
}

double permissible_lambda(double lambda_GFT, double material_factor) {
  return 1.4 * material_factor * lambda_GFT;  // (5); seed 001: S_λ = (h/Ra)/(1.4·h_ref/Ra_ref)
}

Assessment assess(const Inputs& gear, const Inputs& test, double material_factor) {
  if (!(material_factor > 0.0 && material_factor <= 5.0))
    fail("micropitting.material_factor_WW", material_factor, "allowed (0, 5]");
  Assessment a;
  a.gear = evaluate(gear);
  a.reference_test = evaluate(test);
  a.lambda_GFT = a.reference_test.lambda_min;
  a.lambda_GFP = permissible_lambda(a.lambda_GFT, material_factor);
  a.S_lambda = a.gear.lambda_min / a.lambda_GFP;  // (1)
  return a;
}

}  // namespace gearbench::micropitting::iso15144
