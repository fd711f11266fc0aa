#include "cubic_spline.h"

#include <gsl/gsl_errno.h>
#include <stdexcept>
#include <string>

namespace gearbench::stiffness {

CubicSpline::CubicSpline(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)) {
  gsl_set_error_handler_off();
  spline_.reset(gsl_spline_alloc(gsl_interp_cspline, x_.size()));
  accel_.reset(gsl_interp_accel_alloc());
  if (!spline_ || !accel_) throw std::runtime_error("GSL spline allocation failed");
  if (const int status = gsl_spline_init(spline_.get(), x_.data(), y_.data(), x_.size()); status != GSL_SUCCESS)
    throw std::runtime_error(std::string("GSL spline: ") + gsl_strerror(status));
}

CubicSpline::Cursor::Cursor() : accel_(gsl_interp_accel_alloc(), &gsl_interp_accel_free) {
  if (!accel_) throw std::runtime_error("GSL interpolation accelerator allocation failed");
}

double CubicSpline::value(double x, gsl_interp_accel* accel) const {
  double y = 0.0;
  // The accelerator caches the last interval; evaluation is read-only otherwise.
  if (const int status = gsl_spline_eval_e(spline_.get(), x, accel, &y); status != GSL_SUCCESS)
    throw std::runtime_error(std::string("GSL spline evaluation: ") + gsl_strerror(status));
  return y;
}

double CubicSpline::slope(double x, gsl_interp_accel* accel) const {
  double dy = 0.0;
  if (const int status = gsl_spline_eval_deriv_e(spline_.get(), x, accel, &dy); status != GSL_SUCCESS)
    throw std::runtime_error(std::string("GSL spline derivative: ") + gsl_strerror(status));
  return dy;
}

}  // namespace gearbench::stiffness
