#include "crack_slit.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "model/errors.h"

namespace gearbench::reference::fe {
namespace {

double radius(const Vec2& p) { return std::hypot(p[0], p[1]); }

/// Polar half-angle of the tooth at radius r (the flank is monotone in radius).
double half_angle_at(const ToothOutline& t, double r) {
  const auto& f = t.flank;
  for (std::size_t i = 1; i < f.size(); ++i) {
    if (radius(f[i]) < r) continue;
    const double r0 = radius(f[i - 1]), r1 = radius(f[i]);
    const double w = r1 > r0 ? (r - r0) / (r1 - r0) : 0.0;
    return (1 - w) * std::atan2(f[i - 1][1], f[i - 1][0]) + w * std::atan2(f[i][1], f[i][0]);
  }
  return std::atan2(f.back()[1], f.back()[0]);
}

}  // namespace

Slit pitch_crack_slit(const ToothOutline& tooth, const ToothCrack& crack) {
  if (!(crack.angle > 0.0 && crack.angle < 0.5 * std::acos(-1.0)))
    throw InputError(fmt::format("crack.angle_deg = {}: the FE slit needs an angle in (0, 90) deg",
                                 crack.angle * 180.0 / std::acos(-1.0)));
  // Seed 003, fig. 2: the mouth is the flank point on the reference (pitch) circle.
  const FlankPoint mouth = flank_point_at_radius(tooth, tooth.radii.pitch);
  Slit s;
  s.mouth = mouth.point;
  s.tip = {s.mouth[0] - crack.length * std::cos(crack.angle), s.mouth[1] - crack.length * std::sin(crack.angle)};
  s.flank_index = static_cast<std::size_t>(
      std::find_if(tooth.flank.begin(), tooth.flank.end(), [&](const Vec2& p) { return radius(p) > tooth.radii.pitch; }) -
      tooth.flank.begin());
  // The ligament left between the tip and the opposite (lower) flank, against the tooth's
  // local thickness 2·r·half-angle at the tip's radius.
  const double r = radius(s.tip), half = half_angle_at(tooth, r);
  const double ligament = r * (half + std::atan2(s.tip[1], s.tip[0]));
  if (!(r > tooth.radii.root && ligament > 0.1 * 2.0 * r * half))
    throw InputError(fmt::format(
        "crack.length_mm = {:.6g}: the crack tip (radius {:.3f} mm, root circle {:.3f} mm) leaves a ligament of "
        "{:.3f} mm of a {:.3f} mm section; the FE slit must end inside the tooth with at least 10 % left",
        crack.length * 1e3, r * 1e3, tooth.radii.root * 1e3, ligament * 1e3, 2e3 * r * half));
  return s;
}

double distance_to_slit(const Slit& s, const Vec2& p) {
  const double ex = s.tip[0] - s.mouth[0], ey = s.tip[1] - s.mouth[1];
  const double w = std::clamp(((p[0] - s.mouth[0]) * ex + (p[1] - s.mouth[1]) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
  return std::hypot(p[0] - s.mouth[0] - w * ex, p[1] - s.mouth[1] - w * ey);
}

}  // namespace gearbench::reference::fe
