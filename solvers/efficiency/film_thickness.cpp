#include "film_thickness.h"

#include <cmath>

namespace gearbench::efficiency {

double reduced_modulus(const std::array<model::Material, 2>& m) {
  return 2.0 / ((1.0 - m[0].poisson_ratio * m[0].poisson_ratio) / m[0].youngs_modulus +
                (1.0 - m[1].poisson_ratio * m[1].poisson_ratio) / m[1].youngs_modulus);
}

double hertz_line_pressure(double load_per_length, double reduced_radius, double e_reduced) {
  return std::sqrt(load_per_length * e_reduced / (2.0 * M_PI * reduced_radius));
}

double dowson_higginson_min_film(double load_per_length, double reduced_radius, double entrainment,
                                 double viscosity, double pressure_viscosity, double e_reduced) {
  const double U = viscosity * entrainment / (e_reduced * reduced_radius);
  const double G = pressure_viscosity * e_reduced;
  const double W = load_per_length / (e_reduced * reduced_radius);
  return 2.65 * reduced_radius * std::pow(U, 0.70) * std::pow(G, 0.54) * std::pow(W, -0.13);
}

}  // namespace gearbench::efficiency
