#include "gear_pair_geometry.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "model/errors.h"
#include "involute.h"

namespace gearbench::geometry {

namespace {
constexpr double pi = std::numbers::pi;
std::string mm(double metres) { return fmt::format("{:.4f} mm", metres * 1e3); }
}  // namespace

GearPairGeometry::GearPairGeometry(const model::GearPair& pair) : pair_(pair) {
  compute_pitch_geometry();
  compute_center_distance();
  compute_radii();
  compute_path_of_contact();
  check_feasibility();
}

double GearPairGeometry::gear_ratio() const {
  return static_cast<double>(pair_.teeth[1]) / pair_.teeth[0];
}

// ISO 21771:2007: transverse module and pressure angle, base helix.
void GearPairGeometry::compute_pitch_geometry() {
  const double beta = pair_.helix_angle;
  transverse_module_ = pair_.normal_module / std::cos(beta);
  alpha_t_ = std::atan(std::tan(pair_.normal_pressure_angle) / std::cos(beta));
  beta_b_ = std::atan(std::tan(beta) * std::cos(alpha_t_));
  for (std::size_t i = 0; i < 2; ++i) {
    radii_[i].reference = 0.5 * pair_.teeth[i] * transverse_module_;
    radii_[i].base = radii_[i].reference * std::cos(alpha_t_);
  }
  base_pitch_ = 2.0 * pi * radii_[0].base / pair_.teeth[0];
}

// Working pressure angle from the shifts at zero backlash (ISO 21771:2007):
//   inv α_wt = inv α_t + 2 tan α_n (x1 + x2)/(z1 + z2),   a_w = (r_b1 + r_b2)/cos α_wt.
// A given centre distance fixes α_wt instead (cos α_wt = (r_b1 + r_b2)/a) and must lie
// between the zero-backlash distance (less jams the teeth; 0.1 % of m_n is allowed for
// rounding of printed values) and 0.1·m_n more (more is backlash no shift design intends).
void GearPairGeometry::compute_center_distance() {
  const auto& x = pair_.profile_shift;
  const double z_sum = pair_.teeth[0] + pair_.teeth[1];
  const double inv_wt = involute(alpha_t_) +
                        2.0 * std::tan(pair_.normal_pressure_angle) * (x[0] + x[1]) / z_sum;
  const double base_sum = radii_[0].base + radii_[1].base;
  zero_backlash_a_ = base_sum / std::cos(inverse_involute(inv_wt));
  if (!pair_.center_distance) {
    center_distance_ = zero_backlash_a_;
    alpha_wt_ = inverse_involute(inv_wt);
    return;
  }
  const double a = *pair_.center_distance;
  const double lo = zero_backlash_a_ - 1e-3 * pair_.normal_module;
  const double hi = zero_backlash_a_ + 0.1 * pair_.normal_module;
  if (a < lo || a > hi)
    throw InputError(fmt::format(
        "gear_pair.center_distance_mm = {:.10g}: incompatible with profile_shift sum {} (zero-backlash "
        "centre distance {}); allowed range is [{:.4f}, {:.4f}] mm",
        a * 1e3, x[0] + x[1], mm(zero_backlash_a_), lo * 1e3, hi * 1e3));
  center_distance_ = a;
  alpha_wt_ = std::acos(base_sum / a);
  if (a > zero_backlash_a_ + 1e-3 * pair_.normal_module)
    warnings_.push_back(fmt::format(
        "centre distance {} exceeds the zero-backlash value {} for the shifts: the pair runs "
        "with backlash",
        mm(a), mm(zero_backlash_a_)));
}

// Tip, root, working and form radii. The form radius is where the rack-generated
// involute ends: the rack's straight flank reaches h_fP − ρ_fP(1 − sin α_n) above its
// datum line, which meets the generating line of action at ρ_F from T (ISO 21771:2007, form diameter of a rack-generated gear):
//   ρ_F = r·sin α_t − (h_fP* − x − ρ_fP*(1 − sin α_n))·m_n / sin α_t.
void GearPairGeometry::compute_radii() {
  const double mn = pair_.normal_module;
  for (std::size_t i = 0; i < 2; ++i) {
    auto& r = radii_[i];
    const double x = pair_.profile_shift[i];
    r.tip = pair_.tip_diameter ? 0.5 * (*pair_.tip_diameter)[i]
                               : r.reference + mn * (pair_.addendum_coef + x);
    r.root = r.reference - mn * (pair_.dedendum_coef - x);
    r.working = r.base / std::cos(alpha_wt_);
    const double straight_flank =
        pair_.dedendum_coef - pair_.root_radius_coef * (1.0 - std::sin(pair_.normal_pressure_angle));
    const double rho_form =
        r.reference * std::sin(alpha_t_) - (straight_flank - x) * mn / std::sin(alpha_t_);
    if (rho_form < -1e-9 * mn) {
      const double z_min = 2.0 * (straight_flank - x) * std::cos(pair_.helix_angle) /
                           std::pow(std::sin(alpha_t_), 2);
      const double x_min = straight_flank - pair_.teeth[i] * std::pow(std::sin(alpha_t_), 2) /
                                                (2.0 * std::cos(pair_.helix_angle));
      throw InputError(fmt::format(
          "gear_pair.teeth[{}] = {}: undercut by the generating rack at profile_shift {:.10g}; "
          "allowed is teeth >= {:.1f} at this shift, or profile_shift[{}] >= {:.3f}",
          i, pair_.teeth[i], x, z_min, i, x_min));
    }
    r.form = std::hypot(r.base, std::max(rho_form, 0.0));
  }
}

// Path of contact on the line of action (ISO 21771 §5.4): T1E = √(r_a1² − r_b1²),
// T2A = √(r_a2² − r_b2²), T1C = r_b1·tan α_wt; B = E − p_bt, D = A + p_bt.
void GearPairGeometry::compute_path_of_contact() {
  for (std::size_t i = 0; i < 2; ++i)
    if (radii_[i].tip <= std::max(radii_[i].base, radii_[i].root))
      throw InputError(fmt::format(
          "gear_pair.tip_diameter_mm[{}] = {:.10g}: must exceed the base diameter {} and the root "
          "diameter {}",
          i, 2e3 * radii_[i].tip, mm(2 * radii_[i].base), mm(2 * radii_[i].root)));
  auto& p = path_;
  p.T2 = center_distance_ * std::sin(alpha_wt_);
  p.E = std::sqrt(radii_[0].tip * radii_[0].tip - radii_[0].base * radii_[0].base);
  p.A = p.T2 - std::sqrt(radii_[1].tip * radii_[1].tip - radii_[1].base * radii_[1].base);
  p.C = radii_[0].base * std::tan(alpha_wt_);
  p.B = p.E - base_pitch_;
  p.D = p.A + base_pitch_;
  p.AB = 0.5 * (p.A + p.B);
  p.DE = 0.5 * (p.D + p.E);
}

// Tooth thickness at the tip circle, transverse (ISO 21771:2007, at zero backlash):
//   s_a = d_a·[(π/2 + 2x·tan α_n)/z + inv α_t − inv α_a],  cos α_a = r_b/r_a.
double GearPairGeometry::tip_tooth_thickness(int gear) const {
  const auto i = static_cast<std::size_t>(gear);
  const double alpha_a = std::acos(radii_[i].base / radii_[i].tip);
  const double half_angle =
      (0.5 * pi + 2.0 * pair_.profile_shift[i] * std::tan(pair_.normal_pressure_angle)) /
          pair_.teeth[i] +
      involute(alpha_t_) - involute(alpha_a);
  return 2.0 * radii_[i].tip * half_angle;
}

void GearPairGeometry::check_feasibility() const {
  const char* tip_key = pair_.tip_diameter ? "tip_diameter_mm" : "profile_shift";
  for (int i = 0; i < 2; ++i)
    if (tip_tooth_thickness(i) <= 0.0)
      throw InputError(fmt::format(
          "gear_pair.{}[{}]: gear {} is pointed (tip thickness {}) at tip diameter {}; "
          "reduce the tip diameter or the profile shift",
          tip_key, i, i + 1, mm(tip_tooth_thickness(i)), mm(2 * radii_[i].tip)));
  // Radial clearance: a tip must not reach the mating root circle.
  for (std::size_t i = 0; i < 2; ++i) {
    const double clearance = center_distance_ - radii_[i].tip - radii_[1 - i].root;
    if (clearance < 0.0)
      throw InputError(fmt::format(
          "gear_pair.{}[{}]: tip of gear {} reaches {} into the root circle of gear {}; "
          "reduce the tip diameter or increase the centre distance",
          tip_key, i, i + 1, mm(-clearance), 2 - i));
  }
  // Tip interference: each mating tip must meet the flank on its involute, above the
  // form circle (T1A ≥ ρ_F1 and T2E ≥ ρ_F2).
  const double rho_form1 = std::sqrt(std::max(0.0, std::pow(radii_[0].form, 2) - std::pow(radii_[0].base, 2)));
  const double rho_form2 = std::sqrt(std::max(0.0, std::pow(radii_[1].form, 2) - std::pow(radii_[1].base, 2)));
  if (path_.A < rho_form1 - 1e-9 * pair_.normal_module)
    throw InputError(fmt::format(
        "gear_pair.{}[1]: tip interference: the wheel tip meets the pinion {} below its form "
        "circle (d_Ff1 = {}); reduce tip_diameter_mm[1] or raise profile_shift[0]",
        tip_key, mm(rho_form1 - path_.A), mm(2 * radii_[0].form)));
  if (path_.T2 - path_.E < rho_form2 - 1e-9 * pair_.normal_module)
    throw InputError(fmt::format(
        "gear_pair.{}[0]: tip interference: the pinion tip meets the wheel {} below its form "
        "circle (d_Ff2 = {}); reduce tip_diameter_mm[0] or raise profile_shift[1]",
        tip_key, mm(rho_form2 - (path_.T2 - path_.E)), mm(2 * radii_[1].form)));
  if (contact_ratio_transverse() < 1.0)
    throw InputError(fmt::format(
        "gear_pair: transverse contact ratio {:.4f} is below 1 (path of contact {} shorter than "
        "the base pitch {}); allowed is >= 1: increase the tip diameters or reduce the centre "
        "distance",
        contact_ratio_transverse(), mm(path_.E - path_.A), mm(base_pitch_)));
}

double GearPairGeometry::contact_ratio_transverse() const {
  return (path_.E - path_.A) / base_pitch_;
}

double GearPairGeometry::contact_ratio_overlap() const {
  return pair_.face_width * std::tan(beta_b_) / base_pitch_;
}

double GearPairGeometry::contact_ratio_total() const {
  return contact_ratio_transverse() + contact_ratio_overlap();
}

int GearPairGeometry::pairs_in_contact(double s) const {
  // Pairs sit one base pitch apart on the line of action; count those on [A, E].
  const double tol = 1e-12 * base_pitch_;
  const auto k_lo = static_cast<long>(std::ceil((path_.A - s - tol) / base_pitch_));
  const auto k_hi = static_cast<long>(std::floor((path_.E - s + tol) / base_pitch_));
  return static_cast<int>(std::max(0L, k_hi - k_lo + 1));
}

std::vector<double> GearPairGeometry::positions_in_contact(double s) const {
  const double tol = 1e-12 * base_pitch_;
  const auto k_lo = static_cast<long>(std::ceil((path_.A - s - tol) / base_pitch_));
  const auto k_hi = static_cast<long>(std::floor((path_.E - s + tol) / base_pitch_));
  std::vector<double> positions;
  for (long k = k_lo; k <= k_hi; ++k)
    positions.push_back(std::clamp(s + static_cast<double>(k) * base_pitch_, path_.A, path_.E));
  return positions;
}

std::vector<ContactZone> GearPairGeometry::contact_zones() const {
  std::vector<double> breaks{path_.A, path_.E};
  for (double s = path_.A + base_pitch_; s < path_.E; s += base_pitch_) breaks.push_back(s);
  for (double s = path_.E - base_pitch_; s > path_.A; s -= base_pitch_) breaks.push_back(s);
  std::sort(breaks.begin(), breaks.end());
  std::vector<ContactZone> zones;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    if (breaks[i + 1] - breaks[i] <= 1e-12 * base_pitch_) continue;
    const int pairs = pairs_in_contact(0.5 * (breaks[i] + breaks[i + 1]));
    if (!zones.empty() && zones.back().pairs == pairs)
      zones.back().end = breaks[i + 1];
    else
      zones.push_back({breaks[i], breaks[i + 1], pairs});
  }
  return zones;
}

