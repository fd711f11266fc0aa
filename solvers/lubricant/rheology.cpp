#include "rheology.h"

#include <cmath>

namespace gearbench::lubricant {

double barus_log_ratio(double alpha, double p) { return alpha * p; }

double barus_viscosity(double eta0, double alpha, double p) { return eta0 * std::exp(barus_log_ratio(alpha, p)); }

double roelands_log_ratio(double eta0, double z, double p) {
  return (std::log(eta0) + roelands_ln_eta_inf) * (-1.0 + std::pow(1.0 + p / roelands_p0, z));
}

double roelands_log_ratio_slope(double eta0, double z, double p) {
  return (std::log(eta0) + roelands_ln_eta_inf) * z * std::pow(1.0 + p / roelands_p0, z) / (roelands_p0 + p);
}

double roelands_viscosity(double eta0, double z, double p) { return eta0 * std::exp(roelands_log_ratio(eta0, z, p)); }

double roelands_z_from_alpha(double eta0, double alpha) {
  return alpha * roelands_p0 / (std::log(eta0) + roelands_ln_eta_inf);
}

double dowson_higginson_density_ratio(double p) { return (5.9e8 + 1.34 * p) / (5.9e8 + p); }

double dowson_higginson_density_slope(double p) { return 0.34 * 5.9e8 / ((5.9e8 + p) * (5.9e8 + p)); }

double eyring_shear_rate(double tau, double eta, double eyring_stress) {
  return eyring_stress / eta * std::sinh(tau / eyring_stress);
}

double eyring_stress(double shear_rate, double eta, double eyring_stress) {
  return eyring_stress * std::asinh(eta * shear_rate / eyring_stress);
}

double eyring_equivalent_viscosity(double tau, double eta, double eyring_stress) {
  const double s = tau / eyring_stress;
  return s == 0.0 ? eta : eta * s / std::sinh(s);
}

}  // namespace gearbench::lubricant
