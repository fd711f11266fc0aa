#pragma once
// Dynamic mesh efficiency from a mesh-force time series (seed 000 §2.2, eq. 12): the
// static loss over one mesh period is computed at a few load levels spanning the dynamic
// force range, and the loss at each instant is interpolated from these loss-versus-load
// curves at the instant's mesh phase and force:
//   η_D(t) = 1 − Σ_meshes P[F_n,j(t)] / P_in.
// The force series may come from solvers/dynamics (Spur6Result::mesh_force: the total
// force along the line of action, one mesh) or from a model with several meshes (the two
// halves of a herringbone pair, each a helical mesh).
#include <vector>

#include "mesh_loss.h"

namespace gearbench::efficiency {

struct DynamicEfficiencyOptions {
  int load_levels = 5;   ///< loss curves between the smallest and largest force (seed 000: 5)
  int phases = 100;      ///< mesh positions per loss curve

  /// The keys "load_levels" and "phases" (of the dynamics kind's "dynamic_efficiency" section).
  static const model::OptionTable<DynamicEfficiencyOptions>& table();
  void validate() const { table().validate(*this, "dynamic_efficiency."); }  ///< InputError naming the key
};

struct DynamicEfficiencyResult {
  std::vector<double> time;         ///< [s], as given
  std::vector<double> efficiency;   ///< η_D(t)
  std::vector<double> load_levels;  ///< [N], normal force per mesh
  double mean = 0.0;                ///< mean of η_D over the series
  /// Static efficiency at the nominal operating point, averaged on the same phase grid as
  /// the interpolation (so that the two means differ only by the dynamic loads).
  double static_mean = 0.0;
};

/// The loss-versus-load curves of one drive, in two steps: construction computes the static
/// loss over one mesh period at the nominal force per mesh, so that a friction law refusing
/// the nominal contact (e.g. a Hertz pressure beyond its range) fails there, before the
/// dynamics run whose forces evaluate() then takes.
///
/// `mesh_geometry`: the geometry of ONE mesh (a spur pair or one helical half; a herringbone
/// pair is given as its half and two force series), kept as a copy.
/// `nominal`: the operating point of the whole drive (P_in = T1·ω1; the nominal force per
/// mesh is T1/(r_b1·cos β_b)/meshes).
class DynamicEfficiency {
 public:
  DynamicEfficiency(const geometry::GearPairGeometry& mesh_geometry, const model::OperatingPoint& nominal,
                    MeshLossOptions loss_options, MeshLossMedia media, std::size_t meshes,
                    DynamicEfficiencyOptions options = {});

  /// `mesh_forces[j][i]`: normal force of mesh j at time[i] [N], one series per mesh; a
  /// force ≤ 0 (contact loss) dissipates nothing. The mesh phase is t·mesh_frequency, zero
  /// when a pair enters at A (the convention of Spur6Dynamics' recorded time).
  [[nodiscard]] DynamicEfficiencyResult evaluate(const std::vector<double>& time,
                                                 const std::vector<std::vector<double>>& mesh_forces,
                                                 double mesh_frequency) const;

 private:
  [[nodiscard]] std::vector<double> loss_curve(double normal_force) const;

  geometry::GearPairGeometry geometry_;
  model::OperatingPoint nominal_;
  MeshLossOptions loss_options_;
  MeshLossMedia media_;
  std::size_t meshes_;
  DynamicEfficiencyOptions options_;
  std::vector<double> static_curve_;  ///< loss at the nominal force per mesh [W]
};

/// DynamicEfficiency of mesh_forces.size() meshes, evaluated at once.
DynamicEfficiencyResult dynamic_efficiency(const geometry::GearPairGeometry& mesh_geometry,
                                           const model::OperatingPoint& nominal, const MeshLossOptions& loss_options,
                                           const MeshLossMedia& media, const std::vector<double>& time,
                                           const std::vector<std::vector<double>>& mesh_forces,
                                           double mesh_frequency, DynamicEfficiencyOptions options = {});

}  // namespace gearbench::efficiency
