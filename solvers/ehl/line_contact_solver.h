#pragma once
// FAS multigrid solver of the steady isothermal line-contact EHL problem
// (Venner & Lubrecht, Multilevel Methods in Lubrication, 2000, ch. 6–7):
//   - uniform grids, n_k = (n_0 − 1)·2^k + 1 nodes, full multigrid from the coarsest;
//   - Reynolds equation with central Poiseuille and first-order upwind wedge terms
//     (first order in h: the tests measure the order this gives);
//   - relaxation: Gauss–Seidel (under-relaxed) where ε/h² ≥ ξ, distributive Jacobi
//     (changes (−¼, 1, −¼)) where ε/h² < ξ, P ≥ 0 imposed after each change; by default
//     as line relaxation (all changes of a sweep solved at once, line_relaxation.h), or
//     point by point;
//   - the force balance closes through H0 on the coarsest grid with the FAS right-hand side;
//   - the deformation integral by zero-padded FFT convolution (O(n log n) per sweep).
#include <limits>
#include <string>
#include <vector>

#include "line_contact_problem.h"

namespace gearbench::ehl {

enum class CycleType { V, W };
/// Line: the changes of a sweep solved together from a banded Jacobian (line_relaxation.h).
/// Point: one node at a time with the Jacobian diagonal (the scheme before line relaxation,
/// kept as the fallback of a failed line solve).
enum class Relaxation { line, point };

struct EhlOptions {
  int levels = 5;                 ///< grid levels, 641 nodes from 41 (seed 001 uses 6)
  int coarsest_nodes = 41;        ///< nodes on the coarsest grid (seed 001: 41)
  CycleType cycle = CycleType::W;  ///< W converges in ~10 cycles where V needs 40–80
  int pre_sweeps = 2;             ///< relaxations before the coarse-grid correction
  int post_sweeps = 2;            ///< relaxations after it
  int coarsest_sweeps = 10;       ///< relaxations (then one H0 update) per coarsest visit
  int max_cycles = 200;           ///< cap: more is a convergence failure
  double tolerance = 1e-8;        ///< on the scaled residual and the force balance
  Relaxation relaxation = Relaxation::line;
  int line_band = 2;              ///< neighbours of the Jacobian kept in a line solve
  // Under-relaxation, measured over a suite of 15 (M, L, grid) cases from M 1 to 1000, L 0
  // to 20 and 641 to 5121 nodes: line relaxation with 0.3 and 0.2 converged 13 of them
  // (point relaxation with 0.3 and 0.1: 8); 0.5 for Gauss–Seidel lines diverged at high L,
  // and 0.1 for the Jacobi lines is what M = 1000, L = 0 needs (the solver's fallback).
  double omega_gauss_seidel = 0.3;
  double omega_jacobi = 0.2;
  double h0_damping = 0.15;       ///< H0 ← H0 + c·S·(∫P − F)/F on the coarsest grid
                                  ///< (S = 1 Hertzian, the film guess in rigid units)
  double xi_threshold = 1.0;      ///< ε/h² splitting Gauss–Seidel from Jacobi (0.3 and 1
                                  ///< converge the same suite cases; 1 in fewer cycles)
  /// Coarse nodes where the injected pressure varies on the coarse mesh's scale are held
  /// (fas_multigrid.cpp, hold_unresolved): on fine grids the resolved pressure spike (and at
  /// L = 0 from 10241 nodes the outlet) otherwise drives the coarse problems to divergence.
  /// Off by default: on 641 nodes it costs up to twice the cycles at high L (M = 10, L = 15:
  /// 45 against 22) and fails where the plain scheme converges (M = 1, L = 15); the first
  /// fallback turns it on.
  bool hold_unresolved = false;
  double x_in = 0.0, x_out = 0.0; ///< domain; both 0 picks the problem's default
  bool direct_deformation = false; ///< the O(n²) sum instead of the FFT (the benchmarks' baseline)

