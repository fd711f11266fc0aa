#pragma once
// FAS multigrid solver of the steady isothermal line-contact EHL problem
// (Venner & Lubrecht, Multilevel Methods in Lubrication, 2000, ch. 6–8):
//   - uniform grids, n_k = (n_0 − 1)·2^k + 1 nodes, full multigrid from the coarsest; W-cycles
//     on the levels next to the coarsest grid, V above, Anderson-accelerated on each level;
//     levels are added until the estimated discretisation error of H_c and H_min is below
//     grid.target_error, or the grid is given;
//   - Reynolds equation with central Poiseuille and second-order upwind wedge terms
//     (reynolds_stencil.h);
//   - relaxation: Jacobi lines (distributive, zero-sum pattern (−½, 1, −½)) where the film's
//     kernel response matters, then point Gauss–Seidel (with the piezoviscous response dε/dP
//     in the derivative) where the Poiseuille term dominates; every change limited to
//     |Δ ln ε| ≤ change_limit; local Newton at the pressure spike and local sweeps at the
//     outlet's free boundary;
//   - coarse grids with their own ε and ρ̄ and the fine film injected (FAS); the coarsest grid
//     solved directly in (P, H0) (coarsest_solve.h);
// The design and its measurements: docs/research/ehl-multigrid-rebuild.md.
//   - the solve stops when the per-cycle change of H_c, H_min, H0 and the pressurised film is a
//     small fraction of its own discretisation-error estimate (or at a residual tolerance, if asked);
//   - the deformation integral by zero-padded FFT convolution (O(n log n) per sweep).
#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "line_contact_problem.h"
#include "model/option_table.h"
#include "model/solve_status.h"

