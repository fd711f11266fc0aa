#include "speed_sweep.h"

#include <fmt/format.h>
#include <numbers>

#include "model/errors.h"

namespace gearbench::dynamics {

namespace {

model::OptionTable<SpeedSweepSpec> make_table() {
  model::OptionTable<SpeedSweepSpec> t;
  t.number("from", &SpeedSweepSpec::from_rpm, model::Range::positive(1e6),
           {.description = "the first pinion speed", .unit = "rpm", .required = true});
  t.number("to", &SpeedSweepSpec::to_rpm, model::Range::positive(1e6),
           {.description = "the last pinion speed, above from", .unit = "rpm", .required = true});
  t.integer("points", &SpeedSweepSpec::points, 2, 10000,
            {.description = "equally spaced speeds from from to to", .required = true});
  t.rule([](const SpeedSweepSpec& s, const std::string& prefix) {
    if (!(s.to_rpm > s.from_rpm))
      throw InputError(fmt::format("{}to = {}: must be above {}from = {}", prefix, model::format_value(s.to_rpm),
                                   prefix, model::format_value(s.from_rpm)));
  });
  return t;
}

}  // namespace

const model::OptionTable<SpeedSweepSpec>& SpeedSweepSpec::table() {
  static const auto t = make_table();
  return t;
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
