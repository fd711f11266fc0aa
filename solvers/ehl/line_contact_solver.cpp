#include "line_contact_solver.h"

#include <cmath>
#include <fmt/format.h>

#include "fas_multigrid.h"
#include "model/errors.h"

namespace gearbench::ehl {

std::string EhlOptions::describe() const {
  const std::string grid =
      nodes > 0    ? fmt::format("{} nodes", nodes)
      : levels > 0 ? fmt::format("{} levels from {} nodes", levels, coarsest_nodes)
                 : fmt::format("levels to a {:g} % error (at most {}) from {}", 100.0 * target_error, max_levels,
                               coarsest_nodes > 0 ? fmt::format("{} nodes", coarsest_nodes)
                                                  : std::string("a coarsest grid sized by the film"));
  const std::string rule = stop == StopRule::discretisation_error
                               ? fmt::format("stop at {:g} of the error estimate", error_fraction)
                               : fmt::format("stop at residual {:.0e}", tolerance);
  const std::string method =
      single_grid ? std::string("single grid, a relaxation and an H0 update per cycle")
                  : fmt::format("FMG + {}({},{}){}{}", cycle == CycleType::W ? 'W' : cycle == CycleType::F ? 'F' : 'V',
                                pre_sweeps, post_sweeps,
                                cycle == CycleType::W ? fmt::format(" on {} levels, V above", w_cycle_levels) : "",
                                acceleration_depth > 0 ? fmt::format(" with Anderson({})", acceleration_depth) : "");
  return fmt::format("{}, ω {:g}/{:g}, κ {:g}, lines ±{}, |Δ ln ε| ≤ {:g}, {}{}; {}", method, omega_gauss_seidel,
                     omega_jacobi, relaxation_switch, line_band, change_limit, grid,
                     direct_deformation ? ", direct deformation sum" : "", rule);
}

std::string EhlResult::summary() const {
  return fmt::format("{}: {} levels ({} nodes), {} cycles, {:.1f} work units ({:.1f} after full multigrid's cycles), "
                     "{:.3f} s; h_min {:.4e} m, h_c {:.4e} m, p_max {:.4e} Pa; error estimate {}",
                     converged ? "converged" : "NOT converged", levels, X.size(), cycles, work_units,
                     work_units_iterating, seconds, h_min, h_central, p_max,
                     std::isnan(error_estimate)    ? std::string("none")
                     : std::isinf(error_estimate) ? std::string("none on this grid (its accuracy is unknown)")
                                                  : fmt::format("{:.2g}", error_estimate));
}

double EhlOptions::domain_in(const LineContactProblem& problem) const {
  return x_in != 0.0 || x_out != 0.0 ? x_in : problem.x_in();
}

double EhlOptions::domain_out(const LineContactProblem& problem) const {
  return x_in != 0.0 || x_out != 0.0 ? x_out : problem.x_out();
}

double film_spacing_ratio(const LineContactProblem& problem, const EhlOptions& options) {
  if (options.nodes <= 0) return 0.0;
  const double length = options.domain_out(problem) - options.domain_in(problem);
  return length / static_cast<double>(options.nodes - 1) / std::sqrt(problem.isoviscous_film());
}

void refuse_grid_not_resolving_film(const LineContactProblem& problem, const EhlOptions& options) {
  const double ratio = film_spacing_ratio(problem, options);
  if (ratio <= finest_film_spacing) return;
  // The intervals scale as 1/h: a double, no overflow at extreme loads.
  const double fewest = std::ceil(ratio * static_cast<double>(options.nodes - 1) / finest_film_spacing) + 1.0;
  double grid = 257.0;  // the grids of issue 19's range, 2^k + 1 nodes
  while (grid < fewest) grid = 2.0 * grid - 1.0;
  throw InputError(fmt::format(
      "grid.nodes = {}: too coarse for the film at this load (Moes' isoviscous film {:.3g} m); allowed are "
      "≥ {:.0f} nodes, a spacing ≤ {:g}·√film (four nodes where the rigid gap grows by one film), e.g. {:.0f}; or "
      "leave grid.nodes out for the grid chosen by grid.target_error",
      options.nodes, problem.isoviscous_film() * problem.film_scale(), fewest, finest_film_spacing, grid));
}

LineContactSolver::LineContactSolver(const LineContactProblem& problem, EhlOptions options)
    : problem_(problem), options_(std::move(options)) {
  options_.validate();
}

EhlResult LineContactSolver::try_solve() const { return FasMultigrid(problem_, options_, ContactState{}).solve(); }

EhlResult LineContactSolver::solve() const {
  auto r = try_solve();
  if (!r.converged) throw ConvergenceError(r.message + "; " + r.summary());
  return r;
}

}  // namespace gearbench::ehl
