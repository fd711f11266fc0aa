#pragma once
// The one time-stepping march of the dynamics models (docs/dynamics-model.md, "The march"):
// from the static state through the run-up into a recorded window sampled at a fixed rate,
// restarting the integrator at every break time of the model (a pair enters or leaves,
// friction reverses, an impact pulse starts or ends) and at every root of its contact
// functions (contact loss). The models (Spur6Dynamics, Herringbone12Dynamics) supply the
// equations through DynamicsModel; reference/ode/fixed_step.h has the same shape for the
// independent RK4 references.
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "integrator.h"

namespace gearbench::dynamics {

/// What the march needs of a model. `t_mid` is the midpoint of the interval between two
/// break times that holds t: it fixes the pair set (and pulse) of the interval, so the
/// right-hand side is smooth on it.
class DynamicsModel {
 public:
  virtual ~DynamicsModel() = default;
  [[nodiscard]] virtual std::size_t state_size() const = 0;
  virtual void derivative(double t, double t_mid, const double* y, double* dydt) const = 0;
  /// The mechanical energy E (kinetic + strain) the energy balance compares.
  [[nodiscard]] virtual double energy(double t, double t_mid, const double* y) const = 0;
  /// Sorted times in (t0, t1) where the right-hand side jumps.
  [[nodiscard]] virtual std::vector<double> break_times(double t0, double t1) const = 0;
  /// Number of contact functions (0: contact is never lost).
  [[nodiscard]] virtual int contact_function_count() const = 0;
  /// The contact functions at y, written into g: the force kinks or jumps at their roots.
  virtual void contact_functions(const double* y, double* g) const = 0;
};

struct MarchPlan {
  double t_record = 0.0;      ///< start of the recorded window [s]
  double t_end = 0.0;         ///< end of the run [s]
  double sample_interval = 0.0;
  std::size_t samples = 0;    ///< recorded at t_record + i·sample_interval
  double longest_call = 0.0;  ///< longest stretch per integrator call (its step limit is per call) [s]
};

/// What the march hands back besides the samples: the states at the ends of the window for
/// the energy balance, and the work done.
struct MarchOutcome {
  std::vector<double> y_record, y_end;  ///< states at t_record and t_end
  double energy_record = 0.0, energy_end = 0.0;
  double t_mid_end = 0.0;               ///< the last interval's midpoint
  /// ½Σ Δk·p² of the break times inside the window: the stiffness jumps' work.
  double jumps = 0.0;
  long steps = 0, rhs_evaluations = 0, contact_events = 0;
};

/// Called at every sample time with the interval's midpoint and the state there.
using Recorder = std::function<void(double t, double t_mid, const std::vector<double>& y)>;

/// Marches `model` from y0 at t = 0 to plan.t_end with the integrator of `options`.
MarchOutcome march(const DynamicsModel& model, const IntegratorOptions& options, const MarchPlan& plan,
                   std::vector<double> y0, const Recorder& record);

/// max |v_i − v_{i−period}| over the last period, relative to the peak-to-peak of v: how
/// far the recorded response is from periodic steady state.
[[nodiscard]] double periodicity(std::span<const double> v, std::size_t period);

}  // namespace gearbench::dynamics
