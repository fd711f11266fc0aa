#include "cubic_spline.h"

#include <stdexcept>

#include "model/gsl_status.h"

namespace gearbench::stiffness {

CubicSpline::CubicSpline(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)) {
  model::gsl_use_status_codes();
  spline_.reset(gsl_spline_alloc(gsl_interp_cspline, x_.size()));
  accel_.reset(gsl_interp_accel_alloc());
  if (!spline_ || !accel_) throw std::runtime_error("GSL spline allocation failed");
  model::gsl_check(gsl_spline_init(spline_.get(), x_.data(), y_.data(), x_.size()), "spline");
}

CubicSpline::Cursor::Cursor() : accel_(gsl_interp_accel_alloc(), &gsl_interp_accel_free) {
  if (!accel_) throw std::runtime_error("GSL interpolation accelerator allocation failed");
}

double CubicSpline::value(double x, gsl_interp_accel* accel) const {
  double y = 0.0;
  // The accelerator caches the last interval; evaluation is read-only otherwise.
  model::gsl_check(gsl_spline_eval_e(spline_.get(), x, accel, &y), "spline evaluation");
  return y;
}

double CubicSpline::slope(double x, gsl_interp_accel* accel) const {
  double dy = 0.0;
  model::gsl_check(gsl_spline_eval_deriv_e(spline_.get(), x, accel, &dy), "spline derivative");
  return dy;
}

}  // namespace gearbench::stiffness
