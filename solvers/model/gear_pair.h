#pragma once
// Plain input data of a cylindrical gear pair, in SI units (m, rad). No algorithms here:
// the involute geometry lives in solvers/geometry.
#include <array>
#include <optional>

namespace gearbench::model {

/// Herringbone pair: two helical halves of opposite hand separated by a groove.
struct Herringbone {
  double groove_width = 0.0;  ///< axial gap between the halves [m]
};

/// External cylindrical gear pair, index 0 = pinion (gear 1), 1 = wheel (gear 2).
/// Rack-profile coefficients refer to the normal module (ISO 53 basic rack by default).
struct GearPair {
  std::array<int, 2> teeth{};
  double normal_module = 0.0;           ///< m_n [m]
  double normal_pressure_angle = 0.0;   ///< α_n [rad]
  double helix_angle = 0.0;             ///< β at the reference cylinder [rad]; for a
                                        ///< herringbone pair, of each half
  double face_width = 0.0;              ///< b [m]; for a herringbone pair, of each half
  std::array<double, 2> profile_shift{};  ///< x1, x2 [-]
  double addendum_coef = 1.0;           ///< h_a* of the gear (h_fP* − c* of the rack)
  double dedendum_coef = 1.25;          ///< h_f* of the gear (addendum of the cutting rack)
  double root_radius_coef = 0.38;       ///< ρ_fP* of the rack tip radius
  std::optional<double> center_distance;             ///< a [m]; else from the shifts
  std::optional<std::array<double, 2>> tip_diameter; ///< d_a [m]; else d + 2 m_n (h_a* + x)
  std::optional<Herringbone> herringbone;

  /// The pair that one mesh of this pair forms: the pair itself, or one helical half of a
  /// herringbone pair (whose helix angle and face width are already those of a half).
  [[nodiscard]] GearPair one_mesh() const {
    GearPair mesh = *this;
    mesh.herringbone.reset();
    return mesh;
  }
};

}  // namespace gearbench::model
