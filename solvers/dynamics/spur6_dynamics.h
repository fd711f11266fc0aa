#pragma once
// 6-DOF dynamics of a spur pair on bearings (production solver #4, first model): the
// equations of docs/dynamics-model.md (seed 003 eqs 12–15) with the energy-method
// single-pair stiffness, healthy or with a cracked pinion tooth, marched by march.h (SUNDIALS,
// restarting at every stiffness switch).
//
// Pipeline: parameters from the case → single-pair stiffness (healthy: spline) → static
// state → run-up over whole revolutions/mesh cycles → recorded window at a fixed sample
// rate → statistics, spectrum (FFTW), natural frequencies of the mean-stiffness system.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "integrator.h"
#include "march.h"
#include "pair_friction.h"
#include "response_analysis.h"
#include "run_status.h"
#include "spur_mesh.h"
#include "geometry/gear_pair_geometry.h"
#include "model/materials.h"

namespace gearbench::dynamics {

struct Spur6Options {
  double bearing_stiffness = 1e8;    ///< k1 = k2 [N/m], x and y (gearbench default)
  double bearing_damping = 1e3;      ///< c1 = c2 [N·s/m]
  double mesh_damping_ratio = 0.07;  ///< ζ_m
  /// μ 0.06 of the constant law (seed 003), or a law of solvers/lubricant (docs, "Friction laws").
  FrictionLawOptions friction{.friction_coefficient = 0.06};
  /// Backlash b [m]: contact loss on (docs, "Contact loss"); none: the linear mesh.
  std::optional<double> backlash;
  std::optional<stiffness::GearCrack> crack;
  stiffness::Fillet fillet = stiffness::Fillet::trochoid;  ///< of the energy-method tooth (mesh stiffness)
  int runup_cycles = 60;             ///< mesh cycles before recording (whole revolutions with a crack)
  int record_cycles = 40;            ///< mesh cycles recorded (at least two revolutions with a crack)
  int samples_per_cycle = 64;
  IntegratorOptions integrator;

  /// The keys of a case of model "spur6" (dynamics_options.cpp).
  static const model::OptionTable<Spur6Options>& table();
  void validate() const { table().validate(*this); }  ///< InputError naming the key
};

/// The model's parameters, derived from the gear pair (exposed for the references).
struct Spur6Parameters {
  double m1 = 0, m2 = 0, I1 = 0, I2 = 0, rb1 = 0, rb2 = 0;
  double k_bearing = 0, c_bearing = 0, T1 = 0, mu = 0, zeta_mesh = 0;
  double T2 = 0;            ///< load torque of the quasi-static balance [N·m]
  double static_force = 0;  ///< F̄ = T1/(R_b1 + ā1) [N]
  double mean_mesh_stiffness = 0, mesh_damping = 0;
  double A = 0, C = 0, E = 0, T1T2 = 0, pbt = 0, contact_speed = 0;
  double crack_mouth = 0;  ///< s where a pitch crack starts to act (the pinion's reference point)
  double face_width = 0;   ///< b [m]
  double backlash = 0;     ///< b [m] with contact loss on
  int z1 = 0;
};

struct Spur6Result {
  std::vector<double> time;                  ///< [s] from the start of recording
  std::vector<double> transmission_error;    ///< δ [m]
  std::vector<double> mesh_force;            ///< F_m [N]
  std::vector<double> friction_force;        ///< F_f [N]
  std::vector<double> bearing_force_x1;      ///< pinion bearing, along the line of action [N]
  double static_mesh_force = 0.0;            ///< F̄ = T1/(R_b1 + ā1) [N]
  double dynamic_factor = 0.0;               ///< max F_m / F0
  using Stats = ResponseStats;
  Stats te, force, friction;
  std::vector<double> spectrum_frequency;    ///< [Hz]
  std::vector<double> spectrum_te;           ///< amplitude of δ [m]
  std::vector<double> natural_frequencies;   ///< [Hz], mean-stiffness system, non-zero
  double mesh_frequency = 0.0;               ///< [Hz]
  double periodicity = 0.0;                  ///< max |δ(t) − δ(t − period)| / p2p over the last period
  double contact_loss_fraction = 0.0;        ///< share of the recorded samples without mesh force
  double back_contact_fraction = 0.0;        ///< share of the recorded samples on the back flanks
  long contact_events = 0;                   ///< roots of the contact functions (restarts), whole run
  EnergyBalance energy;                      ///< over the recorded window
  long steps = 0, rhs_evaluations = 0;
  double seconds = 0.0;
  RunStatus status = RunStatus::periodic;    ///< from the periodicity (run_status)
  std::string message;                       ///< what the status means for the figures
  /// The options as given and as the run used them: with a crack, run-up and record in whole
  /// revolutions (the record at least two).
  Spur6Options options_given, options_used;

