// The fast tier of the verification matrix, one ctest case per registered check: ctest
// fails exactly when `gearbench verify --tier fast` would report a failure.
#include <gtest/gtest.h>

#include "check_registry.h"

namespace gearbench::verification {

/// gtest prints a parameter by its check id rather than its address.
void PrintTo(const CheckSpec* check, std::ostream* os) { *os << check->id; }

namespace {

class VerificationMatrix : public testing::TestWithParam<const CheckSpec*> {};

TEST_P(VerificationMatrix, WithinTolerance) {
  const CheckContext context{GEARBENCH_SOURCE_DIR "/cases"};
  const auto r = run_check(*GetParam(), context);
  ASSERT_TRUE(r.error.empty()) << r.error;
  EXPECT_FALSE(r.failed()) << r.id << ": " << r.quantity << " = " << r.value << " vs reference "
                          << r.reference_value << " (tolerance abs " << r.tolerance.abs
                          << ", rel " << r.tolerance.rel << "; " << r.justification << ")"
                          << (r.reproduction ? " [reproduction: recorded " + std::to_string(r.recorded) + "]" : "");
}

INSTANTIATE_TEST_SUITE_P(
    Fast, VerificationMatrix, testing::ValuesIn(Registry::instance().checks(Tier::fast)),
    [](const testing::TestParamInfo<const CheckSpec*>& param_info) {
      std::string name = param_info.param->id;
      for (auto& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

TEST(VerificationMatrix, HasChecksForEverySeedGeometry) {
  int seeds = 0;
  for (const auto* c : Registry::instance().checks(Tier::fast))
    seeds += c->id.rfind("seed", 0) == 0 ? 1 : 0;
  EXPECT_GE(seeds, 2);
}

}  // namespace
}  // namespace gearbench::verification
