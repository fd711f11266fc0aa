// The fast tier of the verification matrix, one ctest case per registered check and per
// report section: ctest fails exactly when `gearbench verify --tier fast` would (outcome.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "check_registry.h"
#include "outcome.h"

namespace gearbench::verification {

/// gtest prints a parameter by its id rather than its address.
void PrintTo(const CheckSpec* check, std::ostream* os) { *os << check->id; }
void PrintTo(const SectionSpec* section, std::ostream* os) { *os << section->id; }

namespace {

const CheckContext context{GEARBENCH_SOURCE_DIR "/cases"};

template <class Spec>
std::string test_name(const testing::TestParamInfo<const Spec*>& param_info) {
  std::string name = param_info.param->id;
  for (auto& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

class VerificationMatrix : public testing::TestWithParam<const CheckSpec*> {};

TEST_P(VerificationMatrix, WithinTolerance) {
  const auto r = run_check(*GetParam(), context);
  ASSERT_TRUE(r.error.empty()) << r.error;
  EXPECT_NE(r.outcome, reports::Outcome::fail)
      << r.id << ": " << r.quantity << " = " << r.value << " vs reference " << r.reference_value
      << " (tolerance abs " << r.tolerance.abs << ", rel " << r.tolerance.rel << "; " << r.justification << ")"
      << (r.reproduction ? " [reproduction: recorded " + std::to_string(r.recorded) + "]" : "");
}

INSTANTIATE_TEST_SUITE_P(Fast, VerificationMatrix, testing::ValuesIn(Registry::instance().checks(Tier::fast)),
                         test_name<CheckSpec>);

class ReportSections : public testing::TestWithParam<const SectionSpec*> {};

TEST_P(ReportSections, CanBeBuilt) {
  reports::Report report;
  build_section(*GetParam(), context, report);
  for (const auto& f : report.section_failures) ADD_FAILURE() << "section " << f.id << ": " << f.error;
}

INSTANTIATE_TEST_SUITE_P(Fast, ReportSections, testing::ValuesIn(Registry::instance().sections(Tier::fast)),
                         test_name<SectionSpec>);

/// The tags of the seed geometries: cases/seedNNN_<name>_geometry.json gives "seedNNN_<name>".
std::set<std::string> seed_geometry_tags() {
  std::set<std::string> tags;
  const std::string suffix = "_geometry.json";
  for (const auto& entry : std::filesystem::directory_iterator(context.cases_dir)) {
    const auto file = entry.path().filename().string();
    if (file.rfind("seed", 0) == 0 && file.ends_with(suffix)) tags.insert(file.substr(0, file.size() - suffix.size()));
  }
  return tags;
}

// The geometry checks of a seed pair are named geometry.<tag>.<quantity> after its case file.
TEST(VerificationMatrix, HasChecksForEverySeedGeometry) {
  const auto tags = seed_geometry_tags();
  ASSERT_GE(tags.size(), 3u) << "cases/ holds seed000, seed001 and seed004 geometries";
  std::set<std::string> checked;
  for (const auto* c : Registry::instance().checks(Tier::fast))
    for (const auto& tag : tags)
      if (c->id.rfind("geometry." + tag + ".", 0) == 0) checked.insert(tag);
  for (const auto& tag : tags) EXPECT_TRUE(checked.count(tag)) << "no geometry check for cases/" << tag << "_geometry.json";
}

}  // namespace
}  // namespace gearbench::verification
