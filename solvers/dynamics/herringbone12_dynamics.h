#pragma once
// 12-DOF bending–torsion–axial dynamics of a herringbone pair on rolling bearings
// (production solver #4, second model): seed 000 eqs 1–7 as written out in
// docs/dynamics-model.md ("12-DOF herringbone model"), marched by march.h (SUNDIALS).
//
// Pipeline: herringbone geometry → per-half mesh excitation (slicing of the energy-method
// stiffness, friction arms) → quasi-static load and state → run-up → recorded window at a
// fixed sample rate → statistics, spectrum (FFTW), energy balance of the window,
// natural frequencies and mode shapes of the mean-stiffness system (Eigen).
#include <array>
#include <optional>
#include <vector>

#include "integrator.h"
#include "march.h"
#include "geometry/gear_pair_geometry.h"
#include "half_mesh.h"
#include "model/materials.h"
#include "response_analysis.h"
#include "run_status.h"

namespace gearbench::dynamics {

struct Herringbone12Options {
  double radial_stiffness = 5e8;     ///< each half's bearing, pinion and wheel [N/m]
  double radial_damping = 2e3;       ///< [N·s/m]
  double axial_stiffness = 2e8;      ///< wheel halves (and a pinion that does not float) [N/m]
  double axial_damping = 2e3;        ///< [N·s/m]
  std::optional<double> groove_stiffness;  ///< axial coupling of the halves [N/m]; default E·π·r_f²/groove
  double groove_damping = 2e3;       ///< [N·s/m]
  std::optional<double> twist_stiffness;   ///< torsional coupling of the halves [N·m/rad]; default G·π·r_f⁴/(2·groove)
  double twist_damping = 0.0;        ///< [N·m·s/rad]
  bool floating_pinion = true;       ///< no axial bearing on the pinion (seed 000)
  double mesh_damping_ratio = 0.07;  ///< ζ_m per half
  /// Seed 000 eq. 6 pulses, their peak that of eq. 6's mass and spring under the corner's approach
  /// (docs/dynamics-model.md, "Mesh-in impact"); off by default: a helical half engages gradually.
  bool mesh_in_impact = false;
  /// Eq. 6 as printed (the closing speed held through the pulse), for comparison: with
  /// r = F_s·q_s/δ > 1 (seed 000 at 2000 rpm: 3.6) it takes r times the compression the approach supplies.
  bool impact_held_velocity = false;
  double base_pitch_error = 0.0;     ///< f_pb [m], added to the loaded deflection the entering corner closes
  double half_offset = 0.0;          ///< the right half's mesh lags by this fraction of a mesh cycle
  /// Backlash b [m] along the normal, per half: contact loss on (docs, "Contact loss"); none: linear mesh.
  std::optional<double> backlash;
  HalfMeshOptions mesh;
  int runup_cycles = 100;
  int record_cycles = 20;
  int samples_per_cycle = 64;
  IntegratorOptions integrator;

