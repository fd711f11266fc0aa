#pragma once
// A small RAII wrapper of SUNDIALS 6.4 CVODE (serial N_Vector; Adams with fixed-point
// iteration, or BDF with Newton on a dense direct linear solver):
// every SUNDIALS return code is turned into a ConvergenceError or std::runtime_error with
// the flag's name, at once.
#include <functional>
#include <vector>

namespace gearbench::dynamics {

enum class CvodeMethod { bdf, adams };

struct CvodeOptions {
  CvodeMethod method = CvodeMethod::adams;  ///< non-stiff oscillator: Adams takes fewer steps
  double relative_tolerance = 1e-8;
  double absolute_tolerance = 1e-12;
  long max_steps = 100000;        ///< between two output times
};

class CvodeIntegrator {
 public:
  /// dy/dt = f(t, y), written into dydt.
  using Rhs = std::function<void(double t, const double* y, double* dydt)>;

  CvodeIntegrator(std::size_t size, Rhs rhs, const CvodeOptions& options);
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  /// Starts (or restarts, after a discontinuity of f) at t0 from y0.
  void reset(double t0, const std::vector<double>& y0);
  /// Integrates to t_out exactly, never past `stop` (a discontinuity of f); returns y(t_out).
  const std::vector<double>& advance(double t_out, double stop);
  [[nodiscard]] long steps() const;
  [[nodiscard]] long rhs_evaluations() const;

 private:
  struct Handles;
  void release();
  Handles* handles_;
  Rhs rhs_;
  std::vector<double> y_;
  bool initialised_ = false;
};

}  // namespace gearbench::dynamics