// Flank radii of curvature are the distances to the base-circle tangent points,
// ρ1 = T1Y and ρ2 = T2Y; each flank point moves along the profile at ω·ρ (rolling speed),
// so u1 = ω1·ρ1, u2 = ω2·ρ2 with ω2 = ω1·z1/z2 (Niemann & Winter II, §21.3).
ContactKinematics GearPairGeometry::kinematics(double s, double pinion_speed) const {
  ContactKinematics k;
  k.position = s;
  k.pinion_radius = std::hypot(radii_[0].base, s);
  k.rho1 = s;
  k.rho2 = path_.T2 - s;
  k.reduced_radius = k.rho1 * k.rho2 / (k.rho1 + k.rho2);
  k.reduced_radius_normal = k.reduced_radius / std::cos(beta_b_);
  k.u1 = pinion_speed * k.rho1;
  k.u2 = pinion_speed / gear_ratio() * k.rho2;
  k.entrainment = 0.5 * (k.u1 + k.u2);
  k.sliding = k.u1 - k.u2;
  k.slide_to_roll = k.entrainment > 0.0 ? k.sliding / k.entrainment : 0.0;
  k.specific_sliding1 = k.u1 > 0.0 ? k.sliding / k.u1 : 0.0;
  k.specific_sliding2 = k.u2 > 0.0 ? -k.sliding / k.u2 : 0.0;
  return k;
}

