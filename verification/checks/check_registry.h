#pragma once
// The verification matrix: every solver-against-reference check and seed reproduction
// registers itself here (one static RegisterCheck per check), so that `gearbench verify`
// and the ctest gate run exactly the same checks and a new solver adds checks without
// touching either.
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "model/case_reader.h"
#include "report.h"

namespace gearbench::verification {

enum class Tier { fast, full };

/// Where checks find their case files.
struct CheckContext {
  std::string cases_dir;
  [[nodiscard]] std::string case_path(const std::string& file) const { return cases_dir + "/" + file; }
  /// The gear-pair sections of a case file (the kind's own keys are not read).
  [[nodiscard]] model::GearCase gear_case(const std::string& file) const;
};

/// A copy of v with every element multiplied by factor (unit changes for figures).
std::vector<double> scaled(std::vector<double> v, double factor);

struct CheckValue {
  double value = 0.0;
  double reference = 0.0;
  nlohmann::json diagnostics = nlohmann::json::object();
};

struct CheckSpec {
  std::string id;
  std::string section;
  std::string solver;
  std::string reference;
  std::string quantity;
  std::string unit;
  reports::Tolerance tolerance;
  std::string justification;
  Tier tier = Tier::fast;
  std::function<CheckValue(const CheckContext&)> run;
  /// Seed reproductions only: the figure reached when the gap to the paper was analysed,
  /// and the relative drift from it that counts as a regression.
  std::optional<double> recorded;
  double recorded_tolerance = 0.0;
};

/// Adds figures and notes of one report section.
struct SectionSpec {
  std::string id;
  Tier tier = Tier::fast;
  std::function<void(const CheckContext&, reports::Report&)> add;
};

class Registry {
 public:
  static Registry& instance();
  void add(CheckSpec check);
  void add(SectionSpec section);
  /// Checks of the tier (the full tier includes the fast one), in registration order.
  [[nodiscard]] std::vector<const CheckSpec*> checks(Tier tier) const;
  [[nodiscard]] std::vector<const SectionSpec*> sections(Tier tier) const;

 private:
  std::vector<CheckSpec> checks_;
  std::vector<SectionSpec> sections_;
};

struct RegisterCheck {
  explicit RegisterCheck(CheckSpec check) { Registry::instance().add(std::move(check)); }
};
struct RegisterSection {
  explicit RegisterSection(SectionSpec section) { Registry::instance().add(std::move(section)); }
};

/// Runs one check, timing it, turning an exception into a failed record, and classifies it
/// (outcome.h).
reports::CheckRecord run_check(const CheckSpec& check, const CheckContext& context);

/// Adds one section's figures and notes; a section that throws is a section failure of the
/// report (outcome.h), which gates like a failed check.
void build_section(const SectionSpec& section, const CheckContext& context, reports::Report& report);

/// Runs the tier's checks and sections into a report; `progress` gets one line per check.
/// A non-empty `only` (an ECMAScript regular expression) keeps the checks and sections whose
/// id it matches somewhere; InputError when it is malformed or matches nothing.
reports::Report run_verification(Tier tier, const CheckContext& context,
                                 const std::function<void(const std::string&)>& progress,
                                 const std::string& only = {});

Tier parse_tier(const std::string& name);
std::string tier_name(Tier tier);

}  // namespace gearbench::verification
