#include "ehl_closed_form.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "model/gsl_status.h"

namespace gearbench::reference {

namespace {

using std::numbers::pi;

// ---- GSL helpers: every non-success status becomes a std::runtime_error (model::gsl_check) ---

constexpr std::size_t quadrature_limit = 1000;

// ∫_a^∞ f(x) dx by gsl_integration_qagiu (adaptive Gauss–Kronrod 21 on the map
// x = a + (1 − t)/t). f is any callable double(double).
template <class F>
double integrate_to_infinity(F f, double a, double epsabs, double epsrel) {
  gsl_function g{[](double x, void* p) { return (*static_cast<F*>(p))(x); }, &f};
  std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> ws(
      gsl_integration_workspace_alloc(quadrature_limit), &gsl_integration_workspace_free);
  if (!ws) throw std::runtime_error("GSL: cannot allocate an integration workspace");
  double result = 0.0;
  double abserr = 0.0;
  model::gsl_check(gsl_integration_qagiu(&g, a, epsabs, epsrel, quadrature_limit, ws.get(), &result,
                              &abserr),
        "qagiu");
  return result;
}

// The root of f in [lo, hi] (a sign change) by gsl_root_fsolver_brent, to |hi − lo| < tol.
template <class F>
double find_root(F f, double lo, double hi, double tol) {
  gsl_function g{[](double x, void* p) { return (*static_cast<F*>(p))(x); }, &f};
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  if (!solver) throw std::runtime_error("GSL: cannot allocate a Brent solver");
  model::gsl_check(gsl_root_fsolver_set(solver.get(), &g, lo, hi), "Brent bracket");
  for (int iteration = 0; iteration < 200; ++iteration) {
    model::gsl_check(gsl_root_fsolver_iterate(solver.get()), "Brent iteration");
    lo = gsl_root_fsolver_x_lower(solver.get());
    hi = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(lo, hi, tol, 0.0) == GSL_SUCCESS)
      return gsl_root_fsolver_root(solver.get());
  }
  throw std::runtime_error("GSL Brent: no convergence in 200 iterations");
}

// ---- The rigid-isoviscous Reynolds problem, scaled -------------------------------------
//
// h³p'/(12η0) = ū(h − h*) (Reynolds integrated once, ū = (u1 + u2)/2), h = h0 + x²/(2R).
// With x = √(2Rh0)·ξ, h = h0(1 + ξ²), H* = h*/h0 and p = P·η0ū√(2Rh0)/h0²:
//   dP/dξ = 12(1 + ξ² − H*)/(1 + ξ²)³,   P(−∞) = 0,
// and the load w = ∫p dx = (2η0ūR/h0)·∫P dξ, so w·h0/(η0ūR) = 2∫P dξ.

constexpr double inner_epsabs = 1e-13;
constexpr double inner_epsrel = 1e-12;
constexpr double outer_epsabs = 1e-11;
constexpr double outer_epsrel = 1e-10;

double pressure_slope(double xi, double film_at_peak) {
  const double film = 1.0 + xi * xi;
  return 12.0 * (film - film_at_peak) / (film * film * film);
}

// P(ξ) = ∫_{−∞}^{ξ} dP/dξ' dξ'; the slope is even in ξ', so this is ∫_{−ξ}^{∞}.
double scaled_pressure(double xi, double film_at_peak) {
  return integrate_to_infinity([film_at_peak](double s) { return pressure_slope(s, film_at_peak); },
                               -xi, inner_epsabs, inner_epsrel);
}

// w·h0/(η0ūR) = 2∫_{−∞}^{ξ_end} P dξ = 2∫_{−ξ_end}^{∞} P(−s) ds.
double load_constant(double film_at_peak, double xi_end) {
  return 2.0 * integrate_to_infinity(
                   [film_at_peak](double s) { return scaled_pressure(-s, film_at_peak); },
                   -xi_end, outer_epsabs, outer_epsrel);
}

// P(+∞) = ∫_{−∞}^{∞} dP/dξ dξ = 2∫_0^∞ dP/dξ dξ (even slope).
double pressure_at_infinity(double film_at_peak) {
  return 2.0 * integrate_to_infinity(
                   [film_at_peak](double s) { return pressure_slope(s, film_at_peak); }, 0.0,
                   inner_epsabs, inner_epsrel);
}

// The pressure peaks where dP/dξ = 0 upstream, at ξ = −√(H* − 1).
double peak_pressure(double film_at_peak) {
  return scaled_pressure(-std::sqrt(film_at_peak - 1.0), film_at_peak);
}

constexpr double root_tolerance = 1e-11;

}  // namespace

