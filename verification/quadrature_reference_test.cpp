// Tests of reference/quadrature, the GSL reference for the energy-method tooth model of
// docs/stiffness-model.md: Tian's closed-form integrands, closed forms for the straight
// section, the fillet (cut or not at the tooth-space centre line) and cracked beams integrated
// in x, the crack rules, continuity at R_f = R_b, the wheel's roll angle, the Hertz form and
// the path of contact.
#include <gtest/gtest.h>

#include <fmt/core.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "quadrature/energy_quadrature.h"
#include "support/test_support.h"

namespace gearbench::reference {
namespace {

constexpr double deg = M_PI / 180.0;
using Crack = QuadCrack::Type;

// Seed 003 (Xu et al. 2022): m 2 mm, z 20/25, b 20 mm, α 20°, E 212 GPa, ν 0.289.
model::GearPair seed003() { return testing_support::seed003_pair(); }

const model::Material steel{212e9, 0.289, 7850};
constexpr double L = 20e-3;

// Hand data of the seed 003 pinion: R_b, α_2 = π/(2z) + inv α, R_f.
const double Rb1 = 20e-3 * std::cos(20 * deg);
const double alpha2 = M_PI / 40.0 + std::tan(20 * deg) - 20 * deg;
const double Rf1 = 20e-3 - 2e-3 * 1.25;

QuadCompliance pinion(double s, QuadBeamStart start, const QuadCrack& crack = {},
                      const model::GearPair& pair = seed003()) {
  return energy_compliance_quadrature(pair, steel, 0, s, start, crack, L);
}

// ∫_lo^hi f by GSL's 61-point Gauss-Kronrod rule (a different rule from the reference's).
template <class Function>
double integrate(Function f, double lo, double hi) {
  gsl_function gf{[](double t, void* p) { return (*static_cast<Function*>(p))(t); }, &f};
  gsl_integration_workspace* work = gsl_integration_workspace_alloc(1000);
  double result = 0.0, abserr = 0.0;
  const int status =
      gsl_integration_qag(&gf, lo, hi, 0.0, 1e-12, 1000, GSL_INTEG_GAUSS61, work, &result, &abserr);
  gsl_integration_workspace_free(work);
  if (status) throw std::runtime_error("test quadrature failed");
  return result;
}

void expect_relative(const QuadCompliance& a, const QuadCompliance& b, double tol) {
  EXPECT_NEAR(a.bending, b.bending, tol * b.bending);
  EXPECT_NEAR(a.shear, b.shear, tol * b.shear);
  EXPECT_NEAR(a.axial, b.axial, tol * b.axial);
}

void expect_equal(const QuadCompliance& a, const QuadCompliance& b) {
  EXPECT_EQ(a.bending, b.bending);
  EXPECT_EQ(a.shear, b.shear);
  EXPECT_EQ(a.axial, b.axial);
}

// (a) Tian (2004), base-circle beam, in his angle (the negative of the spec's α, load at
// −α_1, base circle at α_2). His bending numerator 1 + cos α_1[(α_2 − α)sin α − cos α] is
// (R_b − x cos α_1)/R_b = M(x)/(F·R_b) with the F_a·h_1 term included, because
// x_1 cos α_1 − h_1 sin α_1 = R_b; so all three compliances must agree. Also with a profile
// shift and a helix angle, which enter through R_b and α_2 = π/(2z) + 2x tan α_n/z + inv α_t.
TEST(QuadratureReference, BaseCircleMatchesTianClosedForm) {
  const double E = steel.youngs_modulus, nu = steel.poisson_ratio;
  for (auto [shift, helix] : {std::pair{0.0, 0.0}, std::pair{0.3, 0.0}, std::pair{0.0, 15 * deg}}) {
    model::GearPair g = seed003();
    g.profile_shift = {shift, 0.0};
    g.helix_angle = helix;
    const double at = std::atan(std::tan(20 * deg) / std::cos(helix));
    const double Rb = 20e-3 / std::cos(helix) * std::cos(at);
    const double a2 = M_PI / 40.0 + shift * std::tan(20 * deg) / 10.0 + std::tan(at) - at;
    for (double psi : {0.12, 0.25, std::tan(at), 0.45, 0.6}) {
      const double a1 = psi - a2;
      const auto d = [&](double a) { return std::sin(a) + (a2 - a) * std::cos(a); };
      const auto n = [&](double a) { return (a2 - a) * std::cos(a); };
      QuadCompliance tian;
      tian.bending = integrate(
          [&](double a) {
            const double m = 1.0 + std::cos(a1) * ((a2 - a) * std::sin(a) - std::cos(a));
            return 3.0 * m * m * n(a) / (2.0 * E * L * std::pow(d(a), 3));
          },
          -a1, a2);
      tian.shear = integrate(
          [&](double a) {
            return 1.2 * (1.0 + nu) * n(a) * std::pow(std::cos(a1), 2) / (E * L * d(a));
          },
          -a1, a2);
      tian.axial = integrate(
          [&](double a) { return n(a) * std::pow(std::sin(a1), 2) / (2.0 * E * L * d(a)); },
          -a1, a2);
      SCOPED_TRACE(::testing::Message()
                   << "x = " << shift << ", beta = " << helix << ", psi = " << psi);
      expect_relative(pinion(Rb * psi, QuadBeamStart::base_circle, {}, g), tian, 1e-9);
    }
  }
}

// The straight section (R_f < R_b) adds closed forms to the base-circle beam: constant half
// thickness h_B on [x_F, x_B], x_F = √(R_f² − h_B²), and M/F = R_b − x cos α_1.
TEST(QuadratureReference, StraightSectionAddsClosedForm) {
  const double E = steel.youngs_modulus, G = E / (2.0 * (1.0 + steel.poisson_ratio));
  const double xB = Rb1 * std::cos(alpha2), hB = Rb1 * std::sin(alpha2);
  const double xF = std::sqrt(Rf1 * Rf1 - hB * hB), A = 2.0 * hB * L;
  const double I = std::pow(2.0 * hB, 3) * L / 12.0;
  for (double psi : {0.15, 0.5}) {
    const double c = std::cos(psi - alpha2), s = std::sin(psi - alpha2);
    const QuadCompliance base = pinion(Rb1 * psi, QuadBeamStart::base_circle);
    const QuadCompliance straight = pinion(Rb1 * psi, QuadBeamStart::straight);
    const double bending =
        (std::pow(Rb1 - c * xF, 3) - std::pow(Rb1 - c * xB, 3)) / (3.0 * c * E * I);
    EXPECT_NEAR(straight.bending - base.bending, bending, 1e-9 * straight.bending);
    EXPECT_NEAR(straight.shear - base.shear, 1.2 * c * c * (xB - xF) / (G * A),
                1e-9 * straight.shear);
    EXPECT_NEAR(straight.axial - base.axial, s * s * (xB - xF) / (E * A), 1e-9 * straight.axial);
  }
}

// The spec's fillet of a standard 20° gear with z teeth (m 2 mm), in x: h(x) explicit on
// [x_0, x_B]; x_0 is the tangency x_F = x_B·R_f/(R_f + ρ) unless the arc crosses the
// tooth-space centre line atan(h/x) = π/z first (found here by bisection in x).
struct FilletInX {
  double z;
  double Rb = z * 1e-3 * std::cos(20 * deg), a2 = M_PI / (2 * z) + std::tan(20 * deg) - 20 * deg;
  double Rf = z * 1e-3 - 2.5e-3, xB = Rb * std::cos(a2), hB = Rb * std::sin(a2);
  double rho = (Rb * Rb - Rf * Rf) / (2.0 * (Rf - hB)), xF = xB * Rf / (Rf + rho);
  double h(double x) const { return hB + rho - std::sqrt(rho * rho - (x - xB) * (x - xB)); }
  double x0() const {
    if (std::atan(h(xF) / xF) <= M_PI / z) return xF;
    double lo = xF, hi = xB;
    for (int i = 0; i < 60; ++i)
      (std::atan(h(0.5 * (lo + hi)) / (0.5 * (lo + hi))) > M_PI / z ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
  }
};

// The fillet part of the improved beam (improved − base_circle) integrated in x, for z = 20
// (arc cut at the tooth-space centre line) and z = 30 (arc down to the root circle).
TEST(QuadratureReference, FilletMatchesIntegrationInX) {
  const double E = steel.youngs_modulus, G = E / (2.0 * (1.0 + steel.poisson_ratio));
  for (int z : {20, 30}) {
    const FilletInX f{double(z)};
    EXPECT_EQ(f.x0() > f.xF, z == 20);
    model::GearPair g = seed003();
    g.teeth = {z, 25};
    const double psi = std::tan(20 * deg), c = std::cos(psi - f.a2), s = std::sin(psi - f.a2);
    const QuadCompliance base = pinion(f.Rb * psi, QuadBeamStart::base_circle, {}, g);
    const QuadCompliance improved = pinion(f.Rb * psi, QuadBeamStart::circular_arc, {}, g);
    const auto t = [&](double x) { return 2.0 * f.h(x); };
    const double bending = integrate(
        [&](double x) { return 12.0 * std::pow(f.Rb - c * x, 2) / (E * std::pow(t(x), 3) * L); },
        f.x0(), f.xB);
    const double shear =
        integrate([&](double x) { return 1.2 * c * c / (G * t(x) * L); }, f.x0(), f.xB);
    const double axial = integrate([&](double x) { return s * s / (E * t(x) * L); }, f.x0(), f.xB);
    SCOPED_TRACE(z);
    EXPECT_NEAR(improved.bending - base.bending, bending, 1e-9 * improved.bending);
    EXPECT_NEAR(improved.shear - base.shear, shear, 1e-9 * improved.shear);
    EXPECT_NEAR(improved.axial - base.axial, axial, 1e-9 * improved.axial);
  }
}

// The seed 003 pinion as a beam in x, for cracked beams: h(x) by bisection on the involute
// (x grows with α) above B; below it the fillet (improved) or the constant h_B (straight).
struct BeamInX {
  QuadBeamStart start;
  FilletInX fillet{20};
  double xB = fillet.xB, hB = fillet.hB;
  double x_of(double a) const { return Rb1 * ((a + alpha2) * std::sin(a) + std::cos(a)); }
  double h_of(double a) const { return Rb1 * ((a + alpha2) * std::cos(a) - std::sin(a)); }
  double x0() const {
    if (start == QuadBeamStart::base_circle) return xB;
    return start == QuadBeamStart::circular_arc ? fillet.x0() : std::sqrt(Rf1 * Rf1 - hB * hB);
  }
  double h(double x) const {
    if (x < xB) return start == QuadBeamStart::circular_arc ? fillet.h(x) : hB;
    double lo = -alpha2, hi = 1.0;
    for (int i = 0; i < 60; ++i) (x_of(0.5 * (lo + hi)) < x ? lo : hi) = 0.5 * (lo + hi);
    return h_of(0.5 * (lo + hi));
  }
};

// Cracked beams (cases 1 to 3 of seed 003, ν ≠ 45° so that sin ν and cos ν differ), integrated
// here in x with the spec's thickness rule, load at the pinion tip.
TEST(QuadratureReference, CrackedBeamMatchesIntegrationInX) {
  const double E = steel.youngs_modulus, G = E / (2.0 * (1.0 + steel.poisson_ratio));
  const double psi = contact_path_quadrature(seed003()).end / Rb1, a1 = psi - alpha2;
  const double c = std::cos(a1), sn = std::sin(a1);
  const struct {
    Crack type;
    QuadBeamStart start;
    double q, nu;
  } cases[] = {{Crack::pitch, QuadBeamStart::circular_arc, 2.0e-3, 30 * deg},
               {Crack::pitch, QuadBeamStart::straight, 2.2e-3, 60 * deg},  // h_c < 0
               {Crack::root, QuadBeamStart::circular_arc, 1.0e-3, 30 * deg},
               {Crack::root, QuadBeamStart::base_circle, 1.0e-3, 60 * deg}};
  for (const auto& k : cases) {
    const BeamInX beam{k.start};
    const double x1 = beam.x_of(a1), h1 = beam.h_of(a1), ag = std::tan(20 * deg) - alpha2;
    const double xm = k.type == Crack::pitch ? beam.x_of(ag) : beam.x0();
    const double hm = k.type == Crack::pitch ? beam.h_of(ag) : beam.h(beam.x0());
    const double xc = xm - k.q * std::cos(k.nu), hc = hm - k.q * std::sin(k.nu);
    const auto t = [&](double x) {
      return x < xc ? 2.0 * beam.h(x) : beam.h(x) + std::min(beam.h(x), hc);
    };
    std::vector<double> pts{beam.x0(), x1};
    for (double b : {beam.xB, xc})
      if (b > beam.x0() && b < x1) pts.insert(pts.end() - 1, b);
    std::sort(pts.begin(), pts.end());
    QuadCompliance in_x;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      in_x.bending += integrate(
          [&](double x) {
            return 12.0 * std::pow(c * (x1 - x) - sn * h1, 2) / (E * std::pow(t(x), 3) * L);
          },
          pts[i], pts[i + 1]);
      in_x.shear +=
          integrate([&](double x) { return 1.2 * c * c / (G * t(x) * L); }, pts[i], pts[i + 1]);
      in_x.axial +=
          integrate([&](double x) { return sn * sn / (E * t(x) * L); }, pts[i], pts[i + 1]);
    }
    SCOPED_TRACE(::testing::Message() << "q = " << k.q << ", nu = " << k.nu);
    expect_relative(pinion(Rb1 * psi, k.start, {k.type, k.q, k.nu}), in_x, 1e-9);
  }
}

// (b) q = 0 is the healthy tooth, bit for bit, and a 1 nm crack differs by O(q²), far below
// the quadrature's 1e-10 -- except a root crack on a beam that starts at B (base_circle,
// straight): h_B is a local minimum of h (the involute bulges to R_b·α_2 above B), and the
// spec's rule weakens every section with h > h_c, so any q > 0 removes the bulge.
TEST(QuadratureReference, ZeroLengthCrackIsHealthy) {
  const QuadContactPath path = contact_path_quadrature(seed003());
  for (auto start :
       {QuadBeamStart::base_circle, QuadBeamStart::circular_arc, QuadBeamStart::straight}) {
    for (auto [type, s] :
         {std::pair{Crack::pitch, path.end}, std::pair{Crack::root, path.pitch_point}}) {
      SCOPED_TRACE(::testing::Message() << "start " << static_cast<int>(start) << ", crack "
                                        << static_cast<int>(type));
      const QuadCompliance healthy = pinion(s, start);
      expect_equal(pinion(s, start, {type, 0.0, 45 * deg}), healthy);
      const QuadCompliance tiny = pinion(s, start, {type, 1e-9, 45 * deg});
      if (type == Crack::root && start != QuadBeamStart::circular_arc)
        EXPECT_GT(tiny.bending, (1.0 + 1e-5) * healthy.bending);
      else
        expect_relative(tiny, healthy, 1e-9);
    }
  }
}

// (c) Seed 003's pitch crack (ν = 45°, q = 0, 1, 2, 2.5 mm; 2.5 mm passes the centre
// line): above the pitch circle every compliance grows with q, below it none changes.
TEST(QuadratureReference, PitchCrackGrowsAboveAndIsInertBelow) {
  const QuadContactPath p = contact_path_quadrature(seed003());
  const std::vector<double> q{0.0, 1e-3, 2e-3, 2.5e-3};
  for (double s : {0.5 * (p.pitch_point + p.end), p.end}) {
    QuadCompliance previous = pinion(s, QuadBeamStart::circular_arc);
    for (std::size_t i = 1; i < q.size(); ++i) {
      const QuadCompliance k = pinion(s, QuadBeamStart::circular_arc, {Crack::pitch, q[i], 45 * deg});
      EXPECT_GT(k.bending, previous.bending) << "s = " << s << ", q = " << q[i];
      EXPECT_GT(k.shear, previous.shear) << "s = " << s << ", q = " << q[i];
      EXPECT_GT(k.axial, previous.axial) << "s = " << s << ", q = " << q[i];
      previous = k;
    }
  }
  for (double s : {p.start, 0.5 * (p.start + p.pitch_point)})
    for (double length : q)
      expect_equal(pinion(s, QuadBeamStart::circular_arc, {Crack::pitch, length, 45 * deg}),
                   pinion(s, QuadBeamStart::circular_arc));
}

// A root crack weakens the beam at every load position, more the longer it is.
TEST(QuadratureReference, RootCrackGrowsEverywhere) {
  const QuadContactPath p = contact_path_quadrature(seed003());
  for (double s : {p.start, p.pitch_point, p.end}) {
    double previous = pinion(s, QuadBeamStart::circular_arc).bending;
    for (double length : {0.5e-3, 1e-3, 1.5e-3}) {
      const double k = pinion(s, QuadBeamStart::circular_arc, {Crack::root, length, 45 * deg}).bending;
      EXPECT_GT(k, previous) << "s = " << s << ", q = " << length;
      previous = k;
    }
  }
}

// (d) With z fixed, h_f* moves R_f across R_b by ±ε relative: the improved beam switches
// from fillet to involute start, the straight one from straight section to involute start.
// The change must be below 1e-3 for ε = 1e-6 and shrink in proportion to ε (a jump would not).
TEST(QuadratureReference, ContinuousWhereRootMeetsBaseCircle) {
  const double s = contact_path_quadrature(seed003()).pitch_point;
  const auto at_root_radius = [&](double Rf, QuadBeamStart start) {
    model::GearPair g = seed003();
    g.dedendum_coef = (20e-3 - Rf) / g.normal_module;
    return pinion(s, start, {}, g);
  };
  const auto change_across = [&](double eps, QuadBeamStart start) {
    const QuadCompliance below = at_root_radius(Rb1 * (1.0 - eps), start);
    const QuadCompliance above = at_root_radius(Rb1 * (1.0 + eps), start);
    return std::max({std::abs(below.bending / above.bending - 1.0),
                     std::abs(below.shear / above.shear - 1.0),
                     std::abs(below.axial / above.axial - 1.0)});
  };
  for (auto start : {QuadBeamStart::circular_arc, QuadBeamStart::straight}) {
    const double coarse = change_across(1e-6, start), fine = change_across(1e-8, start);
    EXPECT_LT(coarse, 1e-3);
    EXPECT_NEAR(fine / coarse, 1e-2, 2e-3);
  }
}

// The wheel's roll angle ψ2 = (T1T2 − s)/R_b2: in a pair of equal gears the wheel loaded
// at s is the pinion loaded at T1T2 − s.
TEST(QuadratureReference, WheelMirrorsPinionInEqualPair) {
  model::GearPair g = seed003();
  g.teeth = {25, 25};
  const QuadContactPath p = contact_path_quadrature(g);
  for (double s : {p.start, p.pitch_point, 0.3 * p.start + 0.7 * p.end}) {
    const QuadCompliance wheel =
        energy_compliance_quadrature(g, steel, 1, s, QuadBeamStart::circular_arc, {}, L);
    expect_relative(wheel, pinion(p.line_of_action_length - s, QuadBeamStart::circular_arc, {}, g),
                    1e-11);
  }
}

TEST(QuadratureReference, HertzYangSunForm) {
  const double nu = steel.poisson_ratio, E = steel.youngs_modulus;
  EXPECT_NEAR(hertz_compliance_quadrature(steel, steel, L), 4.0 * (1.0 - nu * nu) / (M_PI * E * L),
              1e-15 / (E * L));
  const model::Material bronze{110e9, 0.34, 8800};
  EXPECT_NEAR(hertz_compliance_quadrature(steel, bronze, L),
              0.5 * (hertz_compliance_quadrature(steel, steel, L) +
                     hertz_compliance_quadrature(bronze, bronze, L)),
              1e-15 / (E * L));
}

// The tip roll limits by Brent against the textbook: E = √(R_a1² − R_b1²) and
// E − A = ε_α·p_bt with ε_α = 1.58424 by hand for seed 003 (R_a 22 and 27 mm).
TEST(QuadratureReference, PathOfContact) {
  const QuadContactPath p = contact_path_quadrature(seed003());
  const double Rb2 = 25e-3 * std::cos(20 * deg), pbt = M_PI * 2e-3 * std::cos(20 * deg);
  EXPECT_NEAR(p.end, std::sqrt(22e-3 * 22e-3 - Rb1 * Rb1), 1e-15);
  EXPECT_NEAR(p.start, p.line_of_action_length - std::sqrt(27e-3 * 27e-3 - Rb2 * Rb2), 1e-15);
  EXPECT_NEAR(p.line_of_action_length, 45e-3 * std::sin(20 * deg), 1e-15);
  EXPECT_NEAR((p.end - p.start) / pbt, 1.58424, 1e-5);
  model::GearPair given = seed003();
  given.tip_diameter = {{43.6e-3, 53e-3}};
  EXPECT_NEAR(contact_path_quadrature(given).end, std::sqrt(21.8e-3 * 21.8e-3 - Rb1 * Rb1), 1e-15);
}

TEST(QuadratureReference, RejectsLoadsOffTheFlankAndCutThroughSections) {
  const model::GearPair g = seed003();
  const QuadContactPath p = contact_path_quadrature(g);
  EXPECT_THROW(pinion(1.01 * p.end, QuadBeamStart::circular_arc), std::domain_error);
  EXPECT_THROW(pinion(p.end, QuadBeamStart::circular_arc, {Crack::pitch, 10e-3, 45 * deg}),
               std::domain_error);
  EXPECT_THROW(pinion(p.end, QuadBeamStart::circular_arc, {Crack::root, -1e-3, 45 * deg}),
               std::invalid_argument);
  EXPECT_THROW(energy_compliance_quadrature(g, steel, 2, p.end, QuadBeamStart::circular_arc, {}, L),
               std::invalid_argument);
  model::GearPair big = g;  // z = 60: R_f = 57.5 mm > R_b = 56.38 mm
  big.teeth = {60, 60};
  EXPECT_THROW(pinion(1e-4, QuadBeamStart::circular_arc, {}, big), std::domain_error);
}

// Prints the seed 003 pinion's healthy compliances at C and E for cross-checking.
TEST(QuadratureReference, PrintSeed003Pinion) {
  const QuadContactPath p = contact_path_quadrature(seed003());
  fmt::print("seed 003 pinion, L = 20 mm, T1C = {:.9f} mm, T1E = {:.9f} mm\n", p.pitch_point * 1e3,
             p.end * 1e3);
  const std::pair<const char*, QuadBeamStart> starts[] = {
      {"base_circle", QuadBeamStart::base_circle},
      {"improved", QuadBeamStart::circular_arc},
      {"straight", QuadBeamStart::straight}};
  for (auto [name, start] : starts)
    for (auto [where, s] : {std::pair{"C", p.pitch_point}, std::pair{"E", p.end}}) {
      const QuadCompliance k = pinion(s, start);
      fmt::print("  {:<11} at {}: 1/k_b = {:.12e}  1/k_s = {:.12e}  1/k_a = {:.12e} m/N\n", name,
                 where, k.bending, k.shear, k.axial);
      EXPECT_GT(k.bending, 0.0);
    }
  fmt::print("  Hertz 1/k_h = {:.12e} m/N\n", hertz_compliance_quadrature(steel, steel, L));
}

}  // namespace
}  // namespace gearbench::reference
