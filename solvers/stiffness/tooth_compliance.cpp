#include "tooth_compliance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>

#include "model/errors.h"

namespace gearbench::stiffness {

namespace {

// 10-point Gauss–Legendre nodes and weights on [−1, 1] (Abramowitz & Stegun, table 25.4):
// exact for polynomials of degree 19, so ~1e-13 relative on a panel of 1/24 of a segment.
constexpr std::array<double, 5> gl_nodes = {0.1488743389816312, 0.4333953941292472,
                                            0.6794095682990244, 0.8650633666889845,
                                            0.9739065285171717};
constexpr std::array<double, 5> gl_weights = {0.2955242247147529, 0.2692667193099963,
                                              0.2190863625159820, 0.1494513491505806,
                                              0.0666713443086881};
constexpr int panels_per_segment = 24;
constexpr double shear_factor = 1.2;  // rectangular section (Yang & Lin 1987, Tian 2004)

}  // namespace

ToothCompliance::ToothCompliance(ToothProfile profile, const model::Material& material,
                                 double face_width, const std::optional<Crack>& crack)
    : profile_(std::move(profile)),
      E_(material.youngs_modulus),
      G_(material.youngs_modulus / (2.0 * (1.0 + material.poisson_ratio))),
      width_(face_width),
      crack_(crack && crack->length > 0.0 ? crack : std::nullopt) {
  if (crack_) {
    // Crack mouth: the reference-circle point of the flank (pitch crack, seed 003) or the
    // beam start (root crack); the tip lies q further along the crack at angle ν.
    const double mouth_x = crack_->type == Crack::Type::pitch
                               ? profile_.involute_point(profile_.reference_roll_angle()).x
                               : profile_.beam_start();
    const double mouth_h = profile_.half_thickness(mouth_x);
    crack_tip_x_ = mouth_x - crack_->length * std::cos(crack_->angle);
    crack_tip_h_ = mouth_h - crack_->length * std::sin(crack_->angle);
    // Past the centre line the section left at the tip is h + h_c; none left: broken tooth.
    const double tip_h = profile_.half_thickness(profile_.tip_x());
    if (tip_h + crack_tip_h_ <= 0.0)
      throw InputError(fmt::format(
          "crack.length_mm = {:.10g}: the crack leaves no section under the tooth tip (tip half "
          "thickness {:.4f} mm, crack tip {:.4f} mm past the centre line); the tooth is broken",
          crack_->length * 1e3, tip_h * 1e3, -crack_tip_h_ * 1e3));
  }
  healthy_ = build_table(false);
  if (crack_) cracked_ = build_table(true);
}

std::optional<double> ToothCompliance::crack_tip_thickness() const {
  return crack_ ? std::optional<double>(crack_tip_h_) : std::nullopt;
}

// Limiting-line rule (Chen & Shao 2011; seed 003 eqs 6–11): above the crack tip the
// cracked side keeps only min(h, h_c).
double ToothCompliance::thickness(double x, bool cracked) const {
  const double h = profile_.half_thickness(x);
  if (cracked && x >= crack_tip_x_) return h + std::min(h, crack_tip_h_);
  return 2.0 * h;
}

ToothCompliance::Moments ToothCompliance::panel_moments(double a, double b, bool cracked) const {
  Moments m;
  const double half = 0.5 * (b - a);
  const double mid = 0.5 * (a + b);
  const double x0 = profile_.beam_start();
  for (std::size_t k = 0; k < gl_nodes.size(); ++k)
    for (const double sign : {-1.0, 1.0}) {
      const double x = mid + sign * half * gl_nodes[k];
      const double t = thickness(x, cracked);
      const double w = half * gl_weights[k];
      const double xi = x - x0;
      const double inv_EI = 12.0 / (E_ * t * t * t * width_);
      m.J0 += w * inv_EI;
      m.J1 += w * inv_EI * xi;
      m.J2 += w * inv_EI * xi * xi;
      m.JA += w / (t * width_);
    }
  return m;
}

// Panels: each smooth stretch of h(x) (fillet or straight part, involute, and either side
// of the crack's break points, where the thickness kinks) gets its own uniform panels.
ToothCompliance::Table ToothCompliance::build_table(bool cracked) const {
  std::vector<double> breaks{profile_.beam_start(), profile_.tip_x()};
  if (profile_.fillet_end_x() > profile_.beam_start()) breaks.push_back(profile_.fillet_end_x());
  if (cracked) {
    if (crack_tip_x_ > breaks[0] && crack_tip_x_ < profile_.tip_x()) breaks.push_back(crack_tip_x_);
    for (const double dc : profile_.x_where_thickness(crack_tip_h_))
      if (dc > crack_tip_x_) breaks.push_back(dc);
  }
  std::sort(breaks.begin(), breaks.end());
  Table table;
  table.ends.push_back(breaks.front());
  table.cumulative.push_back({});
  for (std::size_t s = 0; s + 1 < breaks.size(); ++s)
    for (int p = 1; p <= panels_per_segment; ++p) {
      const double a = table.ends.back();
      const double b = breaks[s] + (breaks[s + 1] - breaks[s]) * p / panels_per_segment;
      const Moments m = panel_moments(a, b, cracked);
      Moments c = table.cumulative.back();
      c.J0 += m.J0;
      c.J1 += m.J1;
      c.J2 += m.J2;
      c.JA += m.JA;
      table.ends.push_back(b);
      table.cumulative.push_back(c);
    }
  return table;
}

ToothCompliance::Moments ToothCompliance::moments_to(const Table& table, double x1, bool cracked) const {
  const auto it = std::upper_bound(table.ends.begin(), table.ends.end(), x1);
  const auto k = static_cast<std::size_t>(std::max<long>(0, (it - table.ends.begin()) - 1));
  Moments m = table.cumulative[std::min(k, table.cumulative.size() - 1)];
  const double a = table.ends[std::min(k, table.ends.size() - 1)];
  if (x1 > a) {
    const Moments partial = panel_moments(a, x1, cracked);
    m.J0 += partial.J0;
    m.J1 += partial.J1;
    m.J2 += partial.J2;
    m.JA += partial.JA;
  }
  return m;
}

bool ToothCompliance::crack_active(double roll_angle) const {
  if (!crack_) return false;
  // Seed 003: a pitch crack has no effect while the load is below its mouth (α_1 < α_g).
  return crack_->type == Crack::Type::root || roll_angle > profile_.reference_roll_angle();
}

ComplianceComponents ToothCompliance::components(const FlankPoint& load, double x_end, bool cracked) const {
  const Moments m = moments_to(cracked ? cracked_ : healthy_, x_end, cracked);
  const double c = std::cos(load.alpha);
  const double s = std::sin(load.alpha);
  const double K = c * (load.x - profile_.beam_start()) - s * load.h;
  return {K * K * m.J0 - 2.0 * K * c * m.J1 + c * c * m.J2,
          shear_factor * c * c * m.JA / G_,
          s * s * m.JA / E_};
}

ComplianceComponents ToothCompliance::at(double roll_angle, CrackMode mode) const {
  const FlankPoint load = profile_.involute_point(roll_angle);
  const bool cracked = crack_ && (mode == CrackMode::active ||
                                  (mode == CrackMode::automatic && crack_active(roll_angle)));
  return components(load, load.x, cracked);
}

ComplianceComponents ToothCompliance::centre_line_point(double roll_angle) const {
  const FlankPoint load = profile_.involute_point(roll_angle);
  return components(load, load.x - load.h * std::tan(load.alpha), false);
}

}  // namespace gearbench::stiffness