// ---- Dimensionless groups --------------------------------------------------------------
// Definitions as in docs/research/ehl.md (Notation, §3, §5); exact by definition.

double mean_speed(const LineContact& c) { return 0.5 * (c.u1 + c.u2); }

double speed_parameter(const LineContact& c) {
  return c.viscosity * mean_speed(c) / (c.reduced_modulus * c.reduced_radius);
}

double materials_parameter(const LineContact& c) {
  return c.pressure_viscosity * c.reduced_modulus;
}

double load_parameter(const LineContact& c) {
  return c.load_per_length / (c.reduced_modulus * c.reduced_radius);
}

double moes_speed_parameter(const LineContact& c) {
  return c.viscosity * (c.u1 + c.u2) / (c.reduced_modulus * c.reduced_radius);
}

double moes_load_parameter(const LineContact& c) {
  return load_parameter(c) / std::sqrt(moes_speed_parameter(c));
}

double moes_materials_parameter(const LineContact& c) {
  return materials_parameter(c) * std::pow(moes_speed_parameter(c), 0.25);
}

// Venner & Lubrecht, Multilevel Methods in Lubrication (Elsevier 2000), line contact;
// the groups as derived in docs/research/ehl.md §5 [CONFIRMED-DERIVED]. Exact by definition.
double venner_alpha_bar(const LineContact& c) {
  return c.pressure_viscosity * hertz_max_pressure(c);
}

double venner_lambda_bar(const LineContact& c) {
  const double b = hertz_half_width(c);
  const double R = c.reduced_radius;
  return 12.0 * c.viscosity * mean_speed(c) * R * R / (b * b * b * hertz_max_pressure(c));
}

// ---- Hertz line contact ----------------------------------------------------------------
// H. Hertz (1882); K. L. Johnson, Contact Mechanics (CUP 1985), pp. 99–104: with
// E* = E'/2, b² = 4wR/(πE*) = 8wR/(πE') and p_h = √(wE*/(πR)) = √(wE'/(2πR)); in W = w/(E'R)
// that is b = R√(8W/π), p_h = E'√(W/(2π)). Accuracy: exact for frictionless linear-elastic
// half-spaces (b ≪ R); no error figure stated.

double hertz_half_width(const LineContact& c) {
  return c.reduced_radius * std::sqrt(8.0 * load_parameter(c) / pi);
}

double hertz_max_pressure(const LineContact& c) {
  return c.reduced_modulus * std::sqrt(load_parameter(c) / (2.0 * pi));
}

double hertz_pressure(const LineContact& c, double x) {
  const double r = x / hertz_half_width(c);
  return std::abs(r) < 1.0 ? hertz_max_pressure(c) * std::sqrt(1.0 - r * r) : 0.0;
}

// ---- Regression fits -------------------------------------------------------------------

// D. Dowson & G. R. Higginson, Elasto-hydrodynamic Lubrication (Pergamon 1966; SI ed. 1977).
// Coefficients [2+ CODES], mean speed in U [CONSISTENCY] (docs/research/ehl.md §2).
// Accuracy not stated.
double dowson_higginson_H_min(double U, double G, double W) {
  return 2.65 * std::pow(U, 0.70) * std::pow(G, 0.54) * std::pow(W, -0.13);
}

// D. Dowson & T. Toyoda, Proc. 5th Leeds–Lyon Symposium (1978, publ. 1979).
// Coefficients [2+ CODES], mean speed in U [CONSISTENCY] (docs/research/ehl.md §2).
// Accuracy not stated.
double dowson_toyoda_H_c(double U, double G, double W) {
  return 3.06 * std::pow(U, 0.69) * std::pow(G, 0.56) * std::pow(W, -0.10);
}