  /// The keys of a case of model "herringbone12" (dynamics_options.cpp).
  static const model::OptionTable<Herringbone12Options>& table();
  void validate() const { table().validate(*this); }  ///< InputError naming the key
};

/// The model's parameters (per half where the page says so), exposed for the references.
struct Herringbone12Parameters {
  double m_p = 0, m_g = 0, I_p = 0, I_g = 0;  ///< one half's blank [kg, kg·m²]
  double R_p = 0, R_g = 0, beta_b = 0;       ///< base radii [m], base helix angle [rad]
  double k_radial = 0, c_radial = 0, k_axial_p = 0, c_axial_p = 0, k_axial_g = 0, c_axial_g = 0;
  double k_groove = 0, c_groove = 0;         ///< axial coupling of the halves, pinion and wheel alike
  double k_twist = 0, c_twist = 0;           ///< torsional coupling of the halves, pinion and wheel alike
  double T_p = 0, T_g = 0;                   ///< torques per half [N·m]
  double omega_p = 0, omega_g = 0;           ///< nominal speeds [rad/s]
  double mean_mesh_stiffness = 0;            ///< k̄ per half [N/m]
  double mesh_damping = 0;                   ///< c_m at k̄ [N·s/m]
  double static_force = 0;                   ///< F̄_n per half [N]
  double impact_velocity = 0, impact_force = 0, impact_duration = 0;  ///< the pulse: v_s, peak, τ
  double impact_stiffness = 0;          ///< 1/q_s = k_m at mesh-in [N/m]
  double impact_held_force = 0;         ///< eq. 6 as printed, v_s·√(m_e/q_s) [N]
  double impact_approach_time = 0;      ///< Δt = 2δ/v_s: the corner's approach from first contact to A [s]
  double impact_compression_ratio = 0;  ///< r = F_s,held·q_s/δ = 2/(ω_s·Δt): eq. 6's compression over the approach's
  double impact_entry_fraction = 0;     ///< helical: share of the face in premature contact at one instant
  /// The pinion speed [rad/s] below which the eq. 6 pulse keeps to its premise (r ≤ 1) at this
  /// load: r ∝ Ω at a fixed loaded deflection δ̄ (docs/dynamics-model.md, "Mesh-in impact").
  [[nodiscard]] double impact_premise_speed() const { return omega_p / impact_compression_ratio; }
  double mean_impact_force = 0;              ///< F̄_s = (2/π)·F_s·τ/T [N]
  double period = 0;                         ///< T_mesh [s]
  std::array<double, 2> clock_offset{};      ///< half h's mesh clock is t + clock_offset[h]
};

struct Herringbone12Result {
  std::vector<double> time;                                ///< [s] from the start of recording
  std::array<std::vector<double>, 2> transmission_error;   ///< δ_h along the normal [m]
  std::array<std::vector<double>, 2> mesh_force;           ///< F_nh [N]
  std::array<std::vector<double>, 2> friction_torque;      ///< F_nh·χ_ph on the pinion [N·m]
  std::vector<double> axial_float;                         ///< (z_p1 + z_p2)/2 [m]
  std::vector<double> bearing_force_pinion;                ///< left pinion radial bearing [N]
  double static_mesh_force = 0.0;                          ///< F̄_n per half [N]
  double dynamic_factor = 0.0;                             ///< max over halves of max F_nh / F̄_n
  std::array<ResponseStats, 2> te, force;
  ResponseStats float_stats;
  std::vector<double> spectrum_frequency, spectrum_te;     ///< of δ_1 [Hz, m]
  std::vector<double> natural_frequencies;                 ///< [Hz], rigid-body modes left out
  std::vector<std::vector<double>> mode_shapes;            ///< per frequency, M-normalised q
  double mesh_frequency = 0.0, periodicity = 0.0, load_torque = 0.0;
  double contact_loss_fraction = 0.0;  ///< share of the recorded samples and halves without mesh force
  double back_contact_fraction = 0.0;  ///< share of the recorded samples and halves on the back flanks
  long contact_events = 0;             ///< roots of the contact functions (restarts), whole run
  EnergyBalance energy;
  long steps = 0, rhs_evaluations = 0;
  double seconds = 0.0;
  RunStatus status = RunStatus::periodic;  ///< from the periodicity (run_status)
  std::string message;                     ///< what the status means for the figures
  /// The options as given and as the run used them: the groove coupling's stiffnesses filled
  /// in where the case gave none.
  Herringbone12Options options_given, options_used;

  /// One line: run length, integrator, work, time, status, dynamic factor.
  [[nodiscard]] std::string summary() const;
};

class Herringbone12Dynamics final : public DynamicsModel {
 public:
  /// `geometry` (a herringbone pair, or a spur pair for the reduction to two spur models)
  /// must outlive the solver.
  Herringbone12Dynamics(const geometry::GearPairGeometry& geometry, const std::array<model::Material, 2>& materials,
                        const model::OperatingPoint& operating, Herringbone12Options options);

  [[nodiscard]] Herringbone12Result solve() const;
  [[nodiscard]] const Herringbone12Parameters& parameters() const { return p_; }
  [[nodiscard]] const HalfMesh& mesh() const { return mesh_; }
  /// Size of the state: 12 coordinates, 12 rates, 4 work accumulators.
  [[nodiscard]] std::size_t state_size() const override { return 28; }
  /// dy/dt of the page's equations (pair sets and impact pulses of the interval holding t_mid).
  void derivative(double t, double t_mid, const double* y, double* dydt) const override;
  [[nodiscard]] double energy(double t, double t_mid, const double* y) const override;
  /// Restarts: the halves' spur switches and the start and end of every impact pulse.
  [[nodiscard]] std::vector<double> break_times(double t0, double t1) const override;
  /// The quasi-static state under the mean stiffness, arms and impact pulse (rates and work zero; the
  /// left wheel half at θ = 0).
  [[nodiscard]] std::vector<double> static_state() const;
  [[nodiscard]] std::vector<double> natural_frequencies(std::vector<std::vector<double>>* shapes = nullptr) const;
  /// The eq. 6 pulse of half h at time t (the interval holding t_mid decides if it acts).
  [[nodiscard]] double impact_force(int half, double t, double t_mid) const;
  /// The contact functions of docs/dynamics-model.md, "Contact loss", for both halves:
  /// δ_h, δ_h + b, δ_h + τδ̇_h, δ_h + b + τδ̇_h (τ = c_m/k̄); none without backlash.
  [[nodiscard]] int contact_function_count() const override { return options_.backlash ? 8 : 0; }
  void contact_functions(const double* y, double* g) const override;

 private:
  struct HalfState {
    double delta = 0, delta_rate = 0, force = 0, stiffness = 0, damping = 0, impact = 0;
    double penetration = 0;       ///< δ (linear mesh), or the overlap of the flanks in contact
    double mesh_dissipation = 0;  ///< (F_n − k·p)·δ̇
    bool back = false;
    MeshPoint mesh;
  };
  [[nodiscard]] HalfState half_state(int half, double t, double t_mid, const double* y) const;
  [[nodiscard]] double delta(int half, const double* y, int first) const;  ///< δ_h (first 0) or δ̇_h (first 12)

  Herringbone12Options options_;
  HalfMesh mesh_;
  Herringbone12Parameters p_;
};

}  // namespace gearbench::dynamics
