#pragma once
// Plain input data: elastic solids, operating point and lubricant, in SI units.
#include <array>
#include <optional>

namespace gearbench::model {

struct Material {
  double youngs_modulus = 0.0;  ///< E [Pa]
  double poisson_ratio = 0.0;   ///< ν [-]
  double density = 0.0;         ///< [kg/m³]
};

/// E′ = 2/((1 − ν1²)/E1 + (1 − ν2²)/E2) [Pa], the plane-strain modulus of two bodies in
/// contact (Johnson, Contact Mechanics, 1985, §4.2; Dowson & Higginson's reduced modulus).
inline double reduced_modulus(const std::array<Material, 2>& m) {
  return 2.0 / ((1.0 - m[0].poisson_ratio * m[0].poisson_ratio) / m[0].youngs_modulus +
                (1.0 - m[1].poisson_ratio * m[1].poisson_ratio) / m[1].youngs_modulus);
}

struct OperatingPoint {
  double pinion_speed = 0.0;         ///< ω1 [rad/s]
  double pinion_torque = 0.0;        ///< T1 [N·m]
  double oil_temperature = 0.0;      ///< [K]
  std::array<double, 2> roughness_Ra{};  ///< arithmetic mean roughness per flank [m]
};

/// Lubricant data; which fields a solver needs depends on its kind.
struct Lubricant {
  double viscosity = 0.0;                      ///< η0 at the oil temperature [Pa·s]
  double pressure_viscosity = 0.0;             ///< α [1/Pa]
  std::optional<double> roelands_z;            ///< Roelands pressure index z [-]
  std::optional<double> density;               ///< ρ0 [kg/m³]
  std::optional<double> nu40;                  ///< kinematic viscosity at 40 °C [m²/s]
  std::optional<double> nu100;                 ///< kinematic viscosity at 100 °C [m²/s]
  std::optional<double> thermal_conductivity;  ///< [W/(m·K)]
  std::optional<double> specific_heat;         ///< [J/(kg·K)]
};

}  // namespace gearbench::model
