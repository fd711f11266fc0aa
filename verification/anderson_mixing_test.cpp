// Anderson acceleration (solvers/ehl/anderson_mixing.h), unit tier: on a linear map with an
// eigenvalue of −13, the thermal coupling's measured one, the relaxed iteration diverges and
// Anderson converges; a map at its fixed point gives no step (the safeguard against a
// singular least-squares problem); a residual that jumps clears the history.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ehl/anderson_mixing.h"

namespace gearbench::ehl {
namespace {

/// G(x) = A·x + b with A diagonal: eigenvalues −13, 0.9, 0.5, −0.5; fixed point x* = b/(1 − a).
const std::vector<double> eigenvalues{-13.0, 0.9, 0.5, -0.5}, offsets{1.0, -2.0, 0.5, 3.0};

std::vector<double> map(const std::vector<double>& x) {
  std::vector<double> g(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) g[i] = eigenvalues[i] * x[i] + offsets[i];
  return g;
}

double error(const std::vector<double>& x) {
  double e = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) e = std::max(e, std::abs(x[i] - offsets[i] / (1.0 - eigenvalues[i])));
  return e;
}

TEST(AndersonMixing, ConvergesWhereRelaxationDiverges) {
  const double beta = 0.3;  // 1 − β·(1 + 13) = −3.2: the relaxed iteration diverges
  std::vector<double> relaxed(4, 0.0), accelerated(4, 0.0);
  AndersonMixing anderson({.depth = 5, .mixing = beta});
  for (int k = 0; k < 12; ++k) {
    const auto g = map(relaxed);
    for (std::size_t i = 0; i < 4; ++i) relaxed[i] += beta * (g[i] - relaxed[i]);
    accelerated = anderson.next(accelerated, map(accelerated));
  }
  EXPECT_GT(error(relaxed), 1e3);
  EXPECT_LT(error(accelerated), 1e-9);  // a linear map in 4 dimensions: exact after ~5 steps
  EXPECT_EQ(anderson.restarts(), 0);
}

TEST(AndersonMixing, NoStepAtTheFixedPoint) {
  AndersonMixing anderson({.depth = 3, .mixing = 1.0});
  const std::vector<double> x{1.0, 2.0};
  for (int k = 0; k < 4; ++k) {
    const auto next = anderson.next(x, x);  // ΔF = 0: every column dropped, no NaN
    EXPECT_EQ(next, x);
    EXPECT_EQ(anderson.columns_used(), 0);
  }
}

TEST(AndersonMixing, ResidualJumpClearsTheHistory) {
  AndersonMixing anderson({.depth = 5, .mixing = 0.5, .restart_growth = 10.0});
  std::vector<double> x{0.0};
  x = anderson.next(x, {1.0});
  x = anderson.next(x, {0.9});
  EXPECT_EQ(anderson.columns_used(), 1);
  const auto next = anderson.next(x, {x[0] + 100.0});  // ‖f‖ 100 > 10 × the smallest
  EXPECT_EQ(anderson.restarts(), 1);
  EXPECT_EQ(anderson.columns_used(), 0);
  EXPECT_DOUBLE_EQ(next[0], x[0] + 0.5 * 100.0);
}

}  // namespace
}  // namespace gearbench::ehl
