#include "column_flow.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "lubricant/rheology.h"
#include "model/errors.h"

namespace gearbench::ehl {

double eyring_wall_stress(const std::vector<double>& zeta, const std::vector<double>& viscosity, double sliding,
                          double dpdx, double h, double eyring_stress, std::optional<double> guess) {
  const std::size_t nz = zeta.size();
  const double dz = 1.0 / static_cast<double>(nz - 1);
  const double mean_rate = sliding / h;  // (U_b − U_a)/h: the column's mean shear rate
  // Bracket: where every node shears at most (at least) at the mean rate, the trapezoidal
  // mean falls below (above) it; γ̇_j(τ) = mean_rate at τ_j = τ0·asinh(η_j·rate/τ0) − p_x·h·ζ_j.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t j = 0; j < nz; ++j) {
    const double tau = lubricant::eyring_stress(mean_rate, viscosity[j], eyring_stress) - dpdx * h * zeta[j];
    lo = std::min(lo, tau);
    hi = std::max(hi, tau);
  }
  const double scale = std::max(std::abs(lo), std::abs(hi));
  if (!(hi - lo > 1e-14 * scale)) return lo;
  // Safeguarded Newton on F(τ_a) = Σ w_j·γ̇_j − rate, F′ = Σ w_j·cosh(τ_j/τ0)/η_j > 0 (a step
  // leaving the bracket, or an overflowing sinh, is replaced by bisection), from the guess
  // (the column's root of the last sweep) when it lies inside the bracket, else its middle.
  // cosh = √(1 + sinh²) from the sinh F needs (the slope only steers the steps).
  double tau_a = guess && *guess > lo && *guess < hi ? *guess : 0.5 * (lo + hi);
  for (int it = 0; it < 200; ++it) {
    double F = -mean_rate, dF = 0.0;
    for (std::size_t j = 0; j < nz; ++j) {
      const double w = (j == 0 || j + 1 == nz) ? 0.5 * dz : dz;
      const double sh = std::sinh((tau_a + dpdx * h * zeta[j]) / eyring_stress);
      F += w * (eyring_stress / viscosity[j] * sh);  // γ̇_j, as lubricant::eyring_shear_rate
      dF += w * std::sqrt(1.0 + sh * sh) / viscosity[j];
    }
    if (F == 0.0) return tau_a;
    (F < 0.0 ? lo : hi) = tau_a;
    double next = tau_a - F / dF;
    // A converged Newton step is taken before the bracket test: the step below one ulp of
    // τ_a lands on τ_a itself, which is the bracket's end just set, and the bisection
    // that replaced it took ~40 more steps to reach the same root (a third of all steps).
    if (std::abs(next - tau_a) <= 1e-13 * scale) return next;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - tau_a) <= 1e-13 * scale) return next;
    tau_a = next;
  }
  throw ConvergenceError(fmt::format("Eyring wall stress of a film column did not converge in 200 steps "
                                     "(τ0 = {:.4g} Pa, bracket [{:.6g}, {:.6g}] Pa)", eyring_stress, lo, hi));
}

ColumnFlow column_flow(const std::vector<double>& zeta, std::vector<double> viscosity, std::vector<double> density,
                       double Ua, double Ub, double dpdx, double h, std::optional<double> eyring_stress,
                       std::optional<double> wall_stress_guess) {
  ColumnFlow c;
  c.viscosity = std::move(viscosity);
  c.rho = std::move(density);
  complete_column_flow(zeta, Ua, Ub, dpdx, h, eyring_stress, wall_stress_guess, c);
  return c;
}

void complete_column_flow(const std::vector<double>& zeta, double Ua, double Ub, double dpdx, double h,
                          std::optional<double> eyring_stress, std::optional<double> wall_stress_guess, ColumnFlow& c) {
  const std::size_t nz = zeta.size();
  const double dz = 1.0 / static_cast<double>(nz - 1);
  const double dU = Ub - Ua;
  c.eta_star = c.viscosity;
  c.eyring_wall_stress = 0.0;
  if (eyring_stress) {
    const double tau_a = eyring_wall_stress(zeta, c.viscosity, dU, dpdx, h, *eyring_stress, wall_stress_guess);
    c.eyring_wall_stress = tau_a;
    for (std::size_t j = 0; j < nz; ++j)
      c.eta_star[j] = lubricant::eyring_equivalent_viscosity(tau_a + dpdx * h * zeta[j], c.viscosity[j], *eyring_stress);
  }
  c.f0.assign(nz, 0.0);
  c.f1.assign(nz, 0.0);
  for (std::size_t j = 1; j < nz; ++j) {  // trapezoid: exact for f0, f1 when η* is uniform
    c.f0[j] = c.f0[j - 1] + 0.5 * dz * (1.0 / c.eta_star[j - 1] + 1.0 / c.eta_star[j]);
    c.f1[j] = c.f1[j - 1] + 0.5 * dz * (zeta[j - 1] / c.eta_star[j - 1] + zeta[j] / c.eta_star[j]);
  }
  c.eta_e = 1.0 / c.f0.back();
  c.eta_e_prime = 1.0 / c.f1.back();
  c.rho_e = film_integral(c.rho);
  c.rho_e1 = film_integral(nz, [&c](std::size_t j) { return c.rho[j] * c.f0[j]; });
  c.rho_e2 = film_integral(nz, [&c](std::size_t j) { return c.rho[j] * c.f1[j]; });
  const double ratio = c.eta_e / c.eta_e_prime;
  c.u.resize(nz);
  c.shear_rate.resize(nz);
  c.stress.resize(nz);
  for (std::size_t j = 0; j < nz; ++j) {
    c.u[j] = Ua + dpdx * h * h * (c.f1[j] - ratio * c.f0[j]) + c.eta_e * dU * c.f0[j];
    c.shear_rate[j] = (dpdx * h * (zeta[j] - ratio) + c.eta_e * dU / h) / c.eta_star[j];
    c.stress[j] = c.eta_star[j] * c.shear_rate[j];
  }
}

}  // namespace gearbench::ehl
