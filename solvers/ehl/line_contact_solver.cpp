#include "line_contact_solver.h"

#include <fmt/format.h>

#include "fas_multigrid.h"
#include "model/errors.h"

namespace gearbench::ehl {

void EhlOptions::validate() const {
  if (levels < 1 || levels > 14)
    throw InputError(fmt::format("grid.levels = {}: allowed range is [1, 14]", levels));
  if (coarsest_nodes < 9 || coarsest_nodes > 100001)
    throw InputError(fmt::format("grid.coarsest_nodes = {}: allowed range is [9, 100001]", coarsest_nodes));
  if (max_cycles < 1 || max_cycles > 100000)
    throw InputError(fmt::format("grid.max_cycles = {}: allowed range is [1, 100000]", max_cycles));
  if (line_band < 1 || line_band > 8)
    throw InputError(fmt::format("grid.line_band = {}: allowed range is [1, 8]", line_band));
  if (!(omega_gauss_seidel > 0.0 && omega_gauss_seidel <= 1.0) || !(omega_jacobi > 0.0 && omega_jacobi <= 1.0))
    throw InputError(fmt::format("grid.omega_gauss_seidel = {}, grid.omega_jacobi = {}: allowed range is (0, 1]",
                                 omega_gauss_seidel, omega_jacobi));
  if (!(tolerance > 0.0 && tolerance < 1.0))
    throw InputError(fmt::format("grid.tolerance = {}: allowed range is (0, 1)", tolerance));
  if ((x_in != 0.0 || x_out != 0.0) && !(x_in < 0.0 && x_out > 0.0))
    throw InputError(fmt::format("grid.x_in = {}, grid.x_out = {}: need x_in < 0 < x_out", x_in, x_out));
}

EhlOptions EhlOptions::point_relaxation() {
  EhlOptions o;
  o.relaxation = Relaxation::point;
  o.omega_jacobi = 0.1;
  o.xi_threshold = 0.3;
  return o;
}

std::string EhlResult::summary() const {
  return fmt::format("{} cycles, {:.1f} work units, {:.3f} s; h_min {:.4e} m, h_c {:.4e} m, p_max {:.4e} Pa",
                     cycles, work_units, seconds, h_min, h_central, p_max);
}

LineContactSolver::LineContactSolver(const LineContactProblem& problem, EhlOptions options)
    : problem_(problem), options_(std::move(options)) {
  options_.validate();
}

std::vector<EhlOptions> LineContactSolver::fallback_schemes(const EhlOptions& options) {
  std::vector<EhlOptions> schemes{options};
  EhlOptions toggled = options;
  toggled.hold_unresolved = !options.hold_unresolved;
  schemes.push_back(toggled);
  EhlOptions next = options;
  next.omega_jacobi = 0.5 * options.omega_jacobi;
  schemes.push_back(next);
  EhlOptions wider_jacobi = options;
  wider_jacobi.xi_threshold = 100.0 * options.xi_threshold;
  schemes.push_back(wider_jacobi);
  if (options.levels > 2) {
    EhlOptions finer_coarsest = wider_jacobi;
    finer_coarsest.levels = options.levels - 1;
    finer_coarsest.coarsest_nodes = 2 * options.coarsest_nodes - 1;
    schemes.push_back(finer_coarsest);
  }
  if (options.relaxation == Relaxation::line) {
    next.relaxation = Relaxation::point;
    schemes.push_back(next);
  }
  if (options.cycle == CycleType::W) {
    next.cycle = CycleType::V;
    schemes.push_back(next);
  }
  return schemes;
}

std::string LineContactSolver::describe(const EhlOptions& o) {
  return fmt::format("{}, {}, ω_GS {}, ω_J {}, ξ {}, coarsest grid {} nodes{}", o.cycle == CycleType::W ? 'W' : 'V',
                     o.relaxation == Relaxation::line ? "line" : "point", o.omega_gauss_seidel, o.omega_jacobi,
                     o.xi_threshold, o.coarsest_nodes, o.hold_unresolved ? ", unresolved coarse nodes held" : "");
}

// Where line W-cycles converge they need ~10–20 cycles; near the limits of the (M, L) map a
// scheme can diverge where a more cautious one converges (on 2561 nodes and more, L ≳ 15
// needs the held coarse nodes; M = 1000, L = 0 needs ω_J = 0.1; M = 2, L = 20 and 22.5 on 641
// nodes need the continuation in α).
// A failed solve is therefore repeated from scratch with the next fallback, and the result
// says which scheme counted and after how many attempts.
EhlResult LineContactSolver::try_solve() const {
  EhlResult r = solve_with_fallbacks(problem_);
  if (r.converged || !(problem_.data().pressure_viscosity > 0.0)) return r;
  EhlResult c = solve_by_continuation();
  c.attempts += r.attempts;
  c.work_units += r.work_units;
  c.seconds += r.seconds;
  if (c.converged) return c;
  r.attempts = c.attempts;
  r.work_units = c.work_units;
  r.seconds = c.seconds;
  r.cycle_type += "; then " + c.cycle_type;
  return r;
}

EhlResult LineContactSolver::solve_with_fallbacks(const LineContactProblem& problem) const {
  EhlResult r;
  double work = 0.0, seconds = 0.0;
  const auto schemes = fallback_schemes(options_);
  for (std::size_t k = 0; k < schemes.size(); ++k) {
    r = FasMultigrid(problem, schemes[k], ContactState{}).solve();
    work += r.work_units;
    seconds += r.seconds;
    r.attempts = static_cast<int>(k + 1);
    r.cycle_type = describe(schemes[k]) + (k == 0 ? "" : fmt::format(" (attempt {})", k + 1));
    if (r.converged) break;
  }
  r.work_units = work;
  r.seconds = seconds;
  return r;
}

// Continuation in the pressure–viscosity coefficient (α, and Roelands' z with it, which is
// proportional to α): the contact is solved at α/2, then α is raised in steps, each started
// from the last converged solution on the same grid (the domain and the scaling do not
// depend on α). A step that fails is halved and retried; one that converges lets the next
// grow by half; at most 32 solves. The final solve is the given problem's, to the same
// tolerance.
EhlResult LineContactSolver::solve_by_continuation() const {
  constexpr double first_fraction = 0.5, first_step = 0.125, smallest_step = 1.0 / 512.0;
  constexpr int max_solves = 32;  // M = 5, L = 25 on 2561 nodes, the hardest point reached, needs 19
  const auto scaled = [this](double fraction) {
    LineContactData d = problem_.data();
    d.pressure_viscosity *= fraction;
    d.roelands_z *= fraction;
    return d;
  };
  const LineContactProblem start(scaled(first_fraction));
  EhlResult last = solve_with_fallbacks(start);
  EhlOptions stepping = options_;
  stepping.hold_unresolved = true;
  double reached = first_fraction, step = first_step, work = last.work_units, seconds = last.seconds;
  int solves = 1;
  while (last.converged && reached < 1.0 && step >= smallest_step && solves < max_solves) {
    const double next = std::min(1.0, reached + step);
    const LineContactProblem problem(scaled(next));
    EhlResult r = FasMultigrid(problem, stepping, ContactState{}).solve(WarmStart{last.P, last.H0, 0.0});
    ++solves;
    work += r.work_units;
    seconds += r.seconds;
    if (r.converged) {
      last = std::move(r);
      reached = next;
      step *= 1.5;
    } else {
      step *= 0.5;
    }
  }
  if (!last.converged) reached = 0.0;
  last.converged = last.converged && reached == 1.0;
  last.attempts = 1;
  last.work_units = work;
  last.seconds = seconds;
  last.cycle_type = describe(stepping) +
                    (last.converged ? fmt::format(", continuation in α from {}·α in {} solves", first_fraction, solves)
                     : reached == 0.0
                         ? fmt::format(", continuation in α: the start at {}·α did not converge", first_fraction)
                         : fmt::format(", continuation in α from {}·α stalled at {:.3g}·α after {} solves",
                                       first_fraction, reached, solves));
  return last;
}

std::string EhlResult::failure_message(double tolerance) const {
  return fmt::format("EHL multigrid did not converge in {} cycles (residual {:.3e}, force balance {:.3e}, "
                     "tolerance {:.1e}) with any of {} schemes (last: {})",
                     cycles, residual_history.empty() ? 0.0 : residual_history.back(),
                     force_history.empty() ? 0.0 : force_history.back(), tolerance, attempts, cycle_type);
}

EhlResult LineContactSolver::solve() const {
  auto r = try_solve();
  if (!r.converged) throw ConvergenceError(r.failure_message(options_.tolerance) + "; " + r.summary());
  return r;
}

}  // namespace gearbench::ehl
