#pragma once
// The generated root fillet for the GSL reference, derived here on its own route: as the
// rack rolls by δ = R·φ on the reference circle, the centre C of its tip round (radius ρ)
// runs on a trochoid, and the round touches the gear where its normal passes through the
// pitch point I (Willis). A circle's normal passes through its centre, so the contact is on
// the line I C, ρ beyond C:
//
//   P(φ) = C + ρ·(C − I)/|C − I|,   C = (R + v_c, u_c + R·φ),   I = (R, 0)
//
// in the fixed frame (X along the tooth-space centre line at φ = 0, Y tangential), turned
// back by φ into the gear and by π/z more into the tooth frame (x on the tooth centre line).
// The parameter is the gear's roll angle φ, where the production solver (solvers/stiffness)
// runs over the round's normal angle; the two share no code. Spur pairs only (a helical
// rack's transverse round is an ellipse, whose normals miss its centre).
#include "model/gear_pair.h"

namespace gearbench::reference {

struct TrochoidFillet {
  double R = 0;            ///< reference (rolling) radius [m]
  double space_angle = 0;  ///< π/z
  double rho = 0;          ///< ρ_fP [m]
  double uc = 0, vc = 0;   ///< round centre in rack coordinates (u along, v out of the rolling line) [m]
  double phi_form = 0;     ///< roll angle at which the round meets the involute (form circle)
  double phi_root = 0;     ///< roll angle at which it cuts the root circle

  /// Tooth-frame point (x, h) at roll angle φ and dx/dφ.
  struct Point {
    double x, h, dx;
  };
  [[nodiscard]] Point at(double phi) const;
};

/// The fillet of gear `gear` (0 pinion, 1 wheel). Throws std::invalid_argument for a
/// helical pair, no tip radius, or a round that does not fit the rack tooth, and
/// std::domain_error when the round centre is not inside the rolling circle (v_c ≥ 0).
TrochoidFillet trochoid_fillet(const model::GearPair& pair, int gear);

}  // namespace gearbench::reference
