#include "line_contact_solver.h"

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
