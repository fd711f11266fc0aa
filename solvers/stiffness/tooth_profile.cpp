#include "tooth_profile.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/involute.h"

namespace gearbench::stiffness {

ToothProfile::ToothProfile(const geometry::GearPairGeometry& pair, int gear, BeamStart start)
    : start_(start) {
  const auto& g = pair.pair();
  const auto i = static_cast<std::size_t>(gear);
  const auto& radii = pair.radii(gear);
  Rb_ = radii.base;
  Rf_ = radii.root;
  // Half tooth angle at the base circle (Tian 2004, with profile shift):
  //   α_2 = π/(2z) + 2x·tan α_n/z + inv α_t.
  alpha2_ = std::numbers::pi / (2.0 * g.teeth[i]) +
            2.0 * g.profile_shift[i] * std::tan(g.normal_pressure_angle) / g.teeth[i] +
            geometry::involute(pair.transverse_pressure_angle());
  xB_ = Rb_ * std::cos(alpha2_);
  hB_ = Rb_ * std::sin(alpha2_);
  reference_roll_ = std::tan(pair.transverse_pressure_angle());
  tip_ = involute_point(std::sqrt(radii.tip * radii.tip / (Rb_ * Rb_) - 1.0));

  alpha_start_ = -alpha2_;
  x0_ = xB_;
  if (start_ == BeamStart::base_circle) return;
  if (Rf_ >= Rb_) {
    // The beam starts on the involute at the root circle: r(α)² = R_b²[1 + (α + α_2)²].
    alpha_start_ = std::sqrt(Rf_ * Rf_ / (Rb_ * Rb_) - 1.0) - alpha2_;
    x0_ = involute_x(alpha_start_);
  } else if (start_ == BeamStart::improved) {
    // Arc centred at (x_B, h_B + ρ), tangent to the root circle (docs/stiffness-model.md).
    rho_ = (Rb_ * Rb_ - Rf_ * Rf_) / (2.0 * (Rf_ - hB_));
    x0_ = xB_ * Rf_ / (Rf_ + rho_);
  } else {
    x0_ = std::sqrt(Rf_ * Rf_ - hB_ * hB_);  // constant thickness h_B down to the root circle
  }
}

double ToothProfile::involute_x(double alpha) const {
  return Rb_ * ((alpha + alpha2_) * std::sin(alpha) + std::cos(alpha));
}

double ToothProfile::involute_h(double alpha) const {
  return Rb_ * ((alpha + alpha2_) * std::cos(alpha) - std::sin(alpha));
}

FlankPoint ToothProfile::involute_point(double roll_angle) const {
  const double alpha = roll_angle - alpha2_;
  return {alpha, involute_x(alpha), involute_h(alpha)};
}

// x(α) increases with α (dx/dα = R_b(α + α_2)cos α ≥ 0): Newton's method kept inside a
// shrinking bracket [lo, hi], bisecting whenever a step would leave it.
double ToothProfile::involute_alpha_at(double x) const {
  double lo = alpha_start_;
  double hi = tip_.alpha;
  double alpha = lo + (hi - lo) * std::clamp((x - involute_x(lo)) / (tip_.x - involute_x(lo)), 0.0, 1.0);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double f = involute_x(alpha) - x;
    if (f > 0.0) hi = alpha; else lo = alpha;
    const double slope = Rb_ * (alpha + alpha2_) * std::cos(alpha);
    double next = slope > 0.0 ? alpha - f / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - alpha) <= 1e-15 * std::max(1.0, std::abs(alpha)) || hi - lo < 1e-16) return next;
    alpha = next;
  }
  return alpha;
}

double ToothProfile::half_thickness(double x) const {
  if (x >= xB_ || start_ == BeamStart::base_circle || Rf_ >= Rb_)
    return involute_h(involute_alpha_at(x));
  if (start_ == BeamStart::straight) return hB_;
  const double dx = x - xB_;
  return hB_ + rho_ - std::sqrt(rho_ * rho_ - dx * dx);  // seed 003 eq. 1 (arc)
}

std::optional<double> ToothProfile::x_where_thickness(double value) const {
  // h(x) decreases monotonically from the beam start to the tip.
  double lo = x0_, hi = tip_.x;
  if (!(half_thickness(lo) > value && half_thickness(hi) < value)) return std::nullopt;
  for (int iteration = 0; iteration < 200 && hi - lo > 1e-15 * hi; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    (half_thickness(mid) > value ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace gearbench::stiffness
