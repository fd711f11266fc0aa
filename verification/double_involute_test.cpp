// Double-involute geometry (seed 002, issue 10): a zero step reduces to the ordinary
// involute pair; the contact-line lengths of a stepped helical pair agree with a direct
// construction in reference/construction that intersects the line of action with the tooth
// flanks slice by slice; L(t) is linear between the breakpoints (the seed's t_G21 … t_D22);
// the rack's waist arc is the circle the closed form says; bad racks give clear errors.
#include <gtest/gtest.h>

#include <cmath>

#include "construction/double_involute_contact.h"
#include "geometry/double_involute.h"
#include "support/test_support.h"

namespace {

using namespace gearbench;
using geometry::DoubleInvolutePair;
using geometry::ToothZone;

constexpr double deg = M_PI / 180.0;

/// The helical pair of cases/seed002_double_involute_oil_film.json: 25/38, m_n 3 mm,
/// α_n 20°, β 15°, b 40 mm (overlap ratio 1.10).
model::GearPair helical_pair() {
  auto p = testing_support::spur_pair(25, 38, 3.0, 20.0, 40.0);
  p.helix_angle = 15.0 * deg;
  return p;
}

model::DoubleInvoluteRack stepped_rack() {
  model::DoubleInvoluteRack r;
  r.tip_tangential_shift = 0.1;
  r.root_tangential_shift = 0.1;
  r.waist_tip_depth = 0.05;
  r.waist_root_depth = 0.3;
  return r;
}

// A zero step is the ordinary involute: the zones join at the pitch point into A..E, and
// the contact lines are those of GearPairGeometry (ISO 21771 clipping) to rounding. The
// lengths are sums of a few clipped differences of positions of ~30 mm: 1e-12 relative is
// a few hundred ulps. Also with a waist depth (no step means no waist whatever l_a*, l_d*).
TEST(DoubleInvolute, ZeroStepIsTheOrdinaryInvolute) {
  for (const double beta : {0.0, 15.0}) {
    for (const double depth : {0.0, 0.3}) {
      auto pair = helical_pair();
      pair.helix_angle = beta * deg;
      const geometry::GearPairGeometry g(pair);
      model::DoubleInvoluteRack rack;
      rack.waist_tip_depth = rack.waist_root_depth = depth;
      const DoubleInvolutePair di(g, rack);
      SCOPED_TRACE(testing::Message() << "beta " << beta << ", depth " << depth);
      EXPECT_EQ(di.step(), 0.0);
      EXPECT_EQ(di.zone(ToothZone::root).begin, g.path().A);
      EXPECT_EQ(di.zone(ToothZone::root).end, di.zone(ToothZone::tip).begin);
      EXPECT_EQ(di.zone(ToothZone::tip).end, g.path().E);
      EXPECT_NEAR(di.zone_contact_ratio(ToothZone::root) + di.zone_contact_ratio(ToothZone::tip),
                  g.contact_ratio_transverse(), 1e-14);
      const double pb = g.base_pitch_transverse();
      for (int i = 0; i < 200; ++i) {
        const double tau = (i + 0.37) / 200 * pb;  // off the breakpoints, where spur lengths jump
        EXPECT_NEAR(di.contact_line_length(tau), g.contact_line_length(g.path().A + tau),
                    1e-12 * g.contact_line_length(g.path().A + tau));
        // Radii of curvature per zone: every piece sits on the ordinary path with the
        // ordinary curvature (the positions of the pairs in contact, spur).
        if (beta == 0.0) {
          const auto pieces = di.contact_pieces(tau);
          const auto positions = g.positions_in_contact(g.path().A + tau);
          ASSERT_EQ(pieces.size(), positions.size());
          for (std::size_t k = 0; k < pieces.size(); ++k)
            EXPECT_NEAR(pieces[k].s_begin, positions[k], 1e-15);
        }
      }
    }
  }
}

// Against the direct construction: 24 mesh instants over one period of the stepped helical
// pair, the total length and the second pair's L_G2 and L_D2. The construction resolves the
// ends of a piece by bisection to ~1e-20 m of face and its line intersections by Brent to
// 1e-14 of the bracket; both sides are trigonometry on ~0.1 m coordinates, so 1e-9 m (1e-8
// of a 60 mm line) is rounding with a margin, while a wrong step (δ) or a wrong zone end
// shows as millimetres. The construction also measures that the pinion's tip involute
// meets the wheel's root involute at the very point the pair's other involutes fix.
TEST(DoubleInvolute, ContactLinesMatchTheDirectConstruction) {
  const auto pair = helical_pair();
  const auto rack = stepped_rack();
  const geometry::GearPairGeometry g(pair);
  const DoubleInvolutePair di(g, rack);
  const reference::DoubleInvoluteConstruction construction(pair, rack);
  const double pb = g.base_pitch_transverse();
  double largest = 0.0;
  for (int i = 0; i < 24; ++i) {
    const double tau = (i + 0.5) / 24 * pb;
    const auto c = construction.at(construction.engagement_angle() + tau / construction.base_radius_pinion());
    SCOPED_TRACE(testing::Message() << "tau " << tau);
    EXPECT_NEAR(di.contact_line_length(tau), c.total_length, 1e-9);
    EXPECT_LT(c.conjugacy_error, 1e-9);
    double root2 = 0.0, tip2 = 0.0;  // pair 2 is pinion tooth −1 of the construction
    for (const auto& p : c.pieces)
      if (p.tooth == -1) (p.tip_zone ? tip2 : root2) += p.length;
    EXPECT_NEAR(di.pair_contact_length(2, ToothZone::root, tau), root2, 1e-9);
    EXPECT_NEAR(di.pair_contact_length(2, ToothZone::tip, tau), tip2, 1e-9);
    largest = std::max(largest, std::abs(di.contact_line_length(tau) - c.total_length));
  }
  RecordProperty("largest_length_deviation_m", std::to_string(largest));
}

// Between consecutive breakpoints every contact line slides through its zone without
// meeting an end, so L(τ) and each pair's L_G, L_D are linear there (the seed's eqs 2–3):
// the midpoint equals the mean of the ends to rounding. A missing breakpoint (a kink inside
// an interval) breaks this by the size of the kink.
TEST(DoubleInvolute, LengthsAreLinearBetweenBreakpoints) {
  const geometry::GearPairGeometry g(helical_pair());
  const DoubleInvolutePair di(g, stepped_rack());
  auto t = di.breakpoints();
  t.push_back(t.front() + g.base_pitch_transverse());
  ASSERT_GE(t.size(), 5u);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double a = t[i] + 1e-9 * (t[i + 1] - t[i]), b = t[i + 1] - 1e-9 * (t[i + 1] - t[i]);
    const double mid = 0.5 * (a + b);
    EXPECT_NEAR(di.contact_line_length(mid), 0.5 * (di.contact_line_length(a) + di.contact_line_length(b)), 1e-12);
    for (const auto z : {ToothZone::root, ToothZone::tip})
      EXPECT_NEAR(di.pair_contact_length(2, z, mid),
                  0.5 * (di.pair_contact_length(2, z, a) + di.pair_contact_length(2, z, b)), 1e-12);
  }
}

