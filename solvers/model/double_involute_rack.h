#pragma once
// Plain input data of the stepped double-involute basic rack (seed 002, figure 1, after its
// ref. [13]). The rack's tooth is the gear's tooth: from the tip down, the tip straight line
// DE, the waist arc DC of radius ρ_g (tangent to DE at D, cutting the root line at C), the
// root straight line CB and the root arc BA of radius ρ_f (tangent to CB at B). Addendum,
// clearance, root radius and pressure angle are those of model::GearPair (h_a*, h_f* − h_a*,
// ρ_fP*, α_n; one pressure angle for both straight lines, see solvers/geometry/double_involute.h).
// All coefficients refer to the normal module m_n. No algorithms here.

namespace gearbench::model {

struct DoubleInvoluteRack {
  /// y_a*: the tip line DE moved tangentially towards the tooth centre by y_a*·m_n (thinner
  /// tip), measured along the datum line from the ordinary rack flank.
  double tip_tangential_shift = 0.0;
  /// y_d*: the root line CB moved tangentially away from the tooth centre by y_d*·m_n (thicker
  /// root). The step between the two lines is (y_a* + y_d*)·m_n along the datum line.
  double root_tangential_shift = 0.0;
  /// l_a*: depth of D, the lower end of the tip line, below the datum line [m_n].
  double waist_tip_depth = 0.0;
  /// l_d*: depth of C, the upper end of the root line, below the datum line [m_n].
  double waist_root_depth = 0.0;
};

}  // namespace gearbench::model
