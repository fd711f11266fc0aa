#pragma once
// A small RAII wrapper of SUNDIALS 6.4 CVODE (serial N_Vector; Adams with fixed-point
// iteration, or BDF with Newton on a dense direct linear solver), with optional root
// functions (CVodeRootInit) at which advance() stops: every SUNDIALS return code is turned into a ConvergenceError or std::runtime_error with
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
  /// The root functions g_i(t, y), written into g.
  using Roots = std::function<void(double t, const double* y, double* g)>;

  CvodeIntegrator(std::size_t size, Rhs rhs, const CvodeOptions& options);
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  /// Starts (or restarts, after a discontinuity of f) at t0 from y0.
  void reset(double t0, const std::vector<double>& y0);
  /// From now on advance() stops where one of the `count` functions g_i changes sign.
  void set_roots(int count, Roots roots);
  /// Integrates to t_out exactly, never past `stop` (a discontinuity of f), or to the first
  /// root of the root functions before t_out; returns y there (at time()).
  const std::vector<double>& advance(double t_out, double stop);
  /// Roots passed and work done by the restarted segments of advance_across_roots().
  struct RootCrossing {
    long events = 0, steps = 0, rhs_evaluations = 0;
  };
  /// Integrates to t_out exactly (never past `stop`), restarting at every root on the way,
  /// where the right-hand side kinks or jumps (contact loss); a root within `tolerance` of
  /// t_out ends it there. Returns y(t_out).
  const std::vector<double>& advance_across_roots(double t_out, double stop, double tolerance, RootCrossing& work);
  /// The time of the state advance() returned last.
  [[nodiscard]] double time() const { return t_; }
  /// Whether advance() stopped at a root.
  [[nodiscard]] bool at_root() const { return at_root_; }
  [[nodiscard]] long steps() const;
  [[nodiscard]] long rhs_evaluations() const;

 private:
  struct Handles;
  void release();
  Handles* handles_;
  Rhs rhs_;
  Roots roots_;
  std::vector<double> y_;
  double t_ = 0.0;
  bool at_root_ = false;
  bool initialised_ = false;
};

}  // namespace gearbench::dynamics
