#pragma once
// Natural cubic spline through (x_i, y_i) by GSL (gsl_interp_cspline), owning its state.
#include <gsl/gsl_spline.h>

#include <memory>
#include <vector>

namespace gearbench::stiffness {

class CubicSpline {
 public:
  CubicSpline(std::vector<double> x, std::vector<double> y);
  [[nodiscard]] double operator()(double x) const;
  /// dy/dx of the same cubic at x.
  [[nodiscard]] double derivative(double x) const;

 private:
  std::vector<double> x_, y_;
  std::unique_ptr<gsl_spline, decltype(&gsl_spline_free)> spline_{nullptr, &gsl_spline_free};
  std::unique_ptr<gsl_interp_accel, decltype(&gsl_interp_accel_free)> accel_{nullptr, &gsl_interp_accel_free};
};

}  // namespace gearbench::stiffness
