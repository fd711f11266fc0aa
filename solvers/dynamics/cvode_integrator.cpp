#include "cvode_integrator.h"

#include <cvode/cvode.h>
#include <fmt/format.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "model/errors.h"

namespace gearbench::dynamics {

/// What CVODE calls: the right-hand side, plus where its exception waits for the caller.
struct RhsHandle {
  const CvodeIntegrator::Rhs* rhs;
  const CvodeIntegrator::Roots* roots;
  std::exception_ptr error;
  std::string message;  ///< CVODE's own account of its last error (it is not printed)
};

struct CvodeIntegrator::Handles {
  std::unique_ptr<RhsHandle> rhs;
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver solver = nullptr;
  SUNNonlinearSolver fixed_point = nullptr;
  void* cvode = nullptr;
};

namespace {

void check_flag(int flag, const char* call, const std::string& detail = {}) {
  if (flag >= 0) return;
  std::string message = fmt::format("SUNDIALS {} failed: {} ({})", call, CVodeGetReturnFlagName(flag), flag);
  if (!detail.empty()) message += ": " + detail;
  if (flag == CV_TOO_MUCH_WORK || flag == CV_TOO_MUCH_ACC || flag == CV_ERR_FAILURE ||
      flag == CV_CONV_FAILURE)
    throw ConvergenceError(message);
  throw std::runtime_error(message);
}

template <class T>
T* check_pointer(T* pointer, const char* call) {
  if (pointer == nullptr) throw std::runtime_error(fmt::format("SUNDIALS {} returned no object", call));
  return pointer;
}

int rhs_trampoline(realtype t, N_Vector y, N_Vector ydot, void* user_data) {
  auto& handle = *static_cast<RhsHandle*>(user_data);
  try {
    (*handle.rhs)(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
    return 0;
  } catch (...) {
    handle.error = std::current_exception();  // rethrown by advance() after CVode returns
    return -1;                                // unrecoverable: CVODE stops with CV_RHSFUNC_FAIL
  }
}

int root_trampoline(realtype t, N_Vector y, realtype* g, void* user_data) {
  auto& handle = *static_cast<RhsHandle*>(user_data);
  try {
    (*handle.roots)(t, N_VGetArrayPointer(y), g);
    return 0;
  } catch (...) {
    handle.error = std::current_exception();
    return -1;  // CVODE stops with CV_RTFUNC_FAIL
  }
}

/// CVODE reports errors here instead of on stderr; check_flag puts the text into the error.
void keep_error_message(int, const char* module, const char* function, char* message, void* data) {
  static_cast<RhsHandle*>(data)->message = fmt::format("{} in {}: {}", module, function, message);
}

}  // namespace

CvodeIntegrator::CvodeIntegrator(std::size_t size, Rhs rhs, const CvodeOptions& options)
    : handles_(new Handles), rhs_(std::move(rhs)), y_(size, 0.0) {
  try {
    check_flag(SUNContext_Create(nullptr, &handles_->context), "SUNContext_Create");
    const auto n = static_cast<sunindextype>(size);
    handles_->y = check_pointer(N_VNew_Serial(n, handles_->context), "N_VNew_Serial");
    handles_->cvode = check_pointer(
        CVodeCreate(options.method == CvodeMethod::bdf ? CV_BDF : CV_ADAMS, handles_->context), "CVodeCreate");
    check_flag(CVodeInit(handles_->cvode, rhs_trampoline, 0.0, handles_->y), "CVodeInit");
    check_flag(CVodeSStolerances(handles_->cvode, options.relative_tolerance, options.absolute_tolerance),
               "CVodeSStolerances");
    handles_->rhs = std::make_unique<RhsHandle>(RhsHandle{&rhs_, &roots_, nullptr, {}});
    check_flag(CVodeSetUserData(handles_->cvode, handles_->rhs.get()), "CVodeSetUserData");
    check_flag(CVodeSetErrHandlerFn(handles_->cvode, keep_error_message, handles_->rhs.get()), "CVodeSetErrHandlerFn");
    check_flag(CVodeSetMaxNumSteps(handles_->cvode, options.max_steps), "CVodeSetMaxNumSteps");
    if (options.method == CvodeMethod::adams) {
      // Non-stiff: Adams–Moulton with fixed-point iteration, no Jacobian and no linear solves.
      handles_->fixed_point = check_pointer(SUNNonlinSol_FixedPoint(handles_->y, 0, handles_->context),
                                            "SUNNonlinSol_FixedPoint");
      check_flag(CVodeSetNonlinearSolver(handles_->cvode, handles_->fixed_point), "CVodeSetNonlinearSolver");
    } else {
      // Stiff: BDF with Newton iteration on a dense difference-quotient Jacobian.
      handles_->matrix = check_pointer(SUNDenseMatrix(n, n, handles_->context), "SUNDenseMatrix");
      handles_->solver = check_pointer(SUNLinSol_Dense(handles_->y, handles_->matrix, handles_->context), "SUNLinSol_Dense");
      check_flag(CVodeSetLinearSolver(handles_->cvode, handles_->solver, handles_->matrix), "CVodeSetLinearSolver");
    }
  } catch (...) {
    release();
    throw;
  }
}

CvodeIntegrator::~CvodeIntegrator() { release(); }

void CvodeIntegrator::release() {
  if (!handles_) return;
  if (handles_->cvode) CVodeFree(&handles_->cvode);
  if (handles_->solver) SUNLinSolFree(handles_->solver);
  if (handles_->fixed_point) SUNNonlinSolFree(handles_->fixed_point);
  if (handles_->matrix) SUNMatDestroy(handles_->matrix);
  if (handles_->y) N_VDestroy(handles_->y);
  if (handles_->context) SUNContext_Free(&handles_->context);
  delete handles_;
  handles_ = nullptr;
}

void CvodeIntegrator::reset(double t0, const std::vector<double>& y0) {
  if (y0.size() != y_.size()) throw std::invalid_argument("CvodeIntegrator::reset: wrong state size");
  y_ = y0;
  t_ = t0;
  at_root_ = false;
  std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(handles_->y));
  // A restart at a discontinuity keeps the step size reached before it, instead of CVODE's
  // cautious first step: the solution is as smooth on both sides.
  realtype last_step = 0.0;
  if (initialised_) check_flag(CVodeGetLastStep(handles_->cvode, &last_step), "CVodeGetLastStep");
  check_flag(CVodeReInit(handles_->cvode, t0, handles_->y), "CVodeReInit");
  if (last_step > 0.0) check_flag(CVodeSetInitStep(handles_->cvode, last_step), "CVodeSetInitStep");
  initialised_ = true;
}

void CvodeIntegrator::set_roots(int count, Roots roots) {
  roots_ = std::move(roots);
  check_flag(CVodeRootInit(handles_->cvode, count, root_trampoline), "CVodeRootInit");
}

const std::vector<double>& CvodeIntegrator::advance(double t_out, double stop) {
  if (!initialised_) throw std::logic_error("CvodeIntegrator::advance before reset");
  check_flag(CVodeSetStopTime(handles_->cvode, stop), "CVodeSetStopTime");
  realtype t = 0.0;
  const int flag = CVode(handles_->cvode, t_out, handles_->y, &t, CV_NORMAL);
  if (handles_->rhs->error) std::rethrow_exception(std::exchange(handles_->rhs->error, nullptr));
  check_flag(flag, "CVode", handles_->rhs->message);
  t_ = t;
  at_root_ = flag == CV_ROOT_RETURN;
  const double* data = N_VGetArrayPointer(handles_->y);
  std::copy(data, data + y_.size(), y_.begin());
  return y_;
}

const std::vector<double>& CvodeIntegrator::advance_across_roots(double t_out, double stop, double tolerance,
                                                                 RootCrossing& work) {
  advance(t_out, stop);
  while (at_root_) {
    ++work.events;
    work.steps += steps();
    work.rhs_evaluations += rhs_evaluations();
    reset(t_, y_);
    if (t_ > t_out - tolerance) break;  // a root on the target: y is y(t_out)
    advance(t_out, stop);
  }
  return y_;
}

long CvodeIntegrator::steps() const {
  long n = 0;
  check_flag(CVodeGetNumSteps(handles_->cvode, &n), "CVodeGetNumSteps");
  return n;
}

long CvodeIntegrator::rhs_evaluations() const {
  long n = 0;
  check_flag(CVodeGetNumRhsEvals(handles_->cvode, &n), "CVodeGetNumRhsEvals");
  return n;
}

}  // namespace gearbench::dynamics
