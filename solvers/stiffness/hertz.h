#pragma once
// Hertzian contact stiffness of a line contact, independent of load and position
// (Yang & Sun 1985): 1/k_h = 2/(π·L)·[(1 − ν1²)/E1 + (1 − ν2²)/E2], which is
// π·E·L/(4(1 − ν²)) for equal materials.
#include <numbers>

#include "model/materials.h"

namespace gearbench::stiffness {

inline double hertz_stiffness(const model::Material& m1, const model::Material& m2, double face_width) {
  const double compliance =
      2.0 / (std::numbers::pi * face_width) *
      ((1.0 - m1.poisson_ratio * m1.poisson_ratio) / m1.youngs_modulus +
       (1.0 - m2.poisson_ratio * m2.poisson_ratio) / m2.youngs_modulus);
  return 1.0 / compliance;
}

}  // namespace gearbench::stiffness
