#include "tooth_outline.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "model/errors.h"

namespace gearbench::reference::fe {
namespace {

constexpr double pi = std::numbers::pi;

double involute_function(double a) { return std::tan(a) - a; }

/// Inverse of inv α = tan α − α by Newton's method (d inv/dα = tan²α), from α = 0.5 rad,
/// which converges for every operating pressure angle of an external pair (0…60°).
double inverse_involute(double value) {
  double a = 0.5;
  for (int i = 0; i < 60; ++i) {
    const double step = (involute_function(a) - value) / (std::tan(a) * std::tan(a));
    a -= step;
    if (std::abs(step) < 1e-15) break;
  }
  return a;
}

/// One point of the cutting rack's profile in rack coordinates: u along the rolling line
/// (0 at the centre of the cutter tooth, which cuts the tooth space), v normal to it
/// measured from the rolling line, positive away from the gear centre; n the unit normal pointing
/// out of the cutter, i.e. into the gear's material.
struct RackPoint {
  double u, v, nu, nv;
  bool straight_flank;
};

/// The cutter tooth's right half: tip line, tip round ρ_fP, straight flank at α (ISO 53
/// basic rack, its dedendum h_fP = h_f*·m being the cutter's addendum). The rolling line is
/// the gear's reference circle; the rack datum line sits x·m further out (profile shift).
std::vector<RackPoint> rack_profile(const model::GearPair& p, double shift, int samples) {
  const double m = p.normal_module, a = p.normal_pressure_angle;
  const double h = p.dedendum_coef * m, rho = p.root_radius_coef * m;
  const double datum = shift * m;
  // Round centre: ρ above the tip line and ρ inside the flank u = πm/4 + v′ tan α (v′ from
  // the datum line).
  const double vc = -h + rho;
  const double uc = pi * m / 4 + vc * std::tan(a) - rho / std::cos(a);
  if (uc < 0.0)
    throw InputError("gear_pair.root_radius_coef = " + std::to_string(p.root_radius_coef) +
                     ": the rack tip radius does not fit the rack tooth (fe_stiffness)");
  const int n_tip = samples / 10, n_round = samples / 5, n_flank = samples - n_tip - n_round;
  std::vector<RackPoint> out;
  for (int i = 0; i < n_tip; ++i)
    out.push_back({uc * i / n_tip, datum - h, 0.0, -1.0, false});
  for (int i = 0; i < n_round; ++i) {
    const double t = -pi / 2 + (pi / 2 - a) * i / n_round;
    out.push_back({uc + rho * std::cos(t), datum + vc + rho * std::sin(t), std::cos(t), std::sin(t), false});
  }
  // Straight flank from the round's tangent point to well past any gear tip.
  const double v_start = vc - rho * std::sin(a), v_end = (p.addendum_coef + 1.0) * m + std::abs(datum);
  for (int i = 0; i <= n_flank; ++i) {
    const double v = v_start + (v_end - v_start) * i / n_flank;
    out.push_back({pi * m / 4 + v * std::tan(a), datum + v, std::cos(a), -std::sin(a), true});
  }
  return out;
}

}  // namespace

ToothOutline generate_tooth(const model::GearPair& pair, int gear, int samples) {
  if (pair.helix_angle != 0.0)
    throw InputError("gear_pair.helix_angle_deg = " + std::to_string(pair.helix_angle * 180 / pi) +
                     ": fe_stiffness models spur gears only (helix angle 0)");
  const auto g = static_cast<std::size_t>(gear);
  const int z = pair.teeth[g];
  const double m = pair.normal_module, alpha = pair.normal_pressure_angle, x = pair.profile_shift[g];
  ToothOutline t;
  t.teeth = z;
  t.radii.pitch = 0.5 * z * m;
  t.radii.base = t.radii.pitch * std::cos(alpha);
  t.radii.root = t.radii.pitch + m * (x - pair.dedendum_coef);
  t.radii.tip = pair.tip_diameter ? 0.5 * (*pair.tip_diameter)[g]
                                  : t.radii.pitch + m * (pair.addendum_coef + x);
  const double r = t.radii.pitch;
  // Undercut: the straight rack flank reaches below the interference point, the foot of
  // the line of action on the base circle, at depth r·sin²α under the rolling line.
  const double flank_foot = x * m - (pair.dedendum_coef - pair.root_radius_coef * (1 - std::sin(alpha))) * m;
  if (flank_foot < -r * std::sin(alpha) * std::sin(alpha))
    throw InputError("gear_pair.teeth = " + std::to_string(z) + " with profile_shift " + std::to_string(x) +
                     ": the tooth is undercut, which fe_stiffness does not model");

  // Envelope of the rack: at rack position φ the rolling point is u = r·φ, and a rack point
  // belongs to the envelope when its normal passes through that point (Litvin & Fuentes,
  // Gear Geometry and Applied Theory, 2004, ch. 6, equation of meshing).
  for (const auto& q : rack_profile(pair, x, samples)) {
    const double phi = (q.u - q.v * q.nu / q.nv) / r;
    const Vec2 radial{std::cos(phi), std::sin(phi)}, tangent{-std::sin(phi), std::cos(phi)};
    const double along = q.u - r * phi;
    const Vec2 point{(r + q.v) * radial[0] + along * tangent[0], (r + q.v) * radial[1] + along * tangent[1]};
    // The generated side belongs to the tooth centred at +π/z; turn it onto +x and mirror
    // it so that it becomes the upper flank.
    const Vec2 turned = rotate(point, -pi / z);
    if (q.straight_flank && t.involute_start == 0) t.involute_start = t.flank.size();
    t.flank.push_back({turned[0], -turned[1]});
    // The envelope's normal is the rack normal at the point of contact (turned with it).
    const Vec2 n = rotate({q.nu * tangent[0] + q.nv * radial[0], q.nu * tangent[1] + q.nv * radial[1]}, -pi / z);
    t.normal.push_back({n[0], -n[1]});
  }
  // Truncate at the tip circle.
  auto radius = [](const Vec2& p) { return std::hypot(p[0], p[1]); };
  for (std::size_t i = 1; i < t.flank.size(); ++i) {
    if (radius(t.flank[i]) < radius(t.flank[i - 1]) - 1e-12 * r)
      throw InputError("gear_pair: the generated profile of gear " + std::to_string(gear + 1) +
                       " is not monotone in radius (undercut or interference of the rack)");
    if (radius(t.flank[i]) >= t.radii.tip) {
      const double r0 = radius(t.flank[i - 1]), r1 = radius(t.flank[i]);
      const double w = (t.radii.tip - r0) / (r1 - r0);
      const Vec2 chord{t.flank[i - 1][0] + w * (t.flank[i][0] - t.flank[i - 1][0]),
                       t.flank[i - 1][1] + w * (t.flank[i][1] - t.flank[i - 1][1])};
      const double onto_tip = t.radii.tip / radius(chord);  // exactly on the tip circle
      const Vec2 corner{chord[0] * onto_tip, chord[1] * onto_tip};
      const Vec2 n = t.normal[i - 1];
      t.flank.resize(i);
      t.normal.resize(i);
      t.flank.push_back(corner);
      t.normal.push_back(n);
      break;
    }
  }
  if (t.flank.back()[1] <= 0.0)
    throw InputError("gear_pair: the tooth of gear " + std::to_string(gear + 1) + " is pointed below its tip circle");
  return t;
}

FlankPoint flank_point_at_radius(const ToothOutline& tooth, double r) {
  const auto& f = tooth.flank;
  auto rad = [](const Vec2& p) { return std::hypot(p[0], p[1]); };
  // The contact at A or E lies on the tip circle itself: snap rounding-level excess onto it.
  const double radius = std::abs(r - rad(f.back())) < 1e-9 * r ? rad(f.back()) : r;
  for (std::size_t i = std::max<std::size_t>(tooth.involute_start, 1); i < f.size(); ++i) {
    if (rad(f[i]) < radius) continue;
    const double r0 = rad(f[i - 1]), r1 = rad(f[i]);
    if (radius < r0) break;
    const double w = (radius - r0) / (r1 - r0);
    const Vec2 p{f[i - 1][0] + w * (f[i][0] - f[i - 1][0]), f[i - 1][1] + w * (f[i][1] - f[i - 1][1])};
    const auto& n = tooth.normal;
    const Vec2 d{n[i - 1][0] + w * (n[i][0] - n[i - 1][0]), n[i - 1][1] + w * (n[i][1] - n[i - 1][1])};
    const double len = std::hypot(d[0], d[1]);
    return {p, {d[0] / len, d[1] / len}};
  }
  throw InputError("fe_stiffness: load radius " + std::to_string(radius * 1e3) +
                   " mm lies outside the involute flank of the generated tooth");
}

ContactPath contact_path(const model::GearPair& pair) {
  const double m = pair.normal_module, alpha = pair.normal_pressure_angle;
  const double r1 = 0.5 * pair.teeth[0] * m, r2 = 0.5 * pair.teeth[1] * m;
  const double rb1 = r1 * std::cos(alpha), rb2 = r2 * std::cos(alpha);
  ContactPath c;
  // ISO 21771: inv α_w = inv α + 2 tan α (x1 + x2)/(z1 + z2); a = (r1 + r2) cos α / cos α_w.
  double a = 0.0;
  if (pair.center_distance) {
    a = *pair.center_distance;
    c.working_pressure_angle = std::acos((r1 + r2) * std::cos(alpha) / a);
  } else {
    c.working_pressure_angle = inverse_involute(
        involute_function(alpha) + 2 * std::tan(alpha) * (pair.profile_shift[0] + pair.profile_shift[1]) /
                                       (pair.teeth[0] + pair.teeth[1]));
    a = (r1 + r2) * std::cos(alpha) / std::cos(c.working_pressure_angle);
  }
  auto tip = [&](std::size_t g, double r) {
    return pair.tip_diameter ? 0.5 * (*pair.tip_diameter)[g] : r + m * (pair.addendum_coef + pair.profile_shift[g]);
  };
  const double ra1 = tip(0, r1), ra2 = tip(1, r2);
  c.t1t2 = a * std::sin(c.working_pressure_angle);
  c.A = c.t1t2 - std::sqrt(ra2 * ra2 - rb2 * rb2);
  c.E = std::sqrt(ra1 * ra1 - rb1 * rb1);
  c.base_pitch = 2 * pi * rb1 / pair.teeth[0];
  return c;
}

}  // namespace gearbench::reference::fe
