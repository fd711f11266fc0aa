#include "efficiency_closed_form.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "involute_closed_form.h"
#include "model/gsl_status.h"

namespace gearbench::reference {

namespace {

/// Path of contact from the closed forms: A, C, E from T1 and the base pitch.
struct Path {
  double A, C, E, pbt, rb1, u;
};

Path path_of(const model::GearPair& pair) {
  const auto cf = involute_closed_form(pair);
  const double mt = pair.normal_module / std::cos(pair.helix_angle);
  const double at = cf.transverse_pressure_angle;
  const double r1 = 0.5 * pair.teeth[0] * mt, r2 = 0.5 * pair.teeth[1] * mt;
  const double rb1 = r1 * std::cos(at), rb2 = r2 * std::cos(at);
  const double ra1 = pair.tip_diameter ? 0.5 * (*pair.tip_diameter)[0] : r1 + pair.normal_module * (pair.addendum_coef + pair.profile_shift[0]);
  const double ra2 = pair.tip_diameter ? 0.5 * (*pair.tip_diameter)[1] : r2 + pair.normal_module * (pair.addendum_coef + pair.profile_shift[1]);
  Path p{};
  p.E = std::sqrt(ra1 * ra1 - rb1 * rb1);
  p.A = cf.line_of_action_length - std::sqrt(ra2 * ra2 - rb2 * rb2);
  p.C = cf.pitch_point_from_T1;
  p.pbt = M_PI * mt * std::cos(at);
  p.rb1 = rb1;
  p.u = static_cast<double>(pair.teeth[1]) / pair.teeth[0];
  return p;
}

struct Integrand {
  Path p;
};

double shared_sliding(double s, void* data) {
  const Path& p = static_cast<Integrand*>(data)->p;
  const double B = p.E - p.pbt, D = p.A + p.pbt;
  const double share = (s < B || s > D) ? 0.5 : 1.0;
  return share * std::abs(s - p.C);
}

}  // namespace

OhlendorfLossFactor ohlendorf_loss_factor(const model::GearPair& pair) {
  const Path p = path_of(pair);
  const double at = std::atan(std::tan(pair.normal_pressure_angle) / std::cos(pair.helix_angle));
  const double beta_b = std::atan(std::tan(pair.helix_angle) * std::cos(at));
  OhlendorfLossFactor r;
  r.eps_1 = (p.E - p.C) / p.pbt;
  r.eps_2 = (p.C - p.A) / p.pbt;
  r.eps_alpha = r.eps_1 + r.eps_2;
  r.H_V = M_PI * (p.u + 1.0) / (pair.teeth[0] * p.u * std::cos(beta_b)) *
          (1.0 - r.eps_alpha + r.eps_1 * r.eps_1 + r.eps_2 * r.eps_2);
  return r;
}

double agma6011_efficiency(int z1, int z2, double pressure_angle_deg) {
  return 1.0 - (22.0 - 0.8 * pressure_angle_deg) * 0.02 * (z1 + z2) / (static_cast<double>(z1) * z2);
}

double iso14179_mean_coefficient(const model::GearPair& pair, const model::OperatingPoint& operating,
                                 const model::Lubricant& lubricant, double lubricant_factor) {
  const auto cf = involute_closed_form(pair);
  const double at = cf.transverse_pressure_angle;
  const double beta_b = std::atan(std::tan(pair.helix_angle) * std::cos(at));
  const double rb1 = 0.5 * pair.teeth[0] * pair.normal_module / std::cos(pair.helix_angle) * std::cos(at);
  const double rw1 = rb1 / std::cos(cf.working_pressure_angle);
  const double b = pair.face_width * (pair.herringbone ? 2.0 : 1.0);
  const double force_per_width = operating.pinion_torque / rb1 / (b * 1e3);                    // N/mm
  const double v_sum = 2.0 * operating.pinion_speed * rw1 * std::sin(cf.working_pressure_angle);  // m/s
  const double t1c = cf.pitch_point_from_T1, t2c = cf.line_of_action_length - t1c;
  const double rho_red = t1c * t2c / (cf.line_of_action_length * std::cos(beta_b)) * 1e3;        // mm
  const double ra = 0.5 * (operating.roughness_Ra[0] + operating.roughness_Ra[1]) * 1e6;         // µm
  return 0.048 * std::pow(force_per_width / (v_sum * rho_red), 0.2) * std::pow(lubricant.viscosity * 1e3, -0.05) *
         std::pow(ra, 0.25) * lubricant_factor;
}

double spur_loss_factor_quadrature(const model::GearPair& pair) {
  model::gsl_use_status_codes();
  Integrand data{path_of(pair)};
  const Path& p = data.p;
  std::vector<double> points{p.A, p.E - p.pbt, p.C, p.A + p.pbt, p.E};
  std::sort(points.begin(), points.end());
  gsl_function f{&shared_sliding, &data};
  std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> w(
      gsl_integration_workspace_alloc(200), &gsl_integration_workspace_free);
  double result = 0.0, error = 0.0;
  model::gsl_check(gsl_integration_qagp(&f, points.data(), points.size(), 0.0, 1e-12, 200, w.get(), &result, &error),
                   "qagp (loss integral)");
  return (p.u + 1.0) / (p.u * p.rb1 * p.pbt) * result;
}

}  // namespace gearbench::reference
