#include "efficiency_sweep.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "model/errors.h"

namespace gearbench::efficiency {

const model::OptionTable<SweepSpec>& SweepSpec::table() {
  static const auto t = [] {
    model::OptionTable<SweepSpec> table;
    table.number("torque_Nm", &SweepSpec::torques_Nm, model::Range{0.0, 1e9, true, false},
             {.description = "pinion torques to run, one at a time", .unit = "N*m"});
    table.number("speed_rpm", &SweepSpec::speeds_rpm, model::Range{0.0, 1e6, true, false},
             {.description = "pinion speeds to run, one at a time", .unit = "rpm"});
    table.number("pressure_angle_deg", &SweepSpec::pressure_angles_deg, model::Range{10.0, 40.0, true, false},
             {.description = "normal pressure angles to run, one at a time", .unit = "deg"});
    table.rule([](const SweepSpec& s, const std::string& prefix) {
      if (s.torques_Nm.empty() && s.speeds_rpm.empty() && s.pressure_angles_deg.empty())
        throw InputError(prefix.substr(0, prefix.size() - 1) +
                         ": give at least one of torque_Nm, speed_rpm, pressure_angle_deg");
    });
    return table;
  }();
  return t;
}

namespace {

SweepRow run_point(const std::string& parameter, double value, const model::GearPair& pair,
                   const model::OperatingPoint& op, const MeshLossOptions& options, const MeshLossMedia& media) {
  const geometry::GearPairGeometry g(pair);
  const auto r = MeshLoss(g, op, options, media).solve();
  SweepRow row{parameter, value, r.efficiency_mean, r.efficiency_min, r.efficiency_max, r.sliding_loss_mean,
               r.rolling_loss_mean, r.friction_coefficient_mean};
  // Mesh position 0 is a pair entering at A; it has travelled pinion angle × r_b1 along the path.
  const auto& p = g.path();
  const auto travelled = [&](std::size_t i) { return r.mesh_position[i] * g.radii(0).base / (p.E - p.A); };
  row.min_at = travelled(static_cast<std::size_t>(std::min_element(r.efficiency.begin(), r.efficiency.end()) - r.efficiency.begin()));
  row.max_at = travelled(static_cast<std::size_t>(std::max_element(r.efficiency.begin(), r.efficiency.end()) - r.efficiency.begin()));
  row.pitch_at = (p.C - p.A) / (p.E - p.A);
  return row;
}

}  // namespace

std::vector<SweepRow> efficiency_sweep(const model::GearPair& pair, const model::OperatingPoint& base,
                                       const MeshLossOptions& options, const MeshLossMedia& media,
                                       const SweepSpec& spec, const SweepProgress& progress) {
  spec.validate();
  const std::size_t total = spec.torques_Nm.size() + spec.speeds_rpm.size() + spec.pressure_angles_deg.size();
  std::vector<SweepRow> rows;
  const auto report = [&](const std::string& key, double v) {
    if (progress) progress(fmt::format("efficiency sweep {}/{}: {} = {}", rows.size() + 1, total, key, v));
  };
  for (const double t : spec.torques_Nm) {
    report("torque_Nm", t);
    auto op = base;
    op.pinion_torque = t;
    rows.push_back(run_point("torque_Nm", t, pair, op, options, media));
  }
  for (const double n : spec.speeds_rpm) {
    report("speed_rpm", n);
    auto op = base;
    op.pinion_speed = n * std::numbers::pi / 30.0;
    rows.push_back(run_point("speed_rpm", n, pair, op, options, media));
  }
  for (const double a : spec.pressure_angles_deg) {
    report("pressure_angle_deg", a);
    auto p = pair;
    p.normal_pressure_angle = a * std::numbers::pi / 180.0;
    rows.push_back(run_point("pressure_angle_deg", a, p, base, options, media));
  }
  return rows;
}

}  // namespace gearbench::efficiency
