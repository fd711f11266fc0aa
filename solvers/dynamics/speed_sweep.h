#pragma once
// A speed sweep of a dynamics model: the dynamic factor and the rms transmission error at
// equally spaced pinion speeds (issue 21: it lived in app/, while the efficiency sweep lives
// in solvers/efficiency). The sweep does not print: a caller may pass a progress callback
// (the CLI writes it to stderr). A point the model refuses (an InputError, e.g. where the
// mesh-in impact pulse would carry the load) is skipped with its reason, not fatal.
#include <functional>
#include <string>
#include <vector>

#include "model/materials.h"
#include "model/option_table.h"

namespace gearbench::dynamics {

/// Pinion speeds from `from_rpm` to `to_rpm` in `points` equal steps.
struct SpeedSweepSpec {
  double from_rpm = 0.0, to_rpm = 0.0;
  int points = 0;

  /// The keys of a case's "speed_sweep_rpm" section: "from", "to" (above "from") and "points".
  static const model::OptionTable<SpeedSweepSpec>& table();
  void validate() const { table().validate(*this, "speed_sweep_rpm."); }  ///< InputError naming the key
};

/// What one speed point of a model gives.
struct SpeedPoint {
  double mesh_frequency = 0.0;  ///< [Hz]
  double dynamic_factor = 0.0;
  double te_rms = 0.0;          ///< rms transmission error [m]
};

struct SkippedSpeed {
  double speed_rpm = 0.0;
  std::string reason;
};

struct SpeedSweepResult {
  std::vector<double> speed_rpm, mesh_frequency, dynamic_factor, te_rms;
  std::vector<SkippedSpeed> skipped;
};

using SpeedSolve = std::function<SpeedPoint(const model::OperatingPoint&)>;
using SpeedSweepProgress = std::function<void(const std::string&)>;

/// Solves `base` at each speed of `spec` (only the pinion speed changes).
SpeedSweepResult speed_sweep(const SpeedSweepSpec& spec, model::OperatingPoint base, const SpeedSolve& solve,
                             const SpeedSweepProgress& progress = {});

}  // namespace gearbench::dynamics
