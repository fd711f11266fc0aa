#include "sainsot_foundation.h"

#include <cmath>

namespace gearbench::reference {

double sainsot_foundation_compliance(const QuadLoadGeometry& g, double bore_radius,
                                     double youngs_modulus, double face_width) {
  // Coefficients A..F of L*, M*, P*, Q* (docs/research/stiffness.md §1.1).
  static constexpr double table[4][6] = {
      {-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045},
      {60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086},
      {-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236},
      {-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904}};
  const double r_f = std::hypot(g.x0, g.h0);
  const double theta_f = std::atan(g.h0 / g.x0);
  const double h_f = r_f / bore_radius;
  double X[4];
  for (int k = 0; k < 4; ++k)
    X[k] = table[k][0] / (theta_f * theta_f) + table[k][1] * h_f * h_f + table[k][2] * h_f / theta_f +
           table[k][3] / theta_f + table[k][4] * h_f + table[k][5];
  // The force line through (x_1, h_1) at α_1 to the normal of the centre line meets the
  // centre line at x_1 − h_1·tan α_1.
  const double u_f = g.x1 - g.h1 * std::tan(g.alpha1) - r_f;
  const double ratio = u_f / (2.0 * r_f * theta_f);
  const double c2 = std::cos(g.alpha1) * std::cos(g.alpha1);
  const double t2 = std::tan(g.alpha1) * std::tan(g.alpha1);
  return c2 / (youngs_modulus * face_width) * (X[0] * ratio * ratio + X[1] * ratio + X[2] * (1.0 + X[3] * t2));
}

}  // namespace gearbench::reference