// H. P. Pan & B. J. Hamrock, J. Tribol. 111 (1989) 246–251, as commonly quoted
// (docs/research/ehl.md §1). COEFFICIENTS NOT VERIFIED AT THE SOURCE [NOT FOUND].
// Accuracy not stated (not found).
double pan_hamrock_H_min(double U, double G, double W) {
  return 1.714 * std::pow(W, -0.128) * std::pow(U, 0.694) * std::pow(G, 0.568);
}

// Pan & Hamrock (1989), as above: COEFFICIENTS NOT VERIFIED AT THE SOURCE.
// Accuracy not stated (not found).
double pan_hamrock_H_c(double U, double G, double W) {
  return 2.922 * std::pow(W, -0.166) * std::pow(U, 0.692) * std::pow(G, 0.470);
}

double dowson_higginson_h_min(const LineContact& c) {
  return c.reduced_radius * dowson_higginson_H_min(speed_parameter(c), materials_parameter(c),
                                                   load_parameter(c));
}

double dowson_toyoda_h_c(const LineContact& c) {
  return c.reduced_radius *
         dowson_toyoda_H_c(speed_parameter(c), materials_parameter(c), load_parameter(c));
}

double pan_hamrock_h_min(const LineContact& c) {
  return c.reduced_radius *
         pan_hamrock_H_min(speed_parameter(c), materials_parameter(c), load_parameter(c));
}

double pan_hamrock_h_c(const LineContact& c) {
  return c.reduced_radius *
         pan_hamrock_H_c(speed_parameter(c), materials_parameter(c), load_parameter(c));
}

// ---- Moes ------------------------------------------------------------------------------
// H. Moes (1992), as given by Venner & Lubrecht (2000); docs/research/ehl.md §3.
// H_RI = 3/M is exact [CONFIRMED-DERIVED]; 2.621, 1.287, 1.311, s and the outer exponent
// −2s/7 are [CONSISTENCY] (agree with Dowson–Toyoda to 0–9 %). Accuracy not stated.

MoesAsymptotes moes_asymptotes(double M, double L) {
  return {.H_RI = 3.0 / M,
          .H_EI = 2.621 * std::pow(M, -0.2),
          .H_RP = 1.287 * std::pow(L, 2.0 / 3.0),
          .H_EP = 1.311 * std::pow(M, -0.125) * std::pow(L, 0.75)};
}

double moes_H(double M, double L) {
  const MoesAsymptotes a = moes_asymptotes(M, L);
  const double s = (7.0 + 8.0 * std::exp(-2.0 * a.H_EI / a.H_RI)) / 5.0;
  const double isoviscous =
      std::pow(std::pow(a.H_RI, 7.0 / 3.0) + std::pow(a.H_EI, 7.0 / 3.0), 3.0 * s / 7.0);
  // As L → 0 both H_RP and H_EP → 0, the (−7/2)-power sum diverges and this term vanishes.
  const double piezoviscous =
      L > 0.0 ? std::pow(std::pow(a.H_RP, -3.5) + std::pow(a.H_EP, -3.5), -2.0 * s / 7.0) : 0.0;
  return std::pow(isoviscous + piezoviscous, 1.0 / s);
}

double moes_h(const LineContact& c) {
  return moes_H_to_metres(moes_H(moes_load_parameter(c), moes_materials_parameter(c)), c);
}

double moes_H_to_metres(double H, const LineContact& c) {
  return H * c.reduced_radius * std::sqrt(moes_speed_parameter(c));
}

double metres_to_moes_H(double h, const LineContact& c) {
  return h / (c.reduced_radius * std::sqrt(moes_speed_parameter(c)));
}

// ---- Martin ----------------------------------------------------------------------------
// H. M. Martin, "Lubrication of gear teeth", Engineering 102 (1916) 119–121 (not read).
// Constants of docs/research/ehl.md §4 [CONFIRMED-DERIVED], recomputed below by
// rigid_isoviscous_reynolds(). Accuracy: exact for a rigid, isoviscous, flooded contact
// with h0 ≪ R, to the digits printed.

double martin_h0(const LineContact& c) {
  return martin_load_constant * c.viscosity * mean_speed(c) * c.reduced_radius /
         c.load_per_length;
}

