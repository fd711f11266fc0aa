// Unit tests of the line relaxation's held nodes (cavitated, or the coarse nodes of an
// unresolved pressure spike) and of the multigrid option that holds them.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ehl/deformation.h"
#include "ehl/fas_multigrid.h"
#include "ehl/line_contact_solver.h"
#include "ehl/line_relaxation.h"

namespace gearbench::ehl {
namespace {

/// A Gauss–Seidel (Poiseuille-dominated) line of 33 nodes with a smooth residual.
struct Line {
  static constexpr std::size_t n = 33;
  double h = 0.1;
  std::vector<double> eps = std::vector<double>(n, 1.0), rho = std::vector<double>(n, 1.0);
  Deformation deformation{n, h};
  std::vector<double> P = std::vector<double>(n, 1.0), residual = std::vector<double>(n, 0.0);
  std::vector<char> jacobi = std::vector<char>(n, 0);
  Line() {
    P.front() = P.back() = 0.0;
    for (std::size_t i = 1; i + 1 < n; ++i) residual[i] = std::sin(0.3 * static_cast<double>(i));
  }
  std::vector<double> change(const std::vector<char>& held) {
    LineRelaxation line(n, 2);
    const ReynoldsCoefficients c{eps, rho, deformation, h, 0.1, 1.0, 0.0};
    return line.change(c, P, residual, jacobi, 0.3, 0.2, held);
  }
};

TEST(LineRelaxation, HeldNodesDoNotChange) {
  Line line;
  std::vector<char> held(Line::n, 0);
  held[10] = held[11] = held[20] = 1;
  const auto free = line.change({});
  const auto dP = line.change(held);
  for (std::size_t i : {10u, 11u, 20u}) {
    EXPECT_NE(free[i], 0.0) << i;
    EXPECT_EQ(dP[i], 0.0) << i;
  }
  EXPECT_NE(dP[15], 0.0);
  EXPECT_EQ(dP.front(), 0.0);
  EXPECT_EQ(dP.back(), 0.0);
}

TEST(LineRelaxation, NoHeldNodesIsTheDefault) {
  Line line;
  EXPECT_EQ(line.change({}), line.change(std::vector<char>(Line::n, 0)));
}

// The held coarse nodes change the path, not the answer: where both schemes converge they
// reach the same discrete solution to the tolerance (M = 20, L = 10 on 641 nodes).
TEST(FasMultigrid, HoldingUnresolvedNodesKeepsTheSolution) {
  const LineContactProblem p(LineContactData::from_moes(20.0, 10.0));
  EhlOptions o;
  const auto plain = FasMultigrid(p, o, ContactState{}).solve();
  o.hold_unresolved = true;
  const auto held = FasMultigrid(p, o, ContactState{}).solve();
  ASSERT_TRUE(plain.converged);
  ASSERT_TRUE(held.converged);
  double h_min = plain.H[0];
  for (double h : plain.H) h_min = std::min(h_min, h);
  for (std::size_t i = 0; i < plain.H.size(); ++i) EXPECT_NEAR(held.H[i], plain.H[i], 1e-5 * h_min) << i;
}

}  // namespace
}  // namespace gearbench::ehl
