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
#include "model/option_table.h"
#include "cubic_spline.h"
#include "pair_stiffness.h"

namespace gearbench::stiffness {

/// The "crack" section of a case: {"type", "length_mm", "angle_deg", "gear"}; `max_gear` is
/// 2 where either gear may carry the crack, 1 where only the pinion may.
const model::OptionTable<GearCrack>& crack_table(int max_gear = 2);

/// The key "fillet": the root fillet of the energy-method tooth, for every Options that
/// builds one (the stiffness kind's, the dynamics models').
const model::OptionTable<Fillet>& fillet_table();

/// Case keys at the case's root (the table below); defaults are the initialisers here.
struct MeshStiffnessOptions {
  BeamStart beam_start = BeamStart::improved;
  Fillet fillet = Fillet::trochoid;  ///< of the improved beam (docs/stiffness-model.md)
  int positions = 360;            ///< mesh positions over one mesh cycle
  int path_points = 201;          ///< points of the single-pair curve along A..E
  int slices = 50;                ///< face-width slices of a helical pair (spur: 1)
  int spline_nodes = 1025;        ///< sliced pairs: nodes of the single-pair spline on A..E
  bool foundation = true;         ///< include the Sainsot fillet foundation
  std::optional<std::array<double, 2>> bore_radius;  ///< r_int [m]; default r_f/2
  std::optional<GearCrack> crack;

  /// The keys, units, ranges and descriptions of these options (case units).
  static const model::OptionTable<MeshStiffnessOptions>& table();
  /// Throws InputError naming the option key, its value and the allowed range.
  void validate() const { table().validate(*this); }
};

struct MeshStiffnessResult {
  // Healthy teeth: one mesh cycle (the pinion turns 2π/z1), position 0 a pair entering
  // contact at A. With a crack: the cracked tooth's whole engagement A..E (ε_α cycles),
  // the cracked pair in series with healthy neighbours.
  std::vector<double> mesh_position;      ///< pinion rotation [rad]
  std::vector<double> mesh_stiffness;     ///< [N/m], all pairs (and slices, halves)
  std::vector<double> healthy_mesh_stiffness;  ///< with a crack: the same positions, healthy
  // One pair along its path A..E (transverse, whole face width as one slice).
  std::vector<double> path_position;      ///< s from T1 [m]
  std::vector<double> single_pair_stiffness;  ///< [N/m]
  std::array<std::vector<double>, 2> bending, shear, axial, foundation;  ///< [N/m] per gear
  double hertz = 0.0;                     ///< [N/m]
  double mean = 0.0, min = 0.0, max = 0.0;  ///< of mesh_stiffness [N/m]
  double face_width_total = 0.0;          ///< [m] (both halves of a herringbone pair)
  int slices = 1;
  std::vector<std::string> warnings;
  /// The options as given to the solver and as it used them (Ceres' *_given/*_used): a spur
  /// pair is one slice and needs no spline, a helical one spreads the spline over A..E.
  MeshStiffnessOptions options_given, options_used;

  /// Mean mesh stiffness per face width [N/(mm·µm)].
  [[nodiscard]] double mean_per_face_width() const;
};

class MeshStiffness {
 public:
  /// Keeps a reference to `geometry`, which must outlive this object.
  MeshStiffness(const geometry::GearPairGeometry& geometry,
                const std::array<model::Material, 2>& materials, MeshStiffnessOptions options);

  [[nodiscard]] MeshStiffnessResult solve() const;

 private:
  [[nodiscard]] std::array<double, 2> bore_radii() const;
  void single_pair_curve(MeshStiffnessResult& r) const;
  void mesh_cycle(MeshStiffnessResult& r) const;
  /// Stiffness per unit width of all pairs in contact on a transverse slice whose
  /// reference pair is at s0; `cracked_reference` makes that pair the cracked one.
  [[nodiscard]] double transverse_stiffness_per_width(double s0, bool cracked_reference) const;
  /// Healthy pair stiffness per width at s: from the cubic spline of the single-pair curve
  /// for sliced (helical) pairs, where every slice revisits the same curve, else direct.
  [[nodiscard]] double pair_stiffness_per_width(double s, bool healthy) const;

  const geometry::GearPairGeometry& geometry_;
  MeshStiffnessOptions options_;
  PairStiffness pair_;
  std::optional<CubicSpline> healthy_curve_;
};

}  // namespace gearbench::stiffness