namespace gearbench::ehl {

/// V: one coarse-grid visit per cycle (O(N) per cycle); W: two (O(N log N) in 1-D); F: an F-cycle
/// then a V-cycle on the coarse grid (O(N); Trottenberg et al., Multigrid (2001) §2.4.2).
enum class CycleType { V, W, F };
/// When a steady solve is accepted: at its own discretisation error (default), or at a
/// residual tolerance (the users who want one; warm-started solves, which have no estimate).
enum class StopRule { discretisation_error, residual };

/// The options of the EHL multigrid: every default is stated once, here; every range once, in
/// table() (ehl_options.cpp), which validate() and the cases' "grid" section read.
struct EhlOptions {
  int nodes = 0;                  ///< nodes on the finest grid (2^k·(n_0 − 1) + 1)  0 or [9, 1048577]
  int levels = 0;                 ///< grid levels from coarsest_nodes (not with nodes)  [0, 14]
                                  ///< neither nodes nor levels: chosen by target_error
  int coarsest_nodes = 0;         ///< nodes on the coarsest grid; 0: sized by the film   0 or [9, 1025]
  int max_levels = 10;            ///< cap on the levels target_error adds (16385 nodes) [2, 14]
  double target_error = 0.005;    ///< estimated relative error of H_c and H_min to reach (0, 0.5]
  /// W: V-cycles degrade with depth on live coarse grids (0.54 → 0.79 from 2 to 7 levels),
  /// W-cycles do not (0.42) (docs/research/ehl-multigrid-rebuild.md, eighth session).
  CycleType cycle = CycleType::W;
  /// Levels above the coarsest grid on which a W-cycle visits the coarser grid twice; above
  /// them it visits it once, so a cycle costs O(N) instead of the full W-cycle's O(N log N) in
  /// one dimension. 5 was the fewest that converged the 71-point (M, L) map on 16385 nodes (4
  /// left (2, 25) unconverged, sixteenth session; 3 also (5, 20) and (10, 22.5), twenty-third):
  /// the spike's slow mode, which the Anderson-accelerated cycles now remove. With them 2
  /// converged every map (twenty-seventh session); with the coarsest grid halved to h ≤ b/2
  /// the same grids are one level further from it, and 3 keeps W on them: 2 left (1, 17.5) on
  /// 8193 and 16385 nodes unconverged (the finer levels' V-cycles at factor 0.97; twenty-eighth
  /// session).                                                                          [1, 14]
  int w_cycle_levels = 3;
  /// Relaxations before the coarse-grid correction: one, two until the twenty-ninth session.
  /// With the stop rule's factor floored at the last level's (fas_stop.cpp), (1,1) cycles cut
  /// the maps' median work by 10–22 % and converge every map, the rule keeping its claim (worst
  /// 0.81 of its bound against 0.77 with (2,1)); (0,1) broke it (4.3 × at (100, 7.5) without the
  /// floor, 2.6 × at (1000, 0) with it) and (1,1) without the floor left no margin (0.99).
  ///                                                                                [0, 20]
  int pre_sweeps = 1;
  int post_sweeps = 1;            ///< relaxations after it                             [0, 20]
  int max_cycles = 60;            ///< cycles on the finest grid before a failure        [1, 100000]
  StopRule stop = StopRule::discretisation_error;
  /// Discretisation-error rule: accept when the algebraic error the per-cycle change of H_c,
  /// H_min, H0 and the pressurised film leaves, and the force balance, are below this fraction
  /// of the error estimate.                                                     (0, 1]
  double error_fraction = 0.1;
  double tolerance = 1e-8;        ///< residual rule: scaled residual and force balance (0, 1)
  // Relaxation (docs/research/ehl-multigrid-rebuild.md, eighth to tenth sessions).
  double omega_gauss_seidel = 0.8;  ///< under-relaxation of Gauss–Seidel changes      (0, 1]
  /// Under-relaxation of the Jacobi line changes: 0.4 converged the map; 1.0 over-relaxes
  /// (eighth session).                                                                  (0, 1]
  double omega_jacobi = 0.4;
  /// κ: Gauss–Seidel only where the Poiseuille diagonal exceeds κ × the wedge term's own;
  /// scale-free, unlike ε/h² ≥ ξ, which sent more contact nodes to Gauss–Seidel on finer
  /// grids and stalled (20, 5) on 2561 nodes (tenth session).                       [1, 1e3]
  double relaxation_switch = 10.0;
  /// Half-bandwidth of a Jacobi line's Jacobian: 3 removed the contact's complex modes
  /// (eighth session; the plain banded solve without distribution fails).             [1, 16]
  int line_band = 3;
  /// Largest |Δ ln ε| = |d ln ε/dP·ΔP| of one change of P: 0.5 keeps every change in the
  /// exponential's linear range; 3 and 1 left runaways (tenth session).              (0, 10]
  double change_limit = 0.5;
  /// Half-width, in Hertzian half-widths b, of the window around the pressure spike solved by
  /// local Newton after post-smoothing and after each FMG interpolation (at least ±4 nodes).
  /// A width in b, not in nodes: ±4 nodes left (10, 17.5) at 0.52/0.83/no convergence on
  /// 2049/4097/8193 nodes; ±0.05b gives 0.20/0.17/0.27/0.09 on 2049 … 16385, ±0.1b
  /// 0.19/0.08/0.07/0.03 but twice the WU to the discretisation error on 16385 nodes (its
  /// dense solve; thirteenth session).                                                   (0, 1]
  double spike_half_width = 0.05;
  /// Extra sweeps over the last free_boundary_window pressurised nodes after each cycle:
  /// 4 over 16 ended the period-2 oscillation at (20, 10) on 4097 nodes (eighth session).
  int free_boundary_sweeps = 4;   ///<                                                  [0, 20]
  int free_boundary_window = 16;  ///<                                                  [1, 256]
  /// Anderson acceleration of the cycles on a level: the states (P, H0) mixed into the next
  /// cycle's start (Krylov acceleration of nonlinear multigrid, Washio & Oosterlee 1997); 0:
  /// plain cycles; also whether the W-cycle's two coarse visits are mixed. Depth 1 halved the
  /// tail of the 16385-node map and removed the slow spike/force-balance mode at high L; 2 and
  /// 3 cost more (twenty-seventh session). With the coarsest grid at h ≤ b/2 and W on three
  /// levels, 2 takes the force balance at (2, 10) on 2049 nodes to 1e-9 in 6 cycles instead of 9
  /// (mean factor 0.099 against 0.214) and lowers the maps' maxima (16385 nodes 260 → 211 WU,
  /// its residual rule 364 → 224), medians equal (twenty-eighth session).           [0, 10]
  int acceleration_depth = 2;
  double x_in = 0.0, x_out = 0.0; ///< domain; both 0 picks the problem's default
  /// The domain's ends in use: x_in and x_out where given, else the problem's.
  [[nodiscard]] double domain_in(const LineContactProblem& problem) const;
  [[nodiscard]] double domain_out(const LineContactProblem& problem) const;
  bool direct_deformation = false; ///< the O(n²) sum instead of the FFT (the benchmarks' baseline)
  /// Relaxation on the finest grid alone, the benchmarks' single-grid baseline (issue 19): no
  /// coarse grid and no local treatment; a cycle is one relaxation sweep followed by the force
  /// balance's H0 update (single_grid_h0_gain). Needs `nodes`; stops by the residual rule.
  bool single_grid = false;

