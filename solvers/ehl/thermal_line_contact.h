#pragma once
// Steady thermal line-contact EHL (TEHL), seed 001 §1–2: the generalized Reynolds equation
// of Yang Peiran with the effective film coefficients (ρ/η)_e and ρ* of a temperature field
// across the film, the film equation with deformation, the load balance, and the energy
// equation in the film and both solids (film_temperature.h). Pipeline:
//   1. the isothermal solution at the inlet temperature (LineContactSolver);
//   2. temperature sweeps for the current pressure and film;
//   3. the generalized-Reynolds factors per node, (ρ/η)_e/(ρ/η)_iso and ρ*/ρ_iso at the node's
//      pressure, frozen into the FAS multigrid, which re-solves pressure and film from the
//      last solution;
//   4. back to 2 until the temperature and the minimum film stop changing; the factors are
//      the fixed point F = G(F) of steps 2–3, accelerated by Anderson mixing on ln F
//      (anderson_mixing.h), and the stop estimates h_min's remaining error from the observed
//      contraction.
// At the fixed point the factors are those of the converged temperature and pressure, so the
// solution is the coupled one; freezing them only changes the path to it. Temperature lives
// on the finest pressure grid (the coarse grids inject its factors), a simplification of
// seed 001's finest-and-coarsest scheme.
// Rheology (options.film.rheology): Newtonian, or Ree–Eyring inside the film, where the
// equivalent viscosity τ/γ̇ enters the generalized-Reynolds factors, the velocity profile and
// the shear heating τ·∂u/∂z (column_flow.h). Traction: the film's wall stress on surface a;
// a Newtonian film with an Eyring stress also reports τ0·asinh(τ_N/τ0) of its Newtonian wall
// stress (post-processing, `friction_coefficient_eyring`).
#include <optional>
#include <string>
#include <vector>

#include "film_temperature.h"
#include "line_contact_solver.h"
#include "model/solve_status.h"

