// The relaxation sweep: Jacobi lines where the film's kernel response matters, point Gauss–Seidel
// where the Poiseuille term dominates, every change limited to the exponential's linear range
// (docs/research/ehl-multigrid-rebuild.md, eighth to tenth sessions).
#include "fas_multigrid_impl.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <Eigen/Sparse>

namespace gearbench::ehl {

void FasMultigrid::Impl::relax(Level& l, std::size_t first, std::size_t end, const FilmBase* base) {
  if (end == 0) end = l.n - 1;
  const auto start = std::chrono::steady_clock::now();
  // The nodes whose film and coefficients the sweep reads: the changes reach first − 1 … end
  // (the distribution), the operator reads the film two nodes upstream and ε one node either side.
  const std::size_t lo = first >= 3 ? first - 3 : 0, hi = std::min(l.n - 1, end + 2);
  const auto refresh_film = [&] {
    if (base)
      update_film_window(l, *base, lo, hi);
    else
      update_film(l);
  };
  refresh_film();
  if (base)
    update_coefficients_window(l, lo, hi);
  else
    update_coefficients(l);
  const auto c = coefficients(l);
  std::vector<double> jacobi_change(l.n, 0.0), jacobi_residual(l.n, 0.0);
  std::vector<char> is_jacobi(l.n, 0);
  for (std::size_t i = first; i < end; ++i) {
    if (poiseuille_dominates(l, c, i)) continue;
    const double r = l.f[i] - operator_at(l, i);
    const double derivative = c.jacobian(i, i) - 0.5 * (c.jacobian(i, i - 1) + c.jacobian(i, i + 1));
    if (stays_at_zero(l, i, r, derivative)) continue;
    jacobi_change[i] = limit_change(l, i, o_.omega_jacobi * r / derivative);
    jacobi_residual[i] = r;
    is_jacobi[i] = 1;
  }
  solve_jacobi_lines(l, c, is_jacobi, jacobi_residual, jacobi_change);
  for (std::size_t i = 1; i + 1 < l.n; ++i) {
    if (jacobi_change[i] == 0.0) continue;
    l.P[i] += jacobi_change[i];
    if (i > 1 && !l.cavitated_on_finer[i - 1]) l.P[i - 1] -= 0.5 * jacobi_change[i];
    if (i + 2 < l.n && !l.cavitated_on_finer[i + 1]) l.P[i + 1] -= 0.5 * jacobi_change[i];
  }
  for (auto& p : l.P) p = std::max(p, 0.0);
  l.P.front() = l.P.back() = 0.0;
  refresh_film();
  // Gauss–Seidel nodes after the Jacobi lines, so that they see (and answer) the lines'
  // distributed changes and film.
  for (std::size_t i = first; i < end; ++i) {
    if (is_jacobi[i] || l.cavitated_on_finer[i]) continue;
    const double r = l.f[i] - operator_at(l, i);
    const double old = l.P[i];
    l.P[i] = std::max(0.0, old + limit_change(l, i, o_.omega_gauss_seidel * r / gauss_seidel_derivative(c, i)));
    move_film_near(l, i, l.P[i] - old);
  }
  refresh_film();
  node_sweeps_ += static_cast<double>(hi - lo + 1);
  l.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool FasMultigrid::Impl::poiseuille_dominates(const Level& l, const ReynoldsCoefficients& c, std::size_t i) const {
  ReynoldsCoefficients frozen = c;
  frozen.eps_face_dP_left = frozen.eps_face_dP_right = nullptr;
  const double poiseuille = (l.eps_face[i - 1] + l.eps_face[i]) / (l.h * l.h);
  const double wedge = frozen.jacobian(i, i) + poiseuille;
  return !(poiseuille < o_.relaxation_switch * std::abs(wedge));
}

void FasMultigrid::Impl::solve_jacobi_lines(const Level& l, const ReynoldsCoefficients& c, const std::vector<char>& is_jacobi,
                        const std::vector<double>& residual, std::vector<double>& change) const {
  const auto band = static_cast<std::size_t>(o_.line_band);
  const auto J = [&](std::size_t k, std::size_t j) { return (j == 0 || j + 1 >= l.n) ? 0.0 : c.jacobian(k, j); };
  std::size_t i = 1;
  while (i + 1 < l.n) {
    if (!is_jacobi[i]) { ++i; continue; }
    std::size_t b = i;
    while (b + 2 < l.n && is_jacobi[b + 1]) ++b;
    const std::size_t a = i, m = b - a + 1;
    std::vector<Eigen::Triplet<double>> t;
    std::vector<double> row;  // J(k, q) for q = first − 1 … last + 1, each evaluated once
    for (std::size_t k = a; k <= b; ++k) {
      const std::size_t first = k >= a + band ? k - band : a, last = std::min(b, k + band);
      row.resize(last - first + 3);
      for (std::size_t q = first - 1; q <= last + 1; ++q) row[q + 1 - first] = J(k, q);
      for (std::size_t q = first; q <= last; ++q)
        t.emplace_back(static_cast<int>(k - a), static_cast<int>(q - a),
                       row[q + 1 - first] - 0.5 * (row[q - first] + row[q + 2 - first]));
    }
    Eigen::SparseMatrix<double> A(static_cast<int>(m), static_cast<int>(m));
    A.setFromTriplets(t.begin(), t.end());
    Eigen::VectorXd rhs(static_cast<int>(m));
    for (std::size_t k = a; k <= b; ++k) rhs(static_cast<int>(k - a)) = residual[k];
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::NaturalOrdering<int>> lu;
    lu.compute(A);
    if (lu.info() == Eigen::Success) {
      const Eigen::VectorXd d = lu.solve(rhs);
      if (d.allFinite())
        for (std::size_t k = a; k <= b; ++k)
          change[k] = limit_change(l, k, o_.omega_jacobi * d(static_cast<int>(k - a)));
    }
    i = b + 1;
  }
}

bool FasMultigrid::Impl::stays_at_zero(const Level& l, std::size_t i, double r, double derivative) {
  return l.cavitated_on_finer[i] || stays_cavitated(l.P[i], r, derivative);
}

double FasMultigrid::Impl::gauss_seidel_derivative(const ReynoldsCoefficients& c, std::size_t i) {
  const double with_eps = c.jacobian(i, i);
  if (with_eps < 0.0) return with_eps;
  ReynoldsCoefficients frozen = c;
  frozen.eps_face_dP_left = frozen.eps_face_dP_right = nullptr;
  return frozen.jacobian(i, i);
}

void FasMultigrid::Impl::move_film_near(Level& l, std::size_t i, double delta) const {
  const double c = problem_.deformation_factor() / pi;
  for (std::size_t k = i >= 2 ? i - 2 : 0; k <= std::min(l.n - 1, i + 2); ++k)
    l.H[k] -= c * l.deformation.kernel(k > i ? k - i : i - k) * delta;
}

double FasMultigrid::Impl::limit_change(const Level& l, std::size_t i, double change) const {
  const double s = std::abs(l.eps_log_slope[i]);
  if (s * std::abs(change) <= o_.change_limit) return change;
  return std::copysign(o_.change_limit / s, change);
}

}  // namespace gearbench::ehl
