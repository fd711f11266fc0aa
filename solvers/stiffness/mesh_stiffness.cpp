#include "mesh_stiffness.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <numeric>

#include "hertz.h"
#include "model/errors.h"

namespace gearbench::stiffness {

namespace {
void reject_helical_crack(const geometry::GearPairGeometry& g, const MeshStiffnessOptions& o) {
  if (o.crack && g.base_helix_angle() > 0.0)
    throw InputError(fmt::format("gear_pair.helix_angle_deg = {:.6g}: cracks are modelled for spur gears only "
                                 "(allowed is 0 with a crack)", g.pair().helix_angle * 180.0 / M_PI));
}
}  // namespace

double MeshStiffnessResult::mean_per_face_width() const {
  return mean / (face_width_total * 1e3) * 1e-6;
}

MeshStiffness::MeshStiffness(const geometry::GearPairGeometry& geometry,
                             const std::array<model::Material, 2>& materials,
                             MeshStiffnessOptions options)
    : geometry_(geometry),
      options_((options.validate(), reject_helical_crack(geometry, options), std::move(options))),
      pair_(geometry, materials, {options_.beam_start, options_.fillet}, bore_radii(), options_.crack,
            options_.foundation) {
  if (geometry_.base_helix_angle() > 0.0 && options_.slices > 1) {
    const auto& p = geometry_.path();
    std::vector<double> s(static_cast<std::size_t>(options_.spline_nodes)), k(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
      s[i] = p.A + (p.E - p.A) * static_cast<double>(i) / static_cast<double>(s.size() - 1);
      k[i] = pair_.stiffness_per_width(s[i], true);
    }
    healthy_curve_.emplace(std::move(s), std::move(k));
  }
}

double MeshStiffness::pair_stiffness_per_width(double s, bool healthy) const {
  const auto& p = geometry_.path();
  if (!healthy || !healthy_curve_ || s < p.A || s > p.E) return pair_.stiffness_per_width(s, healthy);
  return (*healthy_curve_)(s);
}

// Default bore: half the root radius (h_f = 2, inside Sainsot's fitted range).
std::array<double, 2> MeshStiffness::bore_radii() const {
  if (options_.bore_radius) {
    for (int gear = 0; gear < 2; ++gear)
      if ((*options_.bore_radius)[gear] >= geometry_.radii(gear).root)
        throw InputError(fmt::format(
            "bore_diameter_mm[{}] = {:.10g}: must be below the root diameter {:.4f} mm", gear,
            2e3 * (*options_.bore_radius)[gear], 2e3 * geometry_.radii(gear).root));
    return *options_.bore_radius;
  }
  return {0.5 * geometry_.radii(0).root, 0.5 * geometry_.radii(1).root};
}

MeshStiffnessResult MeshStiffness::solve() const {
  MeshStiffnessResult r;
  r.slices = geometry_.base_helix_angle() > 0.0 ? options_.slices : 1;
  r.options_given = options_;
  r.options_used = options_;
  r.options_used.slices = r.slices;
  r.face_width_total = geometry_.pair().face_width * (geometry_.pair().herringbone ? 2.0 : 1.0);
  r.warnings = pair_.warnings();
  single_pair_curve(r);
  mesh_cycle(r);
  return r;
}

void MeshStiffness::single_pair_curve(MeshStiffnessResult& r) const {
  const auto& p = geometry_.path();
  const double b = geometry_.pair().face_width;
  r.hertz = b / pair_.compliance(p.C).hertz;
  for (int i = 0; i < options_.path_points; ++i) {
    const double s = p.A + (p.E - p.A) * i / (options_.path_points - 1);
    const auto c = pair_.compliance(s);
    r.path_position.push_back(s);
    r.single_pair_stiffness.push_back(b / c.total());
    for (std::size_t g = 0; g < 2; ++g) {
      r.bending[g].push_back(b / c.tooth[g].bending);
      r.shear[g].push_back(b / c.tooth[g].shear);
      r.axial[g].push_back(b / c.tooth[g].axial);
      r.foundation[g].push_back(options_.foundation ? b / c.foundation[g] : 0.0);
    }
  }
}

double MeshStiffness::transverse_stiffness_per_width(double s0, bool cracked_reference) const {
  const double pb = geometry_.base_pitch_transverse();
  double k = 0.0;
  for (const double s : geometry_.positions_in_contact(s0)) {
    const bool is_reference = std::abs(s - s0) < 0.5 * pb;
    k += pair_stiffness_per_width(s, !(cracked_reference && is_reference));
  }
  return k;
}

// A slice j of width b/N at face position y_j = (j + ½)b/N meets the contact that is at
// s0 on the front face at s0 − y_j·tan β_b (contact lines inclined at β_b on the base plane).
void MeshStiffness::mesh_cycle(MeshStiffnessResult& r) const {
  const double pb = geometry_.base_pitch_transverse();
  const double b = geometry_.pair().face_width;
  const double slice_width = b / r.slices;
  const double tan_bb = std::tan(geometry_.base_helix_angle());
  const double halves = geometry_.pair().herringbone ? 2.0 : 1.0;
  const double rb1 = geometry_.radii(0).base;
  // A cracked tooth is followed through its engagement A..E; healthy teeth repeat every
  // base pitch, so one mesh cycle [A, A + p_bt) says everything.
  const bool cracked = pair_.cracked();
  const double span = cracked ? geometry_.path().E - geometry_.path().A : pb;
  const int last = cracked ? options_.positions - 1 : options_.positions;
  for (int i = 0; i < options_.positions; ++i) {
    const double s0 = geometry_.path().A + span * i / last;
    double k = 0.0;
    for (int j = 0; j < r.slices; ++j)
      k += slice_width * transverse_stiffness_per_width(s0 - (j + 0.5) * slice_width * tan_bb, cracked);
    r.mesh_position.push_back((s0 - geometry_.path().A) / rb1);
    r.mesh_stiffness.push_back(halves * k);
    if (cracked) r.healthy_mesh_stiffness.push_back(b * transverse_stiffness_per_width(s0, false));
  }
  const auto [lo, hi] = std::minmax_element(r.mesh_stiffness.begin(), r.mesh_stiffness.end());
  r.min = *lo;
  r.max = *hi;
  r.mean = std::accumulate(r.mesh_stiffness.begin(), r.mesh_stiffness.end(), 0.0) /
           static_cast<double>(r.mesh_stiffness.size());
}

}  // namespace gearbench::stiffness
