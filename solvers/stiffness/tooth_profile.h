#pragma once
// The tooth of one gear as a variable-section cantilever (docs/stiffness-model.md):
// half thickness h(x) along the centre line from the beam start x_0 to the tip, on the
// fillet arc / straight section below the base circle and on the involute above it.
#include <optional>
#include <vector>

#include "geometry/gear_pair_geometry.h"

namespace gearbench::stiffness {

/// Where the cantilever starts (docs/stiffness-model.md, "Where the beam starts").
enum class BeamStart {
  improved,     ///< root circle, circular-arc fillet below the base circle (seed 003)
  straight,     ///< root circle, constant thickness below the base circle (Chen & Shao 2011)
  base_circle,  ///< base circle (Yang & Lin 1987, Tian 2004)
};

/// A point of the loaded flank: load parameter α_1 (= roll angle − α_2) and coordinates.
struct FlankPoint {
  double alpha = 0.0;  ///< Tian's angle α [rad]
  double x = 0.0;      ///< along the centre line from the gear centre [m]
  double h = 0.0;      ///< half thickness [m]
};

class ToothProfile {
 public:
  ToothProfile(const geometry::GearPairGeometry& pair, int gear, BeamStart start);

  /// Flank point at roll angle ψ = α + α_2 (involute part).
  [[nodiscard]] FlankPoint involute_point(double roll_angle) const;
  /// Half thickness at x ∈ [x_0, x_tip].
  [[nodiscard]] double half_thickness(double x) const;

  [[nodiscard]] double beam_start() const { return x0_; }
  [[nodiscard]] double base_point_x() const { return xB_; }
  [[nodiscard]] double tip_x() const { return tip_.x; }
  [[nodiscard]] double alpha2() const { return alpha2_; }
  [[nodiscard]] double base_radius() const { return Rb_; }
  [[nodiscard]] double root_radius() const { return Rf_; }
  [[nodiscard]] double fillet_radius() const { return rho_; }
  [[nodiscard]] BeamStart start() const { return start_; }
  /// Roll angle of the reference-circle point of the flank (the pitch-crack mouth).
  [[nodiscard]] double reference_roll_angle() const { return reference_roll_; }
  /// Largest x < x_tip at which h(x) = value, if h crosses value on the beam.
  [[nodiscard]] std::optional<double> x_where_thickness(double value) const;

 private:
  [[nodiscard]] double involute_x(double alpha) const;
  [[nodiscard]] double involute_h(double alpha) const;
  /// Inverse of x(α) on the involute by safeguarded Newton iteration.
  [[nodiscard]] double involute_alpha_at(double x) const;

  /// α at equally spaced x over the involute part: a tight bracket and start for Newton.
  void tabulate_involute();

  BeamStart start_;
  std::vector<double> alpha_table_;
  double table_x0_ = 0.0, table_dx_ = 0.0;
  double Rb_ = 0.0, Rf_ = 0.0, alpha2_ = 0.0;
  double xB_ = 0.0, hB_ = 0.0;  ///< base-circle point
  double x0_ = 0.0;             ///< beam start
  double rho_ = 0.0;            ///< fillet arc radius (improved, R_f < R_b)
  double alpha_start_ = 0.0;    ///< involute parameter where the involute part starts
  double reference_roll_ = 0.0;
  FlankPoint tip_;
};

}  // namespace gearbench::stiffness
