#pragma once
// Line relaxation of the discrete Reynolds equation of a line contact: the line variant of
// the mixed Gauss–Seidel / distributive Jacobi scheme of Venner & Lubrecht (Multilevel
// Methods in Lubrication, 2000, ch. 7); in one dimension the line is the whole grid.
//
// All changes of one sweep are solved for at once from a banded approximation of the
// Jacobian of L_i(P) = (ε dP/dX)' − υ(ρ̄H)' − (ρ̄H − (ρ̄H)_old)/ΔT:
//   J_ij = Poiseuille stencil + (υ/h + ρ-weighted squeeze)·(D/π)·(ρ̄_i K_|i−j| − ρ̄_{i−1} K_|i−1−j|),
// kept for |i − j| ≤ q (the kernel K of the film's own response). Where ε/h² is small the
// change of node j is distributed as (−¼, 1, −¼) around j (Venner's distributive Jacobi),
// which turns the slowly decaying log kernel into its second difference; the unknowns are
// then δ̃ with δP = D·δ̃, and the system (J·D)·δ̃ = ω·r is banded with half-band q + 1.
// It is solved by GSL's banded LU with partial pivoting. Cavitated nodes (P = 0 whose own
// change would be negative) are held at zero; negative pressures are cut off afterwards.
#include <gsl/gsl_linalg.h>

#include <memory>
#include <vector>

#include "deformation.h"

namespace gearbench::ehl {

/// The frozen coefficients of one grid during a sweep.
struct ReynoldsCoefficients {
  const std::vector<double>& eps;  ///< ε_i = ρ̄H³/(η̄λ) (times the thermal flow factor)
  const std::vector<double>& rho;  ///< ρ̄_i (times the thermal wedge factor)
  const Deformation& deformation;  ///< kernel K_k of the grid
  double h;                        ///< grid spacing
  double film_factor;              ///< D/π: ∂H_k/∂P_j = −(D/π)·K_|k−j|
  double speed;                    ///< υ, the wedge term's entrainment factor
  double time_step;                ///< ΔT (0: steady)
};

class LineRelaxation {
 public:
  /// Workspace for a grid of `nodes` points, keeping the Jacobian to `band` neighbours.
  LineRelaxation(std::size_t nodes, int band);
  ~LineRelaxation();
  LineRelaxation(const LineRelaxation&) = delete;
  LineRelaxation& operator=(const LineRelaxation&) = delete;

  /// The pressure change δP of one sweep. `residual` is f − L(P) at the interior nodes,
  /// `jacobi[i]` marks the nodes relaxed by distributed changes, `omega_*` under-relax the
  /// right-hand side of the two kinds of node. The ends (P = 0) do not change, nor do the
  /// nodes marked in `held` (empty: none), as cavitated nodes do not.
  [[nodiscard]] std::vector<double> change(const ReynoldsCoefficients& c, const std::vector<double>& P,
                                           const std::vector<double>& residual,
                                           const std::vector<char>& jacobi, double omega_gauss_seidel,
                                           double omega_jacobi, const std::vector<char>& held = {});

 private:
  /// ∂L_i/∂P_j in the band |i − j| ≤ q (interior i and j), stored row by row.
  void assemble_jacobian(const ReynoldsCoefficients& c);
  /// The stored ∂L_i/∂P_j; zero outside the band and for the end nodes.
  [[nodiscard]] double jacobian(long i, long j) const;

  std::size_t n_;
  int q_;
  gsl_matrix* band_matrix_;
  gsl_vector* x_;
  gsl_vector_uint* pivots_;
  std::vector<double> jacobian_;  ///< n × (2q + 1): row i holds ∂L_i/∂P_{i−q…i+q}
};

}  // namespace gearbench::ehl
