#pragma once
// Transient isothermal line-contact EHL along the path of contact of a spur pair (seed 004,
// eqs 5–7): the contact point travels from A (engagement) to E (disengagement) at the base
// speed r_b1·ω1, and the reduced radius, the entrainment speed and the load of the pair
// change with it. Everything is scaled to the pitch point C with the full load on one pair
// (seed 004's C_R = R/R_C, C_u = ū/ū_C, C_w = w/w_C), so one dimensionless problem holds
// the whole mesh:
//   d/dX(ε dP/dX) − C_u·d(ρ̄H)/dX − ∂(ρ̄H)/∂T = 0,   H = H0 + X²/(2C_R) − (1/π)∫ln|X−X'|P dX',
//   ∫P dX = (π/2)·C_w,   T = t·ū_C/b_C,
// solved by the FAS multigrid of fas_multigrid.h with implicit Euler in time (first order),
// each step started from the last. The first step is the steady solution at A.
#include <string>
#include <vector>

#include "geometry/gear_pair_geometry.h"
#include "line_contact_solver.h"
#include "model/materials.h"
#include "model/solve_status.h"

namespace gearbench::ehl {

struct TransientMeshOptions {
  int steps = 200;                      ///< time steps from A to E
  std::string load_sharing = "equal";   ///< "equal" (seed 004: half per pair when two mesh) or "iso"
  EhlOptions grid = default_grid();     ///< levels, cycles; max_cycles per time step

  static EhlOptions default_grid();
  /// The case keys beside the gear pair and the fluid (ehl_options.cpp).
  static const model::OptionTable<TransientMeshOptions>& table();
  void validate() const;                ///< InputError naming the key
};

/// The state of the travelling contact at one instant.
struct TransientMeshStep {
  double time = 0.0;              ///< since engagement at A [s]
  double position = 0.0;          ///< contact point on the line of action, from T1 [m]
  double roll_angle = 0.0;        ///< pinion roll angle s/r_b1 [rad]
  double reduced_radius = 0.0;    ///< R [m]
  double entrainment = 0.0;       ///< ū [m/s]
  double sliding = 0.0;           ///< u1 − u2 [m/s]
  double load_per_length = 0.0;   ///< w [N/m]
  double h_central = 0.0;         ///< film at the Hertzian centre X = 0 [m]
  double h_min = 0.0;             ///< [m]
  double p_max = 0.0;             ///< [Pa]
  double hertz_pressure = 0.0;    ///< p_h of the instantaneous steady Hertz contact [Pa]
  int cycles = 0;
  double residual = 0.0;          ///< final scaled Reynolds residual
  double work_units = 0.0;        ///< this step's, in sweeps of its finest grid
  /// Solved by full multigrid (the first steps, and where the contact moved from the last one
  /// solved so), else warm from the previous steps with that step's error estimate.
  bool full_multigrid = false;
};

/// Pressure and film at a named point of the path (A, B, C, D, E).
struct TransientMeshProfile {
  std::string point;
  double position = 0.0;          ///< [m from T1]
  std::vector<double> x;          ///< [m], relative to the contact centre
  std::vector<double> p;          ///< [Pa]
  std::vector<double> h;          ///< [m]
};

/// converged and message: model::SolveStatus (the failed step named in the message).
struct TransientMeshResult : model::SolveStatus {
  std::vector<TransientMeshStep> steps;
  std::vector<TransientMeshProfile> profiles;
  // The reference contact (pitch point, full load).
  double reference_radius = 0.0, reference_load = 0.0, reference_entrainment = 0.0;
  double reference_half_width = 0.0, reference_pressure = 0.0;
  double time_step = 0.0;              ///< Δt [s]
  double dimensionless_time_step = 0.0;  ///< ΔT = Δt·ū_C/b_C
  // Extremes over the mesh.
  double p_max = 0.0, p_max_position = 0.0;
  double h_min = 0.0, h_min_position = 0.0;
  double h_central_min = 0.0, h_central_max = 0.0;
  // Diagnostics.
  int failed_step = -1;                ///< first step that missed the tolerance
  std::vector<double> failed_residual_history;
  std::vector<double> failed_force_history;  ///< |∫P dX − F|/F per cycle of that step
  int total_cycles = 0;
  double work_units = 0.0;
  EhlWork work_by_part;               ///< work_units by part, summed over the steps
  double work_units_iterating = 0.0;  ///< of it, the cycles after the steps' full-multigrid cycles (a warm step's all)
  int full_multigrid_steps = 0;       ///< steps solved by full multigrid (TransientMeshStep)
  double seconds = 0.0;

  [[nodiscard]] std::string summary() const;
};

class TransientMeshEhl {
 public:
  /// `lubricant` supplies η0, α (or z), the viscosity and density models and E′; its radius,
  /// load and speeds are replaced by the pitch-point values from the gears and `operating`.
  /// Keeps a reference to `geometry`, which must outlive this object.
  TransientMeshEhl(const geometry::GearPairGeometry& geometry, const model::OperatingPoint& operating,
                   const LineContactData& lubricant, TransientMeshOptions options);
  /// Marches from A to E. An unconverged step stops the march; the result then has
  /// converged = false and the steps up to the failure.
  [[nodiscard]] TransientMeshResult run() const;

 private:
  [[nodiscard]] LineContactData pitch_contact() const;
  [[nodiscard]] double normal_load_per_length() const;  ///< F_n/b with the whole load on one pair

  const geometry::GearPairGeometry& geometry_;
  model::OperatingPoint operating_;
  LineContactData lubricant_;
  TransientMeshOptions options_;
};

}  // namespace gearbench::ehl
