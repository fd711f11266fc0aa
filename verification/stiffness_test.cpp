// Unit tests of solvers/stiffness: closed-form pieces, the tooth profile's branches,
// stiffness-based load sharing, herringbone halves and the input errors.
#include <gtest/gtest.h>

#include <cmath>

#include "model/errors.h"
#include "support/test_support.h"
#include "stiffness/hertz.h"
#include "stiffness/mesh_stiffness.h"

namespace gearbench::stiffness {
namespace {

constexpr double deg = M_PI / 180.0;
const model::Material steel{212e9, 0.289, 7850};
const std::array<model::Material, 2> steels{steel, steel};

model::GearPair seed003() { return testing_support::seed003_pair(); }
using testing_support::input_error_of;

TEST(Hertz, EqualMaterialsForm) {
  // π·E·L/(4(1 − ν²)) (Yang & Sun 1985).
  EXPECT_NEAR(hertz_stiffness(steel, steel, 0.02), M_PI * 212e9 * 0.02 / (4 * (1 - 0.289 * 0.289)), 1e-3);
  const model::Material soft{70e9, 0.33, 2700};
  EXPECT_LT(hertz_stiffness(steel, soft, 0.02), hertz_stiffness(steel, steel, 0.02));
}

constexpr ToothModel arc{BeamStart::improved, Fillet::circular_arc};

TEST(ToothProfile, ImprovedFilletMeetsInvoluteAtBaseCircle) {
  const geometry::GearPairGeometry g(seed003());
  const ToothProfile p(g, 0, arc);
  ASSERT_LT(p.root_radius(), p.base_radius());
  EXPECT_GT(p.fillet_radius(), 0.0);
  const double xB = p.base_point_x();
  EXPECT_NEAR(p.half_thickness(xB - 1e-12), p.half_thickness(xB + 1e-12), 1e-10);
  EXPECT_LT(p.beam_start(), xB);
  // The fillet thickens the tooth toward the root: thicker than the straight variant.
  const ToothProfile straight(g, 0, {BeamStart::straight});
  EXPECT_GT(p.half_thickness(0.5 * (p.beam_start() + xB)), straight.half_thickness(0.5 * (p.beam_start() + xB)));
}

TEST(ToothProfile, RootAboveBaseStartsOnTheInvolute) {
  auto pair = seed003();
  pair.teeth = {60, 80};
  const geometry::GearPairGeometry g(pair);
  const ToothProfile p(g, 0, arc);
  ASSERT_GT(p.root_radius(), p.base_radius());
  EXPECT_NEAR(std::hypot(p.beam_start(), p.half_thickness(p.beam_start())), p.root_radius(), 1e-12);
}

// The generated fillet starts on the root circle at the polar angle of the rack's tip-line
// end, θ_f = [π/2 + 2 tan α (h_fP* − ρ*) + 2ρ*/cos α]/z (docs/research/stiffness.md §1.4,
// independent of the shift), and meets the involute on the form circle of the geometry
// (ISO 21771) with the same half thickness: shifted and unshifted, R_f below and above R_b,
// ISO 53 profiles A and D.
TEST(ToothProfile, TrochoidRunsFromRootCircleToFormCircle) {
  struct Case { int z; double x, h_fP, rho; };
  for (const Case c : {Case{20, 0.0, 1.25, 0.38}, Case{25, 0.3, 1.25, 0.38}, Case{62, 0.0, 1.25, 0.38},
                       Case{19, 0.2, 1.4, 0.39}, Case{48, -0.2, 1.25, 0.25}}) {
    auto pair = seed003();
    pair.teeth = {c.z, 80};
    pair.profile_shift = {c.x, 0.0};
    pair.dedendum_coef = c.h_fP;
    pair.root_radius_coef = c.rho;
    const geometry::GearPairGeometry g(pair);
    const ToothProfile p(g, 0, {});
    const double x0 = p.beam_start(), h0 = p.half_thickness(x0);
    EXPECT_NEAR(std::hypot(x0, h0), g.radii(0).root, 1e-12) << c.z;
    const double a = pair.normal_pressure_angle;
    const double theta_f = (M_PI / 2 + 2 * std::tan(a) * (c.h_fP - c.rho) + 2 * c.rho / std::cos(a)) / c.z;
    EXPECT_NEAR(std::atan2(h0, x0), theta_f, 1e-12) << c.z;
    const double xF = p.fillet_end_x();
    EXPECT_NEAR(p.half_thickness(xF * (1 - 1e-13)), p.half_thickness(xF * (1 + 1e-13)), 1e-11) << c.z;
    EXPECT_NEAR(std::hypot(xF, p.half_thickness(xF)), g.radii(0).form, 1e-9) << c.z;
  }
}

TEST(ToothProfile, TrochoidNeedsARackTipRadiusThatFits) {
  auto pair = seed003();
  pair.teeth = {25, 30};  // free of undercut without a tip radius
  pair.root_radius_coef = 0.0;
  EXPECT_NE(input_error_of([&] { ToothProfile(geometry::GearPairGeometry(pair), 0, {}); }).find("root_radius_coef"),
            std::string::npos);
  pair.root_radius_coef = 0.5;  // h_fP 1.25 at 20°: the round fits for ρ ≤ 0.472 m_n
  EXPECT_NE(input_error_of([&] { ToothProfile(geometry::GearPairGeometry(pair), 0, {}); }).find("does not fit"),
            std::string::npos);
}

// The beam below the FE's probe Q (where the load line crosses the centre line): with the
// load parallel to the centre line's normal (α_1 = 0) Q is the load point's section and the
// two compliances are the same numbers; at mid-path what lies above Q is, per unit load,
//   bending ∫ M²/(E I) dx with M = cos α_1 (x_1 − x) − sin α_1 h_1,  shear 1.2 cos²α_1 ∫ dx/(G A),
// over [x_Q, x_1], here by Simpson's rule on the profile (2000 intervals on a smooth h:
// ~1e-12 relative, against the production's Gauss panels to 1e-13).
TEST(ToothCompliance, CentreLinePointIsTheBeamBelowTheProbe) {
  const double L = 0.02, E = steel.youngs_modulus, G = E / (2.0 * (1.0 + steel.poisson_ratio));
  const geometry::GearPairGeometry g(seed003());
  const ToothCompliance tooth(ToothProfile(g, 0, {}), steel, L, std::nullopt);
  const double alpha2 = tooth.profile().alpha2();
  const auto flat = tooth.at(alpha2), flat_q = tooth.centre_line_point(alpha2);
  EXPECT_DOUBLE_EQ(flat_q.bending, flat.bending);
  EXPECT_DOUBLE_EQ(flat_q.shear, flat.shear);

  const double psi = 0.5 * (g.path().A + g.path().E) / g.radii(0).base;
  const auto load = tooth.profile().involute_point(psi);
  const double c = std::cos(load.alpha), s = std::sin(load.alpha);
  const double xq = load.x - load.h * s / c;
  constexpr int n = 2000;
  double bending = 0.0, shear = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double x = xq + (load.x - xq) * i / n;
    const double weight = ((i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0)) * (load.x - xq) / (3.0 * n);
    const double t = 2.0 * tooth.profile().half_thickness(x);
    const double M = c * (load.x - x) - s * load.h;
    bending += weight * M * M * 12.0 / (E * t * t * t * L);
    shear += weight * 1.2 * c * c / (G * t * L);
  }
  const auto full = tooth.at(psi), probe = tooth.centre_line_point(psi);
  EXPECT_NEAR(full.bending - probe.bending, bending, 1e-9 * full.bending);
  EXPECT_NEAR(full.shear - probe.shear, shear, 1e-9 * full.shear);
}

TEST(StiffnessLoadSharing, SharesSumToOne) {
  const geometry::GearPairGeometry g(seed003());
  const PairStiffness k(g, steels, {}, {8e-3, 10e-3}, std::nullopt, true);
  const StiffnessLoadSharing sharing(k);
  const auto& p = g.path();
  const double pb = g.base_pitch_transverse();
  for (int i = 1; i < 50; ++i) {
    const double s = p.A + (p.B - p.A) * i / 50.0;
    EXPECT_NEAR(sharing.share(g, s) + sharing.share(g, s + pb), 1.0, 1e-12);
  }
  EXPECT_NEAR(sharing.share(g, p.C), 1.0, 1e-12);  // single contact
  EXPECT_EQ(sharing.name(), "stiffness");
}

TEST(MeshStiffness, HerringboneIsTwoHalves) {
  auto pair = seed003();
  pair.helix_angle = 20 * deg;
  const geometry::GearPairGeometry half(pair);
  pair.herringbone = model::Herringbone{0.01};
  const geometry::GearPairGeometry both(pair);
  MeshStiffnessOptions o;
  o.positions = 30;
  const auto a = MeshStiffness(half, steels, o).solve();
  const auto b = MeshStiffness(both, steels, o).solve();
  EXPECT_NEAR(b.mean, 2.0 * a.mean, 1e-9 * b.mean);
  EXPECT_NEAR(b.mean_per_face_width(), a.mean_per_face_width(), 1e-9);
}

TEST(MeshStiffness, InputErrorsNameTheKey) {
  const geometry::GearPairGeometry g(seed003());
  MeshStiffnessOptions o;
  o.crack = GearCrack{{Crack::Type::pitch, 4e-3, 45 * deg}, 0};
  EXPECT_NE(input_error_of([&] { MeshStiffness(g, steels, o); }).find("crack.length_mm = 4: the crack leaves no section"),
            std::string::npos);
  o.crack.reset();
  o.positions = 1;
  EXPECT_EQ(input_error_of([&] { MeshStiffness(g, steels, o); }), "positions = 1: allowed range is [2, 100000]");
  auto helical = seed003();
  helical.helix_angle = 10 * deg;
  const geometry::GearPairGeometry h(helical);
  MeshStiffnessOptions cracked;
  cracked.crack = GearCrack{{Crack::Type::pitch, 1e-3, 45 * deg}, 0};
  EXPECT_NE(input_error_of([&] { MeshStiffness(h, steels, cracked); }).find("spur gears only"), std::string::npos);
  MeshStiffnessOptions bore;
  bore.bore_radius = std::array<double, 2>{30e-3, 5e-3};
  EXPECT_NE(input_error_of([&] { MeshStiffness(g, steels, bore); }).find("bore_diameter_mm[0] = 60"), std::string::npos);
}

TEST(MeshStiffness, CrackedEngagementSpansThePath) {
  const geometry::GearPairGeometry g(seed003());
  MeshStiffnessOptions o;
  o.positions = 50;
  o.crack = GearCrack{{Crack::Type::pitch, 1e-3, 45 * deg}, 0};
  const auto r = MeshStiffness(g, steels, o).solve();
  ASSERT_EQ(r.healthy_mesh_stiffness.size(), r.mesh_stiffness.size());
  EXPECT_NEAR(r.mesh_position.back(), (g.path().E - g.path().A) / g.radii(0).base, 1e-12);
  EXPECT_DOUBLE_EQ(r.mesh_stiffness.front(), r.healthy_mesh_stiffness.front());  // crack not yet loaded
  EXPECT_LT(r.mesh_stiffness.back(), r.healthy_mesh_stiffness.back());
}

}  // namespace
}  // namespace gearbench::stiffness
