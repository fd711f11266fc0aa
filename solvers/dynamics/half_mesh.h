#pragma once
// The mesh excitation of one helical half of a herringbone pair (docs/dynamics-model.md,
// "12-DOF herringbone model", sections "Mesh stiffness per half" and "Friction arms"):
// the time-varying normal mesh stiffness k_m(t) and the friction torque arms χ_p(t), χ_g(t)
// of seed 000 eq. 5, as functions of the time within a mesh cycle.
//
// Helical (β_b > 0): k_m from the face-width slicing of stiffness::MeshStiffness, the arms
// from the same slices, tabulated over one mesh cycle and represented by their leading mesh
// harmonics (FFTW): the right-hand side is smooth and needs no restarts, and the steps of
// the finite slices (near slices × the mesh frequency) are filtered out.
// Spur (β_b = 0): the transverse pair sum of the 6-DOF model (SpurMesh, the same object the
// 6-DOF model uses), evaluated directly, with its switch times (a pair enters, leaves,
// passes the pitch point).
//
// With a friction law (docs/dynamics-model.md, "Friction laws") the arms depend on the
// half's instantaneous normal force F: spur, per pair from its share F·k_j/Σk; helical,
// tabulated (and represented by their harmonics) at the load levels F_l = (l/4)·F_nom,
// l = 0..12, F_nom = T_p/(R_p·cos β_b), and interpolated linearly in F between them (held
// at the top level beyond 3·F_nom).
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "geometry/gear_pair_geometry.h"
#include "model/materials.h"
#include "pair_friction.h"
#include "spur_mesh.h"

namespace gearbench::dynamics {

/// k_m and the arms at one instant. χ_p, χ_g [m] include μ: the friction moments are
/// −F_n·χ_p on the pinion and +F_n·χ_g on the wheel.
struct MeshPoint {
  double stiffness = 0.0;  ///< k_m [N/m]
  double rate = 0.0;       ///< dk_m/dt [N/(m·s)]
  double chi_pinion = 0.0;
  double chi_wheel = 0.0;
};

/// A truncated Fourier series of a periodic table (FFTW): y given at N equally spaced
/// points from 0 over one period, harmonics 0..H kept.
class FourierSeries {
 public:
  FourierSeries(double period, const std::vector<double>& y, int harmonics);
  [[nodiscard]] double value(double t) const;
  /// The values of several series of one period and length at t, and the first one's
  /// derivative, on one rotation e^{ikωt} (one sincos for all; no allocation): what a
  /// right-hand side needs of k_m and the arms.
  static void evaluate(double t, std::span<const FourierSeries* const> series, std::span<double> values,
                       double& first_derivative);
  /// Largest |series − table| at the table's points.
  [[nodiscard]] double max_table_deviation() const { return deviation_; }

 private:
  double omega_ = 0.0;  ///< 2π/period
  std::vector<double> a_, b_;  ///< cos and sin coefficients, index = harmonic
  double deviation_ = 0.0;
};

struct HalfMeshOptions {
  int slices = 100;     ///< face-width slices of a helical half
  int positions = SpurMesh::mean_positions;  ///< table points over one mesh cycle (helical)
  int harmonics = 24;   ///< mesh harmonics kept of the tables (helical); the slicing's steps lie far above
  FrictionLawOptions friction;  ///< μ = 0 unless the case gives one
  stiffness::Fillet fillet = stiffness::Fillet::trochoid;  ///< of the energy-method tooth (mesh stiffness)

  /// The "mesh" section's keys: slices, positions, harmonics (friction and fillet are root keys
  /// of a case, in Herringbone12Options' table).
  static const model::OptionTable<HalfMeshOptions>& table();
  void validate() const;  ///< InputError naming the key
};

class HalfMesh {
 public:
  /// `geometry` is the herringbone pair (face width per half) or a spur pair; it must
  /// outlive this object.
  HalfMesh(const geometry::GearPairGeometry& geometry, const std::array<model::Material, 2>& materials,
           const model::OperatingPoint& operating, HalfMeshOptions options);

  /// The excitation at time t of the half's own mesh clock (t = 0: a pair enters at A on
  /// the front face), the pair set of the interval holding t_mid (spur; ignored helical).
  /// Under a friction law the arms are those at the nominal force F_nom (see arms()).
  [[nodiscard]] MeshPoint at(double t, double t_mid) const;
  /// Whether the arms depend on the load (a friction law other than the constant one).
  [[nodiscard]] bool load_dependent_friction() const { return !friction_.constant(); }
  /// χ_p, χ_g [m] under the friction law at time t with the half's normal force F [N]
  /// (its magnitude loads the contacts).
  [[nodiscard]] std::array<double, 2> arms(double t, double t_mid, double force) const;
  /// Times in (t0, t1) of the half's own clock where the excitation jumps (spur only).
  [[nodiscard]] std::vector<double> switch_times(double t0, double t1) const;
  [[nodiscard]] double period() const { return period_; }
  [[nodiscard]] double mean_stiffness() const { return mean_.stiffness; }
  [[nodiscard]] const MeshPoint& mean() const { return mean_; }
  /// Largest relative difference between MeshStiffness's slicing and the slices summed
  /// here for the arms (helical; 0 for spur).
  [[nodiscard]] double slicing_consistency() const { return consistency_; }
  /// Largest deviation of the truncated series of k_m from its table, relative to k̄ (helical).
  [[nodiscard]] double truncation() const { return truncation_; }

 private:
  /// Every contact of every slice with the front face's reference pair at s0 (helical).
  [[nodiscard]] std::vector<MeshContact> helical_contacts(double s0) const;
  [[nodiscard]] MeshPoint spur_point(double t, double t_mid, double force) const;
  void build_tables(const std::array<model::Material, 2>& materials);
  void build_load_levels();

  const geometry::GearPairGeometry& geometry_;
  HalfMeshOptions options_;
  SpurMesh spur_;  ///< the transverse pairs: the spur half itself, a helical half's single-pair curve
  double period_ = 0.0;  ///< T_mesh = p_bt/u [s]
  std::optional<FourierSeries> k_, chi_p_, chi_g_;
  PairFriction friction_;
  double nominal_force_ = 0.0;  ///< F_nom = T_p/(R_p·cos β_b) per half [N]
  std::vector<FourierSeries> chi_p_levels_, chi_g_levels_;  ///< arms at F_l = (l/4)·F_nom, l = 0..12
  MeshPoint mean_;
  double consistency_ = 0.0, truncation_ = 0.0;
};

}  // namespace gearbench::dynamics
