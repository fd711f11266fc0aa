#include "coarsest_solve.h"

#include <Eigen/Dense>

namespace gearbench::ehl {

CoarsestStep coarsest_newton_step(const ReynoldsCoefficients& c, const std::vector<double>& P,
                                  const std::vector<double>& residual,
                                  const FilmSensitivity& film, double force_gap) {
  const std::size_t n = P.size();
  const std::size_t m = n - 2;  // interior unknowns; unknown m is δH0
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(m + 1), static_cast<Eigen::Index>(m + 1));
  Eigen::VectorXd b = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m + 1));
  const double h2 = c.h * c.h;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const auto row = static_cast<Eigen::Index>(i - 1);
    if (stays_cavitated(P[i], residual[i], c.jacobian(i, i))) {
      A(row, row) = 1.0;
      continue;
    }
    // Poiseuille flux differences' response to the film of nodes i − 1, i, i + 1:
    // ∂/∂H_k of [ε_{i−½}(P_{i−1} − P_i) + ε_{i+½}(P_{i+1} − P_i)]/h².
    const double q_minus = (P[i - 1] - P[i]) / h2, q_plus = (P[i + 1] - P[i]) / h2;
    const double dH_prev = film.left[i - 1] * q_minus;
    const double dH_here = film.right[i - 1] * q_minus + film.left[i] * q_plus;
    const double dH_next = film.right[i] * q_plus;
    const auto K = [&](std::size_t k, std::size_t j) { return c.deformation.kernel(k > j ? k - j : j - k); };
    for (std::size_t j = 1; j + 1 < n; ++j) {
      // δH_k = −(D/π)K_|k−j| δP_j.
      const double through_film = -c.film_factor * (dH_prev * K(i - 1, j) + dH_here * K(i, j) + dH_next * K(i + 1, j));
      A(row, static_cast<Eigen::Index>(j - 1)) = c.jacobian(i, j) + through_film;
    }
    A(row, static_cast<Eigen::Index>(m)) = c.h0_derivative(i) + dH_prev + dH_here + dH_next;
    b(row) = residual[i];
  }
  // Force balance: h·Σ δP_j = g − h·Σ P_j.
  for (std::size_t j = 1; j + 1 < n; ++j) A(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(j - 1)) = c.h;
  b(static_cast<Eigen::Index>(m)) = force_gap;
  CoarsestStep step;
  if (!A.allFinite() || !b.allFinite()) {
    step.info = StepInfo::non_finite_system;
    return step;
  }
  const Eigen::VectorXd x = A.partialPivLu().solve(b);
  if (!x.allFinite()) {
    step.info = StepInfo::singular;
    return step;
  }
  step.dP.assign(n, 0.0);
  for (std::size_t j = 1; j + 1 < n; ++j) step.dP[j] = x(static_cast<Eigen::Index>(j - 1));
  step.dH0 = x(static_cast<Eigen::Index>(m));
  return step;
}

}  // namespace gearbench::ehl