namespace gearbench::ehl {

/// When the pressure–temperature coupling stops (ThermalEhlOptions::stop).
enum class CouplingStop {
  /// At grid.error_fraction of the discretisation error of h_min and ΔT_max, estimated from the
  /// converged grid half as fine (nested iteration), and never tighter than the tolerances
  /// below; on a grid without a nested start, h_min's from the isothermal solve's own estimate
  /// on that grid (its full-multigrid levels), ΔT_max at temperature_tolerance.
  discretisation_error,
  tolerance,  ///< at temperature_tolerance and film_tolerance on every grid
};

struct ThermalEhlOptions {
  /// The isothermal machinery (levels, cycles, tolerance): a fixed grid, 641 nodes, since
  /// the temperature field lives on it; the warm-started inner solves stop at the residual
  /// tolerance.
  EhlOptions grid = default_grid();
  static EhlOptions default_grid();
  FilmTemperatureOptions film;         ///< nodes across the film and into the solids, switches
  int max_iterations = 60;             ///< pressure–temperature iterations (cap: an error beyond)
  /// Temperature sweeps (each down- and upstream) between pressure solves: one. The factors
  /// move between iterations, so a field resolved further is thrown away. Measured (fifteenth
  /// session, instructions by callgrind, the sliding contact on 641 nodes, V-cycles): the
  /// Eyring film 2.64e9 → 2.31e9 at the same 12 + 22 iterations; the Newtonian one 2.25e9 →
  /// 1.75e9, 14 + 18 → 10 + 19; the Eyring roller on 641/1281/2561 nodes in 15/19/22
  /// iterations. More sweeps stop early at 1e-4 K or at 30 % of the last temperature change.
  int sweeps_per_iteration = 1;
  /// Multigrid cycles per pressure solve while the temperature moves (the last solve must
  /// also meet the multigrid tolerance): one, the coupled multigrid's usual choice. Measured
  /// (641 nodes, nested, discretisation-error stop; CPU s, fine + coarse iterations): the
  /// sliding contact 0.34 s (11+19) at 1 against 0.37 s (8+18) at 3 and 8; its Eyring film
  /// 0.39 s (13+23) against 0.53 s (10+23); the Eyring roller 0.46 s (15+29) against 0.59 s
  /// (15+22). The figures move ≤ 1e-4 (within the stop's tenth of the discretisation error).
  int cycles_per_iteration = 1;
  /// The cycle of the coupling's warm-started pressure solves (the isothermal start keeps
  /// grid.cycle): V. A warm start is already near the solution, so depth costs little: on 641
  /// nodes the last solve to grid.tolerance takes 5–6 V(2,1) cycles (9.4 WU each) where it
  /// took 5 W(2,1) cycles (34 WU each). Measured (fifteenth session, instructions counted by
  /// callgrind, the sliding contact's Eyring film, the nested grids settling on their inexact
  /// solve): 2.64e9 against 3.33e9 with W; the figures move ≤ 5e-6 relative.
  CycleType pressure_cycle = CycleType::V;
  /// Largest temperature change between iterations, relative to the film's largest rise
  /// (at least 10 K, so 1e-2 K for nearly isothermal contacts): 1e-3 settles h_min to ~1e-5
  /// (measured in thermal_ehl_test).
  double temperature_tolerance = 1e-3;
  /// Relative change of h_min between iterations, and its remaining error estimated from the
  /// observed contraction of the factor residual (remaining_film_error in the .cpp).
  double film_tolerance = 1e-5;
  /// The discretisation-error rule (issue 26: the coupling stops on the multigrid's rule):
  /// the fine grid's iterations past a tenth of its own discretisation error move no figure
  /// that matters; the tolerances above stay the floor.
  CouplingStop stop = CouplingStop::discretisation_error;
  /// Anderson's mixing β (anderson_mixing.h): the relaxed step inside the accelerated one.
  /// 0.15: on 1281 nodes the Eyring roller (cases/tehl_point_roller_eyring.json) grows a mode
  /// at 0.3 (residual ×1.08 per iteration from iteration 27 until a restart; 65–69 iterations)
  /// and settles in 29–31 at 0.15; on 2561 nodes 0.3 does not settle in 200 iterations, 0.15
  /// and 0.1 do (72, 68). 0.5 and 0.7 stagnate on 641 nodes (the factor map's eigenvalue near
  /// −13: plain relaxation is stable below 0.14). On 641 nodes 0.15 costs the Newtonian
  /// roller 35 iterations where 0.3 takes 22 (both nested).
  double factor_relaxation = 0.15;
  int anderson_depth = 5;              ///< Anderson's depth m: factor differences kept
  /// Nested iteration: a grid of more nodes than this starts its coupling from the converged
  /// solution of the grid half as fine (itself solved the same way: 2561 on 1281 on 641 on
  /// 321 on 161), interpolated linearly (pressure, ln F, film and solid temperatures); up to
  /// it, from the isothermal solution. Why: the isothermal start's outlet has the Newtonian
  /// pressure spike, whose downstream gradient grows as 1/Δx (|∂p/∂x·h| 7.7τ0 on 641 nodes,
  /// 15τ0 on 1281 on the 1 MN/m roller); an Eyring column at that frozen stress shears at
  /// sinh(τ/τ0)·τ0/η, which rises as the oil heats and thins, and the first temperature sweeps
  /// run away (non-finite at x ≈ 0.95b on 1281 and 2561 nodes). A converged coarser solution
  /// has the Eyring film's own bounded outlet gradient. It also saves fine iterations: the
  /// Newtonian roller takes 33 and 38 on 1281 and 2561 nodes instead of 97 and 74 from the
  /// isothermal start.
  int nested_above_nodes = 161;