  /// The "grid" keys (ranges, units, what an absent key means) and the ranges of the
  /// relaxation settings the C++ API alone sets.
  static const model::OptionTable<EhlOptions>& table();
  void validate() const;          ///< InputError naming the key ("grid.nodes"), the value and its range
  [[nodiscard]] bool adaptive() const { return levels == 0 && nodes == 0; }
  /// Nodes on the finest grid of a fixed grid (levels > 0).
  [[nodiscard]] long finest_nodes() const {
    return static_cast<long>(std::max(coarsest_nodes, 9) - 1) * (1L << (levels - 1)) + 1;
  }
  /// "FMG + W(2,1), ω 0.8/0.4, κ 10, lines ±3, |Δ ln ε| ≤ 0.5, levels to a 1 % error …; stop at 0.1 of the error estimate".
  [[nodiscard]] std::string describe() const;
};

/// A solve's work by the part of the method that did it, in sweeps of the finest grid
/// (EhlResult::work_units is their sum).
struct EhlWork {
  double start = 0.0;          ///< the coarsest grid's start: the Newton solves of its homotopy stages
  double relaxation = 0.0;     ///< the cycles' pre- and post-sweeps over whole grids
  double restriction = 0.0;    ///< the fine residuals and the coarse films and coefficients of the FAS problems
  double coarsest = 0.0;       ///< the coarsest grid's Newton visits within the cycles
  double spike = 0.0;          ///< the pressure spike's local Newton solves
  double free_boundary = 0.0;  ///< the outlet's extra sweeps and their window films
  double interpolation = 0.0;  ///< the films of full multigrid's interpolated starts
  double acceleration = 0.0;   ///< the residuals of the Anderson-mixed states
  [[nodiscard]] double total() const {
    return start + relaxation + restriction + coarsest + spike + free_boundary + interpolation + acceleration;
  }
  /// Part by part: the work of several solves on one grid (a transient's steps).
  EhlWork& operator+=(const EhlWork& o) {
    start += o.start, relaxation += o.relaxation, restriction += o.restriction, coarsest += o.coarsest;
    spike += o.spike, free_boundary += o.free_boundary, interpolation += o.interpolation;
    acceleration += o.acceleration;
    return *this;
  }
  /// Every part times `factor` (node-sweeps to sweeps of a grid: 1/nodes).
  [[nodiscard]] EhlWork scaled(double factor) const {
    return {start * factor,  relaxation * factor,    restriction * factor,   coarsest * factor,
            spike * factor, free_boundary * factor, interpolation * factor, acceleration * factor};
  }
};

/// converged and message: model::SolveStatus.
struct EhlResult : model::SolveStatus {
  // Dimensionless solution on the finest grid.
  std::vector<double> X, P, H;
  double H0 = 0.0;
  // Figures in SI.
  double h_central = 0.0;   ///< film at X = 0 [m]
  double h_min = 0.0;       ///< minimum film [m]
  double x_h_min = 0.0;     ///< its position [m]
  double p_max = 0.0;       ///< [Pa]
  double h_dpdx0 = 0.0;     ///< film where dp/dx first vanishes from the inlet (Moes' film) [m]
  double friction_force = 0.0;        ///< per unit length, Newtonian [N/m]
  double friction_coefficient = 0.0;
  // Diagnostics.
  std::string scheme;       ///< the options used (EhlOptions::describe)
  std::string stop_rule;    ///< the rule that accepted (or would have accepted) the solve
  int levels = 0;           ///< grid levels used
  int cycles = 0;           ///< cycles on the finest grid after full multigrid (a warm start's: all)
  double work_units = 0.0;  ///< every relaxation, restriction, local and coarsest solve of every stage, in finest-grid sweeps
  double work_units_at_error = std::numeric_limits<double>::quiet_NaN();  ///< WU when the stop rule held
  EhlWork work_by_part;     ///< work_units by the part of the method that did it
  /// The WU of the cycles after each level's full-multigrid cycle: what the stop rule's
  /// iterations cost on top of full multigrid with one cycle a level (all of a warm start's work).
  double work_units_iterating = 0.0;
  /// The geometric mean of the per-cycle factors over residual_history ((last/first)^(1/(n − 1)));
  /// NaN with one cycle, except where full multigrid's cycle was accepted: then the factor
  /// measured on the coarser level that stood for it.
  double convergence_factor = std::numeric_limits<double>::quiet_NaN();
  /// The per-cycle factor ρ the error rule took at the stop (the algebraic error left is the last
  /// change times ρ/(1 − ρ)); NaN under the residual rule.
  double rule_factor = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> residual_history;    ///< scaled Reynolds residual per cycle
  std::vector<double> force_history;       ///< |∫P dX − F|/F per cycle
  std::vector<double> seconds_per_level;
  double seconds = 0.0;
  /// The solver's own discretisation-error estimate of H_c and H_min (relative): the change
  /// from the next-coarser grid of full multigrid over 2^p − 1 (p = 2). NaN where there is
  /// none: a single grid, or a warm-started solve without one (a thermal iteration); a warm
  /// start that carried one (WarmStart::error_estimate, a transient's step) reports it.
  double error_estimate = std::numeric_limits<double>::quiet_NaN();
  /// Relative change of h_min and p_max from the next-coarser grid (NaN: none).
  double h_min_change = std::numeric_limits<double>::quiet_NaN();
  double p_max_change = std::numeric_limits<double>::quiet_NaN();
  double coarse_h_min = 0.0, coarse_p_max = 0.0;  ///< on the next-coarser grid [m], [Pa]
  /// Per full-multigrid level: nodes, H_c, H_min (dimensionless) after its cycle.
  std::vector<double> fmg_nodes, fmg_H_c, fmg_H_min;
  /// Per full-multigrid level: the cycles after its full-multigrid cycle under the error rule
  /// (0: the full-multigrid cycle met the rule; the coarsest grid and levels without an
  /// estimate count 0).
  std::vector<int> fmg_cycles;

