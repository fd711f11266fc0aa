#include "thermal_rheology.h"

#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

#include "model/errors.h"
#include "rheology.h"
#include "viscosity_temperature.h"

namespace gearbench::lubricant {

namespace {
constexpr double roelands_temperature = 138.0;  // [K], Roelands (1966) temperature pole
constexpr double T40 = celsius_zero + 40.0, T100 = celsius_zero + 100.0;

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
  if (data.nu40.has_value() || data.nu100.has_value()) {
    if (!data.nu40 || !data.nu100)
      throw InputError("lubricant: give both nu40_mm2_s and nu100_mm2_s for the Ubbelohde–Walther law");
    require_positive(*data.nu40, "lubricant.nu40_mm2_s");
    require_positive(*data.nu100, "lubricant.nu100_mm2_s");
    if (!(*data.nu40 > *data.nu100))
      throw InputError(fmt::format("lubricant.nu100_mm2_s = {} must be below nu40_mm2_s = {}",
                                   *data.nu100 * 1e6, *data.nu40 * 1e6));
    walther_.emplace(T40, *data.nu40 * 1e6, T100, *data.nu100 * 1e6);
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
  roelands_scale_ = std::log(eta0_) + roelands_ln_eta_inf;
  S0_ = data.temperature_viscosity * (T0_ - roelands_temperature) / roelands_scale_;
}

double ThermalRheology::walther_kinematic_viscosity(double T) const {
  if (!walther_) throw std::logic_error("ThermalRheology: the Roelands form has no Ubbelohde–Walther line");
  return walther_->kinematic_viscosity_mm2_s(T) * 1e-6;
}

double ThermalRheology::ambient_density(double T) const { return iso15144_density(data_.density_15C, T); }

double ThermalRheology::ambient_viscosity(double T) const {
  return ambient_density(T) * walther_kinematic_viscosity(T);
}

double ThermalRheology::viscosity(double p, double T) const { return at_pressure(p).viscosity(T); }

ThermalRheology::AtPressure ThermalRheology::at_pressure(double p) const {
  AtPressure a;
  a.r_ = this;
  a.pressure_factor_ = std::pow(1.0 + std::max(p, 0.0) / roelands_p0, z_);
  a.density_ratio_ = dowson_higginson_density_ratio(std::max(p, 0.0));
  return a;
}

double ThermalRheology::AtPressure::viscosity(double T, double* dln_dT) const {
  const ThermalRheology& r = *r_;
  if (r.walther_) {
    // ln η = PF·ln η_T + ln η∞⁻¹·(PF − 1): ∂ln η/∂T = PF·(∂ln ρ/∂T + ∂ln ν/∂T), and from
    // lg lg(ν + 0.7) = A·lg T + B (ν in mm²/s): ∂ln ν/∂T = (ν + 0.7)/ν·ln(ν + 0.7)·A/T.
    const double rho = r.ambient_density(T);
    const double nu = r.walther_->kinematic_viscosity_mm2_s(T);
    const double eta_T = rho * nu * 1e-6;
    if (dln_dT)
      *dln_dT = pressure_factor_ * (-iso15144_density_slope / rho +
                                    (nu + 0.7) / nu * std::log(nu + 0.7) * r.walther_->slope() / T);
    return eta_T * std::exp((std::log(eta_T) + roelands_ln_eta_inf) * (pressure_factor_ - 1.0));
  }
  // ln η = ln η0 + (ln η0 + 9.67)·[−1 + PF·θ^(−S0)], θ = (T − 138)/(T0 − 138):
  // ∂ln η/∂T = −(ln η0 + 9.67)·PF·S0·θ^(−S0)/(T − 138).
  const double theta = (T - roelands_temperature) / (r.T0_ - roelands_temperature);
  const double a = r.roelands_scale_;  // once per oil, not per node: a log less per temperature
  const double term = pressure_factor_ * std::pow(theta, -r.S0_);
  if (dln_dT) *dln_dT = -a * term * r.S0_ / (T - roelands_temperature);
  return r.eta0_ * std::exp(a * (-1.0 + term));
}

double ThermalRheology::density(double p, double T) const { return at_pressure(p).density(T); }

double ThermalRheology::thermal_expansion(double /*p*/, double T) const {
  return -iso15144_density_slope / ambient_density(T);
}

}  // namespace gearbench::lubricant