  void validate() const;          ///< InputError naming the key
  /// Point relaxation as it was before line relaxation (ξ 0.3, ω 0.3/0.1): about half the
  /// cost per sweep of a line sweep (no banded LU), for callers whose contacts it converges.
  [[nodiscard]] static EhlOptions point_relaxation();
};

struct EhlResult {
  // Dimensionless solution on the finest grid.
  std::vector<double> X, P, H;
  double H0 = 0.0;
  // Figures in SI.
  double h_central = 0.0;   ///< film at X = 0 [m]
  double h_min = 0.0;       ///< minimum film [m]
  double x_h_min = 0.0;     ///< its position [m]
  double p_max = 0.0;       ///< [Pa]
  double h_dpdx0 = 0.0;     ///< film where dp/dx first vanishes from the inlet (Moes' film) [m]
  double friction_force = 0.0;        ///< per unit length, Newtonian [N/m]
  double friction_coefficient = 0.0;
  // Diagnostics.
  bool converged = false;
  /// The scheme that converged (or the last one tried), e.g. "W, line, ω_GS 0.3, ω_J 0.2,
  /// ξ 1", with "(attempt k)" when earlier schemes failed.
  std::string cycle_type;
  int attempts = 1;                        ///< solves tried, the fallbacks included
  int cycles = 0;
  double work_units = 0.0;                 ///< finest-grid relaxation sweeps equivalent
  std::vector<double> residual_history;    ///< scaled Reynolds residual per cycle
  std::vector<double> force_history;       ///< |∫P dX − F|/F per cycle
  std::vector<double> seconds_per_level;
  double seconds = 0.0;
  /// Change of H_min and P_max between the solutions on the two finest grids (relative):
  /// the discretisation-error estimate. NaN where there is none: a warm-started solve (a
  /// time step, a thermal iteration, the continuation in α) or a single grid.
  double h_min_change = std::numeric_limits<double>::quiet_NaN();
  double p_max_change = std::numeric_limits<double>::quiet_NaN();
  double coarse_h_min = 0.0, coarse_p_max = 0.0;  ///< on the next-coarser grid [m], [Pa]

  [[nodiscard]] std::string summary() const;
  /// "EHL multigrid did not converge in N cycles (residual, force balance, tolerance) with
  /// any of k schemes (last: …)": the one error message of a failed steady solve.
  [[nodiscard]] std::string failure_message(double tolerance) const;
};

class LineContactSolver {
 public:
  LineContactSolver(const LineContactProblem& problem, EhlOptions options);
  /// Solves by full multigrid; throws ConvergenceError (with the residual history) when the
  /// tolerance is not met within max_cycles. A failed solve is repeated with the fallbacks
  /// of fallback_schemes() before it counts as failed.
  [[nodiscard]] EhlResult solve() const;
  /// The same, returning an unconverged result (converged = false) instead of throwing, so
  /// that a caller can write the diagnostics before it reports the failure.
  [[nodiscard]] EhlResult try_solve() const;

  /// The schemes tried in turn: the given options; the same with hold_unresolved toggled
  /// (holding the coarse nodes of a resolved pressure spike: fine grids at high L); the
  /// Jacobi under-relaxation halved; the Gauss–Seidel split ξ raised 100× (fine grids at
  /// L = 0, where ε/h² ≥ 1 reaches into the contact); the same on one level fewer, from a
  /// coarsest grid of twice the nodes; point relaxation with ω_J halved; the same with
  /// V-cycles. Each is a complete solve from scratch; all solve the same discrete equations
  /// on the same finest grid. When all fail, try_solve() continues in α
  /// (solve_by_continuation).
  [[nodiscard]] static std::vector<EhlOptions> fallback_schemes(const EhlOptions& options);
  [[nodiscard]] static std::string describe(const EhlOptions& options);

 private:
  /// The schemes of fallback_schemes() in turn on `problem`, each from scratch.
  [[nodiscard]] EhlResult solve_with_fallbacks(const LineContactProblem& problem) const;
  /// The contact solved at α/2, then with α raised step by step to its value, each step
  /// warm-started from the last: the last resort of try_solve() for piezoviscous contacts.
  [[nodiscard]] EhlResult solve_by_continuation() const;

  const LineContactProblem& problem_;
  EhlOptions options_;
};

}  // namespace gearbench::ehl