  /// One line: run length, integrator, work, time, status, dynamic factor.
  [[nodiscard]] std::string summary() const;
};

class Spur6Dynamics final : public DynamicsModel {
 public:
  /// Keeps a reference to `geometry`, which must outlive this object.
  Spur6Dynamics(const geometry::GearPairGeometry& geometry, const std::array<model::Material, 2>& materials,
                const model::OperatingPoint& operating, Spur6Options options);

  [[nodiscard]] Spur6Result solve() const;
  [[nodiscard]] const Spur6Parameters& parameters() const { return p_; }
  /// The mesh excitation: pairs in contact, their stiffness, the break times.
  [[nodiscard]] const SpurMesh& mesh_excitation() const { return mesh_; }
  /// Size of the state: 6 coordinates, 6 rates, 3 work accumulators (damping, friction, stiffness).
  [[nodiscard]] std::size_t state_size() const override { return 15; }
  /// The contact functions of docs/dynamics-model.md, "Contact loss": δ, δ + b, δ + τδ̇,
  /// δ + b + τδ̇ (τ = c_m/k̄); none without backlash.
  [[nodiscard]] int contact_function_count() const override { return options_.backlash ? 4 : 0; }
  void contact_functions(const double* y, double* g) const override;
  /// dy/dt of the page's equations for the pair set of the interval holding t_mid.
  void derivative(double t, double t_mid, const double* y, double* dydt) const override;
  [[nodiscard]] double energy(double t, double t_mid, const double* y) const override;
  /// Where the right-hand side jumps: pairs enter, leave, pass the pitch point (or a crack's mouth).
  [[nodiscard]] std::vector<double> break_times(double t0, double t1) const override;
  /// The static state of docs/dynamics-model.md.
  [[nodiscard]] std::vector<double> static_state() const;
  /// Natural frequencies [Hz] of the linear system on the mean mesh stiffness without
  /// friction (Eigen's generalized self-adjoint eigensolver), the rigid-body mode left out.
  [[nodiscard]] std::vector<double> natural_frequencies() const;

 private:
  struct MeshState {
    double force = 0.0, friction = 0.0, moment1 = 0.0, moment2 = 0.0, delta = 0.0, delta_rate = 0.0;
    double stiffness = 0.0, stiffness_rate = 0.0, damping = 0.0;  ///< Σk_j, Σdk_j/dt, Σc_j
    double penetration = 0.0;      ///< p: δ (linear mesh), or the overlap of the flanks in contact
    double mesh_dissipation = 0.0; ///< power of the mesh damping, (F_m − Σk_j·p)·δ̇
    bool back = false;             ///< on the back flanks
  };
  [[nodiscard]] MeshState mesh(double t, double t_mid, const double* y) const;

  const geometry::GearPairGeometry& geometry_;
  Spur6Options options_;
  Spur6Parameters p_;
  PairFriction friction_;
  SpurMesh mesh_;
};

}  // namespace gearbench::dynamics
