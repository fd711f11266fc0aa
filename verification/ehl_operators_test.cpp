// Unit tests of the EHL multigrid's discrete operators: the second-order wedge stencil and the
// Jacobian it implies (whole, by row, and the spike window's and coarsest grid's matrix-free
// Newton matrix with its banded preconditioner), the deformation's FFT embedding and its shared
// FFTW plans, and held nodes of the coarsest grid's Newton steps. The solves that use them are
// in fas_multigrid_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ehl/coarsest_solve.h"
#include "ehl/deformation.h"
#include "ehl/reynolds_stencil.h"
#include "ehl/kernel_jacobian.h"

namespace gearbench::ehl {
namespace {

TEST(ReynoldsStencil, SecondOrderUpwindWedgeFirstOrderAtTheFirstNode) {
  EXPECT_EQ(wedge_weights(1), (std::array<double, 3>{1.0, -1.0, 0.0}));
  EXPECT_EQ(wedge_weights(2), (std::array<double, 3>{1.5, -2.0, 0.5}));
  // The weights differentiate a quadratic exactly: (1.5·4 − 2·1 + 0.5·0)/1 = 4 = d(x²)/dx at x = 2.
  const auto w = wedge_weights(5);
  EXPECT_DOUBLE_EQ(w[0] * 25.0 + w[1] * 16.0 + w[2] * 9.0, 10.0);
}

// The circulant is padded to the first 7-smooth size ≥ 2n − 2 (deformation.cpp): at exactly
// 2n − 2 (n = 2^k + 1) the lags ±(n − 1) share one index, so the end nodes' loads, which reach
// the far end, are what would show a wrong embedding. Fails if the padding were below 2n − 2 or
// the embedding put K_{n−1} anywhere else.
TEST(Deformation, SmoothPaddingKeepsTheLinearConvolutionAtBothEnds) {
  for (const std::size_t n : {2, 3, 17, 100, 129, 641, 1025}) {
    const Deformation d(n, 1.0 / static_cast<double>(n));
    std::vector<double> P(n, 0.0), fft, direct;
    P.front() = 1.0;
    P.back() = -2.0;
    if (n > 2) P[n / 2] = 0.5;
    d.apply(P, fft);
    d.apply_direct(P, direct);
    double scale = 0.0;
    for (const double w : direct) scale = std::max(scale, std::abs(w));
    for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(fft[i], direct[i], 1e-12 * scale) << "n " << n << ", node " << i;
  }
}

// Deformations of one size share the process's FFTW plans (deformation.cpp, plans_for) and
// run them on their own buffers: interleaved, each must still give its own direct sum. Fails
// if a plan ran on the arrays it was made with, or if one object's kernel leaked into another.
TEST(Deformation, SharedPlansKeepEachOperatorsOwnKernelAndBuffers) {
  const std::size_t n = 257;
  const Deformation fine(n, 0.01), coarse(n, 0.04), other_size(129, 0.02);
  std::vector<double> P(n), Q(n), R(129);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = -1.0 + 2.0 * static_cast<double>(i) / static_cast<double>(n - 1);
    P[i] = std::max(0.0, 1.0 - x * x);
    Q[i] = std::exp(-8.0 * x * x);
  }
  for (std::size_t i = 0; i < R.size(); ++i) R[i] = static_cast<double>(i % 7);
  std::vector<double> a, b, c, direct;
  for (int round = 0; round < 2; ++round) {
    fine.apply(P, a);
    coarse.apply(Q, b);
    other_size.apply(R, c);
    const auto expect_direct = [&](const Deformation& d, const std::vector<double>& in, const std::vector<double>& out) {
      d.apply_direct(in, direct);
      double scale = 0.0;
      for (double w : direct) scale = std::max(scale, std::abs(w));
      for (std::size_t i = 0; i < direct.size(); ++i) EXPECT_NEAR(out[i], direct[i], 1e-12 * scale) << "node " << i;
    };
    expect_direct(fine, P, a);
    expect_direct(coarse, Q, b);
    expect_direct(other_size, R, c);
  }
}

/// A 9-node grid with smooth coefficients.
struct Grid {
  static constexpr std::size_t n = 9;
  double h = 0.25;
  std::vector<double> eps_face = std::vector<double>(n - 1, 0.3), rho = std::vector<double>(n, 1.0);
  Deformation deformation{n, h};
  ReynoldsCoefficients coefficients() const { return {eps_face, rho, deformation, h, 0.2, 1.0, 0.0}; }
};

TEST(ReynoldsStencil, UniformFilmShiftDoesNotMoveAnIncompressibleWedge) {
  const Grid g;
  for (std::size_t i = 1; i + 1 < Grid::n; ++i) EXPECT_DOUBLE_EQ(g.coefficients().h0_derivative(i), 0.0) << i;
}

TEST(ReynoldsStencil, JacobianHoldsThePoiseuilleStencilAndTheFilmResponse) {
  const Grid g;
  const auto c = g.coefficients();
  const double h2 = g.h * g.h;
  // Off the Poiseuille stencil only the film's response is left: υ(D/π)Σ_m w_m ρ K_|i−m−j|/h.
  const std::size_t i = 5, j = 1;
  const auto w = wedge_weights(i);
  double film = 0.0;
  for (std::size_t m = 0; m < 3; ++m) film += w[m] * g.deformation.kernel(i - m - j);
  EXPECT_NEAR(c.jacobian(i, j), 0.2 * film / g.h, 1e-14);
  EXPECT_NEAR(c.jacobian(i, i + 1) - 0.3 / h2, 0.2 * (w[0] * g.deformation.kernel(1) + w[1] * g.deformation.kernel(2) +
                                                      w[2] * g.deformation.kernel(3)) / g.h, 1e-12);
}

// A Jacobi line assembles its rows with jacobian_row (the film's derivative taken once a row):
// each entry must be jacobian(i, j)'s, at the first interior node (first-order wedge) and
// inside, with ρ̄'s and ε's responses on. Fails if the row put an entry at the wrong column or
// took the film's derivative of another node.
TEST(ReynoldsStencil, JacobianRowIsTheRowOfJacobianEntries) {
  Grid g;
  for (std::size_t k = 0; k < g.rho.size(); ++k) g.rho[k] = 1.0 + 0.05 * static_cast<double>(k);
  auto c = g.coefficients();
  std::vector<double> rho_dP(g.rho.size()), H(g.rho.size()), P(g.rho.size()), left(g.eps_face.size()), right(g.eps_face.size());
  for (std::size_t k = 0; k < rho_dP.size(); ++k) {
    rho_dP[k] = 0.01 * static_cast<double>(k % 3);
    H[k] = 0.4 + 0.02 * static_cast<double>(k);
    P[k] = 0.5 + 0.1 * static_cast<double>(k % 4);
  }
  for (std::size_t k = 0; k < left.size(); ++k) {
    left[k] = -0.03 * static_cast<double>(k % 2);
    right[k] = -0.02 * static_cast<double>(k % 3);
  }
  c.rho_dP = &rho_dP;
  c.H = &H;
  c.P = &P;
  c.eps_face_dP_left = &left;
  c.eps_face_dP_right = &right;
  for (const std::size_t i : {std::size_t{1}, std::size_t{5}}) {
    const std::size_t first = i > 4 ? i - 4 : 0, last = std::min(i + 3, Grid::n - 1);
    std::vector<double> row(last - first + 1);
    c.jacobian_row(i, first, last, row.data());
    for (std::size_t j = first; j <= last; ++j) EXPECT_EQ(row[j - first], c.jacobian(i, j)) << "row " << i << ", column " << j;
  }
}

// The Newton matrix of the spike's window and, bordered by H0 and the force balance, of the
// coarsest grid, applied without being formed (kernel_jacobian.h): its entries are the Reynolds
// Jacobian's (the film part through the kernel plus the local band), its product is that
// matrix's, and its band's LU (with block elimination for the border) solves a system within
// the band exactly. Fails if a row's film terms sit at the wrong film nodes (entries against
// jacobian), if the product misplaces the kernel sums or drops the border, or if the
// preconditioner's band storage is off by a row.
TEST(KernelJacobian, EntriesProductAndBandSolveAreTheReynoldsJacobians) {
  constexpr std::size_t n = 48;
  const double h = 0.05;
  std::vector<double> eps_face(n - 1), rho(n), rho_dP(n), H(n);
  for (std::size_t i = 0; i < n; ++i) {
    rho[i] = 1.0 + 0.01 * static_cast<double>(i % 5);
    rho_dP[i] = 0.002 * static_cast<double>(i % 3);
    H[i] = 0.3 + 0.01 * static_cast<double>(i);
  }
  for (std::size_t i = 0; i + 1 < n; ++i) eps_face[i] = 0.05 * std::exp(-0.1 * static_cast<double>(i));
  const Deformation deformation(n, h);
  ReynoldsCoefficients c{eps_face, rho, deformation, h, 0.2, 1.0, 0.0};
  c.rho_dP = &rho_dP;
  c.H = &H;
  const auto window = [&](std::size_t first, std::size_t m) {
    KernelJacobian J(deformation, c.film_factor, first, m);
    for (std::size_t i = first; i < first + m; ++i) {
      const auto d = c.film_derivative(i);
      std::array<double, 5> band{};
      for (std::size_t t = 0; t < 5; ++t) band[t] = c.local_jacobian(i, i + t - 2);
      J.set_row(i, {d[2], d[1], d[0], 0.0}, band);
    }
    return J;
  };
  const std::size_t first = 6, m = 30;
  const auto J = window(first, m);
  Eigen::MatrixXd dense(m, m);
  Eigen::VectorXd x(m);
  for (std::size_t r = 0; r < m; ++r) {
    x(static_cast<Eigen::Index>(r)) = std::sin(1.7 * static_cast<double>(r)) + 0.3;
    for (std::size_t q = 0; q < m; ++q) {
      dense(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(q)) = J.entry(r, q);
      EXPECT_NEAR(J.entry(r, q), c.jacobian(first + r, first + q), 1e-12 * std::abs(c.jacobian(first + r, first + r)))
          << r << ", " << q;
    }
  }
  const Eigen::VectorXd product = J * x, expected = dense * x;
  EXPECT_LT((product - expected).norm(), 1e-12 * expected.norm());
  // A window of band_width + 1 nodes lies within the band: its LU is the matrix's.
  const auto small = window(first, BandPreconditioner::band_width + 1);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(small.rows(), 1.0, 2.0);
  const Eigen::VectorXd solved = BandPreconditioner().compute(small).solve(b);
  EXPECT_LT((small * solved - b).norm(), 1e-10 * b.norm());
  // Bordered by H0 and the force balance (the coarsest grid's system): the product carries the
  // border, and the block elimination solves a bordered system within the band exactly.
  const auto bordered = [&](std::size_t nodes) {
    KernelJacobian B(deformation, c.film_factor, first, nodes, true);
    for (std::size_t i = first; i < first + nodes; ++i) {
      const auto d = c.film_derivative(i);
      std::array<double, 5> band{};
      for (std::size_t t = 0; t < 5; ++t) band[t] = c.local_jacobian(i, i + t - 2);
      B.set_row(i, {d[2], d[1], d[0], 0.0}, band);
      B.set_border(i, c.h0_derivative(i) + 0.1 * static_cast<double>(i - first), h);
    }
    return B;
  };
  const auto B = bordered(m);
  Eigen::VectorXd y(m + 1);
  y.head(m) = x;
  y(static_cast<Eigen::Index>(m)) = 0.7;
  Eigen::MatrixXd dense_bordered(m + 1, m + 1);
  for (std::size_t r = 0; r <= m; ++r)
    for (std::size_t q = 0; q <= m; ++q)
      dense_bordered(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(q)) = B.entry(r, q);
  EXPECT_DOUBLE_EQ(B.entry(m, m), 0.0);
  EXPECT_DOUBLE_EQ(B.entry(m, 3), h);
  const Eigen::VectorXd bordered_product = B * y, bordered_expected = dense_bordered * y;
  EXPECT_LT((bordered_product - bordered_expected).norm(), 1e-12 * bordered_expected.norm());
  const auto small_bordered = bordered(BandPreconditioner::band_width + 1);
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(small_bordered.rows(), -1.0, 3.0);
  const Eigen::VectorXd bordered_solved = BandPreconditioner().compute(small_bordered).solve(rhs);
  EXPECT_LT((small_bordered * bordered_solved - rhs).norm(), 1e-10 * rhs.norm());
}

// Twentieth session: a held node's Newton row is the identity with a zero right-hand side, but
// the dense LU's pivoting and GMRES's tolerance gave it a change of 1e-28 … 1e-20, which the
// clipped update kept as a tiny pressure; the next step's rule (P = 0) then no longer held it,
// and the kept Jacobian was refactorized at every step (at (5, 25) on 1025 nodes 2231 WU
// against 862 with the held changes exactly zero, in the same 28 cycles).
TEST(CoarsestNewton, HeldNodesStayExactlyAtZeroInDenseAndKrylovSteps) {
  for (const std::size_t n : {std::size_t{65}, CoarsestNewton::krylov_from_nodes + 40}) {
    const double h = 4.0 / static_cast<double>(n - 1);
    std::vector<double> eps_face(n - 1), rho(n), rho_dP(n), H(n), P(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const double x = -2.0 + h * static_cast<double>(i);
      rho[i] = 1.0 + 0.01 * static_cast<double>(i % 5);
      rho_dP[i] = 0.002 * static_cast<double>(i % 3);
      H[i] = 0.3 + 0.5 * x * x;
      P[i] = std::max(0.0, 1.0 - x * x);  // cavitated beyond |x| = 1
    }
    for (std::size_t i = 0; i + 1 < n; ++i) eps_face[i] = 0.05 * std::exp(-0.01 * static_cast<double>(i));
    const Deformation deformation(n, h);
    ReynoldsCoefficients c{eps_face, rho, deformation, h, 0.2, 1.0, 0.0};
    c.rho_dP = &rho_dP;
    c.H = &H;
    const FilmSensitivity film{std::vector<double>(n - 1, 0.01), std::vector<double>(n - 1, 0.02)};
    std::vector<char> held(n, 0);
    std::vector<double> residual(n, 0.0);
    for (std::size_t i = 1; i + 1 < n; ++i) {
      held[i] = P[i] <= 0.0;
      residual[i] = std::sin(0.37 * static_cast<double>(i));
    }
    CoarsestNewton newton;
    ASSERT_EQ(newton.factorize(c, P, held, film), StepInfo::success) << n;
    EXPECT_EQ(newton.dense(), n < CoarsestNewton::krylov_from_nodes) << n;
    const CoarsestStep step = newton.step(residual, 0.05);
    ASSERT_EQ(step.info, StepInfo::success) << n;
    std::size_t moved = 0, held_count = 0;
    for (std::size_t i = 1; i + 1 < n; ++i) {
      if (!held[i]) continue;
      ++held_count;
      if (step.dP[i] != 0.0) ++moved;
    }
    EXPECT_GT(held_count, n / 4) << n;
    EXPECT_EQ(moved, 0u) << n << " nodes: held changes not exactly zero";
  }
}

}  // namespace
}  // namespace gearbench::ehl
