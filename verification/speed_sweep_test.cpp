// The dynamics speed sweep (solvers/dynamics/speed_sweep.h) on a stand-in model whose figures
// are known functions of the speed: the speeds it visits, what it records, a refused point
// skipped with its reason, the progress it reports and the spec's validation.
#include <gtest/gtest.h>

#include <numbers>

#include "dynamics/speed_sweep.h"
#include "model/errors.h"

namespace gearbench::dynamics {
namespace {

constexpr double rad_per_s_per_rpm = std::numbers::pi / 30.0;

SpeedPoint stand_in(const model::OperatingPoint& op) {
  const double rpm = op.pinion_speed / rad_per_s_per_rpm;
  if (rpm > 2500.0) throw InputError("impact pulse carries the load");
  return {rpm / 60.0 * 20.0, 1.0 + rpm * 1e-4, rpm * 1e-9};
}

TEST(SpeedSweep, VisitsEquallySpacedSpeedsAndRecordsEachPoint) {
  model::OperatingPoint base;
  base.pinion_torque = 50.0;
  std::vector<std::string> lines;
  const auto r = speed_sweep({1000.0, 2000.0, 3}, base, stand_in, [&](const std::string& l) { lines.push_back(l); });
  ASSERT_EQ(r.speed_rpm.size(), 3u);
  EXPECT_DOUBLE_EQ(r.speed_rpm[1], 1500.0);
  EXPECT_DOUBLE_EQ(r.mesh_frequency[2], 2000.0 / 60.0 * 20.0);
  EXPECT_DOUBLE_EQ(r.dynamic_factor[0], 1.1);
  EXPECT_DOUBLE_EQ(r.te_rms[1], 1.5e-6);
  EXPECT_TRUE(r.skipped.empty());
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_NE(lines[1].find("2/3: 1500.0 rpm"), std::string::npos) << lines[1];
}

TEST(SpeedSweep, SkipsARefusedPointWithItsReason) {
  const auto r = speed_sweep({2000.0, 3000.0, 3}, {}, stand_in);
  EXPECT_EQ(r.speed_rpm, (std::vector<double>{2000.0, 2500.0}));
  ASSERT_EQ(r.skipped.size(), 1u);
  EXPECT_DOUBLE_EQ(r.skipped[0].speed_rpm, 3000.0);
  EXPECT_EQ(r.skipped[0].reason, "impact pulse carries the load");
}

TEST(SpeedSweep, RefusesAnEmptyOrBackwardRange) {
  EXPECT_THROW(speed_sweep({2000.0, 1000.0, 3}, {}, stand_in), InputError);
  EXPECT_THROW(speed_sweep({1000.0, 2000.0, 1}, {}, stand_in), InputError);
  EXPECT_THROW(speed_sweep({0.0, 2000.0, 3}, {}, stand_in), InputError);
}

}  // namespace
}  // namespace gearbench::dynamics
