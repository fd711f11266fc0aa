#include "double_involute_contact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "closed_form/involute_closed_form.h"
#include "model/gsl_status.h"

namespace gearbench::reference {

namespace {

constexpr double pi = std::numbers::pi;

struct Vec {
  double x = 0.0, y = 0.0;
};

double wrap(double angle) { return std::remainder(angle, 2.0 * pi); }

/// Brent (GSL) on [lo, hi] where f changes sign, to an interval of 1e-14 of the bracket.
double brent(const std::function<double(double)>& f, double lo, double hi) {
  model::gsl_use_status_codes();
  gsl_function g{[](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); },
                 const_cast<std::function<double(double)>*>(&f)};
  const std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  if (gsl_root_fsolver_set(solver.get(), &g, lo, hi) != GSL_SUCCESS)
    throw std::runtime_error("double-involute construction: no root bracket");
  const double tol = 1e-14 * (hi - lo);
  for (int i = 0; i < 200; ++i) {
    if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS)
      throw std::runtime_error("double-involute construction: Brent iteration failed");
    if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()), gsl_root_fsolver_x_upper(solver.get()), tol,
                               0.0) == GSL_SUCCESS)
      break;
  }
  return gsl_root_fsolver_root(solver.get());
}

/// The first sign change of f on [lo, hi] over n steps that is a zero crossing, not a jump
/// of an angle wrapped at ±π (both ends within ±π/2); Brent inside it. nullopt if none.
std::optional<double> first_root(const std::function<double(double)>& f, double lo, double hi, int n) {
  double a = lo, fa = f(lo);
  for (int i = 1; i <= n; ++i) {
    const double b = lo + (hi - lo) * i / n, fb = f(b);
    if (fa == 0.0) return a;
    if (fa * fb < 0.0 && std::abs(fa) < 0.5 * pi && std::abs(fb) < 0.5 * pi) return brent(f, a, b);
    a = b;
    fa = fb;
  }
  return fa == 0.0 ? std::optional<double>(a) : std::nullopt;
}

}  // namespace

DoubleInvoluteConstruction::DoubleInvoluteConstruction(const model::GearPair& pair,
                                                       const model::DoubleInvoluteRack& rack, int face_samples)
    : pair_(pair), rack_(rack), face_samples_(face_samples) {
  zero_step_ = rack.tip_tangential_shift + rack.root_tangential_shift == 0.0;
  const double beta = pair.helix_angle;
  mt_ = pair.normal_module / std::cos(beta);
  alpha_t_ = std::atan(std::tan(pair.normal_pressure_angle) / std::cos(beta));
  const auto closed = involute_closed_form(pair);
  alpha_w_ = closed.working_pressure_angle;
  a_ = closed.center_distance;
  line_length_ = a_ * std::sin(alpha_w_);
  const double depth_b = pair.dedendum_coef - pair.root_radius_coef * (1.0 - std::sin(pair.normal_pressure_angle));
  for (int i = 0; i < 2; ++i) {
    const auto k = static_cast<std::size_t>(i);
    r_[i] = 0.5 * pair.teeth[k] * mt_;
    rb_[i] = r_[i] * std::cos(alpha_t_);
    ra_[i] = pair.tip_diameter ? 0.5 * (*pair.tip_diameter)[k]
                               : r_[i] + pair.normal_module * (pair.addendum_coef + pair.profile_shift[k]);
    r_form_[i] = generated_radius(i, depth_b);
    r_waist_root_[i] = generated_radius(i, rack.waist_root_depth);
    r_waist_tip_[i] = generated_radius(i, rack.waist_tip_depth);
  }
  // Wheel phase: its tooth 0's tip involute through the point where the pinion's tooth 0
  // root involute meets the line of action (front face, no rotation).
  const Hit p0 = pinion_hit(0, false, 0.0, 0.0);
  if (!p0.found) throw std::runtime_error("double-involute construction: pinion flank misses the line of action");
  const double window = 2.0 * pi / pair.teeth[1];
  const auto phase = first_root(
      [&](double ph) {
        const Hit w = wheel_hit(0, true, 0.0, 0.0, ph);
        return w.found ? std::clamp((w.s - p0.s) / rb_[1], -1.0, 1.0) : 10.0;
      },
      -window, window, 64);
  if (!phase) throw std::runtime_error("double-involute construction: no wheel phase meets the pinion flank");
  wheel_phase_ = *phase;
  // Start of contact: the wheel tip circle on the line of action, then the pinion rotation
  // that brings tooth 0's root involute there.
  const Vec t1{-rb_[0] * std::sin(alpha_w_), rb_[0] * std::cos(alpha_w_)};
  const double s_a = brent(
      [&](double s) {
        return std::hypot(t1.x + s * std::cos(alpha_w_), t1.y + s * std::sin(alpha_w_) - a_) - ra_[1];
      },
      0.0, line_length_);
  const double pitch_angle = 2.0 * pi / pair.teeth[0];
  const auto angle = first_root(
      [&](double phi) {
        const Hit h = pinion_hit(0, false, phi, 0.0);
        return h.found ? std::clamp((h.s - s_a) / rb_[0], -1.0, 1.0) : 10.0;
      },
      -4.0 * pitch_angle, pitch_angle, 200);
  if (!angle) throw std::runtime_error("double-involute construction: tooth 0 never reaches the start of contact");
  engagement_angle_ = *angle;
}

