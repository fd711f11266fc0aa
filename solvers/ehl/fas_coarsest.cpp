// The coarsest grid: the start (Hertzian guess, homotopy in the piezoviscous exponent) and the
// strict-descent Newton solve in (P, H0) of each visit (coarsest_solve.h).
#include "fas_multigrid_impl.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>

namespace gearbench::ehl {

void FasMultigrid::Impl::solve_coarsest(Level& l, int steps, double tolerance, double merit_reduction) {
  const auto start = std::chrono::steady_clock::now();
  double merit = coarsest_merit(l);
  const double merit_target = merit_reduction * merit;
  for (double taken = 0.0; taken < steps;) {
    const auto c = coefficients(l);
    const std::vector<double> residual = coarsest_residuals(l);
    std::vector<char> held = held_nodes(c, l.P, residual);
    const bool kept = coarsest_newton_.holds(held);
    if (!kept && !factorize_coarsest(l, c, std::move(held))) break;
    const CoarsestStep step = coarsest_newton_.step(residual, l.g - integral(l));
    coarsest_sweeps() += coarsest_newton_.dense() ? dense_solve_cost * std::pow(static_cast<double>(l.n), 2)
                                                  : krylov_solve_cost(coarsest_newton_.jacobian(), step.iterations);
    // Backtracking: the largest of 1, ½, ¼, … that lowers the merit; none does: the solve
    // keeps its last iterate (strict descent: a Newton step on a live coarse grid can
    // otherwise leave the region where its problem is meaningful, eighth session).
    const std::vector<double> P0 = l.P;
    const double H00 = H0_;
    double theta = 1.0, trial = merit;
    bool descended = false;
    for (int halving = 0; step.info == StepInfo::success && halving <= max_halvings; ++halving, theta *= 0.5) {
      for (std::size_t i = 1; i + 1 < l.n; ++i) l.P[i] = std::max(0.0, P0[i] + theta * step.dP[i]);
      H0_ = H00 + theta * step.dH0;
      trial = coarsest_merit(l);
      descended = trial < merit;
      if (descended) break;
    }
    if (!descended) {
      l.P = P0;
      H0_ = H00;
      // A kept factorization that no longer gives a descent direction is replaced by the
      // Jacobian at the present iterate; a fresh one that gives none ends the solve.
      if (!kept) {
        if (step.info != StepInfo::success) fail_on_coarsest(l, step.info);
        break;
      }
      coarsest_newton_.forget();
      (void)coarsest_merit(l);  // the film and coefficients of the restored iterate
      continue;
    }
    taken += kept ? chord_step_share : 1.0;
    // The factorization is kept for the next step only where the iteration is in Newton's
    // region: a full step that lowered the merit by chord_merit_ratio or more. After a damped
    // step the Jacobian moves with P; a kept one then found a "descent" into H0 < 0 from which
    // no step descended (a 161-node oil-film solve at M 1.75, L 27.1, seventeenth session).
    if (theta < 1.0 || trial > chord_merit_ratio * merit) coarsest_newton_.forget();
    merit = trial;
    if (merit <= merit_target) break;
    double largest = 0.0, size = 1e-300;
    for (std::size_t i = 1; i + 1 < l.n; ++i) {
      largest = std::max(largest, std::abs(l.P[i] - P0[i]));
      size = std::max(size, l.P[i]);
    }
    if (largest <= tolerance * size && std::abs(H0_ - H00) <= tolerance * std::max(std::abs(H0_), 1.0)) break;
  }
  update_film(l);
  l.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool FasMultigrid::Impl::factorize_coarsest(Level& l, const ReynoldsCoefficients& c, std::vector<char> held) {
  const StepInfo info = coarsest_newton_.factorize(c, l.P, std::move(held), film_sensitivity(l));
  // Dense: its entries (uncounted before the nineteenth session) and its LU; else the band's.
  if (info == StepInfo::success) {
    const auto& J = coarsest_newton_.jacobian();
    coarsest_sweeps() += coarsest_newton_.dense()
                             ? dense_step_cost * std::pow(static_cast<double>(l.n), 3) + J.dense_cost() / multiply_adds_per_sweep
                             : BandPreconditioner::factorize_cost(J) / multiply_adds_per_sweep;
  }
  if (info != StepInfo::success) fail_on_coarsest(l, info);
  return info == StepInfo::success;
}

void FasMultigrid::Impl::fail_on_coarsest(const Level& l, StepInfo info) {
  const auto& d = problem_.data();
  failure_ = fmt::format(
      "EHL coarsest grid ({} nodes): the (P, H0) Newton system {}; the contact in the solver's scaling: "
      "M {:.3g}, L {:.3g}, λ {:.3g}, load F {:.3g}, pressure scale {:.3g} Pa",
      l.n, info == StepInfo::singular ? "is singular" : "has non-finite coefficients", d.moes_M(), d.moes_L(),
      problem_.lambda(), problem_.load(), problem_.pressure_scale());
}

std::vector<double> FasMultigrid::Impl::coarsest_residuals(const Level& l) const {
  std::vector<double> r = residuals(l);
  for (std::size_t i = 0; i < l.n; ++i)
    if (l.cavitated_on_finer[i]) r[i] = 0.0;
  return r;
}

double FasMultigrid::Impl::coarsest_merit(Level& l) {
  update_film(l);
  update_coefficients(l);
  coarsest_sweeps() += static_cast<double>(l.n);
  const auto r = coarsest_residuals(l);
  double sum = 0.0;
  for (std::size_t i = 1; i + 1 < l.n; ++i) {
    const double part = complementarity_residual(l.P[i], r[i]);
    sum += part * part;
  }
  const double gap = (l.g - integral(l)) / l.h;
  return sum + gap * gap;
}

void FasMultigrid::Impl::start_on_coarsest() {
  Level& l = *levels_.front();
  make_finest(l);
  starting_ = true;
  if (state_.nearby.P.empty())
    start_by_homotopy(l);
  else
    start_from_nearby(l);
  starting_ = false;
}

void FasMultigrid::Impl::start_by_homotopy(Level& l) {
  initial_guess(l);
  const double exponent_at_hertz = problem_.log_viscosity(problem_.hertz_pressure() / problem_.pressure_scale());
  const int stages = std::max(1, static_cast<int>(std::ceil(exponent_at_hertz / homotopy_step)));
  for (int s = 0; s <= stages && failure_.empty(); ++s) {
    viscosity_exponent_ = static_cast<double>(s) / stages;
    solve_coarsest(l, coarsest_steps_per_stage, s == stages ? coarsest_tolerance : homotopy_tolerance);
  }
  viscosity_exponent_ = 1.0;
}

void FasMultigrid::Impl::start_from_nearby(Level& l) {
  const WarmStart& nearby = state_.nearby;
  const std::size_t stride = (levels_.back()->n - 1) / (l.n - 1);
  for (std::size_t i = 0; i < l.n; ++i) l.P[i] = nearby.P[i * stride];
  H0_ = nearby.H0;
  solve_coarsest(l, coarsest_steps_per_stage, coarsest_tolerance);
}

void FasMultigrid::Impl::initial_guess(Level& l) {
  const double amplitude = 2.0 * state_.load / pi;
  for (std::size_t i = 0; i < l.n; ++i) l.P[i] = amplitude * std::sqrt(std::max(0.0, 1.0 - l.X[i] * l.X[i]));
  l.P.front() = l.P.back() = 0.0;
  H0_ = 0.0;
  update_film(l);
  double h_in_contact = l.H[0];
  for (std::size_t i = 0; i < l.n; ++i)
    if (std::abs(l.X[i]) < 1.0) h_in_contact = std::min(h_in_contact, l.H[i]);
  H0_ = problem_.isoviscous_film() - h_in_contact;
  update_film(l);
  add_inlet_pressure(l);
}

void FasMultigrid::Impl::add_inlet_pressure(Level& l) {
  update_coefficients(l);
  std::size_t centre = 0;
  for (std::size_t i = 0; i < l.n; ++i)
    if (std::abs(l.X[i]) < std::abs(l.X[centre])) centre = i;
  const double flux = l.rho[centre] * l.H[centre];
  // Reynolds' equation integrated once: ε dP/dX = υ(ρ̄H − ρ̄_c·H_c), marched from P = 0 at X_in
  // over the faces up to the guess's contact at X = −1.
  for (std::size_t i = 0; i + 1 < l.n && l.X[i + 1] < -1.0; ++i) {
    const double rho_h = 0.5 * (l.rho[i] * l.H[i] + l.rho[i + 1] * l.H[i + 1]);
    l.P[i + 1] = std::max(0.0, l.P[i] + state_.speed * l.h * (rho_h - flux) / l.eps_face[i]);
  }
  update_film(l);
}

}  // namespace gearbench::ehl
