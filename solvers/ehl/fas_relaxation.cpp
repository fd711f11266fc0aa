// The relaxation sweep: Jacobi lines where the film's kernel response matters, point Gauss–Seidel
// where the Poiseuille term dominates, every change limited to the exponential's linear range
// (docs/research/ehl-multigrid-rebuild.md, eighth to tenth sessions).
#include "fas_multigrid_impl.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

// LAPACK's banded LU with partial pivoting (the Fortran symbol; Debian's liblapack).
extern "C" void dgbsv_(const int* n, const int* kl, const int* ku, const int* nrhs, double* ab, const int* ldab,
                       int* ipiv, double* b, const int* ldb, int* info);

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
  // The sweep's work vectors span its own nodes (entry i − first): a sweep over a window (the
  // free boundary's) costs the window, not the grid.
  const std::size_t m = end - first;
  std::vector<double> jacobi_change(m, 0.0), jacobi_residual(m, 0.0);
  std::vector<char> is_jacobi(m, 0);
  for (std::size_t i = first; i < end; ++i) {
    if (poiseuille_dominates(l, c, i)) continue;
    const double r = l.f[i] - operator_at(l, i);
    std::array<double, 3> J{};  // ∂L_i/∂P_{i−1}, ∂L_i/∂P_i, ∂L_i/∂P_{i+1}
    c.jacobian_row(i, i - 1, i + 1, J.data());
    const double derivative = J[1] - 0.5 * (J[0] + J[2]);
    if (stays_at_zero(l, i, r, derivative)) continue;
    jacobi_change[i - first] = o_.omega_jacobi * r / derivative;
    jacobi_residual[i - first] = r;
    is_jacobi[i - first] = 1;
  }
  solve_jacobi_lines(l, c, first, is_jacobi, jacobi_residual, jacobi_change);
  add_distributed_changes(l, first, jacobi_change);
  // P ≥ 0 where the changes reached, first − 1 … end: the whole grid for a whole-grid sweep, so
  // that an interpolated start's negative pressures are removed.
  for (std::size_t i = first - 1; i <= end; ++i) l.P[i] = std::max(l.P[i], 0.0);
  l.P.front() = l.P.back() = 0.0;
  refresh_film();
  // Gauss–Seidel nodes after the Jacobi lines, so that they see (and answer) the lines'
  // distributed changes and film.
  for (std::size_t i = first; i < end; ++i) {
    if (is_jacobi[i - first] || l.cavitated_on_finer[i]) continue;
    const double r = l.f[i] - operator_at(l, i);
    const double old = l.P[i];
    l.P[i] = std::max(0.0, old + limit_change(l, i, o_.omega_gauss_seidel * r / gauss_seidel_derivative(c, i)));
    move_film_near(l, i, l.P[i] - old);
  }
  refresh_film();
  // A sweep over a window is the free boundary's (relax_free_boundary), over the grid a cycle's.
  (base ? node_sweeps_.free_boundary : node_sweeps_.relaxation) += static_cast<double>(hi - lo + 1);
  l.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void FasMultigrid::Impl::relax_single_grid(Level& l) {
  relax(l);
  H0_ += single_grid_h0_gain * (integral(l) - l.g);
}

bool FasMultigrid::Impl::poiseuille_dominates(const Level& l, const ReynoldsCoefficients& c, std::size_t i) const {
  ReynoldsCoefficients frozen = c;
  frozen.eps_face_dP_left = frozen.eps_face_dP_right = nullptr;
  const double poiseuille = (l.eps_face[i - 1] + l.eps_face[i]) / (l.h * l.h);
  const double wedge = frozen.jacobian(i, i) + poiseuille;
  return !(poiseuille < o_.relaxation_switch * std::abs(wedge));
}

void FasMultigrid::Impl::solve_jacobi_lines(const Level& l, const ReynoldsCoefficients& c, std::size_t first,
                                            const std::vector<char>& is_jacobi, const std::vector<double>& residual,
                                            std::vector<double>& change) const {
  const auto band = static_cast<std::size_t>(o_.line_band);
  const std::size_t end = first + is_jacobi.size();
  std::vector<double> band_storage, d, row;  // row: J(k, q) for q = lo − 1 … hi + 1, each evaluated once
  std::vector<int> pivots;
  std::size_t i = first;
  while (i < end) {
    if (!is_jacobi[i - first]) { ++i; continue; }
    std::size_t b = i;
    while (b + 1 < end && is_jacobi[b + 1 - first]) ++b;
    const std::size_t a = i, m = b - a + 1;
    // LAPACK band storage for dgbsv: kl = ku = band, ab(kl + ku + 1 + r − c, c) = A(r, c) with
    // kl extra rows for the fill-in of partial pivoting, column-major, leading dimension 3·band + 1.
    const int n = static_cast<int>(m), kl = static_cast<int>(band), ku = kl, ldab = 2 * kl + ku + 1, nrhs = 1;
    band_storage.assign(static_cast<std::size_t>(ldab) * m, 0.0);
    for (std::size_t k = a; k <= b; ++k) {
      const std::size_t lo = k >= a + band ? k - band : a, hi = std::min(b, k + band);
      row.resize(hi - lo + 3);
      c.jacobian_row(k, lo - 1, hi + 1, row.data());
      if (lo == 1) row.front() = 0.0;  // the boundary nodes P_0 and P_{n−1} do not move
      if (hi + 2 == l.n) row.back() = 0.0;
      for (std::size_t q = lo; q <= hi; ++q) {
        const auto r = static_cast<std::ptrdiff_t>(k - a), col = static_cast<std::ptrdiff_t>(q - a);
        band_storage[static_cast<std::size_t>(kl + ku + r - col + col * ldab)] =
            row[q + 1 - lo] - 0.5 * (row[q - lo] + row[q + 2 - lo]);
      }
    }
    d.resize(m);
    for (std::size_t k = a; k <= b; ++k) d[k - a] = residual[k - first];
    pivots.resize(m);
    int info = 0;
    dgbsv_(&n, &kl, &ku, &nrhs, band_storage.data(), &ldab, pivots.data(), d.data(), &n, &info);
    if (info == 0 && std::all_of(d.begin(), d.end(), [](double v) { return std::isfinite(v); }))
      for (std::size_t k = a; k <= b; ++k) change[k - first] = o_.omega_jacobi * d[k - a];
    i = b + 1;
  }
}

void FasMultigrid::Impl::add_distributed_changes(Level& l, std::size_t first,
                                                 const std::vector<double>& amplitude) const {
  // change[k]: the change of P at node first − 1 + k, over the nodes first − 1 … end the
  // distribution reaches.
  std::vector<double> change(amplitude.size() + 2, 0.0);
  for (std::size_t k = 0; k < amplitude.size(); ++k) {
    const double a = amplitude[k];
    if (a == 0.0) continue;
    const std::size_t i = first + k;
    change[k + 1] += a;
    if (i > 1 && !l.cavitated_on_finer[i - 1]) change[k] -= 0.5 * a;
    if (i + 2 < l.n && !l.cavitated_on_finer[i + 1]) change[k + 2] -= 0.5 * a;
  }
  for (std::size_t k = 0; k < change.size(); ++k)
    if (change[k] != 0.0) l.P[first + k - 1] += limit_change(l, first + k - 1, change[k]);
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
  l.film_of.valid = false;
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