// The rack line at `depth`·m_n below the datum (x·m_n outside the generating pitch line)
// touches the gear at the foot of the perpendicular from the generating pitch point P0 =
// (0, r) onto it; that foot lies on the generating line through P0 inclined at α_t, at the
// height (x − depth)·m_n above the pitch line.
double DoubleInvoluteConstruction::generated_radius(int gear, double depth) const {
  const double t = (pair_.profile_shift[static_cast<std::size_t>(gear)] - depth) * pair_.normal_module /
                   std::sin(alpha_t_);
  return std::hypot(t * std::cos(alpha_t_), r_[gear] + t * std::sin(alpha_t_));
}

// A flank is the clockwise side of a tooth centred at θ_c: at radius r it sits at
// θ_c − ψ − inv α_t + inv α_r, cos α_r = r_b/r, ψ the half-thickness angle at the
// reference circle (ISO 21771:2007 tooth thickness; the stepped rack's half thickness at
// the datum is π/4 + x·tan α_n − y_a* for the tip line and + y_d* for the root line).
// The pinion turns clockwise by `angle`, the wheel anticlockwise by angle·z1/z2; a slice at
// face position z is turned by z·tan β/r (opposite senses on the two gears).
DoubleInvoluteConstruction::Hit DoubleInvoluteConstruction::pinion_hit(int tooth, bool tip_line, double angle,
                                                                       double z) const {
  const double x = pair_.profile_shift[0];
  const double h = pi / 4 + x * std::tan(pair_.normal_pressure_angle) +
                   (tip_line ? -rack_.tip_tangential_shift : rack_.root_tangential_shift);
  const double psi = h * pair_.normal_module / (std::cos(pair_.helix_angle) * r_[0]);
  const double centre =
      0.5 * pi + 2.0 * pi * tooth / pair_.teeth[0] - angle + z * std::tan(pair_.helix_angle) / r_[0];
  const Vec t1{-rb_[0] * std::sin(alpha_w_), rb_[0] * std::cos(alpha_w_)};
  auto residual = [&](double s) {
    const Vec p{t1.x + s * std::cos(alpha_w_), t1.y + s * std::sin(alpha_w_)};
    const double r = std::hypot(p.x, p.y);
    const double ar = std::acos(std::min(1.0, rb_[0] / r));
    return wrap(std::atan2(p.y, p.x) - (centre - psi - (std::tan(alpha_t_) - alpha_t_) + std::tan(ar) - ar));
  };
  const auto s = first_root(residual, 1e-9 * line_length_, line_length_, 48);
  return s ? Hit{true, *s} : Hit{};
}

DoubleInvoluteConstruction::Hit DoubleInvoluteConstruction::wheel_hit(int tooth, bool tip_line, double angle,
                                                                      double z, double phase) const {
  const double x = pair_.profile_shift[1];
  const double h = pi / 4 + x * std::tan(pair_.normal_pressure_angle) +
                   (tip_line ? -rack_.tip_tangential_shift : rack_.root_tangential_shift);
  const double psi = h * pair_.normal_module / (std::cos(pair_.helix_angle) * r_[1]);
  const double centre = -0.5 * pi + phase + 2.0 * pi * tooth / pair_.teeth[1] +
                        angle * pair_.teeth[0] / pair_.teeth[1] - z * std::tan(pair_.helix_angle) / r_[1];
  const Vec t1{-rb_[0] * std::sin(alpha_w_), rb_[0] * std::cos(alpha_w_)};
  auto residual = [&](double s) {
    const Vec q{t1.x + s * std::cos(alpha_w_), t1.y + s * std::sin(alpha_w_) - a_};
    const double r = std::hypot(q.x, q.y);
    const double ar = std::acos(std::min(1.0, rb_[1] / r));
    return wrap(std::atan2(q.y, q.x) - (centre - psi - (std::tan(alpha_t_) - alpha_t_) + std::tan(ar) - ar));
  };
  const auto s = first_root(residual, 0.0, line_length_ * (1.0 - 1e-9), 48);
  return s ? Hit{true, *s} : Hit{};
}

