#include "efficiency_sweep.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "model/errors.h"

namespace gearbench::efficiency {

void SweepSpec::validate() const {
  const auto check = [](const std::vector<double>& values, const char* key, double lo, double hi) {
    for (const double v : values)
      if (!(v > lo && v <= hi))
        throw InputError(fmt::format("sweep.{} = {}: allowed range is ({}, {}]", key, v, lo, hi));
  };
  check(torques_Nm, "torque_Nm", 0.0, 1e9);
  check(speeds_rpm, "speed_rpm", 0.0, 1e6);
  check(pressure_angles_deg, "pressure_angle_deg", 10.0, 40.0);
  if (torques_Nm.empty() && speeds_rpm.empty() && pressure_angles_deg.empty())
    throw InputError("sweep: give at least one of torque_Nm, speed_rpm, pressure_angle_deg");
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
