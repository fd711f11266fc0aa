#pragma once
// The Newton matrix of the discrete Reynolds equation on a range of nodes, applied without
// being formed, and the banded preconditioner its GMRES solve uses: the pressure spike's window
// (FasMultigrid::Impl::relax_spike) and, bordered by H0 and the force balance, the coarsest grid
// (coarsest_solve.h).
//
// Row i of the Jacobian is J_ij = Σ_k (∂L_i/∂H_k)·(−(D/π)K_|k−j|) + B_ij: the film terms of
// row i (k = i−2 … i+1: the wedge, the squeeze, ε's film response) see every pressure of the
// range through the elastic kernel K, and the rest (Poiseuille, ε's and ρ̄'s pressure response)
// is a band |i − j| ≤ 2. Formed and factorized densely, the spike window cost (2w + 1)³/150
// sweeps a step: on 16385 nodes at (10, 0) the ±0.05b window (237 nodes) was 41 of a solve's
// 79 WU (nineteenth session). Applied, it costs one kernel sum over the range, m(m + 3)
// multiply–adds; GMRES (Saad & Schultz 1986; Eigen's unsupported IterativeSolvers) with the
// band |i − j| ≤ 8 of J as preconditioner takes ~2 products a solve to a relative residual of
// 1e-3 (~4 with the band ±3). The matrix-free product follows Eigen's "matrix-free solvers" page.
// Bordered, the unknowns are (δP, δH0) and the last row is the force balance h·Σ δP_j: the
// preconditioner solves the bordered band by block elimination (one more band solve).
#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "deformation.h"

namespace gearbench::ehl {
class KernelJacobian;
}

namespace Eigen::internal {
// The traits Eigen's iterative solvers need of a matrix-free operator (Eigen's documentation).
template <>
struct traits<gearbench::ehl::KernelJacobian> : public traits<SparseMatrix<double>> {};
}  // namespace Eigen::internal

namespace gearbench::ehl {

class KernelJacobian : public Eigen::EigenBase<KernelJacobian> {
 public:
  using Scalar = double;
  using RealScalar = double;
  using StorageIndex = int;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic, IsRowMajor = false };

  /// The m nodes first … first + m − 1 of a grid with kernel `deformation` and
  /// ∂H_k/∂P_j = −film_factor·K_|k−j|; every row the identity until it is set. Bordered: one
  /// more unknown (δH0) and one more row (the force balance), both zero until they are set.
  KernelJacobian(const Deformation& deformation, double film_factor, std::size_t first, std::size_t m,
                 bool bordered = false);

  /// Row of node i: ∂L_i/∂H_k for k = i−2 … i+1 and the band part ∂L_i/∂P_j for j = i−2 … i+2.
  void set_row(std::size_t i, const std::array<double, 4>& dL_dH, const std::array<double, 5>& band);
  /// Bordered: ∂L_i/∂H0 of node i's row, and ∂(force)/∂P_j of node j's column.
  void set_border(std::size_t i, double dL_dH0, double dforce_dP);

  [[nodiscard]] Eigen::Index rows() const { return static_cast<Eigen::Index>(m_ + (bordered_ ? 1 : 0)); }
  [[nodiscard]] Eigen::Index cols() const { return rows(); }
  /// Nodes of the range (the unknowns without the border).
  [[nodiscard]] std::size_t nodes() const { return m_; }
  [[nodiscard]] bool bordered() const { return bordered_; }
  /// The border: ∂L/∂H0 (column) and the force balance's row over the nodes.
  [[nodiscard]] const Eigen::VectorXd& border_column() const { return column_; }
  [[nodiscard]] const Eigen::VectorXd& border_row() const { return row_; }
  /// J_rq for window rows and columns r, q.
  [[nodiscard]] double entry(std::size_t r, std::size_t q) const;
  /// J·x: the kernel sum u_k = Σ_q K_|k−q|·x_q over the film nodes the rows read, then each row.
  [[nodiscard]] Eigen::VectorXd apply(const Eigen::VectorXd& x) const;
  /// Multiply–adds of one entry (up to four kernel terms and the band) and of the dense matrix.
  static constexpr double entry_cost = 5.0;
  [[nodiscard]] double dense_cost() const { return entry_cost * static_cast<double>(rows() * rows()); }
  /// Multiply–adds of one product.
  [[nodiscard]] double product_cost() const {
    return static_cast<double>(m_) * static_cast<double>(m_ + 3 + (bordered_ ? 2 : 0));
  }

