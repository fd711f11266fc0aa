#include "speed_sweep.h"

#include <fmt/format.h>
#include <numbers>

#include "model/errors.h"

namespace gearbench::dynamics {

void SpeedSweepSpec::validate() const {
  if (!(from_rpm > 0.0)) throw InputError(fmt::format("speed_sweep_rpm.from = {}: must be above 0 rpm", from_rpm));
  if (!(to_rpm > from_rpm))
    throw InputError(fmt::format("speed_sweep_rpm.to = {}: must be above speed_sweep_rpm.from = {}", to_rpm, from_rpm));
  if (points < 2) throw InputError(fmt::format("speed_sweep_rpm.points = {}: must be at least 2", points));
}

SpeedSweepResult speed_sweep(const SpeedSweepSpec& spec, model::OperatingPoint base, const SpeedSolve& solve,
                             const SpeedSweepProgress& progress) {
  spec.validate();
  SpeedSweepResult out;
  for (int i = 0; i < spec.points; ++i) {
    const double rpm = spec.from_rpm + (spec.to_rpm - spec.from_rpm) * i / (spec.points - 1);
    base.pinion_speed = rpm * std::numbers::pi / 30.0;
    SpeedPoint point;
    try {
      point = solve(base);
    } catch (const InputError& e) {
      if (progress) progress(fmt::format("speed sweep {}/{}: {:.1f} rpm skipped: {}", i + 1, spec.points, rpm, e.what()));
      out.skipped.push_back({rpm, e.what()});
      continue;
    }
    if (progress)
      progress(fmt::format("speed sweep {}/{}: {:.1f} rpm, mesh {:.1f} Hz, dynamic factor {:.4f}", i + 1, spec.points,
                           rpm, point.mesh_frequency, point.dynamic_factor));
    out.speed_rpm.push_back(rpm);
    out.mesh_frequency.push_back(point.mesh_frequency);
    out.dynamic_factor.push_back(point.dynamic_factor);
    out.te_rms.push_back(point.te_rms);
  }
  return out;
}

}  // namespace gearbench::dynamics