  /// "grid", "rheology" and the "thermal" section (ehl_options.cpp).
  static const model::OptionTable<ThermalEhlOptions>& table();
  void validate() const;               ///< InputError naming the key
};

/// converged and message: model::SolveStatus (the iteration or the isothermal start that stopped).
struct ThermalEhlResult : model::SolveStatus {
  lubricant::ShearRheology rheology = lubricant::ShearRheology::newtonian;  ///< of the film solved
  // Figures (SI).
  double h_central = 0.0, h_min = 0.0, x_h_min = 0.0, p_max = 0.0;
  double temperature_rise_max = 0.0;        ///< film, max(T − T0) [K]
  double x_temperature_rise_max = 0.0;      ///< its position [m]
  std::array<double, 2> wall_temperature_rise_max{};  ///< surfaces a (pinion) and b [K]
  double friction_force = 0.0;              ///< traction on surface a, per length [N/m]
  double friction_coefficient = 0.0;
  std::optional<double> friction_coefficient_eyring;  ///< Newtonian film with τ0: post-processed limit
  // Isothermal solution at T0 (the start), for comparison.
  double isothermal_h_central = 0.0, isothermal_h_min = 0.0, isothermal_p_max = 0.0;
  double isothermal_friction_coefficient = 0.0;
  HeatBalance heat;                          ///< per unit length [W/m]
  // Fields for figures: x [m], p [Pa], h [m], and T [K] at ζ_j (film) and s_k (solids).
  std::vector<double> x, p, h, zeta, solid_depth;
  std::vector<std::vector<double>> film_temperature;                ///< [i][j]
  std::array<std::vector<std::vector<double>>, 2> solid_temperature; ///< [body][i][k]
  // Diagnostics.
  int iterations = 0;                               ///< on this grid
  int coarse_grid_iterations = 0;                   ///< on the coarser grids of a nested solve
  std::vector<double> temperature_change_history;  ///< [K] per iteration
  std::vector<double> h_min_history;                ///< [m] per iteration
  std::vector<double> factor_residual_history;      ///< ‖ln G(F) − ln F‖₂ per iteration
  /// The stop's tolerances as used on this grid: relative h_min change, temperature change [K];
  /// and the discretisation-error estimate of h_min (relative) they came from, when there was one.
  double film_tolerance_used = 0.0, temperature_tolerance_used = 0.0;
  std::optional<double> h_min_error_estimate;
  int pressure_cycles = 0;
  double work_units = 0.0;                          ///< multigrid sweeps in this grid's units, all grids
  EhlWork work_by_part;                             ///< work_units part by part (their sum)
  double depth = 0.0;                               ///< solid depth d [m]
  double seconds = 0.0;
  EhlResult pressure;                               ///< the last multigrid result

  [[nodiscard]] std::string summary() const;
};

class ThermalLineContact {
 public:
  /// `contact` carries radius, load, speeds and E′ (its lubricant fields are replaced by the
  /// rheology's at the inlet temperature).
  ThermalLineContact(const LineContactData& contact, const lubricant::ThermalRheology& rheology,
                     const model::ThermalSolids& solids, ThermalEhlOptions options);
  /// Throws ConvergenceError (with the histories) when the iteration does not converge.
  [[nodiscard]] ThermalEhlResult solve() const;
  /// The same, returning converged = false instead of throwing (also when the isothermal
  /// start does not converge: `pressure` then holds it).
  [[nodiscard]] ThermalEhlResult try_solve() const;

  /// The isothermal contact data at the inlet temperature (Roelands, Dowson–Higginson).
  [[nodiscard]] const LineContactData& isothermal_data() const { return data_; }

 private:
  struct NestedStart;  ///< a converged solution handed to the grid twice as fine (.cpp)
  struct CouplingTolerances {
    double film;                        ///< relative h_min change
    double temperature;                 ///< [K]
    std::optional<double> h_min_error;  ///< the estimate they came from (relative)
  };
  /// The stop's tolerances on `grid` at the current h_min [m] and largest rise [K] (CouplingStop).
  [[nodiscard]] CouplingTolerances tolerances(const EhlOptions& grid, const NestedStart* nested,
                                              double isothermal_error, double h_min, double rise) const;
  [[nodiscard]] ThermalEhlResult solve_nested(const EhlOptions& grid, NestedStart* end) const;
  [[nodiscard]] ThermalEhlResult coupled(const EhlOptions& grid, const NestedStart* start, NestedStart* end) const;
  void fill_figures(const LineContactProblem& problem, const EhlResult& pressure, const FilmTemperature& field,
                    ThermalEhlResult& r) const;

  LineContactData data_;
  const lubricant::ThermalRheology& rheology_;
  model::ThermalSolids solids_;
  ThermalEhlOptions options_;
};

}  // namespace gearbench::ehl
