#pragma once
// Temperature- and pressure-dependent viscosity and density of a lubricant for thermal EHL.
// Temperatures in K, pressures in Pa, viscosities in Pa·s, densities in kg/m³.
//
// Two viscosity–temperature laws, selected by the data given:
//  - Roelands with a temperature term (Roelands 1966, in the form of Yang & Wen, J. Tribol.
//    112 (1990) 631, eq. 5):
//      η = η0·exp{(ln η0 + 9.67)·[−1 + (1 + p/p0)^z·((T − 138)/(T0 − 138))^(−S0)]},
//      S0 = β·(T0 − 138)/(ln η0 + 9.67), β the viscosity–temperature coefficient [1/K];
//  - Ubbelohde–Walther at ambient pressure (ASTM D341; ISO/TR 15144-1:2010, as quoted by
//    seed 001 eq. 1.3): lg lg(ν + 0.7) = A·lg T + B with ν in mm²/s and T in K, A and B
//    from ν40 and ν100; η(T) = ρ(T)·ν(T), and the Roelands pressure factor at η(T) with a
//    temperature-independent z (Roelands 1966 found z nearly independent of temperature).
// Density: the linear law of ISO/TR 15144-1 (seed 001 eq. 1.3), ρ(T) = ρ15 − 0.7·(T − 15 °C)
// [kg/m³], times the Dowson–Higginson pressure factor (5.9e8 + 1.34p)/(5.9e8 + p).
#include <optional>

#include "model/materials.h"
#include "viscosity_temperature.h"

namespace gearbench::lubricant {

class ThermalRheology {
 public:
  /// Throws InputError (naming the lubricant keys) on unphysical data. `inlet_temperature`
  /// T0 [K] is where η0 and α are given and where the oil flows in.
  ThermalRheology(const model::ThermalLubricant& data, double inlet_temperature);

  [[nodiscard]] double viscosity(double p, double T) const;      ///< η(p, T)

  /// η(p, T) and ρ(p, T) along one pressure: Roelands' pressure factor (1 + p/p0)^z and the
  /// Dowson–Higginson density ratio are evaluated once (a film column's nodes share p, and the
  /// temperature sweeps hold p frozen), so each temperature costs one pow (Roelands form) and
  /// ∂ln η/∂T comes analytically with it.
  class AtPressure {
   public:
    /// η(p, T) (the same arithmetic as viscosity(p, T)); with `dln_dT`, ∂ln η/∂T [1/K] there.
    [[nodiscard]] double viscosity(double T, double* dln_dT = nullptr) const;
    /// ρ(p, T): the ambient density at T times the Dowson–Higginson ratio at p.
    [[nodiscard]] double density(double T) const { return r_->ambient_density(T) * density_ratio_; }

   private:
    friend class ThermalRheology;
    const ThermalRheology* r_ = nullptr;
    double pressure_factor_ = 1.0;
    double density_ratio_ = 1.0;  ///< ρ(p, T)/ρ(0, T)
  };
  [[nodiscard]] AtPressure at_pressure(double p) const;
  [[nodiscard]] double density(double p, double T) const;        ///< ρ(p, T)
  /// (1/ρ)·∂ρ/∂T at (p, T) [1/K] (the compression-work coefficient of the energy equation).
  [[nodiscard]] double thermal_expansion(double p, double T) const;
  [[nodiscard]] double inlet_viscosity() const { return eta0_; }  ///< η(0, T0)
  [[nodiscard]] double roelands_z() const { return z_; }
  [[nodiscard]] const model::ThermalLubricant& data() const { return data_; }
  [[nodiscard]] double inlet_temperature() const { return T0_; }

  /// Kinematic viscosity by Ubbelohde–Walther [m²/s] (Walther form only: throws otherwise).
  [[nodiscard]] double walther_kinematic_viscosity(double T) const;

 private:
  [[nodiscard]] double ambient_density(double T) const;  ///< ρ(0, T)
  [[nodiscard]] double ambient_viscosity(double T) const;  ///< η(0, T)

  model::ThermalLubricant data_;
  double T0_ = 0.0;
  std::optional<WaltherLine> walther_;  ///< set for the Ubbelohde–Walther form
  double eta0_ = 0.0, z_ = 0.0, S0_ = 0.0;
  double roelands_scale_ = 0.0;  ///< ln η0 + 9.67: Roelands' exponent scale, a constant of the oil
};

}  // namespace gearbench::lubricant
