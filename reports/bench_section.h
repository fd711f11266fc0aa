#pragma once
// The benchmark record of `gearbench bench` as a report section: every benchmark's time and
// counters, and the side-by-side ratios against the baselines measured in the same run.
#include <nlohmann/json.hpp>

#include "report.h"

namespace gearbench::reports {

/// Throws InputError when the record is not a `gearbench bench` record.
Note benchmark_note(const nlohmann::json& record);

}  // namespace gearbench::reports
