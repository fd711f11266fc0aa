// Unit tests of the friction laws (solvers/lubricant/friction_laws) and of the loss
// integration and dynamic efficiency (solvers/efficiency): unit systems, limits, identities
// and the sign of the loss for every law and operating point.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "closed_form/ehl_closed_form.h"
#include "efficiency/dynamic_efficiency.h"
#include "efficiency/film_thickness.h"
#include "efficiency/mesh_loss.h"
#include "lubricant/friction_laws.h"
#include "support/test_support.h"

namespace gearbench {
namespace {

using namespace lubricant;
using testing_support::input_error_of;

XuKahramanInputs xu_point() { return {0.8, 0.3, 10.0, 44.0, 0.01, 0.4}; }

// --- Xu & Kahraman ------------------------------------------------------------------------------

// With ν0 = 1 cP the products |SR|·P_h·log10 ν0 vanish and f = b1 + b5 + b9·e^S: the
// exponential term carries b5 (original form), not b4 as seed 000 prints it.
TEST(FrictionLaws, XuKahramanUsesB5InTheExponentialTerm) {
  XuKahramanInputs in{1.0, 0.5, 1.0, 1.0, 1.0, 0.0};
  const double expected = std::exp(-8.916465 + 2.812084 + 0.620305) * std::pow(0.5, 1.036077);
  EXPECT_NEAR(xu_kahraman(in), expected, 1e-14 * expected);
}

// Gear-like conditions (P_h 0.8 GPa, SR 0.3, 10 m/s, 44 cP, R 10 mm, S 0.4 µm) give a
// coefficient of the order the paper reports for 75W90 (a few hundredths); sliding
// direction does not matter and pure rolling has no sliding friction.
TEST(FrictionLaws, XuKahramanMagnitudeAndSymmetry) {
  auto in = xu_point();
  const double mu = xu_kahraman(in);
  EXPECT_GT(mu, 0.005);
  EXPECT_LT(mu, 0.1);
  in.slide_to_roll = -0.3;
  EXPECT_DOUBLE_EQ(xu_kahraman(in), mu);
  in.slide_to_roll = 0.0;
  EXPECT_EQ(xu_kahraman(in), 0.0);
}

TEST(FrictionLaws, XuKahramanRejectsOtherUnitSystems) {
  auto pa = xu_point();
  pa.hertz_pressure_GPa = 8e8;
  EXPECT_NE(input_error_of([&] { (void)xu_kahraman(pa); }).find("xu_kahraman.hertz_pressure"), std::string::npos);
  auto mpa = xu_point();
  mpa.hertz_pressure_GPa = 800;
  EXPECT_NE(input_error_of([&] { (void)xu_kahraman(mpa); }).find("GPa"), std::string::npos);
  auto pas = xu_point();
  pas.viscosity_cP = 0.044;
  EXPECT_NE(input_error_of([&] { (void)xu_kahraman(pas); }).find("not Pa·s"), std::string::npos);
  auto mm = xu_point();
  mm.radius_m = 10.0;
  EXPECT_NE(input_error_of([&] { (void)xu_kahraman(mm); }).find("not millimetres"), std::string::npos);
  auto metres = xu_point();
  metres.roughness_um = 4e-7;
  EXPECT_NE(input_error_of([&] { (void)xu_kahraman(metres); }).find("in metres?"), std::string::npos);
}

TEST(FrictionLaws, XuKahramanFromSiConverts) {
  ContactState c;
  c.hertz_pressure = 8e8;
  c.u1 = 11.5;
  c.u2 = 8.5;
  c.viscosity = 0.044;
  c.reduced_radius = 0.01;
  c.roughness_Ra = 0.4e-6;
  const auto in = XuKahramanInputs::from_si(c);
  EXPECT_DOUBLE_EQ(in.hertz_pressure_GPa, 0.8);
  EXPECT_DOUBLE_EQ(in.entrainment_m_s, 10.0);
  EXPECT_DOUBLE_EQ(in.slide_to_roll, 0.3);
  EXPECT_DOUBLE_EQ(in.viscosity_cP, 44.0);
  EXPECT_NEAR(in.roughness_um, 0.4 * std::sqrt(M_PI / 2.0), 1e-15);  // rms from Ra (Gaussian)
}

// --- Benedict & Kelley --------------------------------------------------------------------------

// The SI constant 29.66 is the US form's 3.17e8 (W lb/in, V in/s) converted: the two agree
// to the four digits printed (29.66 vs 29.6616...), so within 2e-5 in μ.
TEST(FrictionLaws, BenedictKelleySiMatchesUsForm) {
  const BenedictKelleyInputs in{250750.0, 80.0, 0.5, 2.0, 0.4};
  const double w_lb_in = in.load_per_length_N_m / 175.1268;
  const double vs = in.sliding_m_s / 0.0254, vr = in.rolling_sum_m_s / 0.0254;
  const double c_r = 50.0 / (50.0 - in.roughness_um / 0.0254);
  const double us = 0.0127 * c_r * std::log10(3.17e8 * w_lb_in / (in.viscosity_cP * vs * vr * vr));
  EXPECT_NEAR(benedict_kelley(in), us, 2e-5);
}

TEST(FrictionLaws, BenedictKelleyIsCappedAtThePitchPoint) {
  EXPECT_EQ(benedict_kelley({250750.0, 80.0, 0.0, 2.0, 0.4}), benedict_kelley_cap);
  EXPECT_EQ(benedict_kelley({250750.0, 80.0, 1e-12, 2.0, 0.4}), benedict_kelley_cap);
  EXPECT_NE(input_error_of([] { (void)benedict_kelley({250750.0, 80.0, 0.5, 2.0, 1.5}); }).find("roughness"),
            std::string::npos);
}

// --- ISO/TR 14179-2 -----------------------------------------------------------------------------

TEST(FrictionLaws, Iso14179ExponentsAndUnits) {
  const Iso14179Inputs in{250.0, 2.0, 5.5, 80.0, 0.4, 1.0};
  const double mu = iso14179_mean(in);
  EXPECT_NEAR(mu, 0.048 * std::pow(250.0 / 11.0, 0.2) * std::pow(80.0, -0.05) * std::pow(0.4, 0.25), 1e-15);
  auto doubled = in;
  doubled.load_per_width_N_mm *= 2;
  EXPECT_NEAR(iso14179_mean(doubled) / mu, std::pow(2.0, 0.2), 1e-14);
  auto per_metre = in;
  per_metre.load_per_width_N_mm = 250e3 * 1.0;  // N/m by mistake
  EXPECT_NE(input_error_of([&] { (void)iso14179_mean(per_metre); }).find("not N/m"), std::string::npos);
  auto metres = in;
  metres.reduced_radius_mm = 0.0055;
  EXPECT_NE(input_error_of([&] { (void)iso14179_mean(metres); }).find("not m"), std::string::npos);
  auto smooth = in;
  smooth.roughness_um = 0.0;
  EXPECT_NE(input_error_of([&] { (void)iso14179_mean(smooth); }).find("needs Ra > 0"), std::string::npos);
}

// --- Mixed law ------------------------------------------------------------------------------

TEST(FrictionLaws, FluidShareLimits) {
  EXPECT_EQ(fluid_load_share(0.0), 0.0);
  EXPECT_NEAR(fluid_load_share(1.0), 1.21 / 1.37, 1e-15);
  EXPECT_NEAR(fluid_load_share(1.999), 1.0, 1e-3);  // continuous to 1e-3 where the full film starts
  EXPECT_EQ(fluid_load_share(2.0), 1.0);
  EXPECT_EQ(fluid_load_share(50.0), 1.0);
  for (double l = 0.05; l < 1.9; l += 0.05) EXPECT_GT(fluid_load_share(l + 0.05), fluid_load_share(l)) << l;
  EXPECT_DOUBLE_EQ(mixed_friction(1.0, 0.03, 0.1), 0.03);
  EXPECT_DOUBLE_EQ(mixed_friction(0.0, 0.03, 0.1), 0.1);
  EXPECT_NEAR(composite_rms_roughness(0.4e-6, 0.4e-6), std::sqrt(2.0 * M_PI / 2.0) * 0.4e-6, 1e-20);
}

TEST(FrictionLaws, ModelNames) {
  EXPECT_EQ(parse_friction_model("mixed", "friction.model"), FrictionModel::mixed);
  EXPECT_NE(input_error_of([] { (void)parse_friction_model("coulomb", "friction.model"); }).find("friction.model = \"coulomb\""),
            std::string::npos);
}

// --- Film ---------------------------------------------------------------------------------------

// The solver's Dowson–Higginson film against the independent closed form of reference/.
TEST(Film, DowsonHigginsonMatchesReference) {
  reference::LineContact c{0.0055, 250750.0, 0.9, 1.1, 2.2637e11, 0.08, 2.2e-8};
  const double h = efficiency::dowson_higginson_min_film(c.load_per_length, c.reduced_radius, 0.5 * (c.u1 + c.u2),
                                                         c.viscosity, c.pressure_viscosity, c.reduced_modulus);
  EXPECT_NEAR(h, reference::dowson_higginson_h_min(c), 1e-12 * h);
  EXPECT_NEAR(efficiency::hertz_line_pressure(c.load_per_length, c.reduced_radius, c.reduced_modulus),
              reference::hertz_max_pressure(c), 1e-9 * reference::hertz_max_pressure(c));
}

}  // namespace
}  // namespace gearbench
