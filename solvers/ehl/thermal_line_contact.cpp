#include "thermal_line_contact.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <fmt/format.h>

#include "anderson_mixing.h"
#include "fas_multigrid.h"
#include "model/errors.h"

namespace gearbench::ehl {

EhlOptions ThermalEhlOptions::default_grid() {
  EhlOptions o;
  o.nodes = 641;
  o.stop = StopRule::residual;  // the isothermal start and the thermal re-solves to one tolerance
  // Two pre-sweeps, not the steady default's one: the coupling's pressure re-solves are capped
  // at cycles_per_iteration, and with one the Newtonian sliding point (tehl_point_sliding) took
  // 19 coupling iterations and 461 WU instead of 12 and 379 (its Eyring film 13 and 362 against
  // 12 and 385); the thermal checks 14.0 s against 13.1 (twenty-ninth session).
  o.pre_sweeps = 2;
  return o;
}

std::string ThermalEhlResult::summary() const {
  return fmt::format("{} thermal iterations (+{} on coarser grids), {:.3f} s; h_min {:.4e} m (isothermal {:.4e}), h_c {:.4e} m, "
                     "p_max {:.4e} Pa, film temperature rise {:.2f} K",
                     iterations, coarse_grid_iterations, seconds, h_min, isothermal_h_min, h_central, p_max, temperature_rise_max);
}

ThermalLineContact::ThermalLineContact(const LineContactData& contact, const lubricant::ThermalRheology& rheology,
                                       const model::ThermalSolids& solids, ThermalEhlOptions options)
    : data_(contact), rheology_(rheology), solids_(solids), options_(std::move(options)) {
  options_.validate();
  data_.viscosity = rheology.inlet_viscosity();
  data_.roelands_z = rheology.roelands_z();
  data_.pressure_viscosity = rheology.data().pressure_viscosity;
  data_.viscosity_model = ViscosityModel::roelands;
  data_.density_model = DensityModel::dowson_higginson;
}

ThermalEhlResult ThermalLineContact::solve() const {
  auto r = try_solve();
  if (!r.converged)
    throw ConvergenceError(fmt::format(
        "thermal EHL did not converge in {} iterations (last temperature change {:.3e} K, relative tolerance {:.1e}; "
        "pressure solve {}); {}",
        r.iterations, r.temperature_change_history.empty() ? 0.0 : r.temperature_change_history.back(),
        options_.temperature_tolerance, r.pressure.converged ? "converged" : "NOT converged", r.summary()));
  return r;
}

namespace {
double largest_change(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b) {
  double change = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < a[i].size(); ++j) change = std::max(change, std::abs(a[i][j] - b[i][j]));
  return change;
}

/// The remaining relative error of h_min, estimated from the last iterations: a change per
/// iteration is an error estimate only when the iteration contracts fast. With the factor
/// residual contracting by q per iteration (the geometric mean over the last three: Anderson's
/// steps are not monotone one by one), what is left of h_min's drift is the geometric tail
/// d·q/(1 − q) of its largest change d over the same iterations (the largest, since h_min
/// can turn and change little for one iteration), and never less than d. Infinite before
/// there are four iterations or when the residual does not contract.
double remaining_film_error(const std::vector<double>& h_min, const std::vector<double>& residuals) {
  constexpr std::size_t span = 3;
  const std::size_t k = residuals.size();
  if (k <= span || h_min.size() <= span || !(residuals[k - 1 - span] > 0.0))
    return std::numeric_limits<double>::infinity();
  const double q = std::cbrt(residuals[k - 1] / residuals[k - 1 - span]);
  if (!(q < 1.0)) return std::numeric_limits<double>::infinity();
  double change = 0.0;
  for (std::size_t i = h_min.size() - span; i < h_min.size(); ++i)
    change = std::max(change, std::abs(h_min[i] - h_min[i - 1]) / h_min[i]);
  return change * std::max(1.0, q / (1.0 - q));
}
}  // namespace

struct ThermalLineContact::NestedStart {
  std::vector<double> P;            ///< dimensionless pressure
  double H0 = 0.0;
  double h_min = 0.0;               ///< [m]
  double temperature_rise_max = 0.0;  ///< [K]
  std::vector<double> log_factors;  ///< ln F: flow factors, then wedge factors
  std::optional<FilmTemperature> field;
  int iterations = 0;               ///< thermal iterations of this grid and its coarser ones
  int pressure_cycles = 0;          ///< multigrid cycles of this grid and its coarser ones
  EhlWork work;                     ///< in this grid's sweeps, its coarser grids' work included
};

