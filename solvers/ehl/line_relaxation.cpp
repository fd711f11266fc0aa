#include "line_relaxation.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "model/gsl_status.h"

namespace gearbench::ehl {

LineRelaxation::LineRelaxation(std::size_t nodes, int band)
    : n_(nodes), q_(band) {
  if (nodes < 5 || band < 1) throw std::invalid_argument("LineRelaxation needs ≥ 5 nodes and band ≥ 1");
  const std::size_t m = n_ - 2;            // interior unknowns
  const std::size_t b = static_cast<std::size_t>(q_) + 1;  // half-band of J·D
  band_matrix_ = gsl_matrix_alloc(m, 3 * b + 1);  // GSL band LU storage: N × (2·lb + ub + 1)
  x_ = gsl_vector_alloc(m);
  jacobian_.assign(n_ * static_cast<std::size_t>(2 * q_ + 1), 0.0);
  pivots_ = gsl_vector_uint_alloc(m);
}

LineRelaxation::~LineRelaxation() {
  gsl_vector_uint_free(pivots_);
  gsl_vector_free(x_);
  gsl_matrix_free(band_matrix_);
}

void LineRelaxation::assemble_jacobian(const ReynoldsCoefficients& c) {
  const long n = static_cast<long>(n_);
  const long width = 2 * q_ + 1;
  std::fill(jacobian_.begin(), jacobian_.end(), 0.0);
  const double h2 = c.h * c.h;
  for (long i = 1; i + 1 < n; ++i) {
    const double em = 0.5 * (c.eps[i - 1] + c.eps[i]);
    const double ep = 0.5 * (c.eps[i] + c.eps[i + 1]);
    for (long j = std::max(1L, i - q_); j <= std::min(n - 2, i + q_); ++j) {
      // Wedge and squeeze: −υ(ρ̄_i δH_i − ρ̄_{i−1} δH_{i−1})/h − ρ̄_i δH_i/ΔT, δH_k = −(D/π)K δP.
      const double K_i = c.deformation.kernel(static_cast<std::size_t>(std::labs(i - j)));
      const double K_im1 = c.deformation.kernel(static_cast<std::size_t>(std::labs(i - 1 - j)));
      double value = c.speed * c.film_factor * (c.rho[i] * K_i - c.rho[i - 1] * K_im1) / c.h;
      if (c.time_step > 0.0) value += c.film_factor * c.rho[i] * K_i / c.time_step;
      // Poiseuille: (ε_{i−½}(P_{i−1} − P_i) + ε_{i+½}(P_{i+1} − P_i))/h², faces by the mean.
      if (j == i) value -= (em + ep) / h2;
      if (j == i - 1) value += em / h2;
      if (j == i + 1) value += ep / h2;
      jacobian_[static_cast<std::size_t>(i * width + (j - i + q_))] = value;
    }
  }
}

double LineRelaxation::jacobian(long i, long j) const {
  if (std::labs(i - j) > q_) return 0.0;
  return jacobian_[static_cast<std::size_t>(i * (2 * q_ + 1) + (j - i + q_))];
}

std::vector<double> LineRelaxation::change(const ReynoldsCoefficients& c, const std::vector<double>& P,
                                           const std::vector<double>& residual,
                                           const std::vector<char>& jacobi, double omega_gauss_seidel,
                                           double omega_jacobi, const std::vector<char>& held_nodes) {
  const long m = static_cast<long>(n_) - 2;
  const long b = q_ + 1;
  assemble_jacobian(c);
  // Column j of J·D: J's column j, less a quarter of its neighbours' where j is distributive.
  const auto column_entry = [&](long i, long j) {
    const double direct = jacobian(i, j);
    return jacobi[j] ? direct - 0.25 * (jacobian(i, j - 1) + jacobian(i, j + 1)) : direct;
  };
  // A cavitated node stays at zero when its own change would make it negative.
  std::vector<char> held(n_, 0);
  for (long i = 1; i <= m; ++i)
    held[i] = (P[i] <= 0.0 && residual[i] / column_entry(i, i) <= 0.0) || (!held_nodes.empty() && held_nodes[i]);

  gsl_matrix_set_zero(band_matrix_);
  for (long col = 0; col < m; ++col) {
    const long j = col + 1;
    for (long row = std::max(0L, col - b); row <= std::min(m - 1, col + b); ++row) {
      const long i = row + 1;
      const double a = held[i] ? (i == j ? 1.0 : 0.0) : (held[j] ? 0.0 : column_entry(i, j));
      gsl_matrix_set(band_matrix_, col, 2 * b + row - col, a);  // A(row, col), GSL band layout
    }
    gsl_vector_set(x_, col, held[j] ? 0.0 : residual[j] * (jacobi[j] ? omega_jacobi : omega_gauss_seidel));
  }
  model::gsl_use_status_codes();
  model::gsl_check(gsl_linalg_LU_band_decomp(m, b, b, band_matrix_, pivots_), "band LU of the EHL line step");
  model::gsl_check(gsl_linalg_LU_band_svx(b, b, band_matrix_, pivots_, x_), "band solve of the EHL line step");

  std::vector<double> dP(n_, 0.0);
  for (long j = 1; j <= m; ++j) {
    const double d = gsl_vector_get(x_, j - 1);
    dP[j] += d;
    if (jacobi[j]) {
      dP[j - 1] -= 0.25 * d;
      dP[j + 1] -= 0.25 * d;
    }
  }
  dP.front() = dP.back() = 0.0;
  return dP;
}

}  // namespace gearbench::ehl
