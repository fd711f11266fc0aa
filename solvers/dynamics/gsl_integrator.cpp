// The rk8pd integrator of integrator.h on GSL 2.7 odeiv2: the Prince–Dormand 8(9) stepper
// under the standard step control (D_i = atol + rtol·|y_i|, max norm), driven by
// gsl_odeiv2_evolve_apply. docs/research/gsl-odeiv2/NOTE.md has the measurement that made
// it the default.
//
// - Output and stop times: evolve_apply steps onto its end time exactly, so an output time
//   is a step end. A step shortened to land on one does not shorten the next: the step size
//   from before it is kept (unless a step was rejected on the way).
// - Restarts: gsl_odeiv2_evolve_reset and gsl_odeiv2_step_reset, keeping the step size.
// - Roots: GSL has none. After every accepted step the root functions are compared with
//   their values at the step start; on a sign change the earliest crossing is located by
//   re-stepping from the step start with a shorter single step (gsl_odeiv2_step_apply, no
//   larger than the accepted one, so no less accurate), by regula falsi (Illinois, with a
//   bisection fallback) on the function crossing first, to CVODE's root tolerance
//   100·ε·(|t| + |h|). advance() returns the state just past the root, where the function
//   has its new sign, so the restart there does not find the same root again.
// - Every GSL status goes through model/gsl_status.h; a step size underflow is a
//   ConvergenceError, as SUNDIALS' failures are; so is a run that cannot keep its state finite
//   (a step giving a non-finite state is retried shorter); an exception of the right-hand side is
//   rethrown once GSL has returned.
#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <utility>

#include "integrator.h"
#include "model/errors.h"
#include "model/gsl_status.h"

namespace gearbench::dynamics {

namespace {

template <class T>
T* check_pointer(T* pointer, const char* call) {
  if (pointer == nullptr) throw std::runtime_error(fmt::format("GSL {} returned no object", call));
  return pointer;
}

/// Whether g_i changed sign from a to b (a root of g_i in between, or at b).
bool crossed(double a, double b) { return a != 0.0 && (b == 0.0 || (a < 0.0) != (b < 0.0)); }

class GslIntegrator final : public Integrator {
 public:
  GslIntegrator(std::size_t size, Rhs rhs, const IntegratorOptions& options);
  ~GslIntegrator() override { release(); }
  GslIntegrator(const GslIntegrator&) = delete;
  GslIntegrator& operator=(const GslIntegrator&) = delete;

  void reset(double t0, const std::vector<double>& y0) override;
  void set_roots(int count, Roots roots) override;
  const std::vector<double>& advance(double t_out, double stop) override;
  long steps() const override { return steps_; }
  long rhs_evaluations() const override { return rhs_evaluations_; }

 private:
  static int function(double t, const double y[], double dydt[], void* data);
  void rethrow();
  /// Locates the earliest root over the accepted step from (t0, y_start_) to (t_, y_).
  void locate_root(double t0);
  /// y_try_ = one rk8pd step of length x from (t0, y_start_).
  void step_from_start(double t0, double x);
  void release();

