#pragma once
// The FAS multigrid machinery shared by the steady and the transient line-contact solvers
// (Venner & Lubrecht 2000, ch. 6–8): grid hierarchy, relaxation by Jacobi lines and
// Gauss–Seidel, local treatment of the pressure spike and the free boundary, coarse grids with
// their own coefficients, the coarsest grid solved directly in (P, H0), full multigrid and the
// stop at the discretisation error (the internals: fas_multigrid_impl.h). The contact state generalises the
// steady problem of LineContactProblem by the factors of a transient along a gear mesh
// (seed 004's C_R, C_u, C_w, here relative to the problem's reference contact):
//   H = H0 + κ·X²/2 − (D/π)∫ln|X − X'|P dX',
//   d/dX(ε dP/dX) − υ·d(ρ̄H)/dX − (ρ̄H − (ρ̄H)_old)/ΔT = 0,   ∫P dX = F,
// with κ = R_ref/R, υ = ū/ū_ref, T = t·ū_ref/ℓ and implicit Euler in time.
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "line_contact_solver.h"

namespace gearbench::ehl {

/// A previous solution to start from instead of full multigrid (same finest grid).
struct WarmStart {
  std::vector<double> P;
  double H0 = 0.0;
  /// The relative discretisation-error estimate of a nearby solution on this grid (a previous
  /// time step's, from its full multigrid). Given, a warm solve under the error rule stops at
  /// error_fraction of it; none (NaN), or under the residual rule, at grid.tolerance.
  double error_estimate = std::numeric_limits<double>::quiet_NaN();
  /// The per-cycle factor the nearby solve's rule took (EhlResult::rule_factor): with the
  /// estimate, the floor of the warm solve's factor.
  double rule_factor = std::numeric_limits<double>::quiet_NaN();
};

struct ContactState {
  double curvature = 1.0;   ///< κ = R_ref/R
  double speed = 1.0;       ///< υ = ū/ū_ref
  double load = 0.0;        ///< F = ∫P dX; 0 takes the problem's load
  double time_step = 0.0;   ///< ΔT; 0 is steady
  std::vector<double> rho_h_old;  ///< (ρ̄H) of the previous step on the finest grid
  /// Thermal film (generalized Reynolds equation, Yang & Wen 1990): per finest-grid node,
  /// the Poiseuille coefficient (ρ/η)_e and the wedge density ρ* relative to the isothermal
  /// ρ̄/η̄ and ρ̄ at the same pressure. Frozen during a solve; coarse grids inject them.
  /// Empty: isothermal (all factors 1).
  std::vector<double> flow_factor, wedge_factor;
  /// The solution of a nearby contact on the finest grid (the previous time step's): full
  /// multigrid's start on the coarsest grid is injected from it and solved by Newton at the full
  /// viscosity, without the homotopy in the piezoviscous exponent that the Hertzian guess needs.
  /// Empty P: that cold start.
  WarmStart nearby;
  /// Whether the state carries fields on the finest grid (which then must be fixed).
  [[nodiscard]] bool has_fields() const {
    return !rho_h_old.empty() || !flow_factor.empty() || !wedge_factor.empty() || !nearby.P.empty();
  }
};

class FasMultigrid {
 public:
  FasMultigrid(const LineContactProblem& problem, const EhlOptions& options, ContactState state);
  ~FasMultigrid();
  FasMultigrid(const FasMultigrid&) = delete;
  FasMultigrid& operator=(const FasMultigrid&) = delete;

  /// Full multigrid (or the warm start), then cycles to the stop rule; unconverged results
  /// come back with converged = false.
  EhlResult solve(const std::optional<WarmStart>& warm = std::nullopt);
  /// ρ̄H on the finest grid of the current solution (the next step's (ρ̄H)_old).
  std::vector<double> rho_h();

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gearbench::ehl
