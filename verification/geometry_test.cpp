// Unit tests of solvers/geometry: the involute inverse, the seed pairs' figures against
// hand calculation, load sharing, and the feasibility errors.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/gear_pair_geometry.h"
#include "geometry/involute.h"
#include "geometry/load_sharing.h"
#include "model/errors.h"
#include "support/test_support.h"

namespace gearbench::geometry {
namespace {

constexpr double deg = M_PI / 180.0;

model::GearPair seed004() { return testing_support::seed004_pair(); }

std::string error_of(const model::GearPair& g) {
  return testing_support::input_error_of([&] { GearPairGeometry{g}; });
}

TEST(Involute, InverseRoundTrips) {
  for (double a = 0.5; a < 80.0; a += 0.5)
    EXPECT_NEAR(inverse_involute(involute(a * deg)), a * deg, 1e-13) << a;
  EXPECT_THROW(inverse_involute(-1e-3), std::domain_error);
}

// Hand calculation (standard pair, a = 54 mm): ε_α = [√(24² − 19.93877²) + √(34² − 29.00185²)
// − 54·sin 25°]/(π·2·cos 25°) = (13.35836 + 17.74523 − 22.82138)/5.694518 = 1.45442.
TEST(GearPairGeometry, Seed004ByHand) {
  const GearPairGeometry g(seed004());
  EXPECT_NEAR(g.center_distance(), 54e-3, 1e-15);
  EXPECT_NEAR(g.working_pressure_angle(), 25 * deg, 1e-14);
  EXPECT_NEAR(g.contact_ratio_transverse(), 1.45442, 1e-5);
  EXPECT_DOUBLE_EQ(g.contact_ratio_overlap(), 0.0);
  EXPECT_NEAR(g.radii(0).tip, 24e-3, 1e-15);
  EXPECT_NEAR(g.radii(1).root, 29.5e-3, 1e-15);
  const auto& p = g.path();
  EXPECT_LT(p.A, p.B);
  EXPECT_LT(p.B, p.C);  // C lies in the single zone for this pair
  EXPECT_LT(p.C, p.D);
  EXPECT_LT(p.D, p.E);
  EXPECT_EQ(g.pairs_in_contact(p.C), 1);
  EXPECT_EQ(g.pairs_in_contact(p.AB), 2);
  EXPECT_TRUE(g.warnings().empty());
}

TEST(GearPairGeometry, SlidingChangesSignAtPitchPoint) {
  const GearPairGeometry g(seed004());
  const auto& p = g.path();
  EXPECT_LT(g.kinematics(p.A, 100.0).sliding, 0.0);  // pinion root: wheel faster
  EXPECT_GT(g.kinematics(p.E, 100.0).sliding, 0.0);  // pinion tip: pinion faster
  const auto k = g.kinematics(p.C, 100.0);
  EXPECT_NEAR(k.sliding, 0.0, 1e-12);
  EXPECT_NEAR(k.u1, 100.0 * g.radii(0).base * std::tan(g.working_pressure_angle()), 1e-12);
}

TEST(LoadSharing, IsoSpurPairsSumToOne) {
  const GearPairGeometry g(seed004());
  const IsoLoadSharing iso;
  const EqualLoadSharing equal;
  const auto& p = g.path();
  const double pb = g.base_pitch_transverse();
  for (int i = 1; i < 100; ++i) {  // inside A..B: the shares jump at the zone limits
    const double s = p.A + (p.B - p.A) * i / 100.0;  // a pair in A..B, its partner in D..E
    EXPECT_NEAR(iso.share(g, s) + iso.share(g, s + pb), 1.0, 1e-12);
    EXPECT_NEAR(equal.share(g, s) + equal.share(g, s + pb), 1.0, 1e-12);
  }
  EXPECT_NEAR(iso.share(g, p.A), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(iso.share(g, p.C), 1.0, 1e-12);
  EXPECT_THROW(make_load_sharing("stiff", "load_sharing"), InputError);
}

TEST(GearPairGeometry, HelicalContactLineLengthBounds) {
  auto pair = seed004();
  pair.helix_angle = 15 * deg;
  const GearPairGeometry g(pair);
  const double b = pair.face_width;
  const double cb = std::cos(g.base_helix_angle());
  for (int i = 0; i < 50; ++i) {
    const double L = g.contact_line_length(g.path().A + g.base_pitch_transverse() * i / 50.0);
    // Never more than ceil(ε_γ) full-width lines of b/cos β_b, and never without contact.
    EXPECT_GT(L, 0.5 * b / cb);
    EXPECT_LE(L, std::ceil(g.contact_ratio_total()) * b / cb + 1e-12);
  }
  pair.herringbone = model::Herringbone{0.01};
  const GearPairGeometry h(pair);
  EXPECT_NEAR(h.contact_line_length(h.path().C), 2.0 * g.contact_line_length(g.path().C), 1e-15);
}

TEST(Feasibility, UndercutNamesTeethAndMinimum) {
  auto g = seed004();
  g.normal_pressure_angle = 20 * deg;
  g.root_radius_coef = 0.38;  // ISO 53 A at 20° (seed 004's 25° pair carries the full-round radius)
  g.teeth = {12, 40};
  const auto msg = error_of(g);
  EXPECT_NE(msg.find("gear_pair.teeth[0] = 12: undercut"), std::string::npos) << msg;
  EXPECT_NE(msg.find("teeth >= 17.1"), std::string::npos) << msg;
  g.profile_shift = {0.4, 0.0};
  EXPECT_EQ(error_of(g), "");
}

TEST(Feasibility, CenterDistanceMustMatchShifts) {
  auto g = seed004();
  g.center_distance = 53.9e-3;
  EXPECT_NE(error_of(g).find("gear_pair.center_distance_mm = 53.9: incompatible"), std::string::npos);
  g.center_distance = 54.1e-3;  // 0.05 m_n of backlash: allowed, with a warning
  EXPECT_EQ(error_of(g), "");
  EXPECT_EQ(GearPairGeometry(g).warnings().size(), 1u);
}

TEST(Feasibility, ContactRatioBelowOne) {
  auto g = seed004();
  g.tip_diameter = std::array<double, 2>{45.0e-3, 65.5e-3};
  EXPECT_NE(error_of(g).find("transverse contact ratio 0.49"), std::string::npos) << error_of(g);
}

TEST(Feasibility, TipBelowBaseCircle) {
  auto g = seed004();
  g.tip_diameter = std::array<double, 2>{39.0e-3, 68.0e-3};
  EXPECT_NE(error_of(g).find("gear_pair.tip_diameter_mm[0] = 39: must exceed the base diameter"),
            std::string::npos) << error_of(g);
}

}  // namespace
}  // namespace gearbench::geometry
