#include "quadrature/trochoid_fillet.h"

#include <cmath>
#include <stdexcept>

namespace gearbench::reference {

TrochoidFillet trochoid_fillet(const model::GearPair& pair, int gear) {
  if (pair.helix_angle != 0.0) throw std::invalid_argument("the reference trochoid is for spur pairs");
  const double m = pair.normal_module, alpha = pair.normal_pressure_angle;
  TrochoidFillet f;
  f.R = 0.5 * pair.teeth[gear] * m;
  f.space_angle = M_PI / pair.teeth[gear];
  f.rho = pair.root_radius_coef * m;
  if (!(f.rho > 0.0)) throw std::invalid_argument("the rack has no tip radius");
  // The round is ρ above the cutter's tip line, v = x·m − h_fP·m, and ρ inside its straight
  // flank, which is π m/4 from the tooth-space centre on the datum line v = x·m and leans
  // towards it by tan α per unit depth below the datum.
  f.vc = (pair.profile_shift[gear] - pair.dedendum_coef) * m + f.rho;
  const double flank_at_centre = M_PI * m / 4.0 + (f.vc - pair.profile_shift[gear] * m) * std::tan(alpha);
  f.uc = -(flank_at_centre - f.rho / std::cos(alpha));
  if (f.uc > 0.0) throw std::invalid_argument("the rack's tip round does not fit its tooth");
  if (f.vc >= 0.0) throw std::domain_error("the round centre lies on or outside the rolling circle");
  // Root: C straight below I (C − I along −X). Form: C − I along the flank's outward normal
  // (−sin α, −cos α), i.e. u_c + R·φ = v_c·cot α.
  f.phi_root = -f.uc / f.R;
  f.phi_form = (f.vc / std::tan(alpha) - f.uc) / f.R;
  return f;
}

TrochoidFillet::Point TrochoidFillet::at(double phi) const {
  const double DX = vc, DY = uc + R * phi;  // C − I
  const double d = std::hypot(DX, DY);
  const double PX = R + vc + rho * DX / d, PY = uc + R * phi + rho * DY / d;
  // d/dφ of the fixed-frame point: C' = (0, R), (D/|D|)' = D'/d − D (D·D')/d³ with D' = (0, R).
  const double dPX = rho * (-DX * DY * R / (d * d * d));
  const double dPY = R + rho * (R / d - DY * DY * R / (d * d * d));
  // Tooth frame: turned by θ = π/z − φ; dθ/dφ = −1 adds −J·P, J the quarter turn.
  const double theta = space_angle - phi, c = std::cos(theta), s = std::sin(theta);
  const double TX = dPX + PY, TY = dPY - PX;
  return {c * PX - s * PY, s * PX + c * PY, c * TX - s * TY};
}

}  // namespace gearbench::reference
