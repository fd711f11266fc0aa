#pragma once
// Independent numerical reference for the steady, isothermal, smooth line contact (EHL):
// a damped Newton–Raphson solver with a dense Jacobian in the manner of Houpert & Hamrock,
// J. Tribol. 108 (1986) 411–420. It shares no code with solvers/ehl (multigrid) and uses its
// own discretisation; docs/ehl-model.md, "Independent numerical reference (reference/ehl_newton)",
// gives the equations, the discretisation and the values measured with it.
//
// Problem (Hertzian scaling, Venner & Lubrecht, Multilevel Methods in Lubrication, 2000;
// the links are derived in docs/research/ehl.md §5): X = x/b, P = p/p_h, H = h·R/b²,
//   d/dX(ε dP/dX) − dH/dX = 0,  ε = H³/(η̄·λ̄),  λ̄ = 3π²/(8M²),  η̄ = exp(ᾱP),  ᾱ = L·√(M/2π),
//   H = H0 + X²/2 − (1/π)∫ ln|X − X′|·P(X′) dX′,   ∫P dX = π/2,
// incompressible, Barus; Reynolds outlet as the complementarity P ≥ 0, −L(P) ≥ 0, P·L(P) = 0.
// Films are returned in Moes' units H_M = (h/R)·U_Σ^(−1/2), U_Σ = η0(u1 + u2)/(E′R):
// h/R = H·b²/R² = H·8W/π and M = W·U_Σ^(−1/2) give H_M = (8M/π)·H.
#include <array>
#include <limits>
#include <vector>

namespace gearbench::reference {

struct EhlNewtonOptions {
  /// Rigid surfaces (deformation off): H = H0 + X²/2; the rigid-isoviscous (Martin) limit.
  bool rigid = false;
  /// Domain [x_in, x_out] and start of the uniform core x_core, in X = x/b. NaN: the defaults
  /// of ehl_newton_domain().
  double x_in = std::numeric_limits<double>::quiet_NaN();
  double x_core = std::numeric_limits<double>::quiet_NaN();
  double x_out = std::numeric_limits<double>::quiet_NaN();
  double core_fraction = 0.7;  ///< share of the nodes on the uniform core [x_core, x_out]
  int max_iterations = 100;    ///< Newton iterations per solve (65 needed at M = 10, L = 17.5, 1025 nodes)
  double tolerance = 1e-9;     ///< on max |complementarity residual| and |force balance|
};

struct EhlNewtonDomain {
  double x_in = 0.0, x_core = 0.0, x_out = 0.0;
};

/// Default domain. With s = 1.3865/M, Martin's inlet length √(2R·h0)/b in Hertz widths
/// (h0 = 4.8950·η0ūR/w, so (s·M)² = 2·4.8950·π/16): elastic x_in = −(4.5 + 100·s),
/// x_core = −(1.5 + 3s), x_out = 1.5 + 1.5·s; rigid x_in = −100·s, x_core = −3s, x_out = 1.5·s.
/// 100·s upstream leaves 4/(4.895·100²) ≈ 1e-4 of Martin's load outside the domain.
EhlNewtonDomain ehl_newton_domain(double M, bool rigid);

struct EhlNewtonResult {
  double M = 0.0, L = 0.0;
  int nodes = 0;
  double H_c = 0.0;      ///< film at X = 0, Moes units
  double H_min = 0.0;    ///< minimum film, Moes units
  double X_min = 0.0;    ///< its position, X = x/b
  double H0 = 0.0;       ///< the film constant of the Hertzian scaling
  double p_max = 0.0;    ///< max p/p_h
  double x_cavitation = 0.0;  ///< first node downstream of the pressure where P = 0
  bool converged = false;
  int iterations = 0;         ///< Newton iterations of the last (successful) solve
  int solves = 0;             ///< solves of the continuation in ᾱ (1: none needed)
  double residual = 0.0;      ///< final max |residual|
  std::vector<double> residual_history;  ///< of the last solve, one per iteration
  std::vector<double> X, P, H;           ///< nodes, P = p/p_h and H (Hertzian scaling)
};

/// Solves the Moes point (M, L) on `nodes` nodes. Starts from the Hertz pressure with H0 from
/// Moes' formula (M ≥ 5) or from the rigid solution (M < 5); when that fails it continues in ᾱ
/// from 0. Never throws for a failed solve: converged = false. Throws std::invalid_argument for
/// bad input (M ≤ 0, L < 0, nodes < 5).
EhlNewtonResult ehl_newton_line_contact(double M, double L, int nodes, const EhlNewtonOptions& options = {});

/// Martin's load constant w·h_min/(η0·ū·R) = 2M·H_min (Moes units; derived in the docs).
double ehl_newton_martin_constant(const EhlNewtonResult& r);

/// The observed order and Richardson value of three values on grids halving the spacing:
/// p = log2((v1 − v2)/(v2 − v3)), value = v3 + (v3 − v2)/(2^p − 1), error = |value − v3|.
/// When the changes do not shrink monotonically (ratio ≤ 1: no asymptotic range, e.g. values
/// converged to their noise floor), value = v3, p = NaN and error = |v3 − v2|.
struct RichardsonValue {
  double value = 0.0, order = 0.0, error = 0.0;
};
RichardsonValue richardson_observed(double v1, double v2, double v3);

/// Grid-converged values from three nested grids n, 2n − 1, 4n − 3 (each solve starts from the
/// last one interpolated), by richardson_observed.
struct EhlNewtonGridStudy {
  std::array<EhlNewtonResult, 3> solves;
  RichardsonValue H_c, H_min;  ///< Moes units
  bool converged = false;      ///< all three solves converged
};

EhlNewtonGridStudy ehl_newton_grid_study(double M, double L, int coarse_nodes,
                                         const EhlNewtonOptions& options = {});

}  // namespace gearbench::reference
