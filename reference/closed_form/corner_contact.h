#pragma once
// The premature ("corner") contact of the next tooth pair of a loaded pair, constructed
// exactly in the transverse plane from the model data alone (no solvers/ code): the check of
// the first-order impact velocity of the 12-DOF model's mesh-in impact (docs/dynamics-model.md,
// "Mesh-in impact"; seed 000 eq. 6).
//
// Under load the pinion is ahead of its conjugate position by the transverse deflection δ
// (an involute turned about its base centre is the same involute moved along its normals,
// by r_b1 times the angle). The wheel's tip corner of the entering pair therefore meets the
// pinion flank before it reaches A, off the line of action. The gap between that corner
// (moving rigidly with the wheel) and the pinion flank (rigidly with the pinion) is
// r_b1·(θ_s(X) − Θ), θ_s(X) = ψ + inv α(r) the base-circle angle from which the involute
// through X unrolls (X at radius r, polar angle ψ, in the pinion's frame; cos α = r_b1/r):
// involutes of one base circle lie r_b1·Δθ_s apart along their common normals, exactly.
// The gap is zero, with zero rate, when the corner is at A (conjugate action); contact under
// load is where it equals δ, found by bisection; its rate there is the impact velocity.
#include "model/gear_pair.h"

namespace gearbench::reference {

struct CornerContact {
  double lead_time = 0.0;          ///< Δt before the corner would reach A [s]
  double approach_velocity = 0.0;  ///< v_s: closing rate of the gap at contact [m/s]
};

/// `pinion_speed` [rad/s], `deflection` δ [m] along the transverse line of action (> 0).
/// Throws std::invalid_argument for a non-positive speed or deflection, std::runtime_error
/// if the gap does not reach δ within a mesh cycle before A.
CornerContact corner_contact(const model::GearPair& pair, double pinion_speed, double deflection);

}  // namespace gearbench::reference
