// ISO/TR 15144-1 method B (solvers/micropitting/iso15144_micropitting): each formula against a
// hand value or the closed form it must equal, and consistency of the seven-point evaluation.
// No published worked example of the TR could be found in this session (Annex B's numbers are
// not available here), so there is no end-to-end number to reproduce; see docs/iso15144.md.
//
// Tolerances: where the test evaluates the same exact formula by another route (a hand value
// computed with Python's float64, a closed form rewritten), the tolerance is 1e-12 relative:
// only rounding separates the two (a few ulp through pow/log10, amplified ≤ 1e2).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "closed_form/involute_closed_form.h"
#include "micropitting/iso15144_micropitting.h"
#include "kind_registry.h"
#include "model/errors.h"
#include "model/json_reader.h"

namespace gearbench::micropitting::iso15144 {
namespace {
using reference::involute_closed_form;

constexpr double rounding = 1e-12;
constexpr double deg = std::numbers::pi / 180.0;

Oil seed_oil() { return Oil{320e-6, 20e-6, 900.0, OilBase::polyalphaolefin, 0.8}; }

/// Seed 001's gear pair, operating point and data (cases/seed001_micropitting.json).
Inputs seed001() {
  Inputs in;
  in.pair.teeth = {21, 35};
  in.pair.normal_module = 16e-3;
  in.pair.normal_pressure_angle = 20.0 * deg;
  in.pair.helix_angle = 10.0 * deg;
  in.pair.face_width = 0.32;
  in.pair.profile_shift = {0.71, 0.8031};
  in.pair.center_distance = 0.476;
  in.materials = {model::Material{200e9, 0.3, 7830.0}, model::Material{200e9, 0.3, 7830.0}};
  in.solids = {Solid{50.0, 7830.0, 485.0}, Solid{50.0, 7830.0, 485.0}};
  in.pinion_speed = 20.0 * 2.0 * std::numbers::pi / 60.0;
  in.pinion_torque = 2470e3 / in.pinion_speed;
  in.K_v = 1.05;
  in.K_Hbeta = 1.15;
  in.roughness_Ra = {0.6e-6, 0.6e-6};
  in.oil_temperature = 363.0;
  in.oil = seed_oil();
  in.method = LubricationMethod::spray;
  return in;
}

/// A spur pair with equal gears: everything is mirror-symmetric about C.
Inputs symmetric_spur() {
  Inputs in = seed001();
  in.pair.teeth = {30, 30};
  in.pair.normal_module = 4e-3;
  in.pair.helix_angle = 0.0;
  in.pair.face_width = 0.03;
  in.pair.profile_shift = {0.0, 0.0};
  in.pair.center_distance.reset();
  in.pinion_speed = 150.0;
  in.pinion_torque = 500.0;
  return in;
}

// ---- Lubricant ------------------------------------------------------------------------------

TEST(Iso15144Lubricant, WaltherLawPassesThroughItsTwoPoints) {
  // By construction A, B put the line through (313 K, ν40) and (373 K, ν100).
  EXPECT_NEAR(kinematic_viscosity(seed_oil(), 313.0), 320e-6, 320e-6 * rounding);
  EXPECT_NEAR(kinematic_viscosity(seed_oil(), 373.0), 20e-6, 20e-6 * rounding);
}

TEST(Iso15144Lubricant, WaltherLawHandValues) {
  // Hand values (Python float64, the same law): ν(363 K) = 27.7514515063169 mm²/s,
  // ν(311 K) = 367.263766158362 mm²/s.
  EXPECT_NEAR(kinematic_viscosity(seed_oil(), 363.0) * 1e6, 27.751451506316936, 27.75 * rounding);
  EXPECT_NEAR(kinematic_viscosity(seed_oil(), 311.0) * 1e6, 367.26376615836216, 367.3 * rounding);
}

TEST(Iso15144Lubricant, DensityIsLinearFromRho15) {
  // ρ(15 °C) = ρ15 and ρ(90 °C) = 900 − 0.7·75 = 847.5 kg/m³ exactly (20).
  EXPECT_NEAR(density(seed_oil(), 288.0), 900.0, 900.0 * rounding);
  EXPECT_NEAR(density(seed_oil(), 363.0), 847.5, 847.5 * rounding);
}

TEST(Iso15144Lubricant, PressureViscosityOfPao) {
  // (10): α_38 = 1.466e-8·η_38^0.0507, η_38 = ν(311 K)·ρ(311 K) = 0.324624442907376 Pa·s by
  // hand → 1.38471691712552e-8 1/Pa; (8) returns α_38 itself at 311 K.
  const Oil o = seed_oil();
  EXPECT_NEAR(pressure_viscosity_38(o), 1.3847169171255187e-08, 1.4e-8 * rounding);
  EXPECT_NEAR(pressure_viscosity(o, 311.0), pressure_viscosity_38(o), 1.4e-8 * rounding);
  // The coefficient falls with temperature (516·(1/T − 1/311) < 0 above 311 K).
  EXPECT_LT(pressure_viscosity(o, 400.0), pressure_viscosity(o, 311.0));
}

// ---- Factors ---------------------------------------------------------------------------------

TEST(Iso15144Factors, ThermalContactCoefficient) {
  // √(50·7830·485) = 13779.6044935985 (hand).
  EXPECT_NEAR(thermal_contact_coefficient({50.0, 7830.0, 485.0}), 13779.604493598501, 1.4e4 * rounding);
}

TEST(Iso15144Factors, HelicalLoadFactorCurve) {
  // (88)–(90): 1 up to ε_γ = 2, 1.3 from 3.5, continuous at both ends; 2.5 → 1 + 0.2·√1.25.
  EXPECT_DOUBLE_EQ(helical_load_factor(2.0), 1.0);
  EXPECT_NEAR(helical_load_factor(2.0 + 1e-9), 1.0, 1e-4);
  EXPECT_NEAR(helical_load_factor(3.5 - 1e-9), 1.3, 1e-6);
  EXPECT_NEAR(helical_load_factor(2.5), 1.223606797749979, rounding);
}

TEST(Iso15144Factors, SpurLoadSharingSumsToOne) {
  // Two pairs in contact, s and s + p_bt: with Q ≤ 7 they carry the whole load, 1/3 + 2/3 at
  // the ends of the double-contact zones (46)–(48). A grade-8 pair carries (Q − 2)/15 = 0.4 at A.
  const double A = 0.0, pbt = 1.0, E = 1.6, B = E - pbt, D = A + pbt;
  EXPECT_NEAR(load_sharing_spur(A, A, B, D, E, 6), 1.0 / 3.0, rounding);
  // Inside the double-contact zone (open interval: B and D themselves are evaluated as
  // single-contact points, X = 1, as the port's (47) has it).
  for (double s = A + 0.025; s < B; s += 0.05)
    EXPECT_NEAR(load_sharing_spur(s, A, B, D, E, 7) + load_sharing_spur(s + pbt, A, B, D, E, 7), 1.0, rounding)
        << "s = " << s;
  EXPECT_DOUBLE_EQ(load_sharing_spur(0.5 * (B + D), A, B, D, E, 7), 1.0);
  EXPECT_NEAR(load_sharing_spur(A, A, B, D, E, 8), 0.4, rounding);
}

TEST(Iso15144Formulas, FlashTemperatureIsJaegerBand) {
  // Jaeger's uniform band source (half-width b_H = 4ρ_n·p/E_r, Hertz), mean flux
  // q = μ·(π/4)·p·|v_g|, both bodies at the same maximum: θ = 2q·√(2b_H)/(√π·ΣB√v).
  const double mu = 0.05, p = 1.2e9, v1 = 3.0, v2 = 1.5, rho = 0.02, Er = 2.2e11, B = 13779.6;
  const double bH = 4.0 * rho * p / Er;
  const double q = mu * std::numbers::pi / 4.0 * p * std::abs(v1 - v2);
  const double jaeger = 2.0 * q * std::sqrt(2.0 * bH) / (std::sqrt(std::numbers::pi) * (B * std::sqrt(v1) + B * std::sqrt(v2)));
  EXPECT_NEAR(flash_temperature(mu, p, v1 - v2, v1, v2, rho, Er, B, B), jaeger, jaeger * rounding);
  EXPECT_DOUBLE_EQ(flash_temperature(mu, p, 0.0, v1, v1, rho, Er, B, B), 0.0);
}

TEST(Iso15144Formulas, FilmIsDowsonHigginsonWithSlidingParameter) {
  // (4) = Dowson & Higginson's h/R = 1.6·G^0.6·U^0.7·W^−0.13, times S_GF^0.22.
  const double rho = 0.02, G = 3000.0, U = 1e-11, W = 2e-4;
  const double dh = 1.6 * rho * std::pow(G, 0.6) * std::pow(U, 0.7) * std::pow(W, -0.13);
  EXPECT_NEAR(film_thickness(rho, G, U, W, 1.0), dh, dh * rounding);
  EXPECT_NEAR(film_thickness(rho, G, U, W, 0.5) / dh, std::pow(0.5, 0.22), rounding);
}

// ---- The seven points --------------------------------------------------------------------------

TEST(Iso15144Evaluate, GeometryAgreesWithTheInvoluteReference) {
  // ε_α from the path A..E here vs the closed form of involute_closed_form (tip and base
  // diameters, GSL Brent): two exact routes, so rounding only.
  const auto in = seed001();
  const auto r = evaluate(in);
  const auto ref = involute_closed_form(in.pair);
  EXPECT_NEAR(r.contact_ratio_transverse, ref.contact_ratio_transverse, rounding * 10);
  EXPECT_NEAR(r.contact_ratio_overlap, ref.contact_ratio_overlap, rounding);
  EXPECT_NEAR(r.working_pressure_angle, ref.working_pressure_angle, 1e-12);
  // The path points lie on the line of action in order, C between B and D (single contact).
  for (std::size_t i = 1; i < r.points.size(); ++i) EXPECT_LT(r.points[i - 1].position, r.points[i].position);
  EXPECT_NEAR(r.points[3].rho1 + r.points[3].rho2, ref.line_of_action_length, 1e-12);
}

TEST(Iso15144Evaluate, NoSlidingAtThePitchPoint) {
  // At C both flanks roll at the same speed: v_g = 0 → θ_fl = 0 → θ_B = θ_M → S_GF = 1.
  const auto r = evaluate(seed001());
  const auto& c = r.points[3];
  EXPECT_EQ(c.name, "C");
  EXPECT_NEAR(c.v_g, 0.0, 1e-12);
  EXPECT_NEAR(c.flash_temperature, 0.0, 1e-9);
  EXPECT_NEAR(c.sliding_parameter, 1.0, rounding);
  // Elsewhere there is sliding, and with it a flash temperature and a thinner relative film.
  for (std::size_t i : {0u, 6u}) {
    EXPECT_GT(r.points[i].flash_temperature, 1.0);
    EXPECT_LT(r.points[i].sliding_parameter, 1.0);
  }
}

TEST(Iso15144Evaluate, HelicalLoadSharingAndButtressing) {
  // ε_β ≥ 1: X_Y = X_but/ε_α with X_but = 1.3 at A and E, 1 inside (ΔΓ = 0.2 sin β_b).
  const auto in = seed001();
  const auto r = evaluate(in);
  ASSERT_GE(r.contact_ratio_overlap, 1.0);
  EXPECT_NEAR(r.points[0].load_share, 1.3 / r.contact_ratio_transverse, rounding);
  EXPECT_NEAR(r.points[6].load_share, 1.3 / r.contact_ratio_transverse, rounding);
  EXPECT_NEAR(r.points[3].load_share, 1.0 / r.contact_ratio_transverse, rounding);
  auto off = in;
  off.buttressing = false;
  EXPECT_NEAR(evaluate(off).points[0].load_share, 1.0 / r.contact_ratio_transverse, rounding);
}

TEST(Iso15144Evaluate, HertzPressureFromTheLoadPerLength) {
  // p_dyn,Y² = E_r·w/(2π·ρ_n) with w = K·F_t·X_Y/(b·cos α_t·cos β_b) (24)–(26).
  const auto in = seed001();
  const auto r = evaluate(in);
  const double K = in.K_A * in.K_v * in.K_Halpha * in.K_Hbeta;
  for (const auto& y : r.points) {
    const double w = K * r.tangential_force * y.load_share /
                     (in.pair.face_width * std::cos(r.transverse_pressure_angle) * std::cos(r.base_helix_angle));
    const double p = std::sqrt(r.reduced_modulus * w / (2.0 * std::numbers::pi * y.rho_n));
    EXPECT_NEAR(y.p_dyn, p, p * rounding) << y.name;
    EXPECT_NEAR(y.W, 2.0 * std::numbers::pi * p * p / (r.reduced_modulus * r.reduced_modulus), y.W * 1e-11);
  }
}

TEST(Iso15144Evaluate, SymmetricSpurPairIsSymmetricAboutC) {
  // z1 = z2, x1 = x2, equal solids: A↔E, AB↔DE, B↔D are mirror images (speeds swap between
  // the flanks, radii and load shares are equal), so λ must be too — to rounding.
  const auto r = evaluate(symmetric_spur());
  for (int i = 0; i < 3; ++i) {
    const auto& a = r.points[i];
    const auto& b = r.points[6 - i];
    EXPECT_NEAR(a.rho_n, b.rho_n, a.rho_n * 1e-11) << a.name;
    EXPECT_NEAR(a.load_share, b.load_share, 1e-11) << a.name;
    EXPECT_NEAR(a.flash_temperature, b.flash_temperature, 1e-9 * a.flash_temperature) << a.name;
    EXPECT_NEAR(a.lambda, b.lambda, 1e-10 * a.lambda) << a.name;
  }
  // The pitch point has the thickest film of the seven (no flash temperature there).
  for (const auto& y : r.points) EXPECT_LE(y.lambda, r.points[3].lambda);
  EXPECT_TRUE(r.lambda_min_at == "A" || r.lambda_min_at == "E");  // equal to rounding
}

TEST(Iso15144Evaluate, SafetyIsTheRatioOfSpecificFilms) {
  // S_λ = λ_GF,min/(1.4·λ_GFT): a gear assessed against itself has S_λ = 1/1.4.
  const auto in = seed001();
  const auto a = assess(in, in);
  EXPECT_NEAR(a.lambda_GFP, 1.4 * a.lambda_GFT, rounding);
  EXPECT_NEAR(a.S_lambda, 1.0 / 1.4, rounding);
  EXPECT_NEAR(assess(in, in, 0.8).S_lambda, 1.0 / (1.4 * 0.8), rounding);
}

// ---- Input errors ------------------------------------------------------------------------------

std::string message_of(const Inputs& in) {
  try {
    evaluate(in);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Iso15144Inputs, ErrorsNameKeyValueAndRange) {
  auto in = seed001();
  in.K_v = 0.5;
  EXPECT_EQ(message_of(in), "micropitting.K_v = 0.5: allowed range is [1, 10]");
  in = seed001();
  in.oil.nu100 = 400e-6;
  EXPECT_NE(message_of(in).find("micropitting.oil.nu100_mm2_s = 400"), std::string::npos);
  in = seed001();
  in.pair.face_width = 0.1;  // ε_β = 0.35
  EXPECT_NE(message_of(in).find("0 < eps_beta < 1 are not implemented"), std::string::npos);
  in = symmetric_spur();
  in.pair.teeth = {60, 60};
  in.pair.normal_pressure_angle = 14.0 * deg;  // ε_α = 2.24
  EXPECT_NE(message_of(in).find("eps_alpha"), std::string::npos);
}

// ---- The case kind ---------------------------------------------------------------------------

TEST(Iso15144Kind, SeedCaseRunsAndReportsEveryPoint) {
  const auto case_json = model::read_json_file(std::string(GEARBENCH_SOURCE_DIR) + "/cases/seed001_micropitting.json");
  const auto out = app::run_case(case_json);
  ASSERT_EQ(out.at("gear").at("points").size(), 7u);
  EXPECT_EQ(out.at("gear").at("points")[0].at("point"), "A");
  const double s = out.at("S_lambda").get<double>();
  EXPECT_NEAR(s, out.at("lambda_GF_min").get<double>() / out.at("lambda_GFP").get<double>(), rounding);
  auto bad = case_json;
  bad["micropitting"]["K_Hbeta"] = 0.9;
  EXPECT_THROW(app::run_case(bad), InputError);
}

}  // namespace
}  // namespace gearbench::micropitting::iso15144
