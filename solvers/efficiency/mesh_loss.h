#pragma once
// Mesh power loss and efficiency over one mesh period (production solver #3): the sliding
// loss Σ F·μ·|V_s| over the pairs in contact (spur) or over points on every contact line
// (helical, herringbone), as seed 000 eq. 11 and seed 004 eq. 8 integrate it, plus the
// rolling loss of seed 004 eq. 9 from a Dowson–Higginson film at each contact point.
//
// Pipeline: mesh position → contact points (pair positions, or contact-line points) → load
// per unit length from the sharing rule → kinematics, Hertz pressure, film → friction law
// → sliding and rolling loss → instantaneous efficiency; the mean by Gauss–Legendre on
// the smooth pieces of the period (spur) or by the midpoint rule (helical).
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/gear_pair_geometry.h"
#include "geometry/load_sharing.h"
#include "lubricant/friction_laws.h"
#include "model/materials.h"
#include "model/option_table.h"

namespace gearbench::stiffness {
class PairStiffness;
}

namespace gearbench::efficiency {

class EhlFriction;

/// Case keys of the mesh-loss solver: "friction" {"model", "mu", "mu_boundary",
/// "lubricant_factor", "eyring_stress_MPa"}, "load_sharing", "rolling_loss_constant_Pa",
/// "positions", "points_per_line" (the table; defaults are the initialisers here).
struct MeshLossOptions {
  int positions = 200;            ///< mesh positions over one mesh period (the series)
  int points_per_line = 20;       ///< helical: midpoints along every contact line
  std::string load_sharing = "equal";  ///< equal (Ohlendorf) | iso | stiffness (energy method)
  lubricant::FrictionModel friction_model = lubricant::FrictionModel::constant;
  double friction_coefficient = 0.05;  ///< constant μ ("friction.mu")
  double boundary_friction = 0.1;      ///< μ_BL of the mixed law, seed 000: 0.07–0.15
  double lubricant_factor = 1.0;       ///< X_L of ISO/TR 14179-2 (mineral oil 1)
  std::optional<double> eyring_stress; ///< τ0 [Pa] of the "ehl" law (required there, refused elsewhere;
                                       ///< "ehl_thermal" takes lubricant.eyring_stress_MPa, the film's τ0)
  /// Rolling loss of seed 004 eq. 9, P_r = C_r·h_min·ū·l·cos α_wt per contact [W]. Eq. 9
  /// prints 9·h·u_r·l·cos φ × 10⁻³ [kW] without units. Two readings (see rolling_loss_note
  /// in the .cpp): (a) h in µm, u_r in m/s, l in mm, literally as printed: C_r = 9e9 Pa;
  /// (b) the rolling-traction constant 9e4 of Anderson & Loewenthal (NASA TP-1622, 1980),
  /// which eq. 9 resembles, in psi with h, l in inches: C_r = 9e4·6894.757 = 6.2053e8 Pa
  /// (verify at the source). (a) makes the rolling loss as large as the sliding loss for
  /// seed 004 and 10 % of the input power for the seed 000 herringbone pair, against seed
  /// 004's own finding that the sliding loss dominates by an order of magnitude; (b) is the
  /// default, (a) is available as "rolling_loss_constant_Pa": 9e9.
  double rolling_loss_constant = 6.2053e8;

