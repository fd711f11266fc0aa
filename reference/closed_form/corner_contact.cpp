#include "corner_contact.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "involute_closed_form.h"

namespace gearbench::reference {

namespace {
struct Point {
  double x, y;
};
Point rotate(Point p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

// The gap between the entering wheel corner and the pinion flank at time τ from the instant the
// corner would be at A (τ < 0: before), and the one-cycle bracket for the contact under δ.
struct CornerGap {
  CornerGap(const model::GearPair& pair, double pinion_speed) : pinion_speed_(pinion_speed) {
    if (!(pinion_speed > 0.0)) throw std::invalid_argument("corner_contact: pinion speed must be > 0");
    const InvoluteClosedForm form = involute_closed_form(pair);
    const double mt = pair.normal_module / std::cos(pair.helix_angle);
    rb1_ = 0.5 * pair.teeth[0] * mt * std::cos(form.transverse_pressure_angle);
    const double rb2 = 0.5 * pair.teeth[1] * mt * std::cos(form.transverse_pressure_angle);
    const double d2 = pair.teeth[1] * mt;
    const double ra2 = pair.tip_diameter ? 0.5 * (*pair.tip_diameter)[1]
                                         : 0.5 * d2 + pair.normal_module * (pair.addendum_coef + pair.profile_shift[1]);
    const double aw = form.working_pressure_angle;
    // Pinion centre at the origin turning counter-clockwise, wheel centre at (a, 0) turning
    // clockwise; the line of action leaves T1 = r_b1(cos α_w, −sin α_w) along n = (sin α_w, cos α_w).
    const Point T1{rb1_ * std::cos(aw), -rb1_ * std::sin(aw)};
    const double rho_1A = form.line_of_action_length - std::sqrt(ra2 * ra2 - rb2 * rb2);
    A_ = {T1.x + rho_1A * std::sin(aw), T1.y + rho_1A * std::cos(aw)};
    O2_ = {form.center_distance, 0.0};
    w2_ = pinion_speed * rb1_ / rb2;
    cycle_ = 2.0 * M_PI / (pair.teeth[0] * pinion_speed);
    Theta_ = theta_s(A_);
  }
  [[nodiscard]] double theta_s(Point X) const {
    const double alpha = std::acos(rb1_ / std::hypot(X.x, X.y));
    return std::atan2(X.y, X.x) + std::tan(alpha) - alpha;
  }
  [[nodiscard]] double operator()(double tau) const {  // in the pinion's frame
    const Point c = rotate({A_.x - O2_.x, A_.y - O2_.y}, -w2_ * tau);
    return rb1_ * (theta_s(rotate({c.x + O2_.x, c.y + O2_.y}, -pinion_speed_ * tau)) - Theta_);
  }
  /// τ < 0 where the gap equals δ (bisection over one mesh cycle before A).
  [[nodiscard]] double contact_time(double deflection) const {
    if (!(deflection > 0.0)) throw std::invalid_argument("corner_contact: deflection must be > 0");
    double lo = -cycle_, hi = 0.0;
    if (!((*this)(lo) > deflection)) throw std::runtime_error("corner_contact: the gap does not reach the deflection");
    for (int i = 0; i < 200 && hi - lo > 1e-15 * (-lo); ++i) {
      const double mid = 0.5 * (lo + hi);
      ((*this)(mid) > deflection ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }

 private:
  double pinion_speed_, rb1_ = 0, w2_ = 0, cycle_ = 0, Theta_ = 0;
  Point A_{}, O2_{};
};
}  // namespace

CornerContact corner_contact(const model::GearPair& pair, double pinion_speed, double deflection) {
  const CornerGap gap(pair, pinion_speed);
  const double tc = gap.contact_time(deflection), h = 1e-4 * (-tc);
  return {-tc, -(gap(tc + h) - gap(tc - h)) / (2.0 * h)};  // central difference: O(h²) ~ 1e-8 relative
}

// m·ẍ = k·max(0, p − x), p(τ) = δ − gap(τ) before A and δ from A on (conjugate action), x(τ_c) = ẋ(τ_c) = 0;
// classical RK4 at a step of 1/4000 of the spring's period (or of the approach, if shorter), to two periods
// after A: the contact has long opened by then (nothing pulls the mass back).
double entering_pair_peak_force(const model::GearPair& pair, double pinion_speed, double deflection, double mass,
                                double stiffness) {
  if (!(mass > 0.0 && stiffness > 0.0)) throw std::invalid_argument("entering_pair_peak_force: mass and stiffness > 0");
  const CornerGap gap(pair, pinion_speed);
  const double tc = gap.contact_time(deflection);
  const double period = 2.0 * M_PI * std::sqrt(mass / stiffness);
  const auto steps = static_cast<long>(std::ceil((2.0 * period - tc) / std::min(period / 4000.0, -tc / 4000.0)));
  const double h = (2.0 * period - tc) / static_cast<double>(steps);
  auto force = [&](double tau, double x) {
    return stiffness * std::max(0.0, deflection - (tau < 0.0 ? gap(tau) : 0.0) - x);
  };
  double x = 0.0, v = 0.0, peak = 0.0;
  for (long i = 0; i < steps; ++i) {
    const double t = tc + h * static_cast<double>(i);
    const double a1 = force(t, x) / mass, v1 = v;
    const double a2 = force(t + 0.5 * h, x + 0.5 * h * v1) / mass, v2 = v + 0.5 * h * a1;
    const double a3 = force(t + 0.5 * h, x + 0.5 * h * v2) / mass, v3 = v + 0.5 * h * a2;
    const double a4 = force(t + h, x + h * v3) / mass, v4 = v + h * a3;
    x += h / 6.0 * (v1 + 2.0 * v2 + 2.0 * v3 + v4);
    v += h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
    peak = std::max(peak, force(t + h, x));
  }
  return peak;
}

}  // namespace gearbench::reference
