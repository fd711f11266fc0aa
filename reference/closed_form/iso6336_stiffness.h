#pragma once
// ISO 6336-1 method B tooth stiffness (single stiffness c′ and mesh stiffness c_γα, c_γβ),
// from the model data alone. Coefficients C1..C9, C_M, C_B and the ε_α weighting as quoted
// in docs/research/stiffness.md §4 (identical across five public implementations; the
// standard's own text was not available to check against).
#include <string>
#include <vector>

#include "model/gear_pair.h"

namespace gearbench::reference {

struct Iso6336Stiffness {
  double z_n1 = 0.0, z_n2 = 0.0;   ///< virtual numbers of teeth z/(cos²β_b·cos β)
  double q_prime = 0.0;            ///< minimum flexibility of a pair [mm·µm/N]
  double c_prime_theoretical = 0.0;  ///< c′_th = 1/q′ [N/(mm·µm)]
  double C_M = 0.0, C_R = 0.0, C_B = 0.0;
  double c_prime = 0.0;            ///< single stiffness c′ [N/(mm·µm)]
  double c_gamma_alpha = 0.0;      ///< mesh stiffness c_γα = c′(0.75 ε_α + 0.25)
  double c_gamma_beta = 0.0;       ///< c_γβ = 0.85 c_γα
  double contact_ratio_transverse = 0.0;
  std::vector<std::string> warnings;  ///< outside the method's stated validity
};

/// Solid gear blanks (C_R = 1), steel/steel (no material factor), no low-load correction.
Iso6336Stiffness iso6336_stiffness(const model::GearPair& pair);

}  // namespace gearbench::reference
