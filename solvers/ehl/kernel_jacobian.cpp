#include "kernel_jacobian.h"

#include <algorithm>
#include <cmath>

// LAPACK's banded LU with partial pivoting and its solve (the Fortran symbols; Debian's liblapack).
extern "C" void dgbtrf_(const int* m, const int* n, const int* kl, const int* ku, double* ab, const int* ldab,
                        int* ipiv, int* info);
extern "C" void dgbtrs_(const char* trans, const int* n, const int* kl, const int* ku, const int* nrhs,
                        const double* ab, const int* ldab, const int* ipiv, double* b, const int* ldb, int* info,
                        std::size_t trans_length);

namespace gearbench::ehl {

KernelJacobian::KernelJacobian(const Deformation& deformation, double film_factor, std::size_t first, std::size_t m,
                               bool bordered)
    : deformation_(deformation), film_factor_(film_factor), first_(first), m_(m), bordered_(bordered), dL_dH_(m),
      band_(m) {
  for (auto& b : band_) b[2] = 1.0;  // the identity: a row no set_row reaches (a cavitated node)
  if (bordered_) {
    column_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m));
    row_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m));
  }
}

void KernelJacobian::set_border(std::size_t i, double dL_dH0, double dforce_dP) {
  column_(static_cast<Eigen::Index>(i - first_)) = dL_dH0;
  row_(static_cast<Eigen::Index>(i - first_)) = dforce_dP;
}

void KernelJacobian::set_row(std::size_t i, const std::array<double, 4>& dL_dH, const std::array<double, 5>& band) {
  dL_dH_[i - first_] = dL_dH;
  band_[i - first_] = band;
}

double KernelJacobian::entry(std::size_t r, std::size_t q) const {
  if (r == m_) return q == m_ ? 0.0 : row_(static_cast<Eigen::Index>(q));
  if (q == m_) return column_(static_cast<Eigen::Index>(r));
  const std::size_t i = first_ + r, j = first_ + q;
  double value = 0.0;
  for (std::size_t t = 0; t < 4; ++t) {
    if (dL_dH_[r][t] == 0.0 || i + t < 2) continue;
    const std::size_t k = i + t - 2;
    value -= film_factor_ * dL_dH_[r][t] * deformation_.kernel(k > j ? k - j : j - k);
  }
  if (i + 2 >= j && j + 2 >= i) value += band_[r][j + 2 - i];
  return value;
}

Eigen::VectorXd KernelJacobian::apply(const Eigen::VectorXd& x) const {
  // u[t] = Σ_q K_|k−j_q|·x_q for the film nodes k = first − 2 + t, t = 0 … m + 2.
  std::vector<double> u(m_ + 3, 0.0);
  for (std::size_t t = 0; t < m_ + 3; ++t) {
    if (first_ + t < 2) continue;
    const std::size_t k = first_ + t - 2;
    double sum = 0.0;
    for (std::size_t q = 0; q < m_; ++q) {
      const std::size_t j = first_ + q;
      sum += deformation_.kernel(k > j ? k - j : j - k) * x(static_cast<Eigen::Index>(q));
    }
    u[t] = sum;
  }
  Eigen::VectorXd y(rows());
  const double dH0 = bordered_ ? x(static_cast<Eigen::Index>(m_)) : 0.0;
  for (std::size_t r = 0; r < m_; ++r) {
    double value = 0.0;
    for (std::size_t t = 0; t < 4; ++t) value -= film_factor_ * dL_dH_[r][t] * u[r + t];  // k = i − 2 + t
    for (std::size_t t = 0; t < 5; ++t)
      if (r + t >= 2 && r + t - 2 < m_) value += band_[r][t] * x(static_cast<Eigen::Index>(r + t - 2));
    if (bordered_) value += column_(static_cast<Eigen::Index>(r)) * dH0;
    y(static_cast<Eigen::Index>(r)) = value;
  }
  if (bordered_) y(static_cast<Eigen::Index>(m_)) = row_.dot(x.head(static_cast<Eigen::Index>(m_)));
  return y;
}

BandPreconditioner& BandPreconditioner::factorize(const KernelJacobian& J) {
  n_ = static_cast<int>(J.nodes());
  const int kl = band_width, ku = band_width, ldab = 2 * kl + ku + 1;
  // LAPACK band storage: ab(kl + ku + r − c, c) = A(r, c), kl extra rows for the fill-in.
  factors_.assign(static_cast<std::size_t>(ldab) * static_cast<std::size_t>(n_), 0.0);
  const auto n = static_cast<std::size_t>(n_);
  const auto w = static_cast<std::size_t>(band_width);
  for (std::size_t c = 0; c < n; ++c)
    for (std::size_t r = c > w ? c - w : 0; r <= std::min(n - 1, c + w); ++r)
      factors_[static_cast<std::size_t>(kl + ku) + r - c + c * static_cast<std::size_t>(ldab)] = J.entry(r, c);
  pivots_.resize(n);
  int info = 0;
  dgbtrf_(&n_, &n_, &kl, &ku, factors_.data(), &ldab, pivots_.data(), &info);
  info_ = info == 0 ? Eigen::Success : Eigen::NumericalIssue;
  w_.resize(0);
  if (info_ == Eigen::Success && J.bordered()) {
    row_ = J.border_row();
    w_ = band_solve(J.border_column());
    schur_ = row_.dot(w_);
    if (!(std::abs(schur_) > 0.0) || !std::isfinite(schur_)) info_ = Eigen::NumericalIssue;
  }
  return *this;
}

namespace {
/// Entries in a row of the band of J (the preconditioner's width, or the whole matrix).
double band_row_width(const KernelJacobian& J) {
  return std::min(static_cast<double>(J.rows()), 2.0 * BandPreconditioner::band_width + 1.0);
}
}  // namespace

double BandPreconditioner::factorize_cost(const KernelJacobian& J) {
  const auto m = static_cast<double>(J.rows());
  const double width = band_row_width(J);
  return KernelJacobian::entry_cost * m * width + std::min(m * m * m / 3.0, m * width * width / 2.0);
}

double BandPreconditioner::solve_cost(const KernelJacobian& J) {
  return 2.0 * static_cast<double>(J.rows()) * band_row_width(J);
}

Eigen::VectorXd BandPreconditioner::band_solve(Eigen::VectorXd b) const {
  const int kl = band_width, ku = band_width, ldab = 2 * kl + ku + 1, nrhs = 1;
  int info = 0;
  dgbtrs_("N", &n_, &kl, &ku, &nrhs, factors_.data(), &ldab, pivots_.data(), b.data(), &n_, &info, 1);
  return b;
}

Eigen::VectorXd BandPreconditioner::apply_inverse(Eigen::VectorXd b) const {
  if (info_ != Eigen::Success) return b;
  if (w_.size() == 0) return band_solve(std::move(b));
  const auto n = static_cast<Eigen::Index>(n_);
  const Eigen::VectorXd z = band_solve(b.head(n));
  const double dH0 = (row_.dot(z) - b(n)) / schur_;
  Eigen::VectorXd x(n + 1);
  x.head(n) = z - w_ * dH0;
  x(n) = dH0;
  return x;
}

}  // namespace gearbench::ehl
