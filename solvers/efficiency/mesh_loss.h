#pragma once
// Sliding power loss and mesh efficiency over one mesh period (production solver #3, first
// part): the loss Σ F·μ·|V_s| over the pairs in contact (spur) or over points on every
// contact line (helical, herringbone), as seed 000 eq. 11 and seed 004 eq. 10 integrate it.
// Friction: a constant coefficient for now; the regression laws, the mixed law and the EHL
// traction are still to come, as is the rolling loss (it needs the film thickness).
#include <memory>
#include <string>
#include <vector>

#include "geometry/gear_pair_geometry.h"
#include "geometry/load_sharing.h"
#include "model/materials.h"

namespace gearbench::efficiency {

struct MeshLossOptions {
  int positions = 200;            ///< mesh positions over one mesh period
  int points_per_line = 20;       ///< helical: midpoints along every contact line
  std::string load_sharing = "equal";  ///< equal (Ohlendorf: half per pair in double contact) | iso
  double friction_coefficient = 0.05;  ///< constant μ

  void validate() const;          ///< InputError naming the key
};

struct MeshLossResult {
  std::vector<double> mesh_position;   ///< pinion rotation over one mesh period [rad]
  std::vector<double> sliding_loss;    ///< [W]
  std::vector<double> efficiency;      ///< 1 − loss/P_in
  double input_power = 0.0;            ///< T1·ω1 [W]
  double sliding_loss_mean = 0.0;      ///< [W]; exact piecewise Gauss for spur pairs
  double efficiency_mean = 0.0, efficiency_min = 0.0, efficiency_max = 0.0;
  double friction_coefficient_mean = 0.0;
  /// Numeric loss factor H_VL = mean sliding loss / (μ·P_in) (constant μ).
  double loss_factor_numeric = 0.0;
};

class MeshLoss {
 public:
  MeshLoss(const geometry::GearPairGeometry& geometry, const model::OperatingPoint& operating,
           MeshLossOptions options);
  [[nodiscard]] MeshLossResult solve() const;
  /// Instantaneous sliding loss [W] with the front-face contact of a reference pair at s0.
  [[nodiscard]] double sliding_loss(double s0) const;

 private:
  [[nodiscard]] double sliding_speed(double s) const;  ///< |u1 − u2| at s [m/s]
  [[nodiscard]] double spur_loss(double s0) const;
  [[nodiscard]] double helical_loss(double s0) const;
  [[nodiscard]] double spur_mean_loss() const;

  const geometry::GearPairGeometry& geometry_;
  model::OperatingPoint operating_;
  MeshLossOptions options_;
  std::unique_ptr<geometry::LoadSharing> sharing_;
};

}  // namespace gearbench::efficiency
