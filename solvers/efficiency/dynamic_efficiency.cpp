#include "dynamic_efficiency.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numeric>

#include "model/errors.h"

namespace gearbench::efficiency {

namespace {

model::OptionTable<DynamicEfficiencyOptions> make_table() {
  model::OptionTable<DynamicEfficiencyOptions> t;
  t.integer("load_levels", &DynamicEfficiencyOptions::load_levels, 2, 100,
            {.description = "loss curves between the smallest and the largest mesh force of the record (seed 000: 5)"});
  t.integer("phases", &DynamicEfficiencyOptions::phases, 4, 100000,
            {.description = "mesh positions per loss curve, interpolated at each instant's phase"});
  return t;
}

}  // namespace

const model::OptionTable<DynamicEfficiencyOptions>& DynamicEfficiencyOptions::table() {
  static const auto t = make_table();
  return t;
}

namespace {

/// Periodic linear interpolation of a curve given on the midpoints (k + ½)/n of [0, 1).
double at_phase(const std::vector<double>& curve, double phase) {
  const auto n = static_cast<double>(curve.size());
  const double x = phase * n - 0.5;
  const double k = std::floor(x);
  const double w = x - k;
  const auto wrap = [&](double i) { return static_cast<std::size_t>(std::fmod(std::fmod(i, n) + n, n)); };
  return (1.0 - w) * curve[wrap(k)] + w * curve[wrap(k + 1.0)];
}

}  // namespace

DynamicEfficiency::DynamicEfficiency(const geometry::GearPairGeometry& g, const model::OperatingPoint& nominal,
                                     MeshLossOptions loss_options, MeshLossMedia media, std::size_t meshes,
                                     DynamicEfficiencyOptions options)
    : geometry_(g),
      nominal_(nominal),
      loss_options_(std::move(loss_options)),
      media_(std::move(media)),
      meshes_(meshes),
      options_(options) {
  options_.validate();
  if (g.pair().herringbone)
    throw InputError("dynamic_efficiency: give one helical half of a herringbone pair and one force series per half");
  if (meshes_ == 0) throw InputError("dynamic_efficiency: no mesh-force series");
  const double f_nominal = nominal_.pinion_torque / (g.radii(0).base * std::cos(g.base_helix_angle())) /
                           static_cast<double>(meshes_);
  static_curve_ = loss_curve(f_nominal);
}

/// Total loss (sliding + rolling) over one mesh period on `phases` midpoints at one force.
std::vector<double> DynamicEfficiency::loss_curve(double normal_force) const {
  model::OperatingPoint op = nominal_;
  op.pinion_torque = normal_force * geometry_.radii(0).base * std::cos(geometry_.base_helix_angle());
  MeshLossOptions o = loss_options_;
  o.positions = options_.phases;
  const auto r = MeshLoss(geometry_, op, o, media_).solve();
  std::vector<double> loss(r.sliding_loss.size());
  std::transform(r.sliding_loss.begin(), r.sliding_loss.end(), r.rolling_loss.begin(), loss.begin(), std::plus<>());
  return loss;
}

DynamicEfficiencyResult DynamicEfficiency::evaluate(const std::vector<double>& time,
                                                    const std::vector<std::vector<double>>& mesh_forces,
                                                    double mesh_frequency) const {
  if (mesh_forces.size() != meshes_)
    throw InputError(fmt::format("dynamic_efficiency: {} mesh-force series for {} meshes", mesh_forces.size(), meshes_));
  for (const auto& f : mesh_forces)
    if (f.size() != time.size())
      throw InputError(fmt::format("dynamic_efficiency: a force series has {} samples for {} times", f.size(), time.size()));
  if (!(mesh_frequency > 0.0))
    throw InputError(fmt::format("dynamic_efficiency: mesh_frequency = {}: must be positive", mesh_frequency));

  // Load levels: equally spaced over the positive forces of all meshes (seed 000: five).
  double f_lo = HUGE_VAL, f_hi = 0.0;
  for (const auto& series : mesh_forces)
    for (const double f : series)
      if (f > 0.0) f_lo = std::min(f_lo, f), f_hi = std::max(f_hi, f);
  DynamicEfficiencyResult r;
  r.time = time;
  const double p_in = nominal_.pinion_torque * nominal_.pinion_speed;
  r.static_mean = 1.0 - static_cast<double>(meshes_) *
                            std::accumulate(static_curve_.begin(), static_curve_.end(), 0.0) /
                            static_cast<double>(static_curve_.size()) / p_in;
  std::vector<std::vector<double>> curves;
  if (f_hi > 0.0) {
    if (f_hi - f_lo < 1e-12 * f_hi) f_lo = f_hi * (1.0 - 1e-9);  // a constant force: one curve suffices
    for (int k = 0; k < options_.load_levels; ++k) {
      r.load_levels.push_back(f_lo + (f_hi - f_lo) * k / (options_.load_levels - 1));
      curves.push_back(loss_curve(r.load_levels.back()));
    }
  }
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double phase = time[i] * mesh_frequency - std::floor(time[i] * mesh_frequency);
    double loss = 0.0;
    for (const auto& series : mesh_forces) {
      const double f = series[i];
      if (f <= 0.0 || curves.empty()) continue;
      // Linear in the force between the two neighbouring levels.
      const auto upper = std::upper_bound(r.load_levels.begin(), r.load_levels.end() - 1, f);
      const auto k = static_cast<std::size_t>(std::max<std::ptrdiff_t>(upper - r.load_levels.begin(), 1));
      const double w = (f - r.load_levels[k - 1]) / (r.load_levels[k] - r.load_levels[k - 1]);
      loss += (1.0 - w) * at_phase(curves[k - 1], phase) + w * at_phase(curves[k], phase);
    }
    r.efficiency.push_back(1.0 - loss / p_in);
  }
  r.mean = std::accumulate(r.efficiency.begin(), r.efficiency.end(), 0.0) / static_cast<double>(r.efficiency.size());
  return r;
}

DynamicEfficiencyResult dynamic_efficiency(const geometry::GearPairGeometry& g, const model::OperatingPoint& nominal,
                                           const MeshLossOptions& loss_options, const MeshLossMedia& media,
                                           const std::vector<double>& time,
                                           const std::vector<std::vector<double>>& mesh_forces,
                                           double mesh_frequency, DynamicEfficiencyOptions options) {
  return DynamicEfficiency(g, nominal, loss_options, media, mesh_forces.size(), options)
      .evaluate(time, mesh_forces, mesh_frequency);
}

}  // namespace gearbench::efficiency
