#pragma once
// The time integrators of the dynamics models, behind one interface: GSL 2.7 odeiv2's
// rk8pd (Prince–Dormand 8(9) with the standard step control, the default) and SUNDIALS 6.4 CVODE
// (BDF with Newton on a dense matrix; Adams–Moulton with fixed-point iteration) and ARKODE
// ERKStep (explicit Runge–Kutta pairs with an embedded error estimate). The choice is a
// measured one: docs/dynamics-model.md, "Integrators: work–precision", has the study.
//
// Every integrator stops exactly at a given time (CVodeSetStopTime / ERKStepSetStopTime;
// GSL's evolve steps onto its end time),
// restarts after a discontinuity of the right-hand side keeping its last step size, and
// optionally stops at the roots of root functions (CVodeRootInit / ERKStepRootInit; for GSL,
// sign changes over an accepted step located by re-stepping from its start). Every
// SUNDIALS and GSL return code is checked and turned into a ConvergenceError (too much work or
// accuracy, error-test or convergence failures) or std::runtime_error, with the flag's name.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "model/option_table.h"

namespace gearbench::dynamics {

enum class IntegratorMethod {
  rk8pd,             ///< GSL odeiv2 Prince–Dormand 8(9), 13 stages, standard step control
  bdf,               ///< CVODE BDF, Newton on a dense difference-quotient Jacobian
  adams,             ///< CVODE Adams–Moulton, fixed-point iteration (no Jacobian, no linear solves)
  bogacki_shampine,  ///< ARKODE ERK Bogacki–Shampine 3(2), 4 stages
  dormand_prince,    ///< ARKODE ERK Dormand–Prince 5(4), 7 stages (FSAL)
  verner,            ///< ARKODE ERK Verner 6(5), 8 stages
  fehlberg,          ///< ARKODE ERK Fehlberg 8(7), 13 stages
};

/// The method's key in a case file (`integrator.method`) and a line for the docs.
struct IntegratorMethodName {
  IntegratorMethod method;
  const char* key;
  const char* description;
  /// Offered in case files. Verner 6(5) and Fehlberg 8(7) are in the work–precision study
  /// only: ARKODE's error test fails 7 times running on both models at some tolerances, its
  /// estimate falling only as h there, while the right-hand side is smooth (docs, "Integrators").
  bool offered;
};
/// Every method of the work–precision study, in the order of the docs.
std::span<const IntegratorMethodName> integrator_methods();
[[nodiscard]] const char* integrator_key(IntegratorMethod method);

struct IntegratorOptions {
  /// GSL rk8pd at rtol 1e-7: the fastest offered method at the checks' accuracy, 1e-6 of
  /// the transmission error's peak-to-peak, in the work–precision study (docs,
  /// docs/research/gsl-odeiv2/NOTE.md).
  IntegratorMethod method = IntegratorMethod::rk8pd;
  double relative_tolerance = 1e-7;
  /// [m, rad, m/s, rad/s, J alike]: 1e-6·rtol, as the deflections are micrometres.
  double absolute_tolerance = 1e-13;
  int max_steps = 100000;  ///< between two output times

  /// The "integrator" section's keys: "method" (the offered ones), "rtol", "atol", "max_steps".
  static const model::OptionTable<IntegratorOptions>& table();
  void validate() const { table().validate(*this, "integrator."); }  ///< InputError naming the key
};

class Integrator {
 public:
  /// dy/dt = f(t, y), written into dydt.
  using Rhs = std::function<void(double t, const double* y, double* dydt)>;
  /// The root functions g_i(t, y), written into g.
  using Roots = std::function<void(double t, const double* y, double* g)>;

  virtual ~Integrator() = default;
  /// Starts (or restarts, after a discontinuity of f) at t0 from y0.
  virtual void reset(double t0, const std::vector<double>& y0) = 0;
  /// From now on advance() stops where one of the `count` functions g_i changes sign.
  virtual void set_roots(int count, Roots roots) = 0;
  /// Integrates to t_out exactly, never past `stop` (a discontinuity of f), or to the first
  /// root of the root functions before t_out; returns y there (at time()).
  virtual const std::vector<double>& advance(double t_out, double stop) = 0;
  /// Steps taken and right-hand-side evaluations since construction.
  [[nodiscard]] virtual long steps() const = 0;
  [[nodiscard]] virtual long rhs_evaluations() const = 0;

  /// Integrates to t_out exactly (never past `stop`), restarting at every root on the way,
  /// where the right-hand side kinks or jumps (contact loss); a root within `tolerance` of
  /// t_out ends it there. Returns y(t_out); counts the roots passed in `events`.
  const std::vector<double>& advance_across_roots(double t_out, double stop, double tolerance, long& events);
  /// The time of the state advance() returned last.
  [[nodiscard]] double time() const { return t_; }
  /// Whether advance() stopped at a root.
  [[nodiscard]] bool at_root() const { return at_root_; }

 protected:
  std::vector<double> y_;
  double t_ = 0.0;
  bool at_root_ = false;
};

/// The integrator of `options.method` for a state of `size` unknowns.
std::unique_ptr<Integrator> make_integrator(std::size_t size, Integrator::Rhs rhs, const IntegratorOptions& options);
/// The two families behind make_integrator: rk8pd (gsl_integrator.cpp) and the SUNDIALS methods.
std::unique_ptr<Integrator> make_gsl_integrator(std::size_t size, Integrator::Rhs rhs, const IntegratorOptions& options);
std::unique_ptr<Integrator> make_sundials_integrator(std::size_t size, Integrator::Rhs rhs,
                                                     const IntegratorOptions& options);

}  // namespace gearbench::dynamics