double martin_outlet(const LineContact& c) {
  return martin_outlet_constant * std::sqrt(2.0 * c.reduced_radius * martin_h0(c));
}

double martin_film_at_peak(const LineContact& c) {
  return martin_film_at_peak_constant * martin_h0(c);
}

// Reynolds outlet ξ_o > 0: P(ξ_o) = 0 with P'(ξ_o) = 0, i.e. H* = 1 + ξ_o². P(ξ_o; 1 + ξ_o²)
// is positive as ξ_o → 0 and negative at ξ_o = 1, so Brent brackets the root in [0.1, 1].
RigidIsoviscousSolution rigid_isoviscous_reynolds() {
  model::gsl_use_status_codes();
  const double outlet = find_root(
      [](double xi) { return scaled_pressure(xi, 1.0 + xi * xi); }, 0.1, 1.0, root_tolerance);
  const double film_at_peak = 1.0 + outlet * outlet;
  return {.load_constant = load_constant(film_at_peak, outlet),
          .outlet = outlet,
          .film_at_peak = film_at_peak,
          .peak_pressure = peak_pressure(film_at_peak)};
}

// Full Sommerfeld: P(+∞) = 0 fixes H* (= 4/3 by hand; bracketed in [1, 2] here). The
// pressure is then antisymmetric; the half-Sommerfeld film keeps it up to its zero
// crossing (found by Brent in [−0.5, 0.5]) and discards the negative part beyond.
RigidIsoviscousSolution rigid_isoviscous_half_sommerfeld() {
  model::gsl_use_status_codes();
  const double film_at_peak =
      find_root([](double film) { return pressure_at_infinity(film); }, 1.0, 2.0, root_tolerance);
  const double outlet = find_root(
      [film_at_peak](double xi) { return scaled_pressure(xi, film_at_peak); }, -0.5, 0.5,
      root_tolerance);
  return {.load_constant = load_constant(film_at_peak, outlet),
          .outlet = outlet,
          .film_at_peak = film_at_peak,
          .peak_pressure = peak_pressure(film_at_peak)};
}

// ---- Rigid pure squeeze ----------------------------------------------------------------
// Derived here (no printed source checked). Reynolds with a normal approach only:
//   d/dx(h³p'/(12η)) = ∂h/∂t = ḣ0,  h = h0 + x²/(2R).
// By symmetry p'(0) = 0, so h³p'/(12η) = ḣ0·x. With x dx = R dh and p(±∞) = 0 (flooded):
//   p(x) = −∫_x^∞ 12ηḣ0·s/h³ ds = −12ηḣ0·R/(2h²) = 6ηR(−ḣ0)/h(x)².
// With x = √(2Rh0)·ξ, ∫dx/h² = √(2Rh0)/h0²·∫dξ/(1 + ξ²)² = √(2Rh0)/h0²·π/2, so
//   w = ∫p dx = 3√2·π·η·R^(3/2)·(−ḣ0)/h0^(3/2).
// Accuracy: exact for a rigid, isoviscous, fully flooded film (no cavitation), h0 ≪ R.

double squeeze_pressure(double radius, double viscosity, double h0, double h0_rate, double x) {
  const double h = h0 + x * x / (2.0 * radius);
  return 6.0 * viscosity * radius * (-h0_rate) / (h * h);
}

double squeeze_load_per_length(double radius, double viscosity, double h0, double h0_rate) {
  return squeeze_load_constant * viscosity * std::pow(radius, 1.5) * (-h0_rate) /
         std::pow(h0, 1.5);
}

double thermal_loading_parameter(double beta, double eta0, double mean_speed, double conductivity) {
  return beta * eta0 * mean_speed * mean_speed / conductivity;
}

double gupta_thermal_reduction(double hertz_pressure, double reduced_modulus, double L_t, double slide_to_roll) {
  const double numerator = 1.0 - 13.2 * (hertz_pressure / reduced_modulus) * std::pow(L_t, 0.42);
  const double denominator = 1.0 + 0.213 * (1.0 + 2.23 * std::pow(std::abs(slide_to_roll), 0.83)) * std::pow(L_t, 0.64);
  return numerator / denominator;
}

}  // namespace gearbench::reference
