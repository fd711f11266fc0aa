#include "coarsest_solve.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

namespace gearbench::ehl {

std::vector<char> held_nodes(const ReynoldsCoefficients& c, const std::vector<double>& P,
                             const std::vector<double>& residual) {
  std::vector<char> held(P.size(), 0);
  for (std::size_t i = 1; i + 1 < P.size(); ++i) held[i] = stays_cavitated(P[i], residual[i], c.jacobian(i, i));
  return held;
}

ReynoldsRow reynolds_row(const ReynoldsCoefficients& c, const FilmSensitivity& film, const std::vector<double>& P,
                         std::size_t i) {
  // Poiseuille flux differences' response to the film of nodes i − 1, i, i + 1:
  // ∂/∂H_k of [ε_{i−½}(P_{i−1} − P_i) + ε_{i+½}(P_{i+1} − P_i)]/h².
  const double h2 = c.h * c.h;
  const double q_minus = (P[i - 1] - P[i]) / h2, q_plus = (P[i + 1] - P[i]) / h2;
  const auto wedge = c.film_derivative(i);
  ReynoldsRow row;
  row.dL_dH = {wedge[2], wedge[1] + film.left[i - 1] * q_minus,
               wedge[0] + film.right[i - 1] * q_minus + film.left[i] * q_plus, film.right[i] * q_plus};
  for (std::size_t t = 0; t < 5; ++t)
    if (i + t >= 2) row.band[t] = c.local_jacobian(i, i + t - 2);
  row.dL_dH0 = row.dL_dH[0] + row.dL_dH[1] + row.dL_dH[2] + row.dL_dH[3];
  return row;
}

StepInfo CoarsestNewton::factorize(const ReynoldsCoefficients& c, const std::vector<double>& P,
                                   std::vector<char> held, const FilmSensitivity& film) {
  factorized_ = false;
  held_ = std::move(held);
  const std::size_t n = P.size();
  // Unknowns: the interior pressures 1 … n − 2, then δH0; the last row is h·Σ δP_j.
  jacobian_.emplace(c.deformation, c.film_factor, 1, n - 2, true);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (held_[i]) {
      jacobian_->set_border(i, 0.0, c.h);
      continue;
    }
    const ReynoldsRow row = reynolds_row(c, film, P, i);
    const auto finite = [](const auto& values) {
      return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
    };
    if (!finite(row.dL_dH) || !finite(row.band) || !std::isfinite(row.dL_dH0)) return StepInfo::non_finite_system;
    jacobian_->set_row(i, row.dL_dH, row.band);
    jacobian_->set_border(i, row.dL_dH0, c.h);
  }
  if (dense()) {
    const Eigen::Index size = jacobian_->rows();
    Eigen::MatrixXd A(size, size);
    for (Eigen::Index r = 0; r < size; ++r)
      for (Eigen::Index q = 0; q < size; ++q)
        A(r, q) = jacobian_->entry(static_cast<std::size_t>(r), static_cast<std::size_t>(q));
    lu_.compute(A);
  } else {
    gmres_.setTolerance(krylov_tolerance);
    gmres_.setMaxIterations(krylov_iterations);
    gmres_.set_restart(krylov_iterations);
    gmres_.compute(*jacobian_);
    if (gmres_.preconditioner().info() != Eigen::Success) return StepInfo::singular;
  }
  factorized_ = true;
  return StepInfo::success;
}

CoarsestStep CoarsestNewton::step(const std::vector<double>& residual, double force_gap) {
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
  Eigen::VectorXd x;
  if (dense()) {
    x = lu_.solve(b);
  } else {
    x = gmres_.solve(b);
    step.iterations = static_cast<int>(gmres_.iterations());
  }
  if (!x.allFinite()) {
    step.info = StepInfo::singular;
    return step;
  }
  step.dP.assign(n, 0.0);
  // A held node's row is the identity with a zero right-hand side, so its change is zero in
  // exact arithmetic; the LU's pivoting and GMRES's tolerance leave it 1e-28 … 1e-20, which the
  // clipped update kept as a tiny pressure. Such a node is no longer held by the next step's
  // rule (P > 0), so the kept Jacobian was discarded and refactorized at every step.
  for (std::size_t j = 1; j + 1 < n; ++j) step.dP[j] = held_[j] ? 0.0 : x(static_cast<Eigen::Index>(j - 1));
  step.dH0 = x(static_cast<Eigen::Index>(m));
  return step;
}

}  // namespace gearbench::ehl
