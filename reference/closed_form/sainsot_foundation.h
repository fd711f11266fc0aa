#pragma once
// Fillet-foundation compliance of Sainsot, Velex & Duverger, J. Mech. Des. 126 (2004) 748,
// evaluated on the reference's own tooth geometry (reference/quadrature) with the
// definitions of docs/stiffness-model.md: u_f from the root circle along the centre line to
// where the force line crosses it, θ_f and r_f at the beam start, S_f = 2·r_f·θ_f, plain E.
#include "quadrature/energy_quadrature.h"

namespace gearbench::reference {

/// 1/k_f [m/N] over face width L for the load geometry g and bore radius r_int.
double sainsot_foundation_compliance(const QuadLoadGeometry& g, double bore_radius,
                                     double youngs_modulus, double face_width);

}  // namespace gearbench::reference
