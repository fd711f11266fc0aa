#include "foundation.h"

#include <array>
#include <cmath>
#include <fmt/format.h>

namespace gearbench::stiffness {

namespace {

// Sainsot et al. (2004) table: rows L*, M*, P*, Q*; columns A..F.
constexpr std::array<std::array<double, 6>, 4> sainsot_table = {{
    {-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045},
    {60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086},
    {-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236},
    {-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904},
}};

double polynomial(const std::array<double, 6>& c, double h_f, double theta_f) {
  return c[0] / (theta_f * theta_f) + c[1] * h_f * h_f + c[2] * h_f / theta_f + c[3] / theta_f +
         c[4] * h_f + c[5];
}

}  // namespace

FoundationParameters foundation_parameters(const ToothProfile& profile, double bore_radius,
                                           double youngs_modulus, double face_width) {
  const double x0 = profile.beam_start();
  const double h0 = profile.half_thickness(x0);
  return {std::hypot(x0, h0), bore_radius, std::atan2(h0, x0), youngs_modulus, face_width};
}

double foundation_compliance(const FoundationParameters& p, const FlankPoint& load) {
  const double h_f = p.root_radius / p.bore_radius;
  const double L = polynomial(sainsot_table[0], h_f, p.theta_f);
  const double M = polynomial(sainsot_table[1], h_f, p.theta_f);
  const double P = polynomial(sainsot_table[2], h_f, p.theta_f);
  const double Q = polynomial(sainsot_table[3], h_f, p.theta_f);
  const double u_f = load.x - load.h * std::tan(load.alpha) - p.root_radius;
  const double S_f = 2.0 * p.root_radius * p.theta_f;
  const double ratio = u_f / S_f;
  const double c = std::cos(load.alpha);
  const double t = std::tan(load.alpha);
  return c * c / (p.youngs_modulus * p.face_width) *
         (L * ratio * ratio + M * ratio + P * (1.0 + Q * t * t));
}

std::vector<std::string> foundation_validity_warnings(const FoundationParameters& p, int gear) {
  std::vector<std::string> w;
  const double h_f = p.root_radius / p.bore_radius;
  if (h_f < 1.4 || h_f > 7.0)
    w.push_back(fmt::format("gear {}: Sainsot foundation h_f = r_f/r_int = {:.3f} outside its "
                            "fitted range [1.4, 7]: extrapolated", gear + 1, h_f));
  if (p.theta_f < 0.01 || p.theta_f > 0.12)
    w.push_back(fmt::format("gear {}: Sainsot foundation θ_f = {:.4f} rad outside its fitted "
                            "range [0.01, 0.12]: extrapolated", gear + 1, p.theta_f));
  return w;
}

}  // namespace gearbench::stiffness
