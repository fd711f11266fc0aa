#include "involute_closed_form.h"

#include <cmath>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_roots.h>
#include <memory>
#include <stdexcept>
#include <string>

#include "model/gsl_status.h"

namespace gearbench::reference {

namespace {

double inv(double alpha) { return std::tan(alpha) - alpha; }

struct InvTarget {
  double value;
};

double inv_residual(double alpha, void* params) {
  return inv(alpha) - static_cast<InvTarget*>(params)->value;
}

// Solves inv α = value on (0, 80°) with gsl_root_fsolver_brent to 1e-15 rad.
double solve_involute(double value) {
  model::gsl_use_status_codes();
  InvTarget target{value};
  gsl_function f{&inv_residual, &target};
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  double lo = 1e-9;
  double hi = 80.0 * M_PI / 180.0;
  model::gsl_check(gsl_root_fsolver_set(solver.get(), &f, lo, hi), "root bracket");
  for (int iteration = 0; iteration < 200; ++iteration) {
    model::gsl_check(gsl_root_fsolver_iterate(solver.get()), "root iteration");
    lo = gsl_root_fsolver_x_lower(solver.get());
    hi = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(lo, hi, 1e-15, 0.0) == GSL_SUCCESS)
      return gsl_root_fsolver_root(solver.get());
  }
  throw std::runtime_error("GSL Brent: inverse involute did not converge in 200 iterations");
}

}  // namespace

InvoluteClosedForm involute_closed_form(const model::GearPair& pair) {
  InvoluteClosedForm out;
  const double z1 = pair.teeth[0];
  const double z2 = pair.teeth[1];
  const double mn = pair.normal_module;
  const double an = pair.normal_pressure_angle;
  const double beta = pair.helix_angle;
  const double mt = mn / std::cos(beta);
  const double at = std::atan(std::tan(an) / std::cos(beta));
  out.transverse_pressure_angle = at;

  // Diameters (ISO 21771:2007): d = z·m_t, d_b = d·cos α_t, d_a = d + 2m_n(h_a* + x).
  const double d1 = z1 * mt;
  const double d2 = z2 * mt;
  const double db1 = d1 * std::cos(at);
  const double db2 = d2 * std::cos(at);
  const double da1 = pair.tip_diameter ? (*pair.tip_diameter)[0]
                                       : d1 + 2.0 * mn * (pair.addendum_coef + pair.profile_shift[0]);
  const double da2 = pair.tip_diameter ? (*pair.tip_diameter)[1]
                                       : d2 + 2.0 * mn * (pair.addendum_coef + pair.profile_shift[1]);

  // Working pressure angle: from the centre distance when given (cos α_wt = a_d cos α_t/a),
  // else from the shifts, inv α_wt = inv α_t + 2(x1 + x2) tan α_n/(z1 + z2) (ISO 21771:2007).
  const double a_d = 0.5 * (d1 + d2);
  if (pair.center_distance) {
    out.center_distance = *pair.center_distance;
    out.working_pressure_angle = std::acos(a_d * std::cos(at) / out.center_distance);
  } else {
    out.working_pressure_angle =
        solve_involute(inv(at) + 2.0 * (pair.profile_shift[0] + pair.profile_shift[1]) *
                                     std::tan(an) / (z1 + z2));
    out.center_distance = a_d * std::cos(at) / std::cos(out.working_pressure_angle);
  }
  const double awt = out.working_pressure_angle;
  out.line_of_action_length = out.center_distance * std::sin(awt);
  out.pitch_point_from_T1 = out.line_of_action_length * z1 / (z1 + z2);

  // ε_α = [√(d_a1² − d_b1²) + √(d_a2² − d_b2²) − 2a·sin α_wt] / (2π·m_t·cos α_t)
  // (ISO 21771:2007, written with diameters; p_bt = π·m_t·cos α_t).
  const double pbt = M_PI * mt * std::cos(at);
  out.contact_ratio_transverse =
      (std::sqrt(da1 * da1 - db1 * db1) + std::sqrt(da2 * da2 - db2 * db2) -
       2.0 * out.center_distance * std::sin(awt)) /
      (2.0 * pbt);
  out.contact_ratio_overlap = pair.face_width * std::sin(beta) / (M_PI * mn);

  // A path of length ε_α·p_bt, with pairs one base pitch apart: the double-contact zones
  // at both ends are (ε_α − 1)·p_bt long, the single zone between them (2 − ε_α)·p_bt.
  const double ea = out.contact_ratio_transverse;
  out.single_contact_length = (2.0 - ea) * pbt;
  out.double_contact_length = 2.0 * (ea - 1.0) * pbt;

  // Mean total contact-line length over a mesh cycle: the field of contact, g_α × b on the
  // base plane, is crossed by contact lines one p_bt apart inclined at β_b, so the mean
  // length is g_α·b/(p_bt·cos β_b) = b·ε_α/cos β_b; tan β_b = tan β·cos α_t.
  const double beta_b = std::atan(std::tan(beta) * std::cos(at));
  out.mean_contact_line_length = pair.face_width * ea / std::cos(beta_b);
  return out;
}

}  // namespace gearbench::reference
