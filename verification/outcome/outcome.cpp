#include "outcome.h"

#include <cmath>
#include <exception>

namespace gearbench::verification {

using reports::Outcome;

bool within_tolerance(const reports::CheckRecord& r) {
  return r.error.empty() && std::isfinite(r.value) &&
         r.abs_error() <= r.tolerance.abs + r.tolerance.rel * std::abs(r.reference_value);
}

namespace {
bool drifted_from_recorded(const reports::CheckRecord& r) {
  return std::abs(r.value - r.recorded) > r.recorded_tolerance * std::abs(r.recorded);
}
}  // namespace

Outcome classify(const reports::CheckRecord& r) {
  if (!r.error.empty() || !std::isfinite(r.value)) return Outcome::fail;
  if (!r.reproduction) return within_tolerance(r) ? Outcome::pass : Outcome::fail;
  if (drifted_from_recorded(r)) return Outcome::fail;
  return within_tolerance(r) ? Outcome::reproduced : Outcome::missed;
}

bool gate_passes(const reports::OutcomeCounts& counts) {
  return counts.failed == 0 && counts.sections_failed == 0;
}

void build_section(const std::string& id, const std::function<void(reports::Report&)>& add,
                   reports::Report& report) {
  try {
    add(report);
  } catch (const std::exception& e) {
    report.section_failures.push_back({id, e.what()});
  }
}

}  // namespace gearbench::verification
