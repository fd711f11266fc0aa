#pragma once
// The transverse mesh excitation of a spur pair (docs/dynamics-model.md, "Mesh"): the pairs in
// contact at time t of the mesh clock (t = 0: a pair enters at A), their energy-method
// single-pair stiffness and its rate, the sliding direction of each, the times where the pair
// set changes, and the cycle means of the stiffness and of the friction arms.
//
// One piece for the 6-DOF spur model (Spur6Dynamics) and the spur halves of the 12-DOF model
// (HalfMesh with β_b = 0); a helical half takes its single-pair curve k_pair(s) for the slices.
#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "geometry/gear_pair_geometry.h"
#include "model/materials.h"
#include "pair_friction.h"
#include "stiffness/cubic_spline.h"
#include "stiffness/pair_stiffness.h"

namespace gearbench::dynamics {

/// One contact: position s [m from T1], stiffness k [N/m], sliding sign λ.
struct MeshContact {
  double s = 0.0, k = 0.0, lambda = 0.0;
};

/// Sliding reverses at the pitch point: λ = +1 beyond C (the pinion flank slides ahead), −1
/// before it, 0 at C (docs/dynamics-model.md, "Friction").
[[nodiscard]] inline double sliding_sign(double s, double C) { return s > C ? 1.0 : (s < C ? -1.0 : 0.0); }

/// The friction arms [m] of contacts sharing the normal force F in proportion to their
/// stiffness (docs, "Friction arms", seed 000 eq. 5): χ_1 = scale·Σ f_c·λ_c·k_c·ρ_1c / Σk,
/// χ_2 = scale·Σ f_c·λ_c·k_c·ρ_2c / Σk, ρ_1 = s, ρ_2 = T1T2 − s, f_c = the law's factor at
/// the load per length |F|·(k_c/Σk)/`length`. Zero without contacts.
[[nodiscard]] std::array<double, 2> friction_arms(std::span<const MeshContact> contacts, const PairFriction& friction,
                                                  double T1T2, double force, double length);

/// A pair in contact during one interval between break times.
struct SpurPair {
  double s = 0.0;       ///< position at t, on A..E [m from T1]
  double s_mid = 0.0;   ///< position at the interval's midpoint
  double stiffness = 0.0;  ///< k_j [N/m], whole face width
  double rate = 0.0;       ///< dk_j/dt [N/(m·s)]
  double lambda = 0.0;     ///< sliding sign of the whole interval
};

/// The pairs of one interval (at most three: 1 ≤ ε_α < 2 keeps two, a pair exactly at E a third).
struct SpurPairs {
  std::array<SpurPair, 3> pair{};
  std::size_t count = 0;
  [[nodiscard]] const SpurPair* begin() const { return pair.data(); }
  [[nodiscard]] const SpurPair* end() const { return pair.data() + count; }
};

class SpurMesh {
 public:
  /// Positions over one mesh cycle of the means (k̄ at A + i·p_bt/N, the arms at the midpoints).
  static constexpr int mean_positions = 720;

  /// `geometry` must outlive this object. `crack`: a cracked pinion tooth (tooth 0).
  SpurMesh(const geometry::GearPairGeometry& geometry, const std::array<model::Material, 2>& materials,
           double pinion_speed, stiffness::Fillet fillet, const std::optional<stiffness::GearCrack>& crack = std::nullopt);

  /// Single-pair stiffness k_pair(s) [N/m] of a healthy pair (spline), or of the cracked
  /// tooth's pair with its crack acting or not (integrated directly); s is clamped to A..E.
  [[nodiscard]] double pair_stiffness(double s, bool cracked_tooth = false, bool crack_acting = false) const;
  /// The pairs of the interval holding t_mid at time t (docs, "Mesh"): n whole base pitches
  /// have passed; pair j, j base pitches ahead of the newest, carries pinion tooth (n − j) mod z1.
  [[nodiscard]] SpurPairs pairs(double t, double t_mid) const;
  /// Times in (t0, t1) where the pair set or a pair's friction or crack state changes, sorted.
  [[nodiscard]] std::vector<double> break_times(double t0, double t1) const;
  /// k̄ [N/m] over one mesh cycle, healthy pairs.
  [[nodiscard]] double mean_stiffness() const { return mean_stiffness_; }
  /// The cycle means of friction_arms over the midpoints u·t = (i + ½)·p_bt/N at the normal
  /// force F [N] over the face width (healthy pairs).
  [[nodiscard]] std::array<double, 2> mean_arms(const PairFriction& friction, double force) const;
  [[nodiscard]] double contact_speed() const { return speed_; }  ///< u = ω1·r_b1 [m/s]
  [[nodiscard]] double period() const { return period_; }        ///< T_mesh = p_bt/u [s]
  /// s where a pitch crack starts to act: the pinion's reference point.
  [[nodiscard]] double crack_mouth() const { return crack_mouth_; }

 private:
  const geometry::GearPairGeometry& geometry_;
  std::optional<stiffness::GearCrack> crack_;
  stiffness::PairStiffness pair_;
  std::optional<stiffness::CubicSpline> healthy_;
  /// One spline cursor per pair slot j of pairs(): a cache that const calls move, so a SpurMesh
  /// is not to be shared between threads.
  mutable std::array<stiffness::CubicSpline::Cursor, 3> cursors_;
  double speed_ = 0.0, period_ = 0.0, crack_mouth_ = 0.0, mean_stiffness_ = 0.0;
};

}  // namespace gearbench::dynamics
