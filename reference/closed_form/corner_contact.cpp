#include "corner_contact.h"

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
}  // namespace

CornerContact corner_contact(const model::GearPair& pair, double pinion_speed, double deflection) {
  if (!(pinion_speed > 0.0)) throw std::invalid_argument("corner_contact: pinion speed must be > 0");
  if (!(deflection > 0.0)) throw std::invalid_argument("corner_contact: deflection must be > 0");
  const InvoluteClosedForm form = involute_closed_form(pair);
  const double mt = pair.normal_module / std::cos(pair.helix_angle);
  const double rb1 = 0.5 * pair.teeth[0] * mt * std::cos(form.transverse_pressure_angle);
  const double rb2 = 0.5 * pair.teeth[1] * mt * std::cos(form.transverse_pressure_angle);
  const double d2 = pair.teeth[1] * mt;
  const double ra2 = pair.tip_diameter ? 0.5 * (*pair.tip_diameter)[1]
                                       : 0.5 * d2 + pair.normal_module * (pair.addendum_coef + pair.profile_shift[1]);
  const double aw = form.working_pressure_angle;
  // Pinion centre at the origin turning counter-clockwise, wheel centre at (a, 0) turning
  // clockwise; the line of action leaves T1 = r_b1(cos α_w, −sin α_w) along n = (sin α_w, cos α_w).
  const Point T1{rb1 * std::cos(aw), -rb1 * std::sin(aw)};
  const double rho_1A = form.line_of_action_length - std::sqrt(ra2 * ra2 - rb2 * rb2);
  const Point A{T1.x + rho_1A * std::sin(aw), T1.y + rho_1A * std::cos(aw)};
  const Point O2{form.center_distance, 0.0};
  const double w1 = pinion_speed, w2 = pinion_speed * rb1 / rb2;
  auto theta_s = [rb1](Point X) {
    const double alpha = std::acos(rb1 / std::hypot(X.x, X.y));
    return std::atan2(X.y, X.x) + std::tan(alpha) - alpha;
  };
  const double Theta = theta_s(A);
  // Gap at time τ from the instant the corner is at A (τ < 0: before), in the pinion's frame.
  auto gap = [&](double tau) {
    const Point c = rotate({A.x - O2.x, A.y - O2.y}, -w2 * tau);
    return rb1 * (theta_s(rotate({c.x + O2.x, c.y + O2.y}, -w1 * tau)) - Theta);
  };
  double lo = -2.0 * M_PI / (pair.teeth[0] * w1), hi = 0.0;  // one mesh cycle before A
  if (!(gap(lo) > deflection)) throw std::runtime_error("corner_contact: the gap does not reach the deflection");
  for (int i = 0; i < 200 && hi - lo > 1e-15 * (-lo); ++i) {
    const double mid = 0.5 * (lo + hi);
    (gap(mid) > deflection ? lo : hi) = mid;
  }
  const double tc = 0.5 * (lo + hi), h = 1e-4 * (-tc);
  return {-tc, -(gap(tc + h) - gap(tc - h)) / (2.0 * h)};  // central difference: O(h²) ~ 1e-8 relative
}

}  // namespace gearbench::reference