// Contact lines on the base plane are straight, inclined at β_b, one transverse base
// pitch apart; on face coordinate y ∈ [0, b] the line through s_k on the front face sits
// at s_k − y·tan β_b. The part inside the field A ≤ s ≤ E is (hi − lo)/sin β_b long.
double GearPairGeometry::contact_line_length_one_half(double s0) const {
  const double b = pair_.face_width;
  if (beta_b_ == 0.0) return b * pairs_in_contact(s0);
  const double shift = b * std::tan(beta_b_);
  const auto k_lo = static_cast<long>(std::floor((path_.A - s0) / base_pitch_));
  const auto k_hi = static_cast<long>(std::ceil((path_.E + shift - s0) / base_pitch_));
  double length = 0.0;
  for (long k = k_lo; k <= k_hi; ++k) {
    const double front = s0 + static_cast<double>(k) * base_pitch_;
    const double lo = std::max(path_.A, front - shift);
    const double hi = std::min(path_.E, front);
    if (hi > lo) length += (hi - lo) / std::sin(beta_b_);
  }
  return length;
}

double GearPairGeometry::contact_line_length(double s0) const {
  // The halves of a herringbone pair are mirror images with aligned apexes, so each
  // carries the same contact-line length at every mesh position.
  return (pair_.herringbone ? 2.0 : 1.0) * contact_line_length_one_half(s0);
}

}  // namespace gearbench::geometry
