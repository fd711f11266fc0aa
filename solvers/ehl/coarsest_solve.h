#pragma once
// The coarsest grid's problem solved directly in (P, H0): a Newton step of the discrete
// Reynolds equation (reynolds_stencil.h) with every kernel entry of the film's response,
// bordered by the force balance h·Σ P_j = g. The film's H0 enters the Reynolds equation
// through the wedge and squeeze terms and through ε ∝ H³ in the Poiseuille term; so does
// every pressure, through the deformation: the Jacobian holds both (the caller gives
// ∂ε/∂H), and the step is a Newton step of the whole coarsest problem. Cavitated nodes (P = 0
// whose own change would be negative) are held. The factorization is kept for the steps after it
// while they converge fast (CoarsestNewton).
// Venner & Lubrecht (2000, §8.3) close the force balance by a damped H0 update per coarsest
// visit; a direct solve needs no damping factor and makes the coarsest grid exact.
#include <vector>

#include <Eigen/LU>

#include "reynolds_stencil.h"

namespace gearbench::ehl {

/// ∂ε_{i+½}/∂H_i (left) and ∂ε_{i+½}/∂H_{i+1} (right): the flow's response to the film,
/// through which H0 and, by the deformation, every pressure move the Poiseuille term.
struct FilmSensitivity {
  std::vector<double> left, right;
};

/// Whether a step was found (as Eigen's ComputationInfo): the system's coefficients may be
/// non-finite (a contact whose dimensionless scales a double does not hold: λ, F or p_r of
/// inputs like a load of 1e-300 N/m) or the system singular; then there is no step.
enum class StepInfo { success, non_finite_system, singular };

struct CoarsestStep {
  StepInfo info = StepInfo::success;
  std::vector<double> dP;  ///< pressure change (zero at the ends and at held nodes); empty without a step
  double dH0 = 0.0;        ///< change of the film constant
};

/// The nodes a Newton step holds at zero (stays_cavitated): 1 where held, over the whole grid.
[[nodiscard]] std::vector<char> held_nodes(const ReynoldsCoefficients& c, const std::vector<double>& P,
                                           const std::vector<double>& residual);

/// The Newton matrix of the coarsest problem, factorized once and kept for the steps after
/// (the chord method; KINSOL's modified Newton keeps its Jacobian for up to ten steps in the
/// same way): a step with a kept factorization costs two triangular solves, O(n²), instead of
/// the LU's n³/3. The caller decides when a factorization is too old (fas_coarsest.cpp).
class CoarsestNewton {
 public:
  /// Builds the Jacobian at P with the `held` nodes (held_nodes) fixed, and factorizes it.
  /// Never throws on the system: a failed factorization comes back with its info and leaves
  /// none kept.
  StepInfo factorize(const ReynoldsCoefficients& c, const std::vector<double>& P, std::vector<char> held,
                     const FilmSensitivity& film);
  /// Whether a factorization is kept, and for the same held nodes as `held`.
  [[nodiscard]] bool holds(const std::vector<char>& held) const { return factorized_ && held == held_; }
  void forget() { factorized_ = false; }
  /// The step for `residual` (f − L(P)) and `force_gap` (g − h·Σ P) with the kept
  /// factorization; its info is singular where the solution is not finite.
  [[nodiscard]] CoarsestStep step(const std::vector<double>& residual, double force_gap) const;

 private:
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  std::vector<char> held_;
  bool factorized_ = false;
};

}  // namespace gearbench::ehl
