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
// The same gap drives the reference for the pulse's peak (entering_pair_peak_force).
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

/// The peak contact force [N] of the entering pair in seed 000 eq. 6's own model, a mass `mass` [kg]
/// (the pair's equivalent mass along the normal) and a spring `stiffness` [N/m] (1/q_s), but under the
/// overlap the exact corner approach imposes, p = δ − gap, instead of a closing speed held through the
/// pulse: m·ẍ = k·max(0, p − x) from first contact, integrated numerically (RK4). Eq. 6's
/// v_s·√(m·k) is its limit for an approach long against the spring's period.
double entering_pair_peak_force(const model::GearPair& pair, double pinion_speed, double deflection, double mass,
                                double stiffness);

}  // namespace gearbench::reference