ThermalEhlResult ThermalLineContact::try_solve() const {
  const auto start = std::chrono::steady_clock::now();
  auto r = solve_nested(options_.grid, nullptr);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

namespace {
int finest_nodes(const EhlOptions& grid) { return grid.nodes != 0 ? grid.nodes : grid.finest_nodes(); }

/// prolong_along_x of `blocks` fields of equal length held one after the other in `v`.
std::vector<double> prolong(const std::vector<double>& v, int blocks) {
  const auto nc = static_cast<std::ptrdiff_t>(v.size()) / blocks;
  std::vector<double> out;
  for (int b = 0; b < blocks; ++b) {
    const auto fine = prolong_along_x(std::vector<double>(v.begin() + b * nc, v.begin() + (b + 1) * nc), nodal_mean);
    out.insert(out.end(), fine.begin(), fine.end());
  }
  return out;
}
}  // namespace

ThermalEhlResult ThermalLineContact::solve_nested(const EhlOptions& grid, NestedStart* end) const {
  const int nodes = finest_nodes(grid);
  std::optional<NestedStart> start;
  // The grid half as fine exists: an even number of intervals, and (given as levels) a level to drop.
  const bool halvable = (nodes - 1) % 2 == 0 && (grid.nodes != 0 || grid.levels > 1);
  if (nodes > options_.nested_above_nodes && halvable) {
    EhlOptions half = grid;
    if (grid.nodes != 0) half.nodes = (nodes - 1) / 2 + 1;
    else half.levels = grid.levels - 1;
    start.emplace();
    auto coarse = solve_nested(half, &*start);
    if (!coarse.converged) {
      coarse.fail(fmt::format("thermal EHL on {} nodes: its nested start, the grid of {} nodes, did not converge: {}",
                              nodes, finest_nodes(half), coarse.message));
      return coarse;
    }
  }
  return coupled(grid, start ? &*start : nullptr, end);
}

ThermalLineContact::CouplingTolerances ThermalLineContact::tolerances(const EhlOptions& grid, const NestedStart* nested,
                                                                      double isothermal_error, double h_min,
                                                                      double rise) const {
  CouplingTolerances t{.film = options_.film_tolerance,
                       .temperature = options_.temperature_tolerance * std::max(rise, 10.0),
                       .h_min_error = std::nullopt};
  if (options_.stop != CouplingStop::discretisation_error || !(h_min > 0.0)) return t;
  if (nested) {
    // Richardson: with e ≈ C·Δx², f_h − f_2h ≈ −3e_h. The observed orders along x are 1.85–2.04
    // for h_min, h_c, ΔT_max and μ (docs/thermal-ehl-model.md, "Fine grids and observed orders").
    constexpr double richardson = 3.0;
    t.h_min_error = std::abs(h_min - nested->h_min) / (richardson * h_min);
    t.temperature = std::max(t.temperature, grid.error_fraction * std::abs(rise - nested->temperature_rise_max) / richardson);
  } else if (std::isfinite(isothermal_error)) {
    t.h_min_error = isothermal_error;  // the isothermal solve's own estimate on this grid (its FMG levels)
  }
  if (t.h_min_error) t.film = std::max(t.film, grid.error_fraction * *t.h_min_error);
  return t;
}

ThermalEhlResult ThermalLineContact::coupled(const EhlOptions& grid, const NestedStart* nested,
                                             NestedStart* end) const {
  const LineContactProblem problem(data_);
  ThermalEhlResult r;
  r.rheology = options_.film.rheology;
  // Every pressure solve's work, part by part; work_units is their sum (the stable key).
  const auto count_work = [&r](const EhlWork& w) {
    r.work_by_part += w;
    r.work_units = r.work_by_part.total();
  };
  // The isothermal solution: the start without a nested one, and the comparison the finest grid
  // reports. A nested grid below the finest needs neither.
  EhlResult current;
  double isothermal_error = std::numeric_limits<double>::quiet_NaN();
  if (!nested || !end) {
    current = LineContactSolver(problem, grid).try_solve();
    isothermal_error = current.error_estimate;
    r.isothermal_h_central = current.h_central;
    r.isothermal_h_min = current.h_min;
    r.isothermal_p_max = current.p_max;
    r.isothermal_friction_coefficient = current.friction_coefficient;
    r.pressure_cycles = current.cycles;
    count_work(current.work_by_part);
    if (!current.converged) {  // the start did not converge: a status, not an exception (issue 21)
      r.fail("thermal EHL: the isothermal start did not converge: " + current.message);
      r.pressure = std::move(current);
      return r;
    }
  }
  // A pressure solve while the factors still move: a few cycles to a tolerance that follows the
  // factor residual (inexact Newton's forcing), 1e-5 of it, between grid.tolerance and 1e-5. A
  // pressure resolved far below the factors' own change is thrown away by the next iteration.
  // Measured (641 nodes, nested): pressure cycles 139 → 97 (sliding), 238 → 143 (sliding
  // Eyring), 351 → 212 (Eyring roller; 23 → 28 iterations); h_min moves ≤ 5e-6. Forcing 1e-6
  // saves half as many cycles.
  EhlOptions warm = grid;  // every pressure solve after the isothermal start is warm-started
  warm.cycle = options_.pressure_cycle;
  const auto inexact = [&](double factor_residual) {
    constexpr double pressure_forcing = 1e-5;
    EhlOptions inner = warm;
    inner.max_cycles = std::min(inner.max_cycles, options_.cycles_per_iteration);
    inner.tolerance = std::max(grid.tolerance, std::min(1e-5, pressure_forcing * factor_residual));
    return inner;
  };

  const std::size_t n = nested ? 2 * nested->P.size() - 1 : current.X.size();
  ContactState state;
  state.flow_factor.assign(n, 1.0);
  state.wedge_factor.assign(n, 1.0);
  std::vector<double> log_factors(2 * n, 0.0), log_image(2 * n);
  if (nested) {  // start from the converged solution of the grid half as fine
    log_factors = prolong(nested->log_factors, 2);
    for (std::size_t i = 0; i < n; ++i) {
      state.flow_factor[i] = std::exp(log_factors[i]);
      state.wedge_factor[i] = std::exp(log_factors[n + i]);
    }
    EhlResult first = FasMultigrid(problem, inexact(1.0), state).solve(WarmStart{prolong(nested->P, 1), nested->H0});
    r.pressure_cycles += first.cycles + nested->pressure_cycles;
    // A sweep of the grid half as fine costs its share of nodes of one of this grid's.
    count_work(first.work_by_part);
    count_work(nested->work.scaled(static_cast<double>(nested->P.size()) / static_cast<double>(n)));
    r.coarse_grid_iterations = nested->iterations;
    if (!std::isfinite(first.h_min)) {
      r.fail(fmt::format("thermal EHL on {} nodes: the pressure solve from the nested start is not finite", n));
      r.pressure = std::move(first);
      return r;
    }
    current = std::move(first);
  }

  const double ls = problem.length_scale(), ps = problem.pressure_scale(), hs = problem.film_scale();
  std::vector<double> x(n), p(n), h(n), rho_iso(n), eta_iso(n), poiseuille(n);
  ColumnFlow flow;  // a column's, for its factors: one column's storage for all
  for (std::size_t i = 0; i < n; ++i) x[i] = current.X[i] * ls;
  FilmTemperature field(x, data_.u1, data_.u2, problem.hertz_half_width(), rheology_, solids_, options_.film);
  if (nested) field.interpolate_from(*nested->field);
  const double T0 = rheology_.inlet_temperature();

  // The coupling is the fixed point F = G(F) of the factors, accelerated by Anderson mixing
  // (anderson_mixing.h) on their logarithms: ln F keeps every factor positive whatever the
  // extrapolation, and weighs a node's change relative to its factor, which spans 1e-2 … 1e5
  // along an Eyring film.
  AndersonMixing anderson({.depth = options_.anderson_depth, .mixing = options_.factor_relaxation});
  double h_min_before = current.h_min;
  bool temperature_settled = false;
  for (int it = 0; it < options_.max_iterations; ++it) {
    for (std::size_t i = 0; i < n; ++i) {
      p[i] = current.P[i] * ps;
      h[i] = std::max(current.H[i], 0.0) * hs;
    }
    const auto before = field.film();
    // Sweeps to 1e-4 K, or to 30 % of the last iteration's temperature change while that is
    // larger: resolving the field far below what the next iteration will change wastes sweeps.
    // The fixed point is the same (the tolerance falls with the change); at the stop, where
    // the change is below temperature_tolerance × rise, the field is left within a fraction
    // of that tolerance (ΔT_max moves ≤ 0.014 K of 77.9 K on the sliding contact).
    // Measured (641 nodes, nested, with the pressure forcing below): 0.3 against 0.03 keeps
    // the Eyring contacts' iterations (15, 29) and costs the Newtonian sliding one 2 (10 → 12)
    // at the same time; the Eyring roller takes 25 % less time. Against always 1e-4 K, 0.03
    // alone cut the column solves by 34–48 % at the same iteration counts.
    constexpr double sweep_fraction = 0.3;
    const double sweep_tolerance = r.temperature_change_history.empty()
                                       ? 1e-4
                                       : std::max(1e-4, sweep_fraction * r.temperature_change_history.back());
    // The isothermal coefficients at this pressure; the pressure solve's Poiseuille coefficient
    // is the frozen factor times their ρ/η.
    for (std::size_t i = 0; i < n; ++i) {
      rho_iso[i] = rheology_.density(p[i], T0);
      eta_iso[i] = rheology_.viscosity(p[i], T0);
      poiseuille[i] = state.flow_factor[i] * rho_iso[i] / eta_iso[i];
    }
    field.solve(p, h, poiseuille, sweep_tolerance, options_.sweeps_per_iteration);
    // Generalized-Reynolds factors relative to the isothermal coefficients at the same p.
    bool finite = true;
    for (std::size_t i = 0; i < n; ++i) {
      field.column_flow(i, p, h, flow);
      log_image[i] = std::log(flow.rho_over_eta_e() * eta_iso[i] / rho_iso[i]);
      log_image[n + i] = std::log(flow.rho_star(data_.u1, data_.u2) / rho_iso[i]);
      finite = finite && std::isfinite(log_image[i]) && std::isfinite(log_image[n + i]);
    }
    if (!finite) break;  // a diverged temperature field: not converged
    double residual = 0.0;
    for (std::size_t k = 0; k < 2 * n; ++k) residual += (log_image[k] - log_factors[k]) * (log_image[k] - log_factors[k]);
    r.factor_residual_history.push_back(std::sqrt(residual));
    log_factors = anderson.next(log_factors, log_image);
    for (std::size_t i = 0; i < n; ++i) {
      state.flow_factor[i] = std::exp(log_factors[i]);
      state.wedge_factor[i] = std::exp(log_factors[n + i]);
    }
    // The finest grid's iteration ends only on a pressure solve that met grid.tolerance itself
    // (`full_solve`). A grid below the finest ends on its inexact solve: its solution is the
    // next grid's start and its h_min the next grid's Richardson estimate, which the inexact
    // solve's tolerance (≤ 1e-5 of the factor residual) moves far less than the estimate itself.
    // Measured (fifteenth session, instructions by callgrind, the sliding contact on 641 nodes):
    // the Eyring film 3.52e9 → 3.33e9, the Newtonian one 2.87e9 → 2.71e9; ΔT_max moves 1e-3 K.
    const EhlOptions inner = temperature_settled ? warm : inexact(r.factor_residual_history.back());
    const bool full_solve = inner.tolerance <= grid.tolerance || end != nullptr;
    EhlResult next = FasMultigrid(problem, inner, state).solve(WarmStart{current.P, current.H0});
    r.pressure_cycles += next.cycles;
    count_work(next.work_by_part);
    ++r.iterations;
    const double change = largest_change(field.film(), before);
    r.temperature_change_history.push_back(change);
    r.h_min_history.push_back(next.h_min);
    current = std::move(next);
    if (!std::isfinite(current.h_min) || current.residual_history.empty() ||
        !std::isfinite(current.residual_history.back()))
      break;
    const double film_change = std::abs(current.h_min - h_min_before) / current.h_min;
    h_min_before = current.h_min;
    double rise = 0.0;
    for (const auto& column : field.film())
      for (double T : column) rise = std::max(rise, T - T0);
    const CouplingTolerances t = tolerances(grid, nested, isothermal_error, current.h_min, rise);
    r.film_tolerance_used = t.film;
    r.temperature_tolerance_used = t.temperature;
    r.h_min_error_estimate = t.h_min_error;
    temperature_settled = it > 0 && change <= t.temperature && film_change <= t.film &&
                          remaining_film_error(r.h_min_history, r.factor_residual_history) <= t.film;
    if (temperature_settled && (current.converged || end != nullptr) && full_solve) {
      r.succeed(fmt::format("converged: the temperature and h_min settled in {} thermal iterations (temperature "
                            "change ≤ {:.2e} K, h_min ≤ {:.1e}{}) {}",
                            r.iterations, t.temperature, t.film,
                            t.h_min_error ? fmt::format(": {:.2g} of the estimated discretisation error {:.2e}",
                                                        grid.error_fraction, *t.h_min_error)
                                          : std::string(),
                            end ? "(the start of the grid twice as fine: its last pressure solve inexact)"
                                : "and the last pressure solve met grid.tolerance"));
      break;
    }
  }
  if (!r.converged) {
    const double change = r.temperature_change_history.empty() ? 0.0 : r.temperature_change_history.back();
    if (r.iterations >= options_.max_iterations)
      r.fail(fmt::format("thermal EHL: the thermal iteration did not converge in max_iterations = {} iterations "
                         "(last temperature change {:.3e} K, relative tolerance {:.1e}; last pressure solve {})",
                         r.iterations, change, options_.temperature_tolerance,
                         current.converged ? "converged" : "NOT converged"));
    else
      r.fail(fmt::format("thermal EHL: the thermal iteration diverged after {} iterations (a non-finite "
                         "temperature, factor or film; last temperature change {:.3e} K)", r.iterations, change));
  }
  for (std::size_t i = 0; i < n; ++i) {
    p[i] = current.P[i] * ps;
    h[i] = std::max(current.H[i], 0.0) * hs;
  }
  fill_figures(problem, current, field, r);
  r.heat = field.heat_balance(p, h);
  if (end) {
    end->P = current.P;
    end->H0 = current.H0;
    end->h_min = r.h_min;
    end->temperature_rise_max = r.temperature_rise_max;
    end->log_factors = log_factors;
    end->field.emplace(field);
    end->iterations = r.iterations + r.coarse_grid_iterations;
    end->pressure_cycles = r.pressure_cycles;
    end->work = r.work_by_part;
  }
  r.pressure = std::move(current);
  return r;
}

void ThermalLineContact::fill_figures(const LineContactProblem& problem, const EhlResult& pressure,
                                      const FilmTemperature& field, ThermalEhlResult& r) const {
  const double ls = problem.length_scale(), ps = problem.pressure_scale(), hs = problem.film_scale();
  const std::size_t n = pressure.X.size();
  r.h_central = pressure.h_central;
  r.h_min = pressure.h_min;
  r.x_h_min = pressure.x_h_min;
  r.p_max = pressure.p_max;
  r.x.resize(n);
  r.p.resize(n);
  r.h.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    r.x[i] = pressure.X[i] * ls;
    r.p[i] = pressure.P[i] * ps;
    r.h[i] = std::max(pressure.H[i], 0.0) * hs;
  }
  r.zeta = field.film_coordinates();
  r.solid_depth = field.solid_coordinates();
  r.film_temperature = field.film();
  r.solid_temperature = {field.solid(0), field.solid(1)};
  r.depth = field.depth();
  const double T0 = field.inlet_temperature();
  const std::size_t nz = r.zeta.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < nz; ++j)
      if (r.film_temperature[i][j] - T0 > r.temperature_rise_max) {
        r.temperature_rise_max = r.film_temperature[i][j] - T0;
        r.x_temperature_rise_max = r.x[i];
      }
    r.wall_temperature_rise_max[0] = std::max(r.wall_temperature_rise_max[0], r.film_temperature[i][0] - T0);
    r.wall_temperature_rise_max[1] = std::max(r.wall_temperature_rise_max[1], r.film_temperature[i][nz - 1] - T0);
  }
  // Traction on surface a, the film's wall stress τ_a (η·∂u/∂z of a Newtonian film, the
  // Ree–Eyring stress of an Eyring film), where the film is pressurised (as the isothermal
  // solver: the cavitated film carries no full-film shear). A Newtonian film with an Eyring
  // stress also gives τ0·asinh(τ_a/τ0) of its Newtonian stress (post-processing).
  const double dx = r.x[1] - r.x[0];
  double wall = 0.0, limited = 0.0;
  const auto tau0 = options_.film.rheology == lubricant::ShearRheology::newtonian ? rheology_.data().eyring_stress
                                                                                  : std::nullopt;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (r.p[i] <= 0.0 || r.h[i] <= 0.0) continue;
    const ColumnFlow flow = field.column_flow(i, r.p, r.h);
    const double tau = flow.stress[0];
    wall += tau * dx;
    if (tau0) limited += *tau0 * std::asinh(tau / *tau0) * dx;
  }
  r.friction_force = wall;
  r.friction_coefficient = wall / data_.load_per_length;
  if (tau0) r.friction_coefficient_eyring = limited / data_.load_per_length;
}

}  // namespace gearbench::ehl
