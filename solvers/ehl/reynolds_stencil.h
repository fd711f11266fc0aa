#pragma once
// The discrete Reynolds equation of a line contact on one uniform grid, in the form every
// part of the multigrid shares (residual, relaxation, coarsest-grid solve):
//   L_i = [ε_{i−½}(P_{i−1} − P_i) + ε_{i+½}(P_{i+1} − P_i)]/h²
//         − υ·Σ_m w_m(i)·ρ̄H_{i−m}/h − (ρ̄H_i − (ρ̄H)_old,i)/ΔT,
// with the film H_k = H0 + κX_k²/2 − (D/π)Σ_j K_|k−j| P_j.
// The wedge term is Venner & Lubrecht's second-order upwind difference (Multilevel Methods
// in Lubrication, 2000, §8.2): (1.5·ρ̄H_i − 2·ρ̄H_{i−1} + 0.5·ρ̄H_{i−2})/h, first order,
// (ρ̄H_1 − ρ̄H_0)/h, at the first interior node where no second upstream node exists.
#include <array>
#include <cstddef>
#include <vector>

#include "deformation.h"

namespace gearbench::ehl {

/// Weights w_m of ρ̄H_{i−m}, m = 0, 1, 2, at node i.
[[nodiscard]] inline std::array<double, 3> wedge_weights(std::size_t i) {
  if (i < 2) return {1.0, -1.0, 0.0};
  return {1.5, -2.0, 0.5};
}

/// The cavitation condition P ≥ 0 as every solver of the multigrid applies it: a node at
/// zero whose Newton change r/(∂r/∂P_i) would be negative stays at zero (complementarity).
[[nodiscard]] inline bool stays_cavitated(double P, double residual, double derivative) {
  return P <= 0.0 && residual / derivative <= 0.0;
}

/// What a residual leaves of complementarity unmet: all of it where P > 0, its negative part
/// at P = 0 (the merit of the Newton solves: the coarsest grid's and the spike's).
[[nodiscard]] inline double complementarity_residual(double P, double residual) {
  return P > 0.0 ? residual : (residual < 0.0 ? residual : 0.0);
}

/// The frozen coefficients of one grid during a relaxation sweep or a coarsest-grid solve.
struct ReynoldsCoefficients {
  const std::vector<double>& eps_face;  ///< ε at the faces: entry i is ε_{i+½}, between nodes i and i+1
  const std::vector<double>& rho;       ///< ρ̄_i (times the thermal wedge factor)
  const Deformation& deformation;       ///< kernel K_k of the grid
  double h;                             ///< grid spacing
  double film_factor;                   ///< D/π: ∂H_k/∂P_j = −(D/π)·K_|k−j|
  double speed;                         ///< υ, the wedge term's entrainment factor
  double time_step;                     ///< ΔT (0: steady)
  /// ∂ε_{i+½}/∂P_i and ∂ε_{i+½}/∂P_{i+1} (the piezoviscous response of the flow); null:
  /// ε frozen in the derivative.
  const std::vector<double>* eps_face_dP_left = nullptr;
  const std::vector<double>* eps_face_dP_right = nullptr;
  const std::vector<double>* P = nullptr;  ///< the pressure the ε response multiplies
  /// dρ̄_i/dP_i and the film H_i: the wedge's own density response (null: ρ̄ frozen).
  const std::vector<double>* rho_dP = nullptr;
  const std::vector<double>* H = nullptr;

  /// ∂L_i/∂P_j at frozen ε and ρ̄ (interior i): the Poiseuille stencil and the film's
  /// response through the kernel in the wedge and squeeze terms,
  ///   Σ_m film_derivative(i)_m·(−(D/π)K_|i−m−j|) + local_jacobian(i, j).
  [[nodiscard]] double jacobian(std::size_t i, std::size_t j) const;
  /// jacobian(i, j) for j = first … last into out[j − first], the film's derivative at i taken
  /// once for the row (a Jacobi line's row reads nine entries).
  void jacobian_row(std::size_t i, std::size_t first, std::size_t last, double* out) const;
  /// ∂L_i/∂H_{i−m}, m = 0, 1, 2, at frozen ε and ρ̄: the wedge (and squeeze) terms' response
  /// to the film, which a pressure change reaches through the kernel.
  [[nodiscard]] std::array<double, 3> film_derivative(std::size_t i) const;
  /// The part of ∂L_i/∂P_j that does not pass through the film (zero for |i − j| > 2): the
  /// Poiseuille stencil, ε's piezoviscous response and ρ̄'s own response in the wedge.
  [[nodiscard]] double local_jacobian(std::size_t i, std::size_t j) const;
  /// ∂L_i/∂H0 at frozen ε: the wedge and squeeze terms of a uniform film shift (zero in the
  /// wedge of an incompressible film, whose flux difference does not see H0).
  [[nodiscard]] double h0_derivative(std::size_t i) const;

 private:
  /// Σ_m dL_dH[m]·(−(D/π)K_|i−m−j|): the part of ∂L_i/∂P_j that passes through the film.
  [[nodiscard]] double film_response(const std::array<double, 3>& dL_dH, std::size_t i, std::size_t j) const;
};

}  // namespace gearbench::ehl