  template <typename Rhs>
  Eigen::Product<KernelJacobian, Rhs, Eigen::AliasFreeProduct> operator*(const Eigen::MatrixBase<Rhs>& x) const {
    return Eigen::Product<KernelJacobian, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
  }

 private:
  const Deformation& deformation_;
  double film_factor_;
  std::size_t first_, m_;
  bool bordered_;
  std::vector<std::array<double, 4>> dL_dH_;  // per row: k = i−2 … i+1
  std::vector<std::array<double, 5>> band_;   // per row: j = i−2 … i+2
  Eigen::VectorXd column_, row_;              // the border (empty unless bordered)
};

/// The band |i − j| ≤ band_width of a KernelJacobian, factorized by LAPACK's banded LU (dgbtrf,
/// partial pivoting), in the interface Eigen's iterative solvers expect of a preconditioner.
/// Bordered, [B c; dᵀ 0] is solved by block elimination: z = B⁻¹b, w = B⁻¹c,
/// δH0 = (dᵀz − b_H)/(dᵀw), δP = z − w·δH0.
class BandPreconditioner {
 public:
  static constexpr int band_width = 8;
  BandPreconditioner() = default;
  BandPreconditioner& analyzePattern(const KernelJacobian&) { return *this; }
  BandPreconditioner& factorize(const KernelJacobian& J);
  BandPreconditioner& compute(const KernelJacobian& J) { return factorize(J); }
  template <typename Rhs>
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::MatrixBase<Rhs>& b) const {
    return apply_inverse(Eigen::VectorXd(b));
  }
  [[nodiscard]] Eigen::ComputationInfo info() const { return info_; }
  /// Multiply–adds of factorize (the band's entries and LU) and of one solve (two banded
  /// triangular solves) for J.
  [[nodiscard]] static double factorize_cost(const KernelJacobian& J);
  [[nodiscard]] static double solve_cost(const KernelJacobian& J);

 private:
  [[nodiscard]] Eigen::VectorXd apply_inverse(Eigen::VectorXd b) const;
  [[nodiscard]] Eigen::VectorXd band_solve(Eigen::VectorXd b) const;  // B⁻¹b on the nodes
  int n_ = 0;  // nodes of the band
  std::vector<double> factors_;
  Eigen::VectorXd w_, row_;  // bordered: B⁻¹c and d
  double schur_ = 0.0;       // dᵀB⁻¹c
  std::vector<int> pivots_;
  Eigen::ComputationInfo info_ = Eigen::InvalidInput;
};

}  // namespace gearbench::ehl

namespace Eigen::internal {
template <typename Rhs>
struct generic_product_impl<gearbench::ehl::KernelJacobian, Rhs, SparseShape, DenseShape, GemvProduct>
    : generic_product_impl_base<gearbench::ehl::KernelJacobian, Rhs,
                                generic_product_impl<gearbench::ehl::KernelJacobian, Rhs>> {
  using Scalar = typename Product<gearbench::ehl::KernelJacobian, Rhs>::Scalar;
  template <typename Dest>
  static void scaleAndAddTo(Dest& dst, const gearbench::ehl::KernelJacobian& lhs, const Rhs& rhs, const Scalar& alpha) {
    dst.noalias() += alpha * lhs.apply(rhs);
  }
};
}  // namespace Eigen::internal
