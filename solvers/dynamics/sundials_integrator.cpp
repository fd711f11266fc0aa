// The integrators of integrator.h on SUNDIALS 6.4.1. CVODE and ARKODE's ERKStep have the
// same shape of call for everything the march needs (restart, stop time, evolve, root
// functions, counters), so one class drives either through a table of those calls.
#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <fmt/format.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>

#include "integrator.h"
#include "serial_kernels.h"
#include "model/errors.h"

namespace gearbench::dynamics {

namespace {

/// The calls of one SUNDIALS package, all of the same shape in CVODE and ERKStep.
struct Package {
  const char* name;
  int (*restart)(void*, realtype t, N_Vector y);  // CVodeReInit / ERKStepReset
  int (*set_stop_time)(void*, realtype);
  int (*evolve)(void*, realtype t_out, N_Vector y, realtype* t, int task);
  int (*last_step)(void*, realtype*);
  int (*set_init_step)(void*, realtype);
  int (*root_init)(void*, int, int (*)(realtype, N_Vector, realtype*, void*));
  int (*steps)(void*, long*);
  int (*rhs_evaluations)(void*, long*);
  int (*set_tolerances)(void*, realtype, realtype);
  int (*set_user_data)(void*, void*);
  int (*set_error_handler)(void*, void (*)(int, const char*, const char*, char*, void*), void*);
  int (*set_max_steps)(void*, long);
  char* (*flag_name)(long);
  void (*free)(void**);
  int root_return;
};

// CV_NORMAL = ARK_NORMAL = 1 and CV_ROOT_RETURN = ARK_ROOT_RETURN = 2; the failure flags
// -1..-4 (too much work, too much accuracy, error-test failure, convergence failure) too.
int cvode_rhs_evaluations(void* mem, long* n) { return CVodeGetNumRhsEvals(mem, n); }
constexpr Package cvode{"CVODE", CVodeReInit, CVodeSetStopTime, CVode, CVodeGetLastStep, CVodeSetInitStep,
                        CVodeRootInit, CVodeGetNumSteps, cvode_rhs_evaluations, CVodeSStolerances,
                        CVodeSetUserData, CVodeSetErrHandlerFn, CVodeSetMaxNumSteps, CVodeGetReturnFlagName,
                        CVodeFree, CV_ROOT_RETURN};
constexpr Package erkstep{"ERKStep", ERKStepReset, ERKStepSetStopTime, ERKStepEvolve, ERKStepGetLastStep,
                          ERKStepSetInitStep, ERKStepRootInit, ERKStepGetNumSteps, ERKStepGetNumRhsEvals,
                          ERKStepSStolerances, ERKStepSetUserData, ERKStepSetErrHandlerFn,
                          ERKStepSetMaxNumSteps, ERKStepGetReturnFlagName, ERKStepFree, ARK_ROOT_RETURN};

/// What SUNDIALS calls back: the right-hand side and root functions, plus where their
/// exception waits for the caller and the package's own account of its last error.
struct Callbacks {
  Integrator::Rhs rhs;
  Integrator::Roots roots;
  std::exception_ptr error;
  std::string message;
};

int rhs_trampoline(realtype t, N_Vector y, N_Vector ydot, void* data) {
  auto& c = *static_cast<Callbacks*>(data);
  try {
    c.rhs(t, NV_DATA_S(y), NV_DATA_S(ydot));  // serial vectors: the data without a call through the ops table
    return 0;
  } catch (...) {
    c.error = std::current_exception();  // rethrown by advance() once the package returns
    return -1;                           // unrecoverable: the package stops (RHSFUNC_FAIL)
  }
}

int root_trampoline(realtype t, N_Vector y, realtype* g, void* data) {
  auto& c = *static_cast<Callbacks*>(data);
  try {
    c.roots(t, NV_DATA_S(y), g);
    return 0;
  } catch (...) {
    c.error = std::current_exception();
    return -1;  // the package stops (RTFUNC_FAIL)
  }
}

/// The packages report errors here instead of on stderr; check() puts the text into the error.
void keep_error_message(int, const char* module, const char* function, char* message, void* data) {
  static_cast<Callbacks*>(data)->message = fmt::format("{} in {}: {}", module, function, message);
}

void check_context(int flag, const char* call) {
  if (flag < 0) throw std::runtime_error(fmt::format("SUNDIALS {} failed ({})", call, flag));
}

template <class T>
T* check_pointer(T* pointer, const char* call) {
  if (pointer == nullptr) throw std::runtime_error(fmt::format("SUNDIALS {} returned no object", call));
  return pointer;
}

class SundialsIntegrator final : public Integrator {
 public:
  SundialsIntegrator(std::size_t size, Rhs rhs, const IntegratorOptions& options);
  ~SundialsIntegrator() override { release(); }
  SundialsIntegrator(const SundialsIntegrator&) = delete;
  SundialsIntegrator& operator=(const SundialsIntegrator&) = delete;

