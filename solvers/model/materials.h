#pragma once
// Plain input data: elastic solids, operating point and lubricant, in SI units.
#include <array>
#include <optional>

namespace gearbench::model {

struct Material {
  double youngs_modulus = 0.0;  ///< E [Pa]
  double poisson_ratio = 0.0;   ///< ν [-]
  double density = 7850.0;      ///< [kg/m³]; steel unless a case says otherwise
  std::optional<double> thermal_conductivity;  ///< k_s [W/(m·K)], for thermal EHL (friction law "ehl_thermal")
  std::optional<double> specific_heat;         ///< c_s [J/(kg·K)], for thermal EHL
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
  double oil_temperature = 313.15;   ///< [K]; 40 °C unless a case says otherwise
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
  std::optional<double> temperature_viscosity; ///< β [1/K] of Roelands' temperature term (thermal EHL)
  std::optional<double> eyring_stress;         ///< τ0 [Pa] of a Ree–Eyring film (thermal EHL)
};

/// Load factors of ISO 6336-1 applied to the nominal tooth force (application, dynamic,
/// transverse and face load factors).
struct LoadFactors {
  double K_A = 1.0, K_v = 1.0, K_H_alpha = 1.0, K_H_beta = 1.0;
  [[nodiscard]] double product() const { return K_A * K_v * K_H_alpha * K_H_beta; }
};

/// A lubricant for thermal EHL: temperature-dependent viscosity (Roelands with β, or
/// Ubbelohde–Walther from ν40 and ν100) and density (ISO/TR 15144-1 law from ρ15).
struct ThermalLubricant {
  double density_15C = 0.0;                  ///< ρ15 [kg/m³]
  double pressure_viscosity = 0.0;           ///< α at the inlet temperature [1/Pa]
  double viscosity = 0.0;                    ///< η0 at the inlet temperature [Pa·s] (Roelands form)
  double temperature_viscosity = 0.0;        ///< β [1/K] (Roelands form)
  std::optional<double> nu40, nu100;         ///< [m²/s] (Walther form)
  double thermal_conductivity = 0.0;         ///< k [W/(m·K)]
  double specific_heat = 0.0;                ///< c [J/(kg·K)]
  std::optional<double> eyring_stress;       ///< τ0 [Pa], for the Eyring traction limit
};

/// Thermal data of the two solids (index 0: the pinion / surface a).
struct ThermalSolids {
  std::array<double, 2> conductivity{};   ///< k_s [W/(m·K)]
  std::array<double, 2> specific_heat{};  ///< c_s [J/(kg·K)]
  std::array<double, 2> density{};        ///< ρ_s [kg/m³]
};

}  // namespace gearbench::model
