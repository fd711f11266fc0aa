#include "tooth_profile.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/involute.h"

namespace gearbench::stiffness {

ToothProfile::ToothProfile(const geometry::GearPairGeometry& pair, int gear, ToothModel model)
    : model_(model) {
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
  const bool improved = model_.start == BeamStart::improved;
  if (improved && model_.fillet == Fillet::trochoid) {
    build_trochoid(pair, gear);
  } else if (model_.start != BeamStart::base_circle && Rf_ >= Rb_) {
    // The beam starts on the involute at the root circle: r(α)² = R_b²[1 + (α + α_2)²].
    alpha_start_ = std::sqrt(Rf_ * Rf_ / (Rb_ * Rb_) - 1.0) - alpha2_;
  }
  tabulate_involute();
  fillet_end_x_ = involute_x(alpha_start_);
  if (trochoid_ || model_.start == BeamStart::base_circle) return;
  if (Rf_ >= Rb_)
    x0_ = fillet_end_x_;
  else if (improved)
    build_circular_arc(pair, gear);
  else
    x0_ = std::sqrt(Rf_ * Rf_ - hB_ * hB_);  // constant thickness h_B down to the root circle
}

// The generated fillet runs from the root circle to the form circle, where the involute
// starts (docs/stiffness-model.md, "The generated fillet"); R_f against R_b does not matter.
void ToothProfile::build_trochoid(const geometry::GearPairGeometry& pair, int gear) {
  trochoid_.emplace(pair, gear);
  x0_ = trochoid_->root_point().x;
  const auto form = trochoid_->form_point();
  const double form_radius = std::hypot(form.x, form.h);
  alpha_start_ = std::sqrt(std::max(form_radius * form_radius / (Rb_ * Rb_) - 1.0, 0.0)) - alpha2_;
}

// Arc centred at (x_B, h_B + ρ), tangent to the root circle (docs/stiffness-model.md).
void ToothProfile::build_circular_arc(const geometry::GearPairGeometry& pair, int gear) {
  rho_ = (Rb_ * Rb_ - Rf_ * Rf_) / (2.0 * (Rf_ - hB_));
  x0_ = xB_ * Rf_ / (Rf_ + rho_);
  // The fillets of neighbouring teeth meet on the tooth-space centre line (polar angle
  // π/z): if the arc reaches past it before touching the root circle, the beam starts
  // where it crosses that line (the polar angle falls monotonically from x_0 to x_B).
  const double half_pitch_angle = std::numbers::pi / pair.pair().teeth[static_cast<std::size_t>(gear)];
  if (std::atan2(half_thickness(x0_), x0_) > half_pitch_angle) {
    double lo = x0_, hi = xB_;
    for (int iteration = 0; iteration < 200 && hi - lo > 1e-15 * xB_; ++iteration) {
      const double mid = 0.5 * (lo + hi);
      (std::atan2(half_thickness(mid), mid) > half_pitch_angle ? lo : hi) = mid;
    }
    x0_ = hi;
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

void ToothProfile::tabulate_involute() {
  constexpr int intervals = 256;
  table_x0_ = involute_x(alpha_start_);
  table_dx_ = (tip_.x - table_x0_) / intervals;
  alpha_table_.assign(intervals + 1, 0.0);
  alpha_table_.front() = alpha_start_;
  alpha_table_.back() = tip_.alpha;
  // x(α) is monotone: bisection on α fills the table once per tooth.
  for (int k = 1; k < intervals; ++k) {
    const double target = table_x0_ + k * table_dx_;
    double lo = alpha_table_[static_cast<std::size_t>(k - 1)], hi = tip_.alpha;
    for (int iteration = 0; iteration < 200 && hi - lo > 1e-15; ++iteration) {
      const double mid = 0.5 * (lo + hi);
      (involute_x(mid) < target ? lo : hi) = mid;
    }
    alpha_table_[static_cast<std::size_t>(k)] = 0.5 * (lo + hi);
  }
}

// x(α) increases with α (dx/dα = R_b(α + α_2)cos α ≥ 0): Newton's method kept inside the
// table's bracket [lo, hi] and started from linear interpolation in it, bisecting whenever
// a step would leave the bracket.
double ToothProfile::involute_alpha_at(double x) const {
  const auto last = static_cast<long>(alpha_table_.size()) - 2;
  const long k = std::clamp(static_cast<long>(std::floor((x - table_x0_) / table_dx_)), 0L, last);
  double lo = alpha_table_[static_cast<std::size_t>(k)];
  double hi = alpha_table_[static_cast<std::size_t>(k + 1)];
  const double fraction = std::clamp((x - table_x0_ - static_cast<double>(k) * table_dx_) / table_dx_, 0.0, 1.0);
  double alpha = lo + (hi - lo) * fraction;
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
  if (x >= fillet_end_x_ || model_.start == BeamStart::base_circle) return involute_h(involute_alpha_at(x));
  if (trochoid_) return trochoid_->half_thickness(x);
  if (model_.start == BeamStart::straight) return hB_;
  const double dx = x - xB_;
  return hB_ + rho_ - std::sqrt(rho_ * rho_ - dx * dx);  // seed 003 eq. 1 (arc)
}

// h(x) is smooth on each piece and has few extrema: a scan at 512 points brackets every
// crossing that matters to a quadrature break point, and bisection pins each one down.
std::vector<double> ToothProfile::x_where_thickness(double value) const {
  constexpr int samples = 512;
  std::vector<double> crossings;
  const auto above = [&](double x) { return half_thickness(x) > value; };
  double a = x0_;
  bool above_a = above(a);
  for (int k = 1; k <= samples; ++k) {
    const double b = x0_ + (tip_.x - x0_) * k / samples;
    const bool above_b = above(b);
    if (above_a != above_b) {
      double lo = a, hi = b;
      for (int iteration = 0; iteration < 200 && hi - lo > 1e-15 * hi; ++iteration) {
        const double mid = 0.5 * (lo + hi);
        (above(mid) == above_a ? lo : hi) = mid;
      }
      crossings.push_back(0.5 * (lo + hi));
    }
    a = b;
    above_a = above_b;
  }
  return crossings;
}

}  // namespace gearbench::stiffness
