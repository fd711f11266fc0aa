// The convergence kit (support/convergence.h) on series whose order and limit are known.
#include <gtest/gtest.h>

#include <cmath>

#include "support/convergence.h"

namespace gearbench::verification {
namespace {

/// f_h = 3 + 0.5·h^p on h = 1, 1/r, 1/r².
std::vector<double> power_series(double p, double r) {
  return {3.0 + 0.5, 3.0 + 0.5 * std::pow(r, -p), 3.0 + 0.5 * std::pow(r, -2.0 * p)};
}

TEST(Convergence, ObservedOrderOfAPowerSeries) {
  EXPECT_NEAR(observed_order(power_series(2.0, 2.0)), 2.0, 1e-12);
  EXPECT_NEAR(observed_order(power_series(1.0, 2.0)), 1.0, 1e-12);
  EXPECT_NEAR(observed_order(power_series(4.0, 3.0), 3.0), 4.0, 1e-10);
}

TEST(Convergence, AlternatingChangesHaveNoOrder) {
  EXPECT_TRUE(std::isnan(observed_order(1.0, 2.0, 1.5)));
  EXPECT_TRUE(std::isnan(observed_order(1.0, 2.0, 2.0)));  // the finer change is zero
}

TEST(Convergence, RichardsonRemovesTheLeadingTerm) {
  const auto f = power_series(2.0, 2.0);
  EXPECT_NEAR(richardson(f[1], f[2], 2.0), 3.0, 1e-14);
  EXPECT_NEAR(richardson(f[1], f[2], observed_order(f)), 3.0, 1e-12);
}

// On f_h = 3 + 0.5·h², the finest grid's discretisation error is 0.5/16 = 0.03125 and its
// Richardson estimate exact: an answer 0.003125 off its discrete solution is a tenth of it.
TEST(Convergence, AlgebraicErrorShareOfTheRichardsonEstimate) {
  const auto f = power_series(2.0, 2.0);
  EXPECT_NEAR(algebraic_error_share(f[2] + 0.003125, f[2], f[1], 2.0), 0.1, 1e-12);
  EXPECT_NEAR(algebraic_error_share(f[2] - 0.03125, f[2], f[1], 2.0), 1.0, 1e-12);
}

TEST(Convergence, OrderFromErrors) {
  EXPECT_NEAR(order_from_errors(1.6e-5, 1e-6), 4.0, 1e-12);
  EXPECT_NEAR(order_from_errors(9.0, 1.0, 3.0), 2.0, 1e-12);
}

TEST(Convergence, TableShowsChangesAndTheOrderOfTheThreeFinestRows) {
  ConvergenceTable t("nodes", {"H"});
  const auto f = power_series(2.0, 2.0);
  for (std::size_t i = 0; i < f.size(); ++i) t.add_row(static_cast<double>(1 << (i + 4)) + 1.0, {f[i]});
  const std::string md = t.markdown();
  EXPECT_NE(md.find("| nodes | H | change |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 17 | 3.5 | — |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 33 | 3.125 | -0.375 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| observed order | 2 |"), std::string::npos) << md;
  EXPECT_THROW(t.add_row(65.0, {1.0, 2.0}), std::invalid_argument);
}

}  // namespace
}  // namespace gearbench::verification
