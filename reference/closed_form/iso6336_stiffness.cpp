#include "iso6336_stiffness.h"

#include <cmath>
#include <fmt/format.h>

#include "involute_closed_form.h"

namespace gearbench::reference {

Iso6336Stiffness iso6336_stiffness(const model::GearPair& pair) {
  Iso6336Stiffness r;
  const double beta = pair.helix_angle;
  const double alpha_t = std::atan(std::tan(pair.normal_pressure_angle) / std::cos(beta));
  const double beta_b = std::atan(std::tan(beta) * std::cos(alpha_t));
  // Virtual numbers of teeth of the normal section, the ISO form z/(cos²β_b·cos β)
  // (the approximation z/cos³β is not used).
  const double virtual_factor = 1.0 / (std::pow(std::cos(beta_b), 2) * std::cos(beta));
  r.z_n1 = pair.teeth[0] * virtual_factor;
  r.z_n2 = pair.teeth[1] * virtual_factor;
  const double x1 = pair.profile_shift[0];
  const double x2 = pair.profile_shift[1];

  // q′ = C1 + C2/z_n1 + C3/z_n2 + C4·x1 + C5·x1/z_n1 + C6·x2 + C7·x2/z_n2 + C8·x1² + C9·x2².
  constexpr double C[9] = {0.04723, 0.15551, 0.25791, -0.00635, -0.11654,
                           -0.00193, -0.24188, 0.00529, 0.00182};
  r.q_prime = C[0] + C[1] / r.z_n1 + C[2] / r.z_n2 + C[3] * x1 + C[4] * x1 / r.z_n1 + C[5] * x2 +
              C[6] * x2 / r.z_n2 + C[7] * x1 * x1 + C[8] * x2 * x2;
  r.c_prime_theoretical = 1.0 / r.q_prime;

  // Correction factors: C_M = 0.8 (solid-disc reference), C_R = 1 (solid blanks),
  // C_B = [1 + 0.5(1.2 − h_fP/m_n)]·[1 − 0.02(20° − α_Pn)], basic-rack dedendum h_fP.
  r.C_M = 0.8;
  r.C_R = 1.0;
  const double alpha_pn_deg = pair.normal_pressure_angle * 180.0 / M_PI;
  r.C_B = (1.0 + 0.5 * (1.2 - pair.dedendum_coef)) * (1.0 - 0.02 * (20.0 - alpha_pn_deg));
  r.c_prime = r.c_prime_theoretical * r.C_M * r.C_R * r.C_B * std::cos(beta);

  r.contact_ratio_transverse = involute_closed_form(pair).contact_ratio_transverse;
  r.c_gamma_alpha = r.c_prime * (0.75 * r.contact_ratio_transverse + 0.25);
  r.c_gamma_beta = 0.85 * r.c_gamma_alpha;

  if (x1 + x2 < -0.5 || x1 + x2 > 2.0)
    r.warnings.push_back(fmt::format("ISO 6336-1 method B: x1 + x2 = {:.3f} outside [-0.5, 2]", x1 + x2));
  if (x1 < x2)
    r.warnings.push_back(fmt::format("ISO 6336-1 method B assumes x1 >= x2 (x1 = {}, x2 = {})", x1, x2));
  return r;
}

}  // namespace gearbench::reference
