#pragma once
// Natural cubic spline through (x_i, y_i) by GSL (gsl_interp_cspline), owning its state.
#include <gsl/gsl_spline.h>

#include <memory>
#include <vector>

namespace gearbench::stiffness {

class CubicSpline {
 public:
  /// GSL's interval cache for one caller moving along x (a contact travelling along the path
  /// of contact): the spline's own cache misses, and GSL bisects, whenever calls alternate
  /// between distant points (the pairs in contact, one right-hand side after another).
  class Cursor {
   public:
    Cursor();

   private:
    friend class CubicSpline;
    std::unique_ptr<gsl_interp_accel, decltype(&gsl_interp_accel_free)> accel_{nullptr, &gsl_interp_accel_free};
  };

  CubicSpline(std::vector<double> x, std::vector<double> y);
  [[nodiscard]] double operator()(double x) const { return value(x, accel_.get()); }
  [[nodiscard]] double operator()(double x, Cursor& cursor) const { return value(x, cursor.accel_.get()); }
  /// dy/dx of the same cubic at x.
  [[nodiscard]] double derivative(double x) const { return slope(x, accel_.get()); }
  [[nodiscard]] double derivative(double x, Cursor& cursor) const { return slope(x, cursor.accel_.get()); }

 private:
  [[nodiscard]] double value(double x, gsl_interp_accel* accel) const;
  [[nodiscard]] double slope(double x, gsl_interp_accel* accel) const;

  std::vector<double> x_, y_;
  std::unique_ptr<gsl_spline, decltype(&gsl_spline_free)> spline_{nullptr, &gsl_spline_free};
  std::unique_ptr<gsl_interp_accel, decltype(&gsl_interp_accel_free)> accel_{nullptr, &gsl_interp_accel_free};
};

}  // namespace gearbench::stiffness