  Rhs rhs_;
  Roots roots_;
  int root_count_ = 0;
  std::exception_ptr error_;
  gsl_odeiv2_system system_{};
  gsl_odeiv2_step* step_ = nullptr;
  gsl_odeiv2_control* control_ = nullptr;
  gsl_odeiv2_evolve* evolve_ = nullptr;
  double h_ = 0.0;  ///< the next step size; 0 before the first
  long max_steps_ = 0;
  bool started_ = false;
  long steps_ = 0, rhs_evaluations_ = 0;
  std::vector<double> y_start_, dydt_start_, y_try_, y_error_, g_, g_try_, g_lo_, g_hi_;
};

GslIntegrator::GslIntegrator(std::size_t size, Rhs rhs, const IntegratorOptions& options)
    : rhs_(std::move(rhs)), max_steps_(options.max_steps) {
  options.validate();
  model::gsl_use_status_codes();
  y_.assign(size, 0.0);
  y_start_ = dydt_start_ = y_try_ = y_error_ = y_;
  system_ = gsl_odeiv2_system{function, nullptr, size, this};
  try {
    step_ = check_pointer(gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, size), "gsl_odeiv2_step_alloc");
    control_ = check_pointer(
        gsl_odeiv2_control_standard_new(options.absolute_tolerance, options.relative_tolerance, 1.0, 0.0),
        "gsl_odeiv2_control_standard_new");
    evolve_ = check_pointer(gsl_odeiv2_evolve_alloc(size), "gsl_odeiv2_evolve_alloc");
  } catch (...) {
    release();
    throw;
  }
}

void GslIntegrator::release() {
  if (evolve_) gsl_odeiv2_evolve_free(evolve_);
  if (control_) gsl_odeiv2_control_free(control_);
  if (step_) gsl_odeiv2_step_free(step_);
}

int GslIntegrator::function(double t, const double y[], double dydt[], void* data) {
  auto& self = *static_cast<GslIntegrator*>(data);
  ++self.rhs_evaluations_;
  try {
    self.rhs_(t, y, dydt);
    return GSL_SUCCESS;
  } catch (...) {
    self.error_ = std::current_exception();  // rethrown once GSL returns
    return GSL_EBADFUNC;                     // GSL stops the step and returns this status
  }
}

void GslIntegrator::rethrow() {
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

void GslIntegrator::reset(double t0, const std::vector<double>& y0) {
  if (y0.size() != y_.size()) throw std::invalid_argument("Integrator::reset: wrong state size");
  y_ = y0;
  t_ = t0;
  at_root_ = false;
  model::gsl_check(gsl_odeiv2_evolve_reset(evolve_), "gsl_odeiv2_evolve_reset");
  model::gsl_check(gsl_odeiv2_step_reset(step_), "gsl_odeiv2_step_reset");
  if (root_count_ > 0) roots_(t_, y_.data(), g_.data());
  started_ = true;
}

void GslIntegrator::set_roots(int count, Roots roots) {
  if (count < 0) throw std::invalid_argument("Integrator::set_roots: negative count");
  roots_ = std::move(roots);
  root_count_ = count;
  g_.assign(static_cast<std::size_t>(count), 0.0);
  g_try_ = g_lo_ = g_hi_ = g_;
  if (started_ && count > 0) roots_(t_, y_.data(), g_.data());
}

const std::vector<double>& GslIntegrator::advance(double t_out, double stop) {
  if (!started_) throw std::logic_error("Integrator::advance before reset");
  const double target = std::min(t_out, stop);
  at_root_ = false;
  if (h_ <= 0.0) h_ = 1e-2 * (target - t_);  // the first step; the control corrects it
  for (long taken = 0; t_ < target; ++taken) {
    if (taken >= max_steps_)
      throw ConvergenceError(fmt::format("GSL rk8pd: more than {} steps from t = {} towards t = {} (integrator.max_steps)",
                                         max_steps_, t_, target));
    const double t0 = t_, h_before = h_;
    const std::size_t failed_before = evolve_->failed_steps;
    y_start_ = y_;
    const int status = gsl_odeiv2_evolve_apply(evolve_, control_, step_, &system_, &t_, target, &h_, y_.data());
    rethrow();
    if (status == GSL_FAILURE)  // GSL's step size fell below the rounding of t
      throw ConvergenceError(fmt::format("GSL rk8pd: step size underflow at t = {} (rtol/atol too tight?)", t0));
    model::gsl_check(status, "gsl_odeiv2_evolve_apply");
    ++steps_;
    if (!std::all_of(y_.begin(), y_.end(), [](double v) { return std::isfinite(v); })) {
      // The standard control accepts a step whose error estimate is not a number: reject it
      // here and retry a tenth as long (until max_steps, which ends the run as a ConvergenceError).
      h_ = 0.1 * (t_ - t0);
      t_ = t0;
      y_ = y_start_;
      model::gsl_check(gsl_odeiv2_evolve_reset(evolve_), "gsl_odeiv2_evolve_reset");
      model::gsl_check(gsl_odeiv2_step_reset(step_), "gsl_odeiv2_step_reset");
      continue;
    }
    // A step cut short to land on the target says nothing about the step the solution allows.
    if (t_ == target && evolve_->failed_steps == failed_before) h_ = std::max(h_, h_before);
    if (root_count_ == 0) continue;
    roots_(t_, y_.data(), g_try_.data());
    bool any = false;
    for (int i = 0; i < root_count_; ++i) any = any || crossed(g_[i], g_try_[i]);
    if (!any) {
      std::swap(g_, g_try_);
      continue;
    }
    locate_root(t0);
    return y_;
  }
  return y_;
}

void GslIntegrator::step_from_start(double t0, double x) {
  y_try_ = y_start_;
  const int status = gsl_odeiv2_step_apply(step_, t0, x, y_try_.data(), y_error_.data(), dydt_start_.data(), nullptr,
                                           &system_);
  rethrow();
  model::gsl_check(status, "gsl_odeiv2_step_apply");
}

void GslIntegrator::locate_root(double t0) {
  // dy/dt at the step start, shared by every trial step from it.
  const int status = function(t0, y_start_.data(), dydt_start_.data(), this);
  rethrow();
  model::gsl_check(status, "right-hand side");
  double lo = 0.0, hi = t_ - t0;
  g_lo_ = g_;
  g_hi_ = g_try_;
  std::vector<double> y_hi = y_;
  const double tolerance = 100.0 * DBL_EPSILON * (std::abs(t_) + hi);
  int side = 0, same_side = 0;  // which end moved last (−1 lo, +1 hi) and how often running
  for (int iteration = 0; iteration < 200 && hi - lo > tolerance; ++iteration) {
    // The crossing of the function that crosses first, by the secant through the bracket.
    double x = hi;
    for (int i = 0; i < root_count_; ++i) {
      if (!crossed(g_lo_[i], g_hi_[i])) continue;
      const double denominator = g_lo_[i] - g_hi_[i];
      const double xi = denominator != 0.0 ? lo + (hi - lo) * g_lo_[i] / denominator : hi;
      x = std::min(x, xi);
    }
    // Illinois-like safeguard: an end that has not moved for two steps is approached by halves.
    if (same_side >= 2 || !(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const double margin = 0.5 * tolerance;
    x = std::clamp(x, lo + margin, hi - margin);
    step_from_start(t0, x);
    roots_(t0 + x, y_try_.data(), g_try_.data());
    bool any = false;
    for (int i = 0; i < root_count_; ++i) any = any || crossed(g_lo_[i], g_try_[i]);
    const int moved = any ? +1 : -1;
    same_side = moved == side ? same_side + 1 : 1;
    side = moved;
    if (any) {
      hi = x;
      g_hi_ = g_try_;
      y_hi = y_try_;
    } else {
      lo = x;
      g_lo_ = g_try_;
    }
  }
  t_ = t0 + hi;
  y_ = std::move(y_hi);
  g_ = g_hi_;
  at_root_ = true;
}

}  // namespace

std::unique_ptr<Integrator> make_gsl_integrator(std::size_t size, Integrator::Rhs rhs, const IntegratorOptions& options) {
  return std::make_unique<GslIntegrator>(size, std::move(rhs), options);
}

}  // namespace gearbench::dynamics
