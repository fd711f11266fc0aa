#pragma once
// The coarsest grid's problem solved directly in (P, H0): a Newton step of the discrete
// Reynolds equation (reynolds_stencil.h) with every kernel entry of the film's response,
// bordered by the force balance h·Σ P_j = g. The film's H0 enters the Reynolds equation
// through the wedge and squeeze terms and through ε ∝ H³ in the Poiseuille term; so does
// every pressure, through the deformation: the Jacobian holds both (the caller gives
// ∂ε/∂H), and the step is a Newton step of the whole coarsest problem. Cavitated nodes (P = 0
// whose own change would be negative) are held. The Jacobian (kernel_jacobian.h) is kept for the
// steps after it while they converge fast (CoarsestNewton); below 257 nodes it is formed and
// factorized densely, from 257 on its steps are GMRES steps preconditioned by its bordered band
// (nineteenth session: a dense 257-node LU was 110 WU of a 1025-node solve at M = 1).
// Venner & Lubrecht (2000, §8.3) close the force balance by a damped H0 update per coarsest
// visit; a direct solve needs no damping factor and makes the coarsest grid exact.
#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>
#include <unsupported/Eigen/IterativeSolvers>

#include "kernel_jacobian.h"
#include "reynolds_stencil.h"

namespace gearbench::ehl {

/// ∂ε_{i+½}/∂H_i (left) and ∂ε_{i+½}/∂H_{i+1} (right): the flow's response to the film,
/// through which H0 and, by the deformation, every pressure move the Poiseuille term.
struct FilmSensitivity {
  std::vector<double> left, right;
};

/// Row i of the Reynolds Jacobian in the form KernelJacobian takes: ∂L_i/∂H_k (k = i−2 … i+1:
/// the wedge's and ε's film response, ε ∝ H³), the band ∂L_i/∂P_j (j = i−2 … i+2) and ∂L_i/∂H0
/// (a uniform film shift reaches every film term alike).
struct ReynoldsRow {
  std::array<double, 4> dL_dH{};
  std::array<double, 5> band{};
  double dL_dH0 = 0.0;
};
[[nodiscard]] ReynoldsRow reynolds_row(const ReynoldsCoefficients& c, const FilmSensitivity& film,
                                       const std::vector<double>& P, std::size_t i);

/// Whether a step was found (as Eigen's ComputationInfo): the system's coefficients may be
/// non-finite (a contact whose dimensionless scales a double does not hold: λ, F or p_r of
/// inputs like a load of 1e-300 N/m) or the system singular; then there is no step.
enum class StepInfo { success, non_finite_system, singular };

struct CoarsestStep {
  StepInfo info = StepInfo::success;
  std::vector<double> dP;  ///< pressure change (zero at the ends and at held nodes); empty without a step
  double dH0 = 0.0;        ///< change of the film constant
  int iterations = 0;      ///< GMRES iterations of the step
};

/// The nodes a Newton step holds at zero (stays_cavitated): 1 where held, over the whole grid.
[[nodiscard]] std::vector<char> held_nodes(const ReynoldsCoefficients& c, const std::vector<double>& P,
                                           const std::vector<double>& residual);

/// The Newton matrix of the coarsest problem, built once and kept for the steps after (the
/// chord method; KINSOL's modified Newton keeps its Jacobian for up to ten steps in the same
/// way). The caller decides when it is too old (fas_coarsest.cpp). Up to krylov_from_nodes − 1
/// nodes it is formed and factorized densely (n³/3 multiply–adds, then n² a step); from
/// krylov_from_nodes on, its steps are GMRES steps with its bordered band as preconditioner,
/// about 4 iterations of n² + 34n each to 1e-6. A visit takes a factorization and about two
/// steps: the two cost the same near 65 nodes (measured at (10, 0) on 257 nodes with a 33-node
/// coarsest grid: 71 WU dense, 151 by GMRES; at (1, 20) on 1025 nodes with 257: 4300 against
/// 1371; nineteenth session).
class CoarsestNewton {
 public:
  static constexpr std::size_t krylov_from_nodes = 257;
  /// The GMRES step's relative residual (tighter than the spike's 1e-3: the start solves the
  /// coarsest grid to 1e-8 in P and H0).
  static constexpr double krylov_tolerance = 1e-6;
  static constexpr int krylov_iterations = 60;
  /// Builds the Jacobian at P with the `held` nodes (held_nodes) fixed, and factorizes its band.
  /// Never throws on the system: a failed factorization comes back with its info and leaves
  /// none kept.
  StepInfo factorize(const ReynoldsCoefficients& c, const std::vector<double>& P, std::vector<char> held,
                     const FilmSensitivity& film);
  /// Whether a Jacobian is kept, and for the same held nodes as `held`.
  [[nodiscard]] bool holds(const std::vector<char>& held) const { return factorized_ && held == held_; }
  void forget() { factorized_ = false; }
  /// The kept Jacobian (after a successful factorize).
  [[nodiscard]] const KernelJacobian& jacobian() const { return *jacobian_; }
  /// Whether the kept Jacobian is factorized densely (fewer than krylov_from_nodes nodes).
  [[nodiscard]] bool dense() const { return jacobian_ && jacobian_->nodes() + 2 < krylov_from_nodes; }
  /// The step for `residual` (f − L(P)) and `force_gap` (g − h·Σ P) with the kept Jacobian;
  /// its info is singular where the solution is not finite.
  [[nodiscard]] CoarsestStep step(const std::vector<double>& residual, double force_gap);

 private:
  std::optional<KernelJacobian> jacobian_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  Eigen::GMRES<KernelJacobian, BandPreconditioner> gmres_;
  std::vector<char> held_;
  bool factorized_ = false;
};

}  // namespace gearbench::ehl
