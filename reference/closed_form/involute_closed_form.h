#pragma once
// Closed-form involute gear-pair figures, derived here from the model data alone and
// sharing no code with solvers/geometry. The working pressure angle is found by GSL's
// Brent root bracketing (not Newton, as the solver does), and the contact ratio comes
// from the textbook formula in tip and base diameters, not from a path of contact.
#include "model/gear_pair.h"

namespace gearbench::reference {

struct InvoluteClosedForm {
  double transverse_pressure_angle = 0.0;  ///< α_t [rad]
  double working_pressure_angle = 0.0;     ///< α_wt [rad]
  double center_distance = 0.0;            ///< a [m]
  double line_of_action_length = 0.0;      ///< T1T2 = a·sin α_wt [m]
  double contact_ratio_transverse = 0.0;   ///< ε_α (ISO 21771:2007, transverse contact ratio)
  double contact_ratio_overlap = 0.0;      ///< ε_β = b·sin β/(π·m_n) (ISO 21771:2007, overlap ratio)
  double single_contact_length = 0.0;      ///< (2 − ε_α)·p_bt [m], for 1 ≤ ε_α ≤ 2
  double double_contact_length = 0.0;      ///< 2(ε_α − 1)·p_bt [m], for 1 ≤ ε_α ≤ 2
  double mean_contact_line_length = 0.0;   ///< b·ε_α/cos β_b [m], per helical half
  double pitch_point_from_T1 = 0.0;        ///< T1C = a·sin α_wt·z1/(z1 + z2) [m]
};

/// Evaluates the closed forms. Throws std::runtime_error if GSL's root finder fails.
InvoluteClosedForm involute_closed_form(const model::GearPair& pair);

}  // namespace gearbench::reference
