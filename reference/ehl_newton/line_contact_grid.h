#pragma once
// The discretisation of the Newton line-contact reference (reference/ehl_newton): a smoothly
// stretched node set and the elastic influence coefficients of piecewise-LINEAR pressure
// elements, integrated analytically. Independent of solvers/ehl (which uses a uniform grid
// and piecewise-constant pressure cells). Derivations: docs/ehl-model.md, section
// "Independent numerical reference (reference/ehl_newton)".
#include <Eigen/Dense>
#include <vector>

namespace gearbench::reference::ehl_newton_grid {

/// Nodes X_0 < … < X_{n−1} on [x_in, x_out] from a uniform parameter t_k = k/(n−1): uniform
/// (a fraction `core_fraction` of the nodes) on the core [x_core, x_out], and for t < t_c =
/// 1 − core_fraction X(t) = x_core − k·(t_c − t) − A·(t_c − t)⁴, k the core slope dX/dt and A
/// chosen so that X(0) = x_in. The map is C³ at the junction, so a scheme of order 2 on the
/// uniform parameter stays of order 2, and grids of n and 2n − 1 nodes are nested.
/// Throws std::invalid_argument when x_in is too close for the stretch (A < 0).
std::vector<double> stretched_grid(int nodes, double x_in, double x_core, double x_out,
                                   double core_fraction);

/// Row of the elastic operator at the point x: c_j = −(1/π)·∫ φ_j(X′)·ln|x − X′| dX′ for the
/// hat function φ_j of every node j (so the deformation is Σ_j c_j·P_j for a piecewise-linear
/// pressure). Written into row[0 … n−1].
void deformation_row(const std::vector<double>& X, double x, double* row);

/// The n×n matrix of deformation_row at every node.
Eigen::MatrixXd deformation_matrix(const std::vector<double>& X);

/// Trapezoid weights q_j = (X_{j+1} − X_{j−1})/2: Σ q_j·P_j = ∫P dX exactly for piecewise-linear P.
std::vector<double> trapezoid_weights(const std::vector<double>& X);

}  // namespace gearbench::reference::ehl_newton_grid
