#include "line_contact_solver.h"

#include <fmt/format.h>

#include "fas_multigrid.h"
#include "model/errors.h"

namespace gearbench::ehl {

namespace {
void require(bool ok, const std::string& key, const std::string& value, const std::string& allowed) {
  if (!ok) throw InputError(fmt::format("grid.{} = {}: allowed {}", key, value, allowed));
}
}  // namespace

void EhlOptions::validate() const {
  require(levels >= 0 && levels <= 14, "levels", std::to_string(levels), "range is [0, 14] (0: chosen by target_error)");
  require(nodes == 0 || (nodes >= 9 && nodes <= (1 << 20) + 1), "nodes", std::to_string(nodes),
          "range is [9, 1048577], or 0");
  require(nodes == 0 || levels == 0, "nodes", std::to_string(nodes), "either nodes or levels, not both");
  require(coarsest_nodes == 0 || (coarsest_nodes >= 9 && coarsest_nodes <= 1025), "coarsest_nodes",
          std::to_string(coarsest_nodes), "range is [9, 1025], or 0 (sized by the film)");
  require(levels == 0 || coarsest_nodes > 0, "coarsest_nodes", "0", "with levels given, coarsest_nodes in [9, 1025]");
  require(max_levels >= 2 && max_levels <= 14, "max_levels", std::to_string(max_levels), "range is [2, 14]");
  require(target_error > 0.0 && target_error <= 0.5, "target_error", fmt::format("{}", target_error),
          "range is (0, 0.5]");
  require(pre_sweeps >= 0 && pre_sweeps <= 20, "pre_sweeps", std::to_string(pre_sweeps), "range is [0, 20]");
  require(post_sweeps >= 0 && post_sweeps <= 20, "post_sweeps", std::to_string(post_sweeps), "range is [0, 20]");
  require(pre_sweeps + post_sweeps >= 1, "pre_sweeps", std::to_string(pre_sweeps), "pre_sweeps + post_sweeps >= 1");
  require(max_cycles >= 1 && max_cycles <= 100000, "max_cycles", std::to_string(max_cycles), "range is [1, 100000]");
  require(error_fraction > 0.0 && error_fraction <= 1.0, "error_fraction", fmt::format("{}", error_fraction),
          "range is (0, 1]");
  require(tolerance > 0.0 && tolerance < 1.0, "tolerance", fmt::format("{}", tolerance), "range is (0, 1)");
  require(omega_gauss_seidel > 0.0 && omega_gauss_seidel <= 1.0, "omega_gauss_seidel",
          fmt::format("{}", omega_gauss_seidel), "range is (0, 1]");
  require(omega_jacobi > 0.0 && omega_jacobi <= 1.0, "omega_jacobi", fmt::format("{}", omega_jacobi),
          "range is (0, 1]");
  require(relaxation_switch >= 1.0 && relaxation_switch <= 1e3, "relaxation_switch",
          fmt::format("{}", relaxation_switch), "range is [1, 1000]");
  require(line_band >= 1 && line_band <= 16, "line_band", std::to_string(line_band), "range is [1, 16]");
  require(change_limit > 0.0 && change_limit <= 10.0, "change_limit", fmt::format("{}", change_limit),
          "range is (0, 10]");
  require(spike_window >= 1 && spike_window <= 32, "spike_window", std::to_string(spike_window), "range is [1, 32]");
  require(free_boundary_sweeps >= 0 && free_boundary_sweeps <= 20, "free_boundary_sweeps",
          std::to_string(free_boundary_sweeps), "range is [0, 20]");
  require(free_boundary_window >= 1 && free_boundary_window <= 256, "free_boundary_window",
          std::to_string(free_boundary_window), "range is [1, 256]");
  require((x_in == 0.0 && x_out == 0.0) || (x_in < 0.0 && x_out > 0.0), "x_in",
          fmt::format("{} (x_out {})", x_in, x_out), "x_in < 0 < x_out, or both 0");
  if (levels > 0)
    require(finest_nodes() <= (1L << 20) + 1, "levels", std::to_string(levels),
            fmt::format("at most 1048577 nodes on the finest grid ({} from coarsest_nodes {})", finest_nodes(),
                        coarsest_nodes));
}

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
  return fmt::format("FMG + {}({},{}), ω {:g}/{:g}, κ {:g}, lines ±{}, |Δ ln ε| ≤ {:g}, {}; {}",
                     cycle == CycleType::W ? 'W' : 'V', pre_sweeps, post_sweeps, omega_gauss_seidel, omega_jacobi,
                     relaxation_switch, line_band, change_limit, grid, rule);
}

std::string EhlResult::summary() const {
  return fmt::format("{}: {} levels ({} nodes), {} cycles, {:.1f} work units, {:.3f} s; h_min {:.4e} m, "
                     "h_c {:.4e} m, p_max {:.4e} Pa; error estimate {}",
                     converged ? "converged" : "NOT converged", levels, X.size(), cycles, work_units, seconds, h_min,
                     h_central, p_max,
                     std::isnan(error_estimate) ? std::string("none") : fmt::format("{:.2g}", error_estimate));
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
