#pragma once
// Energy-method mesh stiffness over one mesh cycle (production solver #2): healthy or
// cracked spur teeth, helical and herringbone pairs by slicing the face width.
//
// Pipeline: geometry → tooth profiles → cumulative section integrals → pair stiffness
// along the path A..E → sum of the pairs (and slices) in contact at each mesh position.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geometry/gear_pair_geometry.h"
#include "pair_stiffness.h"

namespace gearbench::stiffness {

struct MeshStiffnessOptions {
  BeamStart beam_start = BeamStart::improved;
  int positions = 360;            ///< mesh positions over one mesh cycle
  int path_points = 201;          ///< points of the single-pair curve along A..E
  int slices = 50;                ///< face-width slices of a helical pair (spur: 1)
  bool foundation = true;         ///< include the Sainsot fillet foundation
  std::optional<std::array<double, 2>> bore_radius;  ///< r_int [m]; default r_f/2
  std::optional<GearCrack> crack;

  /// Throws InputError naming the option key.
  void validate() const;
};

struct MeshStiffnessResult {
  // One mesh cycle: the pinion turns 2π/z1; position 0 is a pair entering contact at A.
  std::vector<double> mesh_position;      ///< pinion rotation [rad]
  std::vector<double> mesh_stiffness;     ///< [N/m], all pairs (and slices, halves)
  // One pair along its path A..E (transverse, whole face width as one slice).
  std::vector<double> path_position;      ///< s from T1 [m]
  std::vector<double> single_pair_stiffness;  ///< [N/m]
  std::array<std::vector<double>, 2> bending, shear, axial, foundation;  ///< [N/m] per gear
  double hertz = 0.0;                     ///< [N/m]
  double mean = 0.0, min = 0.0, max = 0.0;  ///< of mesh_stiffness [N/m]
  double face_width_total = 0.0;          ///< [m] (both halves of a herringbone pair)
  int slices = 1;
  std::vector<std::string> warnings;

  /// Mean mesh stiffness per face width [N/(mm·µm)].
  [[nodiscard]] double mean_per_face_width() const;
};

class MeshStiffness {
 public:
  MeshStiffness(const geometry::GearPairGeometry& geometry,
                const std::array<model::Material, 2>& materials, MeshStiffnessOptions options);

  [[nodiscard]] MeshStiffnessResult solve() const;

 private:
  [[nodiscard]] std::array<double, 2> bore_radii() const;
  void single_pair_curve(MeshStiffnessResult& r) const;
  void mesh_cycle(MeshStiffnessResult& r) const;
  /// Stiffness per unit width of all pairs in contact on a transverse slice whose
  /// reference contact is at s0.
  [[nodiscard]] double transverse_stiffness_per_width(double s0) const;

  const geometry::GearPairGeometry& geometry_;
  MeshStiffnessOptions options_;
  PairStiffness pair_;
};

}  // namespace gearbench::stiffness