// Pinion tooth j meets wheel tooth −j (a pitch of rotation brings tooth j + 1 of the pinion
// and tooth −(j + 1) of the wheel to the places of teeth j and −j).
bool DoubleInvoluteConstruction::in_contact(int tooth, bool tip_zone, double angle, double z,
                                            double* mismatch) const {
  const Hit p = pinion_hit(tooth, tip_zone, angle, z);
  if (!p.found) return false;
  const Vec t1{-rb_[0] * std::sin(alpha_w_), rb_[0] * std::cos(alpha_w_)};
  const Vec point{t1.x + p.s * std::cos(alpha_w_), t1.y + p.s * std::sin(alpha_w_)};
  const double r1 = std::hypot(point.x, point.y), r2 = std::hypot(point.x, point.y - a_);
  bool active = false;
  if (zero_step_) {
    const double pitch_radius = rb_[0] / std::cos(alpha_w_);
    active = r1 >= r_form_[0] && r1 <= ra_[0] && r2 >= r_form_[1] && r2 <= ra_[1] &&
             (tip_zone ? r1 > pitch_radius : r1 <= pitch_radius);
  } else if (tip_zone) {
    active = r1 >= r_waist_tip_[0] && r1 <= ra_[0] && r2 >= r_form_[1] && r2 <= r_waist_root_[1];
  } else {
    active = r1 >= r_form_[0] && r1 <= r_waist_root_[0] && r2 >= r_waist_tip_[1] && r2 <= ra_[1];
  }
  if (!active) return false;
  const Hit w = wheel_hit(-tooth, !tip_zone, angle, z, wheel_phase_);
  *mismatch = std::max(*mismatch, w.found ? std::abs(w.s - p.s) : 1.0);
  return true;
}

ConstructedContact DoubleInvoluteConstruction::at(double angle) const {
  ConstructedContact out;
  const double b = pair_.face_width;
  const int n = pair_.helix_angle == 0.0 ? 1 : face_samples_;
  const Vec t1{-rb_[0] * std::sin(alpha_w_), rb_[0] * std::cos(alpha_w_)};
  auto point3 = [&](int tooth, bool tip, double z) {
    const double s = pinion_hit(tooth, tip, angle, z).s;
    return std::array<double, 3>{t1.x + s * std::cos(alpha_w_), t1.y + s * std::sin(alpha_w_), z};
  };
  for (int tooth = -pair_.teeth[0] / 2; tooth <= pair_.teeth[0] / 2; ++tooth) {
    bool near = false;  // teeth whose flanks miss the line of action on both faces and mid-face
    for (const double z : {0.0, 0.5 * b, b})
      for (const bool tip : {false, true}) near = near || pinion_hit(tooth, tip, angle, z).found;
    if (!near) continue;
    for (const bool tip : {false, true}) {
      auto contact = [&](double z) { return in_contact(tooth, tip, angle, z, &out.conjugacy_error); };
      bool inside = contact(0.0);
      double begin = 0.0;
      for (int i = 1; i <= n; ++i) {
        double lo = b * (i - 1) / n, hi = b * i / n;
        const bool now = contact(hi);
        if (now != inside) {  // bisect the change of the indicator
          for (int k = 0; k < 60; ++k) {
            const double mid = 0.5 * (lo + hi);
            (contact(mid) == inside ? lo : hi) = mid;
          }
        }
        const double edge = now != inside ? (inside ? lo : hi) : hi;
        if (now != inside && !inside) begin = edge;
        if ((now != inside && inside) || (i == n && now)) {
          const double end = now != inside && inside ? edge : b;
          const auto p = point3(tooth, tip, begin), q = point3(tooth, tip, end);
          const double length = pair_.helix_angle == 0.0
                                    ? b
                                    : std::sqrt(std::pow(q[0] - p[0], 2) + std::pow(q[1] - p[1], 2) +
                                                std::pow(q[2] - p[2], 2));
          out.pieces.push_back({tooth, tip, begin, end, length});
          out.total_length += length;
        }
        inside = now;
      }
    }
  }
  return out;
}

}  // namespace gearbench::reference