  void reset(double t0, const std::vector<double>& y0) override;
  void set_roots(int count, Roots roots) override;
  const std::vector<double>& advance(double t_out, double stop) override;
  long steps() const override { return counted_steps_ + count(package_->steps, "GetNumSteps"); }
  long rhs_evaluations() const override { return counted_rhs_ + count(package_->rhs_evaluations, "GetNumRhsEvals"); }

 private:
  void create_cvode(const IntegratorOptions& options, sunindextype n);
  void create_erkstep(const IntegratorOptions& options);
  void check(int flag, const char* call) const;
  long count(int (*getter)(void*, long*), const char* call) const;
  void release();

  const Package* package_ = nullptr;
  Callbacks callbacks_;
  SUNContext context_ = nullptr;
  N_Vector y_vector_ = nullptr;
  SUNMatrix matrix_ = nullptr;
  SUNLinearSolver linear_solver_ = nullptr;
  SUNNonlinearSolver fixed_point_ = nullptr;
  void* memory_ = nullptr;
  bool started_ = false;
  long counted_steps_ = 0, counted_rhs_ = 0;  ///< work of the segments before the last restart
};

SundialsIntegrator::SundialsIntegrator(std::size_t size, Rhs rhs, const IntegratorOptions& options) {
  options.validate();
  y_.assign(size, 0.0);
  callbacks_.rhs = std::move(rhs);
  try {
    check_context(SUNContext_Create(nullptr, &context_), "SUNContext_Create");
    const auto n = static_cast<sunindextype>(size);
    y_vector_ = check_pointer(N_VNew_Serial(n, context_), "N_VNew_Serial");
    // Fused vector operations (one loop per stage combination instead of a chain of
    // N_VLinearSum calls), on compiled kernels: serial_kernels.h. The packages clone this
    // vector, its ops table with it.
    check_context(N_VEnableFusedOps_Serial(y_vector_, SUNTRUE), "N_VEnableFusedOps_Serial");
    install_serial_kernels(y_vector_);
    if (options.method == IntegratorMethod::bdf || options.method == IntegratorMethod::adams)
      create_cvode(options, n);
    else
      create_erkstep(options);
    check(package_->set_tolerances(memory_, options.relative_tolerance, options.absolute_tolerance), "SStolerances");
    check(package_->set_user_data(memory_, &callbacks_), "SetUserData");
    check(package_->set_error_handler(memory_, keep_error_message, &callbacks_), "SetErrHandlerFn");
    check(package_->set_max_steps(memory_, options.max_steps), "SetMaxNumSteps");
  } catch (...) {
    release();
    throw;
  }
}

void SundialsIntegrator::create_cvode(const IntegratorOptions& options, sunindextype n) {
  package_ = &cvode;
  const bool bdf = options.method == IntegratorMethod::bdf;
  memory_ = check_pointer(CVodeCreate(bdf ? CV_BDF : CV_ADAMS, context_), "CVodeCreate");
  check(CVodeInit(memory_, rhs_trampoline, 0.0, y_vector_), "Init");
  if (!bdf) {
    // Non-stiff: Adams–Moulton with fixed-point iteration, no Jacobian and no linear solves.
    fixed_point_ = check_pointer(SUNNonlinSol_FixedPoint(y_vector_, 0, context_), "SUNNonlinSol_FixedPoint");
    check(CVodeSetNonlinearSolver(memory_, fixed_point_), "SetNonlinearSolver");
    return;
  }
  // Stiff: BDF with Newton iteration on a dense difference-quotient Jacobian.
  matrix_ = check_pointer(SUNDenseMatrix(n, n, context_), "SUNDenseMatrix");
  linear_solver_ = check_pointer(SUNLinSol_Dense(y_vector_, matrix_, context_), "SUNLinSol_Dense");
  check(CVodeSetLinearSolver(memory_, linear_solver_, matrix_), "SetLinearSolver");
}

void SundialsIntegrator::create_erkstep(const IntegratorOptions& options) {
  package_ = &erkstep;
  memory_ = check_pointer(ERKStepCreate(rhs_trampoline, 0.0, y_vector_, context_), "ERKStepCreate");
  ARKODE_ERKTableID table = ARKODE_DORMAND_PRINCE_7_4_5;
  if (options.method == IntegratorMethod::bogacki_shampine) table = ARKODE_BOGACKI_SHAMPINE_4_2_3;
  if (options.method == IntegratorMethod::verner) table = ARKODE_VERNER_8_5_6;
  if (options.method == IntegratorMethod::fehlberg) table = ARKODE_FEHLBERG_13_7_8;
  check(ERKStepSetTableNum(memory_, table), "SetTableNum");
}

void SundialsIntegrator::release() {
  if (memory_) package_->free(&memory_);
  if (linear_solver_) SUNLinSolFree(linear_solver_);
  if (fixed_point_) SUNNonlinSolFree(fixed_point_);
  if (matrix_) SUNMatDestroy(matrix_);
  if (y_vector_) N_VDestroy(y_vector_);
  if (context_) SUNContext_Free(&context_);
}

void SundialsIntegrator::check(int flag, const char* call) const {
  if (flag >= 0) return;
  char* name = package_->flag_name(flag);
  std::string message = fmt::format("SUNDIALS {} {} failed: {} ({})", package_->name, call, name ? name : "?", flag);
  std::free(name);  // the packages allocate the name
  if (!callbacks_.message.empty()) message += ": " + callbacks_.message;
  // -1..-4: too much work, too much accuracy asked, error-test or convergence failures.
  if (flag >= -4) throw ConvergenceError(message);
  throw std::runtime_error(message);
}

long SundialsIntegrator::count(int (*getter)(void*, long*), const char* call) const {
  long n = 0;
  check(getter(memory_, &n), call);
  return n;
}

void SundialsIntegrator::reset(double t0, const std::vector<double>& y0) {
  if (y0.size() != y_.size()) throw std::invalid_argument("Integrator::reset: wrong state size");
  y_ = y0;
  t_ = t0;
  at_root_ = false;
  std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(y_vector_));
  // A restart at a discontinuity keeps the step size reached before it instead of a
  // cautious first step: the solution is as smooth on both sides.
  realtype last_step = 0.0;
  if (started_) check(package_->last_step(memory_, &last_step), "GetLastStep");
  // CVodeReInit zeroes the counters, ERKStepReset keeps them: count what the restart drops.
  const long steps_before = steps(), rhs_before = rhs_evaluations();
  check(package_->restart(memory_, t0, y_vector_), "restart");
  counted_steps_ += steps_before - steps();
  counted_rhs_ += rhs_before - rhs_evaluations();
  if (last_step > 0.0) check(package_->set_init_step(memory_, last_step), "SetInitStep");
  started_ = true;
}

void SundialsIntegrator::set_roots(int count, Roots roots) {
  callbacks_.roots = std::move(roots);
  check(package_->root_init(memory_, count, root_trampoline), "RootInit");
}

const std::vector<double>& SundialsIntegrator::advance(double t_out, double stop) {
  if (!started_) throw std::logic_error("Integrator::advance before reset");
  check(package_->set_stop_time(memory_, stop), "SetStopTime");
  realtype t = 0.0;
  const int flag = package_->evolve(memory_, t_out, y_vector_, &t, 1 /* CV_NORMAL = ARK_NORMAL */);
  if (callbacks_.error) std::rethrow_exception(std::exchange(callbacks_.error, nullptr));
  check(flag, "solve");
  t_ = t;
  at_root_ = flag == package_->root_return;
  const double* data = N_VGetArrayPointer(y_vector_);
  std::copy(data, data + y_.size(), y_.begin());
  return y_;
}

}  // namespace

std::unique_ptr<Integrator> make_sundials_integrator(std::size_t size, Integrator::Rhs rhs,
                                                     const IntegratorOptions& options) {
  return std::make_unique<SundialsIntegrator>(size, std::move(rhs), options);
}

}  // namespace gearbench::dynamics