  [[nodiscard]] std::string summary() const;
};

class LineContactSolver {
 public:
  LineContactSolver(const LineContactProblem& problem, EhlOptions options);
  /// Solves by full multigrid; throws ConvergenceError (with the message and summary) when
  /// the stop rule is not met within max_cycles.
  [[nodiscard]] EhlResult solve() const;
  /// The same, returning an unconverged result (converged = false) instead of throwing, so
  /// that a caller can write the diagnostics before it reports the failure.
  [[nodiscard]] EhlResult try_solve() const;

 private:
  LineContactProblem problem_;  ///< a copy: the solver outlives no caller's object
  EhlOptions options_;
};

/// The finest grid's h ≤ finest_film_spacing·√H_est (H_est: LineContactProblem::isoviscous_film),
/// four nodes across √(2·H_est), the length over which the rigid gap X²/2 grows by one film.
/// A coarser grid does not resolve the film, whose discretisation error (a difference of O(1)
/// terms: H0, X²/2 and the deformation) is then most of it. Measured over the in-range map on
/// 65 … 4097 nodes against the default grid's film (thirty-fourth session, docs/ehl-model.md): at
/// M ≥ 20 the grids above 0.35 end 10 % to 53 × off, 33 of 66 below zero and 51 without an error
/// estimate; those at or below it within 40 %, none below zero, all but two with an estimate. At
/// M < 20 no grid loses the film (4–30 % off above 0.35): the bound is conservative there.
inline constexpr double finest_film_spacing = 0.35;

/// The finest grid's spacing over √H_est for a fixed grid of options.nodes (0 without one):
/// what finest_film_spacing bounds.
[[nodiscard]] double film_spacing_ratio(const LineContactProblem& problem, const EhlOptions& options);

/// The validator of a fixed finest grid (grid.nodes of the ehl_line case): InputError naming
/// the fewest nodes that resolve the film where options.nodes is coarser than
/// finest_film_spacing·√H_est. Issue 19's "every N from 257", restated as every N whose grid
/// resolves the film. Not applied where coarse grids serve as starts or for friction alone (the
/// thermal solver's nested grids, the ehl_thermal friction law's 81 nodes); there, and on a
/// grid given by grid.levels, a converged film ≤ 0 is rejected after the solve (FasMultigrid).
void refuse_grid_not_resolving_film(const LineContactProblem& problem, const EhlOptions& options);

}  // namespace gearbench::ehl
