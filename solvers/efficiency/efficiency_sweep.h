#pragma once
// One-parameter sweeps of the static mesh efficiency about a base operating point: input
// torque, pinion speed and pressure angle, as seed 004 tables 2–4 vary them. The solver
// does not print: a caller may pass a progress callback (the CLI writes it to stderr).
#include <functional>
#include <string>
#include <vector>

#include "mesh_loss.h"

namespace gearbench::efficiency {

/// The "sweep" section of an efficiency case: values in the case's units, as the operating
/// point and the gear pair take them.
struct SweepSpec {
  std::vector<double> torques_Nm;            ///< pinion torque values
  std::vector<double> speeds_rpm;            ///< pinion speed values
  std::vector<double> pressure_angles_deg;   ///< normal pressure angle values
  static const model::OptionTable<SweepSpec>& table();
  void validate() const { table().validate(*this, "sweep."); }  ///< InputError naming sweep.<key>
};

struct SweepRow {
  std::string parameter;   ///< "torque_Nm" | "speed_rpm" | "pressure_angle_deg"
  double value = 0.0;
  double efficiency_mean = 0.0, efficiency_min = 0.0, efficiency_max = 0.0;
  double sliding_loss_mean = 0.0, rolling_loss_mean = 0.0;  ///< [W]
  double friction_coefficient_mean = 0.0;
  /// Where the efficiency is lowest and highest, as a fraction of the path A..E travelled
  /// by the pair that entered last (0 = engagement at A): a pair position, not a phase.
  double min_at = 0.0, max_at = 0.0;
  double pitch_at = 0.0;   ///< the pitch point on the same scale, (C − A)/(E − A)
};

using SweepProgress = std::function<void(const std::string&)>;

/// Runs the base point changed in one parameter at a time, in the order torque, speed,
/// pressure angle.
std::vector<SweepRow> efficiency_sweep(const model::GearPair& pair, const model::OperatingPoint& base,
                                       const MeshLossOptions& options, const MeshLossMedia& media,
                                       const SweepSpec& spec, const SweepProgress& progress = {});

}  // namespace gearbench::efficiency
