#include "thermal_rheology.h"

#include <cmath>
#include <fmt/format.h>

#include "model/errors.h"
#include "rheology.h"

namespace gearbench::lubricant {

namespace {
constexpr double celsius_zero = 273.15;      // [K]
constexpr double iso_density_slope = 0.7;    // [kg/(m³·K)], ISO/TR 15144-1 (seed 001 eq. 1.3)
constexpr double walther_offset = 0.7;       // [mm²/s], ASTM D341 / Ubbelohde–Walther
constexpr double roelands_temperature = 138.0;  // [K], Roelands (1966) temperature pole
constexpr double T40 = celsius_zero + 40.0, T100 = celsius_zero + 100.0;

double lglg(double nu_mm2_s) { return std::log10(std::log10(nu_mm2_s + walther_offset)); }

void require_positive(double value, const char* key) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw InputError(fmt::format("{} = {} must be a positive finite number", key, value));
}
}  // namespace

ThermalRheology::ThermalRheology(const model::ThermalLubricant& data, double inlet_temperature)
    : data_(data), T0_(inlet_temperature) {
  require_positive(T0_, "inlet_temperature_K");
  if (T0_ <= roelands_temperature + 20.0)
    throw InputError(fmt::format("inlet_temperature_K = {} must exceed {} K (the Roelands temperature "
                                 "pole is 138 K)", T0_, roelands_temperature + 20.0));
  require_positive(data.density_15C, "lubricant.density_kg_m3");
  require_positive(data.pressure_viscosity, "lubricant.pressure_viscosity_1_per_GPa");
  require_positive(data.thermal_conductivity, "lubricant.thermal_conductivity_W_per_mK");
  require_positive(data.specific_heat, "lubricant.specific_heat_J_per_kgK");
  walther_ = data.nu40.has_value() || data.nu100.has_value();
  if (walther_) {
    if (!data.nu40 || !data.nu100)
      throw InputError("lubricant: give both nu40_mm2_s and nu100_mm2_s for the Ubbelohde–Walther law");
    require_positive(*data.nu40, "lubricant.nu40_mm2_s");
    require_positive(*data.nu100, "lubricant.nu100_mm2_s");
    if (!(*data.nu40 > *data.nu100))
      throw InputError(fmt::format("lubricant.nu100_mm2_s = {} must be below nu40_mm2_s = {}",
                                   *data.nu100 * 1e6, *data.nu40 * 1e6));
    // lg lg(ν + 0.7) = A·lg T + B through (313.15 K, ν40) and (373.15 K, ν100).
    walther_A_ = (lglg(*data.nu40 * 1e6) - lglg(*data.nu100 * 1e6)) / (std::log10(T40) - std::log10(T100));
    walther_B_ = lglg(*data.nu40 * 1e6) - walther_A_ * std::log10(T40);
    eta0_ = ambient_density(T0_) * walther_kinematic_viscosity(T0_);
  } else {
    require_positive(data.viscosity, "lubricant.viscosity_Pa_s");
    if (data.temperature_viscosity < 0.0 || !std::isfinite(data.temperature_viscosity))
      throw InputError(fmt::format("lubricant.temperature_viscosity_1_per_K = {} must be ≥ 0",
                                   data.temperature_viscosity));
    eta0_ = data.viscosity;
  }
  if (eta0_ <= std::exp(-roelands_ln_eta_inf))
    throw InputError(fmt::format("lubricant: the inlet viscosity {:.3g} Pa·s is below the Roelands "
                                 "asymptote 6.31e-5 Pa·s", eta0_));
  z_ = roelands_z_from_alpha(eta0_, data.pressure_viscosity);
  S0_ = data.temperature_viscosity * (T0_ - roelands_temperature) /
        (std::log(eta0_) + roelands_ln_eta_inf);
}

double ThermalRheology::walther_kinematic_viscosity(double T) const {
  const double nu_mm2_s = std::pow(10.0, std::pow(10.0, walther_A_ * std::log10(T) + walther_B_)) - walther_offset;
  return nu_mm2_s * 1e-6;
}

double ThermalRheology::ambient_density(double T) const {
  return data_.density_15C - iso_density_slope * (T - (celsius_zero + 15.0));
}

double ThermalRheology::ambient_viscosity(double T) const {
  return ambient_density(T) * walther_kinematic_viscosity(T);
}

double ThermalRheology::viscosity(double p, double T) const {
  const double pressure_factor = std::pow(1.0 + std::max(p, 0.0) / roelands_p0, z_);
  if (walther_) {
    const double eta_T = ambient_viscosity(T);
    return eta_T * std::exp((std::log(eta_T) + roelands_ln_eta_inf) * (pressure_factor - 1.0));
  }
  const double theta = (T - roelands_temperature) / (T0_ - roelands_temperature);
  return eta0_ * std::exp((std::log(eta0_) + roelands_ln_eta_inf) *
                          (-1.0 + pressure_factor * std::pow(theta, -S0_)));
}

double ThermalRheology::density(double p, double T) const {
  return ambient_density(T) * dowson_higginson_density_ratio(std::max(p, 0.0));
}

double ThermalRheology::thermal_expansion(double /*p*/, double T) const {
  return -iso_density_slope / ambient_density(T);
}

}  // namespace gearbench::lubricant
