#pragma once
// The Newton matrix of the pressure spike's window (FasMultigrid::Impl::relax_spike), applied
// without being formed, and the banded preconditioner its GMRES solve uses.
//
// Row i of the window's Jacobian is J_ij = Σ_k (∂L_i/∂H_k)·(−(D/π)K_|k−j|) + B_ij: the film
// terms of rows i (k = i−2 … i+1: the wedge, the squeeze, ε's film response) see every pressure
// of the window through the elastic kernel K, and the rest (Poiseuille, ε's and ρ̄'s pressure
// response) is a band |i − j| ≤ 2. Formed and factorized densely, the window cost (2w + 1)³/150
// sweeps a step: on 16385 nodes at (10, 0) the ±0.05b window (237 nodes) was 40 of a solve's
// 68 WU (nineteenth session). Applied, it costs one kernel sum over the window, m(m + 3)
// multiply–adds; GMRES (Saad & Schultz 1986; Eigen's unsupported IterativeSolvers) with the
// band |i − j| ≤ 8 of J as preconditioner takes ~2 products a solve to a relative residual of
// 1e-3 (~4 with the band ±3). The matrix-free product follows Eigen's "matrix-free solvers" page.
#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "deformation.h"

namespace gearbench::ehl {
class SpikeJacobian;
}

namespace Eigen::internal {
// The traits Eigen's iterative solvers need of a matrix-free operator (Eigen's documentation).
template <>
struct traits<gearbench::ehl::SpikeJacobian> : public traits<SparseMatrix<double>> {};
}  // namespace Eigen::internal

namespace gearbench::ehl {

class SpikeJacobian : public Eigen::EigenBase<SpikeJacobian> {
 public:
  using Scalar = double;
  using RealScalar = double;
  using StorageIndex = int;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic, IsRowMajor = false };

  /// The window's m nodes first … first + m − 1 of a grid with kernel `deformation` and
  /// ∂H_k/∂P_j = −film_factor·K_|k−j|; every row the identity until it is set.
  SpikeJacobian(const Deformation& deformation, double film_factor, std::size_t first, std::size_t m);

  /// Row of node i: ∂L_i/∂H_k for k = i−2 … i+1 and the band part ∂L_i/∂P_j for j = i−2 … i+2.
  void set_row(std::size_t i, const std::array<double, 4>& dL_dH, const std::array<double, 5>& band);

  [[nodiscard]] Eigen::Index rows() const { return static_cast<Eigen::Index>(m_); }
  [[nodiscard]] Eigen::Index cols() const { return static_cast<Eigen::Index>(m_); }
  /// J_rq for window rows and columns r, q.
  [[nodiscard]] double entry(std::size_t r, std::size_t q) const;
  /// J·x: the kernel sum u_k = Σ_q K_|k−q|·x_q over the film nodes the rows read, then each row.
  [[nodiscard]] Eigen::VectorXd apply(const Eigen::VectorXd& x) const;
  /// Multiply–adds of one product.
  [[nodiscard]] double product_cost() const { return static_cast<double>(m_) * static_cast<double>(m_ + 3); }

  template <typename Rhs>
  Eigen::Product<SpikeJacobian, Rhs, Eigen::AliasFreeProduct> operator*(const Eigen::MatrixBase<Rhs>& x) const {
    return Eigen::Product<SpikeJacobian, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
  }

 private:
  const Deformation& deformation_;
  double film_factor_;
  std::size_t first_, m_;
  std::vector<std::array<double, 4>> dL_dH_;  // per row: k = i−2 … i+1
  std::vector<std::array<double, 5>> band_;   // per row: j = i−2 … i+2
};

/// The band |i − j| ≤ band_width of a SpikeJacobian, factorized by LAPACK's banded LU (dgbtrf,
/// partial pivoting), in the interface Eigen's iterative solvers expect of a preconditioner.
class SpikeBandPreconditioner {
 public:
  static constexpr int band_width = 8;
  SpikeBandPreconditioner() = default;
  SpikeBandPreconditioner& analyzePattern(const SpikeJacobian&) { return *this; }
  SpikeBandPreconditioner& factorize(const SpikeJacobian& J);
  SpikeBandPreconditioner& compute(const SpikeJacobian& J) { return factorize(J); }
  template <typename Rhs>
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::MatrixBase<Rhs>& b) const {
    return solve_band(Eigen::VectorXd(b));
  }
  [[nodiscard]] Eigen::ComputationInfo info() const { return info_; }

 private:
  [[nodiscard]] Eigen::VectorXd solve_band(Eigen::VectorXd b) const;
  int n_ = 0;
  std::vector<double> factors_;
  std::vector<int> pivots_;
  Eigen::ComputationInfo info_ = Eigen::InvalidInput;
};

}  // namespace gearbench::ehl

namespace Eigen::internal {
template <typename Rhs>
struct generic_product_impl<gearbench::ehl::SpikeJacobian, Rhs, SparseShape, DenseShape, GemvProduct>
    : generic_product_impl_base<gearbench::ehl::SpikeJacobian, Rhs,
                                generic_product_impl<gearbench::ehl::SpikeJacobian, Rhs>> {
  using Scalar = typename Product<gearbench::ehl::SpikeJacobian, Rhs>::Scalar;
  template <typename Dest>
  static void scaleAndAddTo(Dest& dst, const gearbench::ehl::SpikeJacobian& lhs, const Rhs& rhs, const Scalar& alpha) {
    dst.noalias() += alpha * lhs.apply(rhs);
  }
};
}  // namespace Eigen::internal