  /// The keys, units, ranges and descriptions of these options, at a case's root (the
  /// "friction" section's keys from friction_keys.h).
  static const model::OptionTable<MeshLossOptions>& table();
  /// InputError naming the key, its value and the allowed range.
  void validate() const { table().validate(*this); }
};

/// What one contact point (or contact-line element) contributes.
struct ContactLoss {
  double sliding = 0.0;      ///< μ·w·l·|u_s| [W]
  double rolling = 0.0;      ///< C_r·h·ū·l·cos α_wt [W]
  double unit_sliding = 0.0; ///< w·l·|u_s| (the sliding loss per unit μ) [W]
  double force = 0.0;        ///< w·l [N]
  double mu = 0.0;
  double film = 0.0;         ///< h_min [m] (0 without lubricant data)
};

struct MeshLossResult {
  std::vector<double> mesh_position;   ///< pinion rotation over one mesh period [rad]
  std::vector<double> sliding_loss;    ///< [W]
  std::vector<double> rolling_loss;    ///< [W]
  std::vector<double> efficiency;      ///< 1 − (sliding + rolling)/P_in
  std::vector<double> friction_coefficient;  ///< load-weighted μ at each position
  double input_power = 0.0;            ///< T1·ω1 [W]
  double sliding_loss_mean = 0.0, rolling_loss_mean = 0.0, power_loss_mean = 0.0;  ///< [W]
  double efficiency_mean = 0.0, efficiency_min = 0.0, efficiency_max = 0.0;
  double friction_coefficient_mean = 0.0;  ///< mean over the period of the load-weighted μ
  /// Numeric loss factor H_VL = mean of Σ w·l·|u_s| over P_in (= mean sliding loss /
  /// (μ·P_in) for a constant μ).
  double loss_factor_numeric = 0.0;
  bool rolling_loss_computed = false;  ///< needs materials and lubricant
  double film_min = 0.0;               ///< smallest h_min over the period [m] (0: not computed)
};

/// Materials and lubricant: needed by every friction law but the constant one, by the
/// rolling loss and by the stiffness sharing.
struct MeshLossMedia {
  std::optional<std::array<model::Material, 2>> materials;
  std::optional<model::Lubricant> lubricant;
};

class MeshLoss {
 public:
  /// Keeps a reference to `geometry`, which must outlive this object.
  MeshLoss(const geometry::GearPairGeometry& geometry, const model::OperatingPoint& operating,
           MeshLossOptions options, MeshLossMedia media = {});
  ~MeshLoss();
  MeshLoss(const MeshLoss&) = delete;
  MeshLoss& operator=(const MeshLoss&) = delete;

  [[nodiscard]] MeshLossResult solve() const;
  /// Sum over every contact point with the front-face contact of a reference pair at s0.
  [[nodiscard]] ContactLoss loss_at(double s0) const;
  /// Instantaneous sliding loss [W] at s0 (kept for the references' comparisons).
  [[nodiscard]] double sliding_loss(double s0) const { return loss_at(s0).sliding; }
  /// The ISO/TR 14179-2 mean coefficient of this pair (needs lubricant data and Ra > 0).
  [[nodiscard]] double iso14179_coefficient() const;
  /// Contact points solved by the "ehl" or "ehl_thermal" law so far (0 for the other laws).
  [[nodiscard]] int ehl_solves() const;

 private:
  [[nodiscard]] ContactLoss point_loss(double s, double load_per_length, double length) const;
  [[nodiscard]] double friction(const lubricant::ContactState& c) const;
  [[nodiscard]] ContactLoss spur_loss(double s0) const;
  [[nodiscard]] ContactLoss helical_loss(double s0) const;
  [[nodiscard]] ContactLoss spur_mean() const;
  [[nodiscard]] bool has_film() const { return media_.materials && media_.lubricant; }

  const geometry::GearPairGeometry& geometry_;
  model::OperatingPoint operating_;
  MeshLossOptions options_;
  MeshLossMedia media_;
  std::unique_ptr<stiffness::PairStiffness> pair_stiffness_;  ///< stiffness sharing only
  std::unique_ptr<geometry::LoadSharing> sharing_;
  std::unique_ptr<EhlFriction> ehl_friction_;  ///< the "ehl" and "ehl_thermal" laws only
  double reduced_modulus_ = 0.0;
  double iso_mu_ = 0.0;            ///< ISO/TR 14179-2 μ_mZ when that law is chosen
  double cos_alpha_wt_ = 1.0;
};

}  // namespace gearbench::efficiency
