#include "mesh_stiffness.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <numeric>

#include "hertz.h"
#include "model/errors.h"

namespace gearbench::stiffness {

void MeshStiffnessOptions::validate() const {
  if (positions < 2 || positions > 100000)
    throw InputError(fmt::format("positions = {}: allowed range is [2, 100000]", positions));
  if (path_points < 2 || path_points > 100000)
    throw InputError(fmt::format("path_points = {}: allowed range is [2, 100000]", path_points));
  if (slices < 1 || slices > 10000)
    throw InputError(fmt::format("slices = {}: allowed range is [1, 10000]", slices));
  if (crack && (crack->gear < 0 || crack->gear > 1))
    throw InputError(fmt::format("crack.gear = {}: allowed values are 1, 2", crack->gear + 1));
}

double MeshStiffnessResult::mean_per_face_width() const {
  return mean / (face_width_total * 1e3) * 1e-6;
}

MeshStiffness::MeshStiffness(const geometry::GearPairGeometry& geometry,
                             const std::array<model::Material, 2>& materials,
                             MeshStiffnessOptions options)
    : geometry_(geometry),
      options_((options.validate(), std::move(options))),
      pair_(geometry, materials, options_.beam_start, bore_radii(), options_.crack, options_.foundation) {}

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

double MeshStiffness::transverse_stiffness_per_width(double s0) const {
  const auto& p = geometry_.path();
  const double pb = geometry_.base_pitch_transverse();
  double k = 0.0;
  for (double s = s0 - std::floor((s0 - p.A) / pb) * pb; s <= p.E; s += pb)
    k += pair_.stiffness_per_width(s);
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
  for (int i = 0; i < options_.positions; ++i) {
    const double s0 = geometry_.path().A + pb * i / options_.positions;
    double k = 0.0;
    for (int j = 0; j < r.slices; ++j)
      k += slice_width * transverse_stiffness_per_width(s0 - (j + 0.5) * slice_width * tan_bb);
    r.mesh_position.push_back((s0 - geometry_.path().A) / rb1);
    r.mesh_stiffness.push_back(halves * k);
  }
  const auto [lo, hi] = std::minmax_element(r.mesh_stiffness.begin(), r.mesh_stiffness.end());
  r.min = *lo;
  r.max = *hi;
  r.mean = std::accumulate(r.mesh_stiffness.begin(), r.mesh_stiffness.end(), 0.0) /
           static_cast<double>(r.mesh_stiffness.size());
}

}  // namespace gearbench::stiffness
