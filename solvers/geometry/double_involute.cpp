#include "double_involute.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <string>

#include "involute.h"
#include "model/errors.h"

namespace gearbench::geometry {

namespace {

constexpr double pi = std::numbers::pi;
const std::string key = "double_involute.";

/// Normal distance of the tip and root lines in units of m_n.
double normal_step(const model::DoubleInvoluteRack& r, double alpha_n) {
  return (r.tip_tangential_shift + r.root_tangential_shift) * std::cos(alpha_n);
}

/// Depth of B below the datum line, where the root arc meets the root line (as for the
/// ISO 53 rack: h_fP* − ρ_fP*(1 − sin α_n)) [m_n].
double root_line_end_depth(const model::GearPair& pair) {
  return pair.dedendum_coef - pair.root_radius_coef * (1.0 - std::sin(pair.normal_pressure_angle));
}

}  // namespace

double waist_radius(const model::DoubleInvoluteRack& rack, double pressure_angle) {
  const double delta = normal_step(rack, pressure_angle);
  if (delta == 0.0) return 0.0;
  const double drop = rack.waist_root_depth - rack.waist_tip_depth;
  const double w = (drop + delta * std::sin(pressure_angle)) / std::cos(pressure_angle);
  return (w * w + delta * delta) / (2.0 * delta);
}

RackProfile rack_profile(const model::DoubleInvoluteRack& rack, const model::GearPair& pair, int points_per_arc) {
  const double alpha = pair.normal_pressure_angle;
  const double t = std::tan(alpha);
  const RackProfile::Point n{std::cos(alpha), std::sin(alpha)};        // outward normal of the right flank
  const RackProfile::Point down{std::sin(alpha), -std::cos(alpha)};    // along the flank, downwards
  auto tip_line = [&](double y) { return RackProfile::Point{pi / 4 - rack.tip_tangential_shift - y * t, y}; };
  auto root_line = [&](double y) { return RackProfile::Point{pi / 4 + rack.root_tangential_shift - y * t, y}; };

  RackProfile p;
  p.waist_radius = waist_radius(rack, alpha);
  p.root_radius = pair.root_radius_coef;
  p.E = tip_line(pair.addendum_coef);
  p.D = tip_line(-rack.waist_tip_depth);
  p.C = root_line(-rack.waist_root_depth);
  p.B = root_line(-root_line_end_depth(pair));
  const RackProfile::Point fillet{p.B.x + p.root_radius * n.x, p.B.y + p.root_radius * n.y};
  p.A = {fillet.x, fillet.y - p.root_radius};

  p.flank = {p.E, p.D};
  if (p.waist_radius > 0.0) {
    // The arc turns from D (tangent to DE) about O_g = D + ρ_g·n until it meets CB.
    const double rho = p.waist_radius;
    const double phi_c = std::acos(1.0 - normal_step(rack, alpha) / rho);
    const RackProfile::Point centre{p.D.x + rho * n.x, p.D.y + rho * n.y};
    for (int i = 1; i < points_per_arc; ++i) {
      const double phi = phi_c * i / points_per_arc;
      p.flank.push_back({centre.x - rho * std::cos(phi) * n.x + rho * std::sin(phi) * down.x,
                         centre.y - rho * std::cos(phi) * n.y + rho * std::sin(phi) * down.y});
    }
  }
  p.flank.push_back(p.C);
  p.flank.push_back(p.B);
  // Root arc about O_f = B + ρ_f·n from the direction −n (at B) to straight down (at A).
  for (int i = 1; i <= points_per_arc; ++i) {
    const double theta = pi + alpha + (0.5 * pi - alpha) * i / points_per_arc;
    p.flank.push_back({fillet.x + p.root_radius * std::cos(theta), fillet.y + p.root_radius * std::sin(theta)});
  }
  return p;
}

DoubleInvolutePair::DoubleInvolutePair(const GearPairGeometry& geometry, const model::DoubleInvoluteRack& rack)
    : geometry_(geometry), rack_(rack) {
  if (geometry_.pair().herringbone)
    throw InputError("gear_pair.herringbone: the double-involute model covers spur and single helical pairs");
  check_profile();
  check_tip_thickness();
  build_zones();
  sweep_ = geometry_.pair().face_width * std::tan(geometry_.base_helix_angle());
  check_continuous_contact();
}

void DoubleInvolutePair::check_profile() const {
  const auto& r = rack_;
  const double alpha = geometry_.pair().normal_pressure_angle;
  if (!(r.tip_tangential_shift >= 0.0 && r.tip_tangential_shift <= 0.5))
    throw InputError(fmt::format("{}tip_tangential_shift = {}: allowed range is [0, 0.5]", key, r.tip_tangential_shift));
  if (!(r.root_tangential_shift >= 0.0 && r.root_tangential_shift <= r.tip_tangential_shift))
    throw InputError(fmt::format(
        "{}root_tangential_shift = {}: allowed range is [0, tip_tangential_shift = {}] (a thicker root than "
        "the tip is thinned jams the coast flanks)",
        key, r.root_tangential_shift, r.tip_tangential_shift));
  const double b_depth = root_line_end_depth(geometry_.pair());
  if (!(r.waist_tip_depth >= 0.0 && r.waist_tip_depth < b_depth))
    throw InputError(fmt::format("{}waist_tip_depth = {}: allowed range is [0, {:.4f}) (D below the datum line, "
                                 "above B)", key, r.waist_tip_depth, b_depth));
  if (normal_step(r, alpha) == 0.0) {
    if (r.waist_root_depth != r.waist_tip_depth)
      throw InputError(fmt::format("{}waist_root_depth = {}: a zero step has no waist; must equal waist_tip_depth "
                                   "= {}", key, r.waist_root_depth, r.waist_tip_depth));
    return;
  }
  // The arc descends from D to C only while it has turned by less than 90° − α_n; that
  // holds exactly when the drop l_d* − l_a* is at least the normal step δ_n (at equality
  // the arc reaches C horizontally), which the closed form of waist_radius gives.
  const double min_depth = r.waist_tip_depth + normal_step(r, alpha);
  if (!(r.waist_root_depth >= min_depth * (1.0 - 1e-12) && r.waist_root_depth < b_depth))
    throw InputError(fmt::format(
        "{}waist_root_depth = {}: allowed range is [{:.4f}, {:.4f}) (at least waist_tip_depth plus the normal "
        "step (y_a* + y_d*)·cos α_n, or the waist arc overhangs; above B)",
        key, r.waist_root_depth, min_depth, b_depth));
}

// The tip line is y_a*·m_n thinner on each flank: the tooth thickness at the reference
// circle is m_n(π/2 + 2x·tan α_n − 2y_a*) and at the tip (ISO 21771:2007, as
// GearPairGeometry::tip_tooth_thickness) s_a = d_a·[(π/2 + 2x·tan α_n − 2y_a*)/z + inv α_t − inv α_a].
void DoubleInvolutePair::check_tip_thickness() const {
  const auto& pair = geometry_.pair();
  for (int i = 0; i < 2; ++i) {
    const auto& radii = geometry_.radii(i);
    const double half_angle =
        (0.5 * pi + 2.0 * pair.profile_shift[static_cast<std::size_t>(i)] * std::tan(pair.normal_pressure_angle) -
         2.0 * rack_.tip_tangential_shift) / pair.teeth[static_cast<std::size_t>(i)] +
        involute(geometry_.transverse_pressure_angle()) - involute(std::acos(radii.base / radii.tip));
    if (half_angle <= 0.0)
      throw InputError(fmt::format(
          "{}tip_tangential_shift = {}: gear {} is pointed (tip thickness {:.4f} mm); reduce the shift or the tip "
          "diameter", key, rack_.tip_tangential_shift, i + 1, 2e3 * radii.tip * half_angle));
  }
}

void DoubleInvolutePair::build_zones() {
  const auto& pair = geometry_.pair();
  const auto& path = geometry_.path();
  const double mn = pair.normal_module;
  const double alpha_t = geometry_.transverse_pressure_angle();
  step_ = (rack_.tip_tangential_shift + rack_.root_tangential_shift) * geometry_.transverse_module() *
          std::cos(alpha_t);
  if (step_ == 0.0) {
    root_ = {path.A, path.C};
    tip_ = {path.C, path.E};
    return;
  }
  // ρ_i(y): where the involute generated by rack height y·m_n touches the line of action.
  auto rho = [&](int gear, double y) {
    const auto i = static_cast<std::size_t>(gear);
    return geometry_.radii(gear).reference * std::sin(alpha_t) + (y + pair.profile_shift[i]) * mn / std::sin(alpha_t);
  };
  const double la = rack_.waist_tip_depth, ld = rack_.waist_root_depth;
  root_ = {path.A, std::min(rho(0, -ld), path.T2 - rho(1, -la))};
  tip_ = {std::max(rho(0, -la), path.T2 - rho(1, -ld)), path.E};
  if (root_.length() <= 0.0 || tip_.length() <= 0.0)
    throw InputError(fmt::format(
        "{}waist_root_depth = {}: the {} zone is empty (root zone {:.4f}…{:.4f} mm, tip zone {:.4f}…{:.4f} mm on "
        "the line of action); reduce the waist depths or raise the tip diameters",
        key, ld, root_.length() <= 0.0 ? "root" : "tip", root_.begin * 1e3, root_.end * 1e3, tip_.begin * 1e3,
        tip_.end * 1e3));
}

double DoubleInvolutePair::zone_contact_ratio(ToothZone z) const {
  return zone(z).length() / geometry_.base_pitch_transverse();
}

double DoubleInvolutePair::mesh_period(double pinion_speed) const {
  return geometry_.base_pitch_transverse() / (pinion_speed * geometry_.radii(0).base);
}

double DoubleInvolutePair::front(int pair, ToothZone z, double travel) const {
  const double pb = geometry_.base_pitch_transverse();
  return geometry_.path().A + travel + (pair - 1) * pb - lag(z);
}

int DoubleInvolutePair::last_pair() const {
  const auto& path = geometry_.path();
  return 2 + static_cast<int>(std::ceil((path.E - path.A + step_ + sweep_) / geometry_.base_pitch_transverse()));
}

double DoubleInvolutePair::piece_length(double f, ToothZone zone_id) const {
  const auto& z = zone(zone_id);
  if (sweep_ == 0.0) {
    // A spur pair is in a zone when its point is; the ends of A..E count (as in
    // GearPairGeometry::pairs_in_contact), and for a zero step the zones meet at C, which
    // belongs to the tip zone only.
    const double tol = 1e-12 * geometry_.base_pitch_transverse();
    const bool below_end = zone_id == ToothZone::root && step_ == 0.0 ? f < z.end - tol : f <= z.end + tol;
    return f >= z.begin - tol && below_end ? geometry_.pair().face_width : 0.0;
  }
  const double lo = std::max(z.begin, f - sweep_), hi = std::min(z.end, f);
  return hi > lo ? (hi - lo) / std::sin(geometry_.base_helix_angle()) : 0.0;
}

std::vector<ContactPiece> DoubleInvolutePair::contact_pieces(double travel) const {
  const double pb = geometry_.base_pitch_transverse();
  const double tau = travel - std::floor(travel / pb) * pb;
  std::vector<ContactPiece> pieces;
  for (int k = 1; k <= last_pair(); ++k)
    for (const auto z : {ToothZone::root, ToothZone::tip}) {
      const double f = front(k, z, tau);
      const double length = piece_length(f, z);
      if (length <= 0.0) continue;
      const auto& iv = zone(z);
      const double lo = sweep_ == 0.0 ? std::clamp(f, iv.begin, iv.end) : std::max(iv.begin, f - sweep_);
      const double hi = sweep_ == 0.0 ? lo : std::min(iv.end, f);
      pieces.push_back({k, z, lo, hi, length});
    }
  return pieces;
}

double DoubleInvolutePair::contact_line_length(double travel) const {
  double total = 0.0;
  for (const auto& p : contact_pieces(travel)) total += p.length;
  return total;
}

double DoubleInvolutePair::pair_contact_length(int pair, ToothZone z, double travel) const {
  const double pb = geometry_.base_pitch_transverse();
  return piece_length(front(pair, z, travel - std::floor(travel / pb) * pb), z);
}

std::vector<double> DoubleInvolutePair::breakpoints() const {
  const double pb = geometry_.base_pitch_transverse();
  std::vector<double> t;
  for (int k = 1; k <= last_pair(); ++k)
    for (const auto z : {ToothZone::root, ToothZone::tip})
      for (const double end : {zone(z).begin, zone(z).end})
        for (const double reach : {0.0, sweep_}) {
          // front(k, z, τ) − reach = end
          const double tau = end + reach - front(k, z, 0.0);
          t.push_back(tau - std::floor(tau / pb) * pb);
        }
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end(), [&](double a, double b) { return b - a <= 1e-12 * pb; }), t.end());
  return t;
}

// L(τ) is piecewise linear between the breakpoints (helical) or piecewise constant (spur),
// so its least value is at a breakpoint or between two.
void DoubleInvolutePair::check_continuous_contact() const {
  const double pb = geometry_.base_pitch_transverse();
  auto t = breakpoints();
  t.push_back(t.front() + pb);
  for (std::size_t i = 0; i + 1 < t.size(); ++i)
    for (const double tau : {t[i], 0.5 * (t[i] + t[i + 1])})
      if (contact_line_length(tau) <= 1e-9 * geometry_.pair().face_width)
        throw InputError(fmt::format(
            "{}waist_root_depth = {}: no tooth pair is in contact at mesh travel {:.4f} mm of the base pitch {:.4f} mm "
            "(root zone {:.4f} mm, tip zone {:.4f} mm long, step {:.4f} mm): shorten the waist, raise the tip "
            "diameters or the helix angle", key, rack_.waist_root_depth, tau * 1e3, pb * 1e3, root_.length() * 1e3,
            tip_.length() * 1e3, step_ * 1e3));
}

}  // namespace gearbench::geometry
