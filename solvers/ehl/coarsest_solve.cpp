#include "coarsest_solve.h"

#include <Eigen/Dense>

namespace gearbench::ehl {

std::vector<char> held_nodes(const ReynoldsCoefficients& c, const std::vector<double>& P,
                             const std::vector<double>& residual) {
  std::vector<char> held(P.size(), 0);
  for (std::size_t i = 1; i + 1 < P.size(); ++i) held[i] = stays_cavitated(P[i], residual[i], c.jacobian(i, i));
  return held;
}

StepInfo CoarsestNewton::factorize(const ReynoldsCoefficients& c, const std::vector<double>& P,
                                   std::vector<char> held, const FilmSensitivity& film) {
  factorized_ = false;
  held_ = std::move(held);
  const std::size_t n = P.size();
  const std::size_t m = n - 2;  // interior unknowns; unknown m is δH0
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(m + 1), static_cast<Eigen::Index>(m + 1));
  const double h2 = c.h * c.h;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const auto row = static_cast<Eigen::Index>(i - 1);
    if (held_[i]) {
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
  }
  // Force balance: h·Σ δP_j = g − h·Σ P_j.
  for (std::size_t j = 1; j + 1 < n; ++j) A(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(j - 1)) = c.h;
  if (!A.allFinite()) return StepInfo::non_finite_system;
  lu_.compute(A);
  factorized_ = true;
  return StepInfo::success;
}

CoarsestStep CoarsestNewton::step(const std::vector<double>& residual, double force_gap) const {
  const std::size_t n = residual.size();
  const std::size_t m = n - 2;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m + 1));
  for (std::size_t i = 1; i + 1 < n; ++i)
    if (!held_[i]) b(static_cast<Eigen::Index>(i - 1)) = residual[i];
  b(static_cast<Eigen::Index>(m)) = force_gap;
  CoarsestStep step;
  if (!b.allFinite()) {
    step.info = StepInfo::non_finite_system;
    return step;
  }
  const Eigen::VectorXd x = lu_.solve(b);
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
