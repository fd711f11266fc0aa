#pragma once
// The outcome rules of the verification matrix: what a check found (pass, reproduced,
// missed, fail) and what gates a commit. `gearbench verify`'s exit code and the ctest gate
// both follow from these rules; reports/ only stores and renders what they decide.
#include <functional>
#include <string>

#include "report.h"

namespace gearbench::verification {

/// |value − reference| ≤ abs + rel·|reference|, for a finite value and no error.
bool within_tolerance(const reports::CheckRecord& r);

/// A check passes or fails by its tolerance. A seed reproduction (r.reproduction) is
/// reproduced within tolerance of the paper's figure, missed outside it (a finding, recorded
/// and explained), and failed only when it drifts from the figure recorded when the gap was
/// analysed by more than r.recorded_tolerance (relative). An error or a non-finite value
/// fails either kind.
reports::Outcome classify(const reports::CheckRecord& r);

/// The gate: no failed check and no report section that could not be built. Missed seed
/// reproductions do not gate.
bool gate_passes(const reports::OutcomeCounts& counts);

/// Runs one report section's `add`; a section that throws is recorded in
/// report.section_failures (a failure of the gate), not turned into a note.
void build_section(const std::string& id, const std::function<void(reports::Report&)>& add,
                   reports::Report& report);

}  // namespace gearbench::verification
