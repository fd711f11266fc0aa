#include "mesh_loss.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numeric>

#include "model/errors.h"

namespace gearbench::efficiency {

void MeshLossOptions::validate() const {
  if (positions < 2 || positions > 1000000)
    throw InputError(fmt::format("positions = {}: allowed range is [2, 1000000]", positions));
  if (points_per_line < 1 || points_per_line > 100000)
    throw InputError(fmt::format("points_per_line = {}: allowed range is [1, 100000]", points_per_line));
  if (!(friction_coefficient >= 0.0 && friction_coefficient <= 0.5))
    throw InputError(fmt::format("friction.mu = {}: allowed range is [0, 0.5]", friction_coefficient));
}

MeshLoss::MeshLoss(const geometry::GearPairGeometry& geometry, const model::OperatingPoint& operating,
                   MeshLossOptions options)
    : geometry_(geometry), operating_(operating), options_((options.validate(), std::move(options))),
      sharing_(geometry::make_load_sharing(options_.load_sharing, "load_sharing")) {
  // Helical pairs carry a uniform load per unit contact-line length; a transverse sharing
  // rule has no meaning there.
  if (geometry_.base_helix_angle() > 0.0 && options_.load_sharing != "equal")
    throw InputError(fmt::format("load_sharing = \"{}\": helical pairs use a uniform load per unit "
                                 "contact-line length; allowed is \"equal\"", options_.load_sharing));
}

double MeshLoss::sliding_speed(double s) const {
  return std::abs(geometry_.kinematics(s, operating_.pinion_speed).sliding);
}

// Spur: each pair in contact carries its share of the normal force F_bn = T1/r_b1.
double MeshLoss::spur_loss(double s0) const {
  const double normal_force = operating_.pinion_torque / geometry_.radii(0).base;
  double loss = 0.0;
  for (const double s : geometry_.positions_in_contact(s0))
    loss += options_.friction_coefficient * sharing_->share(geometry_, s) * normal_force * sliding_speed(s);
  return loss;
}

// Helical: the normal force F_bn = T1/(r_b1·cos β_b) spreads uniformly over the total
// contact-line length L(s0); the line through s_k on the front face sits at s_k − y·tan β_b
// on face position y, and its element dl = dy/cos β_b carries μ·(F_bn/L)·|V_s(s)|·dl.
double MeshLoss::helical_loss(double s0) const {
  const auto& p = geometry_.path();
  const double pb = geometry_.base_pitch_transverse();
  const double tan_bb = std::tan(geometry_.base_helix_angle());
  const double cos_bb = std::cos(geometry_.base_helix_angle());
  const double b = geometry_.pair().face_width;
  const double halves = geometry_.pair().herringbone ? 2.0 : 1.0;
  const double load_per_length =
      operating_.pinion_torque / (geometry_.radii(0).base * cos_bb) / geometry_.contact_line_length(s0);
  const int n = options_.points_per_line;
  double loss = 0.0;
  const double shift = b * tan_bb;
  for (double front = s0 - std::floor((s0 - p.A) / pb) * pb; front <= p.E + shift; front += pb) {
    // The part of this line inside A..E: face positions y with A ≤ front − y·tan β_b ≤ E.
    const double y_lo = std::max(0.0, (front - p.E) / tan_bb);
    const double y_hi = std::min(b, (front - p.A) / tan_bb);
    if (y_hi <= y_lo) continue;
    const double dy = (y_hi - y_lo) / n;
    for (int k = 0; k < n; ++k) {
      const double y = y_lo + (k + 0.5) * dy;
      loss += options_.friction_coefficient * load_per_length * sliding_speed(front - y * tan_bb) * dy / cos_bb;
    }
  }
  return halves * loss;
}

// The spur loss jumps where a pair enters or leaves a zone and bends at the pitch point; in
// between it is a polynomial of degree ≤ 2 in the mesh position (linear sliding speed times
// a linear ISO share). Two-point Gauss–Legendre on every piece makes the mean exact.
double MeshLoss::spur_mean_loss() const {
  const auto& p = geometry_.path();
  const double pb = geometry_.base_pitch_transverse();
  std::vector<double> breaks{p.A, p.A + pb};
  for (const double event : {p.B, p.C, p.D, p.E}) {
    const double phase = p.A + std::fmod(event - p.A, pb);
    if (phase > p.A && phase < p.A + pb) breaks.push_back(phase);
  }
  std::sort(breaks.begin(), breaks.end());
  const double g = 0.5 / std::sqrt(3.0);
  double integral = 0.0;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double a = breaks[k], b = breaks[k + 1], mid = 0.5 * (a + b), half = b - a;
    integral += 0.5 * half * (sliding_loss(mid - g * half) + sliding_loss(mid + g * half));
  }
  return integral / pb;
}

double MeshLoss::sliding_loss(double s0) const {
  return geometry_.base_helix_angle() > 0.0 ? helical_loss(s0) : spur_loss(s0);
}

MeshLossResult MeshLoss::solve() const {
  MeshLossResult r;
  r.input_power = operating_.pinion_torque * operating_.pinion_speed;
  const double pb = geometry_.base_pitch_transverse();
  // Midpoints of the mesh period: every piece of the piecewise-smooth loss gets its share.
  for (int i = 0; i < options_.positions; ++i) {
    const double s0 = geometry_.path().A + pb * (i + 0.5) / options_.positions;
    const double loss = sliding_loss(s0);
    r.mesh_position.push_back((s0 - geometry_.path().A) / geometry_.radii(0).base);
    r.sliding_loss.push_back(loss);
    r.efficiency.push_back(1.0 - loss / r.input_power);
  }
  r.sliding_loss_mean = geometry_.base_helix_angle() > 0.0
                            ? std::accumulate(r.sliding_loss.begin(), r.sliding_loss.end(), 0.0) / options_.positions
                            : spur_mean_loss();
  r.efficiency_mean = 1.0 - r.sliding_loss_mean / r.input_power;
  const auto [lo, hi] = std::minmax_element(r.efficiency.begin(), r.efficiency.end());
  r.efficiency_min = *lo;
  r.efficiency_max = *hi;
  r.friction_coefficient_mean = options_.friction_coefficient;
  r.loss_factor_numeric = options_.friction_coefficient > 0.0
                              ? r.sliding_loss_mean / (options_.friction_coefficient * r.input_power) : 0.0;
  return r;
}

}  // namespace gearbench::efficiency