// The zones: no contact near the pitch point, a gap of 2·l_d*·m_n/sin α_t for zero shifts,
// and the tip involute trailing by δ = (y_a* + y_d*)·m_t·cos α_t.
TEST(DoubleInvolute, ZonesLeaveTheGapAroundThePitchPoint) {
  const geometry::GearPairGeometry g(helical_pair());
  const DoubleInvolutePair di(g, stepped_rack());
  const double at = g.transverse_pressure_angle();
  EXPECT_NEAR(di.zone(ToothZone::tip).begin - di.zone(ToothZone::root).end, 2 * 0.3 * 3e-3 / std::sin(at), 1e-15);
  EXPECT_NEAR(0.5 * (di.zone(ToothZone::tip).begin + di.zone(ToothZone::root).end), g.path().C, 1e-15);
  EXPECT_NEAR(di.step(), 0.2 * g.transverse_module() * std::cos(at), 1e-18);
}

// The waist arc: the profile's arc points lie on the circle of radius ρ_g about D + ρ_g·n,
// the circle passes through C, and C lies on the root line.
TEST(DoubleInvolute, WaistArcIsTangentAtDAndPassesThroughC) {
  const auto pair = helical_pair();
  const auto rack = stepped_rack();
  const auto p = geometry::rack_profile(rack, pair, 16);
  const double a = pair.normal_pressure_angle;
  const double cx = p.D.x + p.waist_radius * std::cos(a), cy = p.D.y + p.waist_radius * std::sin(a);
  EXPECT_NEAR(std::hypot(p.C.x - cx, p.C.y - cy), p.waist_radius, 1e-14);
  EXPECT_NEAR(p.C.x, M_PI / 4 + rack.root_tangential_shift + rack.waist_root_depth * std::tan(a), 1e-15);
  int on_arc = 0;
  for (const auto& q : p.flank)
    if (q.y < p.D.y && q.y > p.C.y) {
      EXPECT_NEAR(std::hypot(q.x - cx, q.y - cy), p.waist_radius, 1e-14);
      ++on_arc;
    }
  EXPECT_EQ(on_arc, 15);
  // The flank descends monotonically from the tip to the root.
  for (std::size_t i = 1; i < p.flank.size(); ++i) EXPECT_LT(p.flank[i].y, p.flank[i - 1].y);
}

TEST(DoubleInvolute, BadRacksNameTheKey) {
  const geometry::GearPairGeometry g(helical_pair());
  auto error = [&](model::DoubleInvoluteRack r) {
    return testing_support::input_error_of([&] { DoubleInvolutePair(g, r); });
  };
  auto r = stepped_rack();
  r.root_tangential_shift = 0.2;  // thicker root than the tip is thinned: jams
  EXPECT_NE(error(r).find("double_involute.root_tangential_shift = 0.2"), std::string::npos) << error(r);
  r = stepped_rack();
  r.waist_root_depth = 0.1;  // drop 0.05 < normal step 0.188: the arc overhangs
  EXPECT_NE(error(r).find("double_involute.waist_root_depth = 0.1"), std::string::npos) << error(r);
  r = stepped_rack();
  r.waist_tip_depth = -0.1;
  EXPECT_NE(error(r).find("double_involute.waist_tip_depth"), std::string::npos) << error(r);
  r = {};
  r.waist_root_depth = 0.2;  // zero step with C below D
  EXPECT_NE(error(r).find("a zero step has no waist"), std::string::npos) << error(r);
  r = stepped_rack();
  r.tip_tangential_shift = 0.5;  // the tip line moved 0.5·m_n in: the pinion's tip is pointed
  r.root_tangential_shift = 0.0;
  r.waist_root_depth = 0.6;
  EXPECT_NE(error(r).find("double_involute.tip_tangential_shift = 0.5: gear 1 is pointed"), std::string::npos)
      << error(r);
  // The same rack on the spur pair: 1.04 pitches of zone with a lag cannot cover the period.
  auto spur = helical_pair();
  spur.helix_angle = 0.0;
  const geometry::GearPairGeometry gs(spur);
  const auto msg = testing_support::input_error_of([&] { DoubleInvolutePair(gs, stepped_rack()); });
  EXPECT_NE(msg.find("no tooth pair is in contact"), std::string::npos) << msg;
}

}  // namespace
