#pragma once
// How a dynamics run went, as its result reports it (issue 21, Ceres' Summary): whether the
// recorded window is the periodic response, a message that says what that means for the
// figures, and the one line the CLI prints.
#include <fmt/format.h>
#include <string>

#include "integrator.h"

namespace gearbench::dynamics {

enum class RunStatus {
  periodic,      ///< the recorded window repeats: its figures are the steady response's
  not_periodic,  ///< the run-up was too short: the figures are a transient's
};
[[nodiscard]] const char* status_name(RunStatus status);  ///< "periodic" | "not_periodic"

/// Above this periodicity (the last recorded period against the one before, relative to the
/// peak-to-peak transmission error) the run has not reached its periodic response: 6e-8 at
/// seed 003's 1000 rpm, 1.5e-2 at 1e6 rpm.
inline constexpr double max_periodicity = 1e-3;

struct RunVerdict {
  RunStatus status;
  std::string message;
};
/// The status of a run whose recording has this periodicity.
[[nodiscard]] RunVerdict run_status(double periodicity);

/// The one line of a result's summary(): run length, integrator, work, time, status and
/// dynamic factor. `Result` is a Spur6Result or Herringbone12Result.
template <class Result>
std::string run_summary(const char* model, const Result& r) {
  const auto& o = r.options_used;
  return fmt::format("{}: {} + {} mesh cycles, {} (rtol {:.0e}): {} steps, {} right-hand sides, {:.2f} s; {} "
                     "(periodicity {:.2g}); dynamic factor {:.4f}",
                     model, o.runup_cycles, o.record_cycles, integrator_key(o.integrator.method),
                     o.integrator.relative_tolerance, r.steps, r.rhs_evaluations, r.seconds, status_name(r.status),
                     r.periodicity, r.dynamic_factor);
}

}  // namespace gearbench::dynamics
