// Unit tests of solvers/lubricant: limits and identities each law must satisfy.
#include <gtest/gtest.h>

#include <cmath>

#include "lubricant/rheology.h"

namespace gearbench::lubricant {
namespace {

TEST(Rheology, BarusAndRoelandsAgreeAtZeroPressure) {
  EXPECT_DOUBLE_EQ(barus_viscosity(0.08, 2e-8, 0.0), 0.08);
  EXPECT_DOUBLE_EQ(roelands_viscosity(0.08, 0.68, 0.0), 0.08);
}

// With z from α, the two laws share d ln η/dp = α at p = 0 (central difference, step
// 1e3 Pa: truncation ~ (d³ ln η/dp³)·h²/6 ≈ 1e-14 relative).
TEST(Rheology, RoelandsSlopeMatchesAlpha) {
  const double eta0 = 0.08, alpha = 2.2e-8, h = 1e3;
  const double z = roelands_z_from_alpha(eta0, alpha);
  const double slope =
      (std::log(roelands_viscosity(eta0, z, h)) - std::log(roelands_viscosity(eta0, z, -h))) / (2 * h);
  EXPECT_NEAR(slope, alpha, 1e-9 * alpha);
}

// Roelands grows slower than Barus at high pressure for z < 1 (its whole point).
TEST(Rheology, RoelandsBelowBarusAtHighPressure) {
  const double eta0 = 0.08, alpha = 2.2e-8;
  const double z = roelands_z_from_alpha(eta0, alpha);
  ASSERT_LT(z, 1.0);
  EXPECT_LT(roelands_viscosity(eta0, z, 1e9), barus_viscosity(eta0, alpha, 1e9));
}

TEST(Rheology, DowsonHigginsonLimits) {
  EXPECT_DOUBLE_EQ(dowson_higginson_density_ratio(0.0), 1.0);
  EXPECT_NEAR(dowson_higginson_density_ratio(5.9e8), 1.17, 1e-15);
  EXPECT_NEAR(dowson_higginson_density_ratio(1e15), 1.34, 1e-6);
}

}  // namespace
}  // namespace gearbench::lubricant
