#pragma once
// Fillet-foundation compliance of Sainsot, Velex & Duverger, J. Mech. Des. 126 (2004) 748:
//
//   1/k_f = cos²α_m/(E·L)·[L*(u_f/S_f)² + M*(u_f/S_f) + P*(1 + Q*·tan²α_m)],
//   X* = A/θ_f² + B·h_f² + C·h_f/θ_f + D/θ_f + E·h_f + F   for X* ∈ {L*, M*, P*, Q*}.
//
// The coefficient table below agrees digit for digit across five public implementations
// (docs/research/stiffness.md §1.1); it has not been checked against the paper's print.
// Definitions (docs/research/stiffness.md §1.3–1.5, gearbench choices where codes differ):
//   α_m  the load angle α_1 of the energy method (force line to the normal of the centre line);
//   u_f  distance along the centre line from the root circle to where the force line crosses
//        the centre line, u_f = x_1 − h_1·tan α_1 − r_f (the geometric meaning in Sainsot's
//        figure; some codes use the contact radius minus r_f instead);
//   θ_f  half angle of the tooth where the beam meets the root circle, measured on the
//        gearbench tooth model (not from a rack formula, whose addendum codes disagree on);
//   S_f  = 2·r_f·θ_f;  h_f = r_f/r_int, r_int the bore radius;  E plain (no plane strain).
// Stated validity (one code lineage): 1.4 ≤ h_f ≤ 7, 0.01 ≤ θ_f ≤ 0.12 rad: outside it the
// fit is extrapolated and a warning is returned.
#include <string>
#include <vector>

#include "tooth_profile.h"

namespace gearbench::stiffness {

struct FoundationParameters {
  double root_radius = 0.0;  ///< r_f [m]
  double bore_radius = 0.0;  ///< r_int [m]
  double theta_f = 0.0;      ///< θ_f [rad]
  double youngs_modulus = 0.0;
  double face_width = 0.0;
};

/// θ_f, r_f of a tooth profile with the given bore.
FoundationParameters foundation_parameters(const ToothProfile& profile, double bore_radius,
                                           double youngs_modulus, double face_width);

/// 1/k_f [m/N] for a load at the flank point with load angle α_1.
double foundation_compliance(const FoundationParameters& p, const FlankPoint& load);

/// Warnings when h_f or θ_f lie outside the fit's stated validity.
std::vector<std::string> foundation_validity_warnings(const FoundationParameters& p, int gear);

}  // namespace gearbench::stiffness
