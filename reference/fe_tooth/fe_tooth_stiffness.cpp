#include "fe_tooth_stiffness.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>

#include "fe_backend.h"
#include "model/errors.h"

namespace gearbench::reference::fe {
namespace {

constexpr double pi = std::numbers::pi;

double distance(const Vec2& a, const Vec2& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

/// Dense outline of the loaded tooth and its two neighbours (tooth coordinates), the curve
/// that refinement projects new boundary vertices onto.
std::vector<Vec2> local_outline(const ToothOutline& t) {
  std::vector<Vec2> out;
  const double tip_half_angle = std::atan2(t.flank.back()[1], t.flank.back()[0]);
  for (int k = -1; k <= 1; ++k) {
    const double turn = 2 * pi * k / t.teeth;
    for (const auto& p : t.flank) out.push_back(rotate({p[0], -p[1]}, turn));
    for (int i = 1; i < 40; ++i) {
      const double a = -tip_half_angle + 2 * tip_half_angle * i / 40.0;
      out.push_back(rotate({t.radii.tip * std::cos(a), t.radii.tip * std::sin(a)}, turn));
    }
    for (auto it = t.flank.rbegin(); it != t.flank.rend(); ++it) out.push_back(rotate(*it, turn));
  }
  return out;
}

Vec2 project_onto(const std::vector<Vec2>& line, const Vec2& p) {
  double best = std::numeric_limits<double>::max();
  Vec2 out = p;
  for (std::size_t i = 1; i < line.size(); ++i) {
    const Vec2& a = line[i - 1];
    const Vec2& b = line[i];
    const double ex = b[0] - a[0], ey = b[1] - a[1], len2 = ex * ex + ey * ey;
    if (len2 == 0.0) continue;
    const double w = std::clamp(((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / len2, 0.0, 1.0);
    const Vec2 q{a[0] + w * ex, a[1] + w * ey};
    const double d = distance(p, q);
    if (d < best) {
      best = d;
      out = q;
    }
  }
  return out;
}

/// Which solves missed fe.tolerance within fe.max_cycles (the first named), or that none did.
std::string convergence_message(const FeToothResult& r) {
  int solves = 0, missed = 0;
  std::string first;
  for (const auto& p : r.positions)
    for (std::size_t g = 0; g < 2; ++g) {
      const auto& fe = p.tooth[g].fe;
      ++solves;
      if (fe.converged) continue;
      if (++missed == 1)
        first = fmt::format("gear {} at s = {:.4g} mm, last relative change {:.2g}", g + 1, p.path_position * 1e3,
                            fe.cycles.empty() ? 0.0 : fe.cycles.back().change);
    }
  const auto& o = r.options_used.fe;
  if (missed == 0)
    return fmt::format("converged: all {} solves met fe.tolerance = {} within fe.max_cycles = {}", solves,
                       model::format_value(o.tolerance), o.max_cycles);
  return fmt::format("not converged: {} of {} solves missed fe.tolerance = {} within fe.max_cycles = {} (first: {}); "
                     "raise fe.max_cycles or fe.tolerance",
                     missed, solves, model::format_value(o.tolerance), o.max_cycles, first);
}

}  // namespace

double hertz_line_compliance(const model::Material& a, const model::Material& b, double face_width) {
  return 2.0 / (pi * face_width) *
         ((1 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
          (1 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
}

FeToothStiffness::FeToothStiffness(const model::GearPair& pair, const std::array<model::Material, 2>& materials,
                                   FeToothOptions options)
    : pair_(pair), materials_(materials), options_(std::move(options)) {
  options_.validate();
  path_ = contact_path(pair_);
  if (!(path_.A < path_.E && path_.A > 0.0 && path_.E < path_.t1t2))
    throw InputError("gear_pair: the path of contact A..E is empty or runs past the base tangents");
  const double m = pair_.normal_module;
  for (int g = 0; g < 2; ++g) {
    const auto i = static_cast<std::size_t>(g);
    teeth_[i] = generate_tooth(pair_, g);
    bore_[i] = options_.bore_radius ? (*options_.bore_radius)[i] : 0.5 * teeth_[i].radii.root;
    GearMeshSizes sizes;
    sizes.near = options_.near_size_modules * m;
    sizes.far = options_.far_size_modules * m;
    sizes.growth = 0.2;
    sizes.focus = {0.5 * (teeth_[i].radii.root + teeth_[i].radii.tip), 0.0};
    meshes_[i] = fe_backend().mesh_gear(teeth_[i], bore_[i], sizes, std::nullopt);
    if (options_.crack && options_.crack->gear == g && options_.crack->length > 0.0) {
      slits_[i] = pitch_crack_slit(teeth_[i], *options_.crack);
      slit_meshes_[i] = fe_backend().mesh_gear(teeth_[i], bore_[i], sizes, slits_[i]);
    }
    outline_[i] = local_outline(teeth_[i]);
  }
}

// The slit's added compliance is taken from the work of the load, Δ(f·u)/F²: by Clapeyron's
// theorem it is exactly twice the strain energy the cut adds per unit force squared — the
// quantity the energy method's cracked sections change — and it does not depend on where a
// probe sits (a probe near the slit sees one lip only; a load below the mouth leaves the
// probe on the shielded side, where it even moves less). The probe compliance of the
// healthy tooth keeps the meaning of the uncracked figures.
ToothCompliance FeToothStiffness::tooth_compliance(int gear, double s, bool vtu, double field_spacing,
                                                   const ToothCompliance* healthy) const {
  if (!slits_[static_cast<std::size_t>(gear)]) return solve_tooth(gear, s, vtu, field_spacing, false);
  const ToothCompliance h = healthy ? *healthy : solve_tooth(gear, s, false, 0.0, false);
  ToothCompliance c = solve_tooth(gear, s, vtu, field_spacing, true);
  c.probe_compliance = c.compliance;
  c.crack_compliance = c.contact_compliance - h.contact_compliance;
  c.compliance = h.compliance + c.crack_compliance;
  c.seconds += healthy ? 0.0 : h.seconds;
  return c;
}

ToothCompliance FeToothStiffness::solve_tooth(int gear, double s, bool vtu, double field_spacing, bool with_slit) const {
  const auto i = static_cast<std::size_t>(gear);
  const auto& t = teeth_[i];
  const double roll = (gear == 0 ? s : path_.t1t2 - s) / t.radii.base;
  ToothCompliance c;
  c.load_radius = t.radii.base * std::sqrt(1 + roll * roll);
  const FlankPoint load = flank_point_at_radius(t, c.load_radius);
  c.load_point = load.point;
  // Hertzian half-width of the line contact (Johnson, Contact Mechanics, 1985, eq. 4.43):
  // b² = 4wR/(πE*), 1/R = 1/ρ1 + 1/ρ2 with the radii of curvature ρ1 = s, ρ2 = T1T2 − s,
  // 1/E* = Σ (1 − ν²)/E.
  const double rho1 = s, rho2 = path_.t1t2 - s, R = rho1 * rho2 / (rho1 + rho2);
  const double E_star = 1.0 / (0.5 * pi * pair_.face_width * hertz_line_compliance(materials_[0], materials_[1], pair_.face_width));
  c.hertz_half_width = std::sqrt(4 * options_.load_per_width * R / (pi * E_star));

  const Vec2 d = load.inward_normal, P = load.point;
  const double b = c.hertz_half_width, near = options_.near_size_modules * pair_.normal_module;
  const double bore = bore_[i], zone = 1.5 * 2 * pi / t.teeth, root = t.radii.root;
  ElasticProblem p;
  p.mesh = with_slit ? slit_meshes_[i] : meshes_[i];
  p.converge_on_load = with_slit;
  p.material = {materials_[i].youngs_modulus, materials_[i].poisson_ratio, !options_.plane_stress};
  p.clamped = [bore](const Vec2& x) { return std::hypot(x[0], x[1]) < bore * (1 + 1e-3); };
  // The slit's faces are free boundary: neither loaded nor on the curved outline (their
  // midpoints lie on the slit's segment, up to rounding).
  const auto slit = with_slit ? slits_[i] : std::nullopt;
  const double on_slit = 1e-6 * pair_.normal_module;
  auto off_slit = [slit, on_slit](const Vec2& x) { return !slit || distance_to_slit(*slit, x) > on_slit; };
  p.loaded = [P, d, b, near, off_slit](const Vec2& x, const Vec2& n) {
    return distance(x, P) < b + 2 * near && n[0] * d[0] + n[1] * d[1] < 0.0 && off_slit(x);
  };
  // Hertz's elliptical pressure p0·√(1 − (r/b)²) (Johnson 1985, eq. 4.44), along the flank.
  p.intensity = [P, b](const Vec2& x) {
    const double r = distance(x, P) / b;
    return r < 1.0 ? std::sqrt(1.0 - r * r) : 0.0;
  };
  p.load_direction = d;
  p.force_per_thickness = options_.load_per_width;
  p.refine_centre = P;
  p.refine_radius = 2 * b;
  p.refine_size = 0.5 * b;
  if (options_.rigid_body)
    p.stiffness_factor = [root](const Vec2& x) { return std::hypot(x[0], x[1]) < root ? 1e3 : 1.0; };
  const auto* line = &outline_[i];
  p.on_outline = [root, zone, off_slit](const Vec2& x) {
    return std::hypot(x[0], x[1]) > 0.99 * root && std::abs(std::atan2(x[1], x[0])) < zone && off_slit(x);
  };
  p.project = [line](const Vec2& x) { return project_onto(*line, x); };
  // Probe: where the load line crosses the tooth centre line (y = 0).
  c.probe = {P[0] - P[1] / d[1] * d[0], 0.0};
  p.probe = c.probe;
  c.cracked = slit.has_value();
  if (slit) c.probe_to_crack = distance_to_slit(*slit, c.probe);
  p.probe_direction = d;
  // Sampling window: the loaded tooth from 1.5 modules under the root circle to the tip,
  // and half a tooth space either side.
  const double m = pair_.normal_module;
  p.field_lower = {root - 1.5 * m, -0.5 * t.radii.tip * 2 * pi / t.teeth};
  p.field_upper = {t.radii.tip, 0.5 * t.radii.tip * 2 * pi / t.teeth};
  p.field_spacing = field_spacing;
  auto fe_options = options_.fe;
  fe_options.vtu = vtu;
  c.fe = fe_backend().solve_elastic(p, fe_options);
  c.compliance = c.fe.value / (options_.load_per_width * pair_.face_width);
  c.contact_compliance = c.fe.cycles.back().load_displacement / (options_.load_per_width * pair_.face_width);
  c.seconds = c.fe.seconds;
  return c;
}

FePosition FeToothStiffness::at(double s, bool vtu) const {
  FePosition r;
  r.path_position = s;
  r.tooth = {tooth_compliance(0, s, vtu), tooth_compliance(1, s)};
  r.hertz_compliance = hertz_line_compliance(materials_[0], materials_[1], pair_.face_width);
  r.pair_stiffness = 1.0 / (r.tooth[0].compliance + r.tooth[1].compliance + r.hertz_compliance);
  r.pair_stiffness_fe_contact = 1.0 / (r.tooth[0].contact_compliance + r.tooth[1].contact_compliance);
  return r;
}

FeToothResult FeToothStiffness::solve(const std::vector<double>& positions) const {
  const auto start = std::chrono::steady_clock::now();
  FeToothResult r;
  r.options_given = r.options_used = options_;
  r.options_used.bore_radius = bore_;
  r.path = path_;
  r.radii = {teeth_[0].radii, teeth_[1].radii};
  r.bore_radius = bore_;
  r.initial_cells = {meshes_[0].quads.size(), meshes_[1].quads.size()};
  for (std::size_t k = 0; k < positions.size(); ++k) {
    const double s = positions[k];
    if (!(s >= path_.A - 1e-12 && s <= path_.E + 1e-12))
      throw InputError(fmt::format("position {} mm lies outside the path of contact [{}, {}] mm", s * 1e3,
                                   path_.A * 1e3, path_.E * 1e3));
    r.positions.push_back(at(s, options_.vtu && k == 0));
    for (const auto& t : r.positions.back().tooth) r.converged = r.converged && t.fe.converged;
  }
  r.message = convergence_message(r);
  if (options_.vtu && !r.positions.empty()) r.vtu = std::move(r.positions.front().tooth[0].fe.vtu);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

FeToothResult FeToothStiffness::solve() const {
  const int n = options_.positions;
  std::vector<double> s;
  for (int i = 0; i < n; ++i) s.push_back(n == 1 ? 0.5 * (path_.A + path_.E) : path_.A + (path_.E - path_.A) * i / (n - 1));
  return solve(s);
}

std::string FeToothResult::summary() const {
  unsigned dofs = 0;
  for (const auto& p : positions)
    for (const auto& t : p.tooth) dofs = std::max(dofs, t.fe.cycles.empty() ? 0u : t.fe.cycles.back().dofs);
  const auto& o = options_used;
  return fmt::format("fe_stiffness: {} positions x 2 teeth, plane {}, degree {}: {}; largest mesh {} dofs; {:.1f} s",
                     positions.size(), o.plane_stress ? "stress" : "strain", o.fe.degree,
                     converged ? "converged" : "NOT converged", dofs, seconds);
}

}  // namespace gearbench::reference::fe
