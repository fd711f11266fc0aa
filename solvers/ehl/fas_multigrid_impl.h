#pragma once
// The FAS multigrid's internals (fas_multigrid.h is the interface), one class whose parts live in
// files by responsibility:
//   fas_multigrid.cpp        the hierarchy of grids and the solve's entry;
//   fas_level.h              one grid of the hierarchy (FasLevel);
//   fas_level.cpp            a level's film, coefficients, operator and residuals;
//   fas_relaxation.cpp       the relaxation sweep (Jacobi lines, Gauss–Seidel, change limit);
//   fas_local_treatments.cpp the spike's local Newton solve and the free boundary's sweeps;
//   fas_coarsest.cpp         the start and the direct solve on the coarsest grid;
//   fas_cycle.cpp            restriction, correction, cycles and full multigrid;
//   fas_stop.cpp             the error estimate, the stop rules and the result's figures;
//   fas_acceleration.cpp     the Anderson acceleration of a level's cycles.
// The design and the measurements behind it: docs/research/ehl-multigrid-rebuild.md.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "anderson_mixing.h"
#include "coarsest_solve.h"
#include "fas_level.h"
#include "fas_multigrid.h"
#include "reynolds_stencil.h"


namespace gearbench::ehl {

class KernelJacobian;


class FasMultigrid::Impl {
 public:
  Impl(const LineContactProblem& problem, const EhlOptions& o, ContactState state);
  EhlResult solve(const std::optional<WarmStart>& warm);

  [[nodiscard]] std::vector<double> rho_h();

 private:
  static constexpr double pi = std::numbers::pi;
  /// Order of the discretisation (second-order wedge, central Poiseuille): the error estimate
  /// of H_c from two grids is their difference over 2^p − 1.
  static constexpr double order = 2.0;
  /// The order H_min converges at, lower: the minimum sits at the outlet constriction beside
  /// the free boundary, where the scheme is first order. Measured (eighteenth session) as the
  /// ratio of successive changes on 4097 … 32769 nodes: 2.8–3.0 at (20, 10), (5, 20),
  /// (10, 22.5), 3.6–3.7 at (2, 10), (50, 5), (100, 5), i.e. orders 1.5–1.9, while H_c's read
  /// 3.8–4.0. With order 2, (10, 22.5) stopped on 513 nodes estimating 0.46 % for an H_min
  /// 0.77 % off its converged value (its 257 → 513 change happened to shrink by 3.9).
  static constexpr double order_h_min = 1.5;
  /// The ratio of successive full-multigrid changes from which the grids count as asymptotic
  /// (2^p = 4 in the limit; 2.5 leaves room for a noisy H_min, fas_stop.cpp).
  static constexpr double asymptotic_ratio = 2.5;
  /// Newton steps of the coarsest grid per visit within a cycle (each visit starts from the
  /// last one's solution), and the visit's stop: its merit (squared residual) down by
  /// `coarsest_visit_reduction`, the residual by 100 (an inexact coarse solve: a correction
  /// need not be solved far below the cycle's own factor), or no step moving P and H0 beyond
  /// coarsest_tolerance. Measured (fourteenth session):
  /// - always one step: the six reference factors on 4097 nodes to three digits for 1–36 %
  ///   fewer WU, but a two-level 81-node solve of the thermal solver's Eyring factors (a seed
  ///   004 contact, M 10.7, L 19.8) stalled at a residual of 0.1 for 60 cycles;
  /// - the merit down by 1e-2 (residual by 10): that solve converges, but the Newtonian 1 MN/m
  ///   thermal roller's last solve no longer met its 1e-8 residual (60 iterations, not converged);
  /// - by 1e-4: both converge (22 and 38 iterations, as with three steps to 1e-8); the six
  ///   factors unchanged (0.045, 0.061, 0.210, 0.040, 0.045, 0.170); the maps 71/71 on the
  ///   default grid and 4097, 8193, 16385 nodes; the default map's median 881 → 597 WU (M ≥ 5:
  ///   364 → 292; M ≤ 2: 3018 → 2019; (1, 17.5) 38522 → 22038).
  static constexpr int coarsest_steps_per_visit = 3;
  static constexpr double coarsest_visit_reduction = 1e-4;
  /// Newton steps per stage of the start on the coarsest grid.
  static constexpr int coarsest_steps_per_stage = 30;
  /// Relative change of P and H0 at which a coarsest-grid Newton solve stops; the stages of
  /// the start before the last need only be close enough to start the next.
  static constexpr double coarsest_tolerance = 1e-8;
  static constexpr double homotopy_tolerance = 1e-3;
  /// The largest coarsest grid: its dense (P, H0) solve costs ~n³/3 multiply–adds.
  static constexpr std::size_t max_coarsest_nodes = 1025;
  /// Halvings of a coarsest-grid Newton step before it is taken as it is.
  static constexpr int max_halvings = 6;
  /// Rise of ln η̄ at the Hertz pressure per stage of the start.
  static constexpr double homotopy_step = 8.0;
  /// A dense Newton step on n nodes is counted as n³/150 node-sweeps: its LU takes ~n³/3
  /// multiply–adds, a banded line sweep with the FFT film ~50 per node.
  static constexpr double dense_step_cost = 1.0 / 150.0;
  /// A step with a kept factorization, two triangular solves of n²/2 multiply–adds each, is
  /// counted as n²/50 node-sweeps.
  static constexpr double dense_solve_cost = 1.0 / 50.0;
  /// Multiply–adds counted as one node-sweep (the constant of the two counts above).
  static constexpr double multiply_adds_per_sweep = 50.0;
  /// The spike's Newton step solved by GMRES to this relative residual (an inexact Newton
  /// step: 1e-3 and an exact LU gave H_c and H_min equal to 7 digits at (10, 17.5) on 16385
  /// nodes, nineteenth session), restarted after and stopped at spike_krylov_iterations.
  static constexpr double spike_krylov_tolerance = 1e-3;
  static constexpr int spike_krylov_iterations = 30;
  /// A coarsest-grid step that lowers the merit by less than this factor has the Jacobian
  /// factorized afresh for the next step. The maps hardly depend on it (seventeenth session,
  /// median WU on the default grid and 4097 nodes: 0.1: 124, 115; 0.25: 124, 114; 0.5: 112, 110;
  /// 1, kept until a step does not descend: 119, 116).
  static constexpr double chord_merit_ratio = 0.5;
  /// What a step with a kept factorization counts against a visit's Newton steps. Counted
  /// whole, a visit's three steps reduced its merit less than three Newton steps, and a contact
  /// that main converged in 5 cycles stalled (M 7.3, L 12.1, 1281 nodes, inlet at X = −9.599);
  /// counted a third, the thermal Eyring roller's coupling stopped at 60 iterations with its
  /// pressure solve unconverged; a half converges both (docs/research/ehl-multigrid-sessions.md, seventeenth session).
  /// That the coupling is this sensitive to the coarsest visits is itself a finding.
  static constexpr double chord_step_share = 1.0 / 2.0;

  using Level = FasLevel;

  /// The figures the stop rule watches, dimensionless, and the level's film and pressure,
  /// whose change over the pressurised zone it watches beside them (change_of).
  struct Watched {
    double H_c = 0.0, H_min = 0.0, H0 = 0.0;
    std::vector<double> H, P;
  };

  // --- hierarchy (fas_multigrid.cpp) ---------------------------------------------------
  void add_level();
  /// The coarsest grid: as given, or the fewest nodes, 32·2^k + 1, whose mesh resolves
  /// both the pressure zone (h ≤ max(b, ℓ)/2, coarsest_zone_spacing: b/2 in Hertzian scaling; in
  /// rigid scaling, M < 3, b ≈ 0.72·M·ℓ, and the domain of 43ℓ needs 129 nodes at M = 1, 65 at
  /// M = 2; b/2 alone would refine without bound as M → 0, where the contact is rigid and its
  /// zone ℓ wide) and the film. At high L the load concentrates in the Hertzian zone
  /// (82 % within −1 … 0.5ℓ at (1, 25)); the earlier h ≤ ℓ put 1.5 nodes in b there: after
  /// each 65-node correction the 129-node grid's relaxation and spike solve moved ∫P by
  /// ∓2.4e-2, and the W-cycle's two visits moved H0 by ±0.016 in turn (force balance stalled
  /// at 2.5e-2 on 4097 nodes; fourteenth session). That alternation is what the mixing of the
  /// two visits removes (visit_coarse_twice). The film: the discretisation error of the film, a
  /// difference of O(1) terms (H0, X²/2 and the deformation), is O(h²), so h ≤ c·√H_est is to keep
  /// the coarse film positive (coarsest_film_spacing, which says where it does not; H_est is
  /// Moes' isoviscous film).
  [[nodiscard]] std::size_t coarsest_nodes() const;
  /// The coarsest grid's h ≤ coarsest_zone_spacing·max(b, ℓ). A quarter (fourteenth session, see
  /// above) made the coarsest grid a quarter of the finest at M ≤ 2 (257 of 1025 nodes at M = 1),
  /// whose Newton visits and start were 74 % of the default map's WU. Half stalled the W-cycle's
  /// two coarse visits at light loads and high L until they were mixed (visit_coarse_twice); with
  /// the mixing and W on three levels it converges every map (default grid, 641 … 16385 nodes,
  /// the residual rule on 1025 … 16385 nodes): default-map WU median / p90 / max 91 / 435 / 1167
  /// → 76 / 186 / 311, and 69 / 162 / 269 with one coarsest visit a cycle (twenty-eighth
  /// session). A whole b or ℓ, with W on two levels, left (2, 17.5 … 25) on the default grid
  /// unconverged.
  static constexpr double coarsest_zone_spacing = 0.5;
  /// c of the coarsest grid's h ≤ c·√H_est. At M = 1000 (H_est ≈ 2.6e-4 in Hertzian units) a
  /// 65-node coarsest grid (h ≈ 6√H_est) starts with a negative film and ends in NaN, 129 nodes
  /// (h ≈ 3√H_est) converge: 3 keeps a factor 2 in h from that failure. It does not keep every
  /// coarse film positive: at M = 100 (L 0–10) it gives 33 nodes, whose film is negative
  /// (converged on 65 nodes too; 129 nodes 3× too thin); W-cycles recover on the finer levels
  /// from 513 nodes, V-cycles do not (twentieth session). c = 1 (issue 19's
  /// first rebuild) made the coarsest grid 513 nodes at M = 1000 and 257 at M = 200, whose
  /// dense Newton steps were most of those solves: 7456 → 349 and 1973 → 180 WU on their default
  /// grids, the 71-point map converging on the default grid and on 4097, 8193 and 16385 nodes
  /// (sixteenth session).
  static constexpr double coarsest_film_spacing = 3.0;
  /// The fewest nodes, 32·2^k + 1 (at most 1025), whose spacing over the domain is ≤ h_target.
  [[nodiscard]] std::size_t nodes_resolving(double h_target) const;
  /// For a given finest grid: the levels down to the coarsest grid that is at least as fine
  /// as the sized one, and at least two levels where the film allows (coarsest_ is set to it).
  /// n − 1 = (n_0 − 1)·2^(levels − 1).
  int levels_for_finest(std::size_t nodes);
  /// The transient's (ρ̄H)_old and the thermal factors of the finest grid, injected into
  /// the coarser ones.
  void inject_fields();

  // --- level state (fas_level.cpp) --------------------------------------------
  void update_film(Level& l);

  /// A pressure and its exact film, from which a window's film is updated locally.
  struct FilmBase {
    std::vector<double> P, H;
  };
  /// Nodes first … last (inclusive).
  struct NodeRange {
    std::size_t first = 0, last = 0;
  };
  /// The film of nodes lo … hi when P has changed since `base` only on `changed` (default:
  /// lo … hi): H_k = base.H_k − (D/π)Σ_j K_|k−j|(P_j − base.P_j), O(window²) instead of the
  /// whole grid's FFT; the film outside the window waits for the next full update.
  void update_film_window(Level& l, const FilmBase& base, std::size_t lo, std::size_t hi) const {
    update_film_window(l, base, lo, hi, {lo, hi});
  }
  void update_film_window(Level& l, const FilmBase& base, std::size_t lo, std::size_t hi,
                          NodeRange changed) const;
  /// Its cost in node-sweeps: a node costs one sweep (its coefficients) or its kernel sum over
  /// the changed nodes, whichever is more.
  [[nodiscard]] static double window_film_cost(std::size_t nodes, std::size_t changed) {
    return static_cast<double>(nodes) * std::max(1.0, static_cast<double>(changed) / multiply_adds_per_sweep);
  }

  /// ε = ρ̄H³/(η̄λ) at the nodes and faces (ε_{i+½} the mean of the nodes') and ρ̄, from the
  /// grid's own P and H; ln η̄ rather than η̄, so that ε underflows to 0 where η̄ would
  /// overflow (ᾱP > 709 at a fine-grid Barus spike).
  void update_coefficients(Level& l);
  /// The same for nodes lo … hi and the faces between them.
  void update_coefficients_window(Level& l, std::size_t lo, std::size_t hi);
  void update_node_coefficients(Level& l, std::size_t i) const;

  /// ∂ε_{i+½}/∂H_i and ∂ε_{i+½}/∂H_{i+1} (ε ∝ H³).
  [[nodiscard]] static FilmSensitivity film_sensitivity(const Level& l);

  [[nodiscard]] ReynoldsCoefficients coefficients(const Level& l) const;

  /// The discrete Reynolds operator at interior node i (reynolds_stencil.h).
  [[nodiscard]] double operator_at(const Level& l, std::size_t i) const;

  [[nodiscard]] std::vector<double> residuals(const Level& l) const;

  [[nodiscard]] static double integral(const Level& l);

  /// Residual of the complementarity problem P ≥ 0, r = f − L(P) ≥ 0 (J < 0), P·r = 0:
  /// the mean of |min(P_i·|J_ii|, r_i)| over the interior, scaled by the largest wedge term.
  /// It vanishes exactly at a solution, cavitated nodes included.
  [[nodiscard]] double scaled_residual(Level& l);

  /// A grid becomes the finest of the cycles: its own coefficients, no FAS right-hand sides.
  void make_finest(Level& l);

  [[nodiscard]] static double film_at_centre(const Level& l);

  // --- relaxation (fas_relaxation.cpp) ----------------------------------------
  /// One relaxation sweep (Venner & Lubrecht 2000, §7.3, in one dimension, with the changes
  /// measured in docs/research/ehl-multigrid-rebuild.md): the Jacobi nodes first, each run of
  /// consecutive ones solved simultaneously as a line and its changes distributed with the
  /// zero-sum pattern (−½, 1, −½); then point Gauss–Seidel on the others, which sees the
  /// lines' changes and film. Every change is limited to the exponential's linear range
  /// (limit_change); P ≥ 0. The film of the next nodes follows a Gauss–Seidel change at once
  /// through the kernel's near entries; the full film is recomputed after each pass.
  /// With a `base`, the sweep covers first … end − 1 only and updates the film and the
  /// coefficients in a window around it (update_film_window): the free boundary's sweeps.
  void relax(Level& l, std::size_t first = 1, std::size_t end = 0, const FilmBase* base = nullptr);
  /// The single-grid baseline's cycle (EhlOptions::single_grid): one relaxation sweep, then
  /// H0 += single_grid_h0_gain·(∫P dX − F), the force-balance relaxation of Venner & Lubrecht's
  /// code (`relaxh0`, Multilevel Methods in Lubrication, 2000), which applies it on the coarsest
  /// grid only.
  void relax_single_grid(Level& l);
  /// The gain of that H0 update in Hertzian units (F = π/2). Venner & Lubrecht's `hfact` is 0.1
  /// with V-cycles (0.05 with W, a quarter of either above L = 10 or M = 1000) on a coarsest
  /// grid; on a fine single grid, whose pressure answers H0 over hundreds of sweeps, 0.1 set H0
  /// oscillating with a growing amplitude. Measured at (10, 0) on 257 nodes, sweeps until H_c
  /// and H_min were within the multigrid's claimed accuracy (1.3e-3): 0.01 340, 0.005 340,
  /// 0.002 370, 0.001 820; on 1025 nodes none of 0.01, 0.002, 3e-4 came within its 4.2e-5 in
  /// 2000 sweeps (errors 17.6, 0.37, 0.30: H0 swinging with a period of ~2500 sweeps).
  static constexpr double single_grid_h0_gain = 0.005;

  /// The scale-free relaxation switch: node i is relaxed by Gauss–Seidel where the Poiseuille
  /// diagonal (ε_{i−½} + ε_{i+½})/h² exceeds κ × the wedge term's own diagonal (the film's
  /// kernel response at frozen ε); elsewhere point Gauss–Seidel is not a smoother and the
  /// node joins a Jacobi line (docs/research/ehl-multigrid-rebuild.md, tenth session).
  [[nodiscard]] bool poiseuille_dominates(const Level& l, const ReynoldsCoefficients& c, std::size_t i) const;

  /// Runs of consecutive Jacobi nodes solved simultaneously: the band |k − j| ≤ line_band of
  /// the Jacobian of the distributed change (−½, 1, −½), by sparse LU (Venner & Lubrecht's
  /// line relaxation in one dimension, their init_line/solve_line). Point distributive Jacobi
  /// leaves complex modes of |λ| ≈ 0.6 in the contact, the line removes them (eighth session).
  /// Where a run's LU fails or its change is not finite, the point changes stay. `change`
  /// returns the amplitudes, not yet limited (add_distributed_changes limits P's change).
  /// Nodes that stay at zero (stays_at_zero) are in no line: a cavitated node's residual is
  /// its complementarity slack, not an error, and solved with the line its (clipped) change
  /// skews its pressurised neighbours' (twelfth session: (200, 0) on 1025 nodes stalled at a
  /// force balance of 2e-6 with the last pressurised node's residual at 1e-2).
  /// The work vectors hold the sweep's nodes first, first + 1, … (entry i − first).
  void solve_jacobi_lines(const Level& l, const ReynoldsCoefficients& c, std::size_t first,
                          const std::vector<char>& is_jacobi, const std::vector<double>& residual,
                          std::vector<double>& change) const;

  /// Adds the Jacobi lines' changes: amplitude δ_i (entry i − first) at node i and −δ_i/2 at
  /// i ± 1 (not on a boundary node nor on one the coarse grid holds at zero), then each node's
  /// total change of P limited (limit_change). The limit is on the change of P, not on the
  /// amplitudes: where Poiseuille outweighs the wedge, the line's distributed Jacobian is
  /// nearly a fourth difference, whose solution has large smooth amplitudes that the pattern
  /// cancels to a small change of P. Clipping the amplitudes node by node broke that
  /// cancellation into a sawtooth: (100, 10) on 4097 nodes stalled under the residual rule,
  /// and converges in 9 cycles with the limit on P (twenty-seventh session, docs/research/ehl-multigrid-sessions.md).
  void add_distributed_changes(Level& l, std::size_t first, const std::vector<double>& amplitude) const;

  /// Node i stays at zero in a sweep: held by the coarse grid's truncation, or cavitated
  /// with a residual r_i of the sign that keeps it there (r_i/∂L_i/∂P_i ≤ 0, the rule of the
  /// coarsest grid's Newton step, coarsest_solve.cpp).
  [[nodiscard]] static bool stays_at_zero(const Level& l, std::size_t i, double r, double derivative);

  /// ∂L_i/∂P_i with the piezoviscous response of ε_i: ½(dε_i/dP)(P_{i−1} − 2P_i + P_{i+1})/h²
  /// (faces by the mean of the nodes), where it keeps the derivative negative; at the
  /// pressure spike of high L, ε falls by e^{ᾱΔP} and this term is what the frozen-ε
  /// derivative misses.
  [[nodiscard]] static double gauss_seidel_derivative(const ReynoldsCoefficients& c, std::size_t i);

  /// The film of nodes i − 2 … i + 2 after a change δ of P_i: δH_k = −(D/π)K_|k−i|δ (the
  /// nodes the next residuals read; the far film waits for the sweep's FFT).
  void move_film_near(Level& l, std::size_t i, double delta) const;

  /// A change of P_i limited to |Δ ln ε_i| = |d ln ε/dP|·|ΔP| ≤ change_limit: a linear model
  /// of ε = ρ̄H³e^{−ᾱP} holds only for |ᾱΔP| of order 1, and larger changes (lines at tiny
  /// ξ, Gauss–Seidel next to the spike, corrections from the spike's restricted residual)
  /// are what ran away (docs/research/ehl-multigrid-rebuild.md, tenth session).
  [[nodiscard]] double limit_change(const Level& l, std::size_t i, double change) const;

  // --- local treatments (fas_local_treatments.cpp) ----------------------------
  /// Local Newton solve of the pressure spike: the nodes within ±spike_half_width of it, with
  /// every kernel coupling of the window and ε's film response, H0 fixed, two steps each
  /// halved until the window's complementarity merit falls. The spike is a grid-scale
  /// feature no coarse grid holds (Brandt's local relaxation of a singularity; eighth session:
  /// the W-cycle's factor 0.25 → 0.12 with it). Expects the film current for P (a
  /// relaxation leaves it so); leaves it current on the returned window only (the step after
  /// it brings the rest up to date: a whole-grid update here cost ~1 of a visit's ~6 sweeps).
  /// Without piezoviscosity there is no spike (it is ε's collapse by e^{−ᾱP} at the outlet):
  /// nothing is solved and the range is the pressure maximum's node alone.
  NodeRange relax_spike(Level& l);
  /// The viscosity rises with pressure, so the film has a Barus spike at the outlet.
  [[nodiscard]] bool piezoviscous() const;
  /// The spike window's half-width, spike_half_width·b, in the grid's unit X = x/ℓ: ℓ = b in
  /// Hertzian scaling, ℓ = √(2RH_Martin) ≈ 1.39b/M in rigid scaling (M < 3). Taken in ℓ, the
  /// window was 0.035b at M = 2 and its edge cut the zone past the spike where ε rises from
  /// 1e-56 to O(1): (2, 25) on 8193 nodes stalled at 0.965 (fourteenth session).
  [[nodiscard]] double spike_half_width_in_X() const;
  /// Node-sweeps of solving a Newton step with a KernelJacobian whose band preconditioner is
  /// factorized (the spike's window, the coarsest grid from 257 nodes): two banded triangular
  /// solves (iterations = 0: a range within the band, solved directly) or, per GMRES iteration
  /// and once for the initial residual, a product and the preconditioner's solves.
  [[nodiscard]] static double krylov_solve_cost(const KernelJacobian& J, int iterations);

  /// The outlet's free boundary, a grid-scale feature like the spike: free_boundary_sweeps
  /// extra sweeps over the last free_boundary_window pressurised nodes and a few beyond
  /// (eighth session: (20, 10) on 4097 nodes converges instead of a period-2 oscillation).
  /// Expects the film current for P except for the changes since `before` on `changed` (the
  /// spike's), which it adds in its window; leaves the film current in the window only. The
  /// next reader of the whole film (a relaxation, the restriction, the stop's figures) brings it
  /// up to date: a full film here was wasted on every coarse visit, whose film the restriction
  /// recomputes or nothing reads (seventeenth session: 13–15 % of the WU, the same figures).
  void relax_free_boundary(Level& l, const FilmBase& before, NodeRange changed);

  // --- coarsest grid (fas_coarsest.cpp) ---------------------------------------
  /// Newton steps in (P, H0) on the coarsest grid (coarsest_solve.h) until the step no
  /// longer moves H0 or P beyond `tolerance` (relative) or the merit has fallen by
  /// `merit_reduction` (0: no such stop), at most `steps`. A step reuses the last
  /// factorization (a chord step) after a full step that lowered the merit by
  /// chord_merit_ratio, for the same held nodes; a chord step that does not descend is
  /// repeated with a fresh factorization; a chord step counts chord_step_share of a step.
  /// Measured (seventeenth session, with the free boundary's film change before it), the
  /// 71-point map on the default grid and on 4097, 8193, 16385 nodes: all converge; median WU
  /// 224 → 131, 180 → 111, 146 → 99, 165 → 121; largest 8038 → 3092, 22451 → 5504,
  /// 21622 → 7392, 12469 → 4283; (1, 20) on its default grid 0.65 → 0.06 s.
  void solve_coarsest(Level& l, int steps, double tolerance, double merit_reduction = 0.0);
  /// Factorizes the coarsest grid's Newton matrix at its present iterate with the `held`
  /// nodes fixed; false (failure_ set) where there is none.
  bool factorize_coarsest(Level& l, const ReynoldsCoefficients& c, std::vector<char> held);
  void fail_on_coarsest(const Level& l, StepInfo info);

  /// Σ of the squared complementarity residuals (r_i where P_i > 0, the negative part of r_i
  /// where P_i = 0) and the squared force balance over h: the merit of the coarsest grid's
  /// Newton steps. Leaves the film and coefficients of the current P.
  [[nodiscard]] double coarsest_merit(Level& l);

  /// The residuals of the coarsest grid's Newton step and merit: zero on the nodes held at
  /// zero (Level::cavitated_on_finer), which the step's cavitation rule then keeps at zero
  /// and the merit does not count.
  [[nodiscard]] std::vector<double> coarsest_residuals(const Level& l) const;

  /// The start on the coarsest grid, its work counted as the start's: start_from_nearby from a
  /// nearby contact's solution (ContactState::nearby), start_by_homotopy without one.
  void start_on_coarsest();
  /// The Hertzian guess, then Newton in (P, H0) through a homotopy in the piezoviscous exponent
  /// (η̄^s, s from 0 to 1 in steps that raise ln η̄ at the Hertz pressure by at most homotopy_step), so that
  /// the first solve is isoviscous and each next one starts close to its solution. It costs a
  /// few dense solves on the coarsest grid.
  void start_by_homotopy(Level& l);
  /// The nearby solution injected into the coarsest grid, and Newton in (P, H0) from it at the
  /// full viscosity: a neighbouring time step's pressure is within Newton's reach where the
  /// Hertzian guess is not. Seed 004's 201 steps (thirtieth session): the start 7.6 → 3.8 WU a
  /// step, the whole step 50.4 → 45.5 WU, p_max moved by 1e-6 of itself and h_min not in its
  /// seven digits (the coarsest grid's solution is the same to its tolerance). Started from the
  /// previous step's coarsest solution itself the start took 1.6 WU, but that is the solver's
  /// state, not a result's.
  void start_from_nearby(Level& l);

  /// Semi-ellipse carrying the load on |X| < 1, H0 from Moes' isoviscous asymptotes
  /// (rigid and elastic) converted to these units, and the inlet's pressure (add_inlet_pressure).
  void initial_guess(Level& l);
  /// The guess's pressure upstream of X = −1: the one that carries the contact's flux ρ̄_c·H_c
  /// through the inlet gap, as in Grubin's inlet analysis (Grubin & Vinogradova 1949: Reynolds'
  /// equation integrated once, dp/dx = 12μū(h − h')/h³ with h' the film where dp/dx = 0; as
  /// derived in tribonet's "Grubin's approximation"). With P = 0 there, the inlet's residual,
  /// υ·d(ρ̄H)/dX ≈ X, made the start's merit: 1098 against 2.7 with this pressure at (M 5,
  /// L 2.5) on a 65-node grid with the inlet at X = −8.2. The Newton steps from the Hertzian
  /// guess alone were damped to 1/16 and then found no descent (under the seventeenth session's
  /// rule that they keep the film positive, which this guess made unnecessary); the cycles after
  /// that start failed or not depending on the fourth digit of X_in. From this guess they are
  /// full steps that converge quadratically (eighteenth session).
  void add_inlet_pressure(Level& l);

  // --- cycles (fas_cycle.cpp) -------------------------------------------------
  /// One V- or W-cycle from level k: pre-smoothing, the FAS coarse problem solved by γ
  /// cycles of the next level (the coarsest directly), the correction, post-smoothing, then
  /// the local treatments of the spike and the free boundary.
  void cycle(std::size_t k) { cycle(k, o_.cycle); }
  void cycle(std::size_t k, CycleType type);

  /// Correction by linear interpolation, applied only inside the pressurised zone (not on
  /// cavitated nodes nor next to them); each change limited like a relaxation change.
  void correct(const Level& coarse, const std::vector<double>& injected, Level& fine) const;

  /// FAS coarse problem: injected pressure and film, the coarse grid's own (live)
  /// coefficients, f_c = L_c(P̄) + R·r (full weighting; no residual where the fine pressure
  /// is cavitated), g_c = ∫P̄ + (g − ∫P); coarse nodes whose fine node is cavitated are held
  /// at zero (Level::cavitated_on_finer).
  void restrict_problem(Level& fine, Level& coarse);

  /// Full multigrid: each level's solution, interpolated, starts the next, which gets one
  /// cycle. The change of H_c and H_min from one level to the next over 2^p − 1 estimates
  /// the discretisation error; with levels chosen by target_error, levels are added until
  /// the estimate is below it. False when a level missed the error rule (r says which).
  [[nodiscard]] bool full_multigrid(EhlResult& r);
  /// Whether full multigrid stops at `levels` levels: a fixed grid's count, the error target
  /// met (from three levels), or the cap.
  [[nodiscard]] bool grid_complete(const EhlResult& r, std::size_t levels) const;

  /// FMG interpolation: cubic in the interior (4-point), linear next to the ends.
  static void interpolate_solution(const Level& coarse, Level& fine);

  /// A previous solution on the finest grid (the last time step) as the start.
  void start_from(const WarmStart& warm);

  // --- stop and figures (fas_stop.cpp) ----------------------------------------
  /// The relative change of a figure between the full-multigrid levels `back` and `back` + 1
  /// below the last (0: the last level's change).
  [[nodiscard]] static double level_change(std::span<const double> figures, std::size_t back = 0);
  [[nodiscard]] static double level_error_estimate(std::span<const double> figures, double p);
  /// A new full-multigrid level: the previous level's h_min and p_max become the coarse ones.
  void record_fmg_level(EhlResult& r, std::size_t k);

  [[nodiscard]] Watched watched(Level& l);

  /// The level's figures after a cycle replace its full-multigrid ones, and the error
  /// estimate is recomputed from them.
  void update_fmg_level(EhlResult& r, std::size_t k);

  /// Cycles on level k until the algebraic error left (change_of, times ρ/(1 − ρ)) and the force
  /// balance are below error_fraction of the discretisation-error estimate, which is recomputed each
  /// cycle from the level's figures and the converged coarser levels'. The Barus pressure spike
  /// is left out: p_max does not converge with the grid (docs/ehl-model.md).
  /// `fmg_change`: the level's full-multigrid cycle's change from the interpolated start (the
  /// previous change of the figures' own per-cycle factor).
  /// `first_film_estimate`: the estimate while the level has none of its own, the first with a
  /// film after levels without one (update_fmg_level), so that the next level's estimate rests
  /// on a converged level (NaN: none).
  void iterate_to_error(EhlResult& r, std::size_t k, double fmg_change,
                        double first_film_estimate = std::numeric_limits<double>::quiet_NaN());
  /// The index of the first of the trailing full-multigrid levels whose film is positive (their
  /// count: none when the last level's is not).
  [[nodiscard]] static std::size_t first_level_with_film(const EhlResult& r);
  /// Whether level k's full-multigrid cycle alone, which changed the figures by `change` from
  /// the interpolated start, meets iterate_to_error's rule at the factor measured on the last
  /// coarser level that iterated. Accepts the level (r) if so.
  [[nodiscard]] bool fmg_cycle_reaches_error(EhlResult& r, std::size_t k, double change);
  /// The discretisation error the last full-multigrid change alone gives, δ_k/(2^p − 1) for
  /// H_c and H_min: at most the level's estimate (level_error_estimate).
  [[nodiscard]] static double last_change_estimate(const EhlResult& r);
  /// The largest relative change between two states of H_c, H_min and H0 (H0's against H_c).
  [[nodiscard]] static double figures_change(const Watched& now, const Watched& before);
  /// figures_change and film_change, the larger: the change the stop rule reads.
  [[nodiscard]] static double change_of(const Watched& now, const Watched& before);
  /// The largest change of the film at a node pressurised in either state, over H_min.
  [[nodiscard]] static double film_change(const Watched& now, const Watched& before);
  /// The discretisation-error rule as the result states it, at the bound of the last level.
  [[nodiscard]] std::string error_rule(double bound) const;

  /// Cycles until the scaled residual and the force balance meet the tolerance.
  void iterate_to_residual(EhlResult& r);
  /// A warm start's cycles on the finest grid to iterate_to_error's rule, at the nearby
  /// solution's estimate (WarmStart::error_estimate): the finest grid is the only level, and
  /// its first cycle plays full multigrid's, the nearby solve's factor the floor of its own.
  void iterate_warm_start_to_error(EhlResult& r, const WarmStart& warm);

  // --- acceleration of the cycles (fas_acceleration.cpp) ------------------------------
  /// Anderson acceleration of a level's cycles (EhlOptions::acceleration_depth): a cycle is a
  /// fixed-point map G of the level's state x = (P, H0), and the next cycle starts from the
  /// mixture of the last states and their images (AndersonMixing; Walker & Ni 2011). This is
  /// Krylov acceleration of nonlinear multigrid (Washio & Oosterlee, ETNA 6 (1997) 271–290):
  /// it removes the few slow modes a cycle leaves, here the one no coarse grid holds, the
  /// Barus spike's load answering the coarse grid's H0 correction (docs/research/ehl-multigrid-sessions.md,
  /// twenty-first and twenty-seventh sessions). A mixed start whose scaled residual or force
  /// balance is above the cycle's own image's is not taken: the image is, and the history
  /// starts again (a mixture of two spikes is not a spike, and P ≥ 0 clips it).
  struct CycleAcceleration {
    std::unique_ptr<AndersonMixing> mixing;  ///< null: plain cycles
    std::vector<double> start;              ///< (P, H0) the last cycle started from
  };
  [[nodiscard]] CycleAcceleration start_acceleration(const Level& l) const;
  /// After a cycle from a.start to its image (l.P, H0_), whose scaled residual and force
  /// balance are the last of r's histories: sets the next cycle's start.
  void accelerate(CycleAcceleration& a, Level& l, const EhlResult& r);
  /// A fresh mixing history (none for plain cycles and for the single-grid baseline, whose
  /// sweeps are the benchmarks' unaccelerated reference).
  [[nodiscard]] std::unique_ptr<AndersonMixing> new_mixing() const;
  /// Sets level l's P (≥ 0, zero where the finer grid is cavitated) and H0 to the state x.
  void set_state(Level& l, const std::vector<double>& x);
  /// The W-cycle's two visits of level k (below a W level), the second's image mixed with the
  /// first's by Anderson's depth-1 step (the secant of the two visits): the nonlinear analogue
  /// of the K-cycle, whose two coarse iterations are combined by a Krylov step (Notay &
  /// Vassilevski, Numer. Linear Algebra Appl. 15 (2008) 473–487). Without it, where the level
  /// holds the Barus spike's load but not its response to H0 (a grid too coarse for the
  /// spike), the two visits' H0 corrections alternate: at (1, 25) with a 129-node coarsest
  /// grid the 257-node level's spike solve moved the force balance by ±3.9e-2 after each, and
  /// the 513-node level's cycles stalled at 3.7e-2 (docs/research/ehl-multigrid-sessions.md, twenty-eighth session).
  /// The mixture is taken unguarded: the level's correction and relaxation follow it, and a
  /// guard like accelerate()'s changed no map's convergence (all 0 failures, medians within 2 %).
  /// Not for the coarsest grid (k = 0), which a W-cycle visits once (cycle()). The mixing's few
  /// vector operations are not counted (as correct()'s are not).
  void visit_coarse_twice(std::size_t k);

  /// Appends the fine grid's scaled residual and force balance to the histories, and sets
  /// convergence_factor from them (mean_factor).
  void record_residual(EhlResult& r, Level& fine);
  /// The geometric mean of the per-cycle factors over a residual history, (last/first)^(1/(n − 1));
  /// NaN with fewer than two entries. EhlResult::convergence_factor is this of its history.
  [[nodiscard]] static double mean_factor(const std::vector<double>& history);

  /// The larger of the last two per-cycle factors of the scaled residual (the first cycle's
  /// against the residual after full multigrid).
  [[nodiscard]] static double residual_factor(const EhlResult& r, double after_fmg);

  /// A residual or force balance that is not finite, or above 10 (scaled: a first cycle
  /// starts near 1e-2), does not come back; nor does an iteration with a failure_.
  [[nodiscard]] bool diverged(const EhlResult& r) const;

  void accept(EhlResult& r, std::string message);

  static void reject(EhlResult& r, std::string message);

  void fill_figures(const Level& l, EhlResult& r) const;
  /// A converged answer with a film ≤ 0 rejected (the grid does not resolve the film), and one
  /// the error rule could not estimate (`unestimated`) marked as of unknown accuracy.
  void qualify_answer(EhlResult& r, bool unestimated) const;

  // --- helpers ---------------------------------------------------------------------------
  [[nodiscard]] double force_balance(const Level& l) const { return std::abs(integral(l) - l.g) / state_.load; }

  [[nodiscard]] static double last(const std::vector<double>& v) { return v.empty() ? 0.0 : v.back(); }

  [[nodiscard]] double work_units() const { return node_sweeps_.total() / static_cast<double>(levels_.back()->n); }
  /// The node-sweeps of the coarsest grid's Newton steps: the start's, or a cycle's visit's.
  [[nodiscard]] double& coarsest_sweeps() { return starting_ ? node_sweeps_.start : node_sweeps_.coarsest; }
  /// Runs iterate(), counting its work as the stop rule's iterations (EhlResult::work_units_iterating).
  template <typename Iterate>
  void counted_as_iterating(Iterate iterate) {
    const double before = node_sweeps_.total();
    iterate();
    iterating_sweeps_ += node_sweeps_.total() - before;
  }
  /// The last pressurised node (the outlet's free boundary); 0 if none.
  [[nodiscard]] static std::size_t last_pressurised(const std::vector<double>& P);
  /// The pressure spike: the last local maximum of P before the outlet's cavitation.
  [[nodiscard]] static std::size_t spike_index(const std::vector<double>& P);
  /// Relative change |a − b|/|b|, 0 for b = 0 = a.
  [[nodiscard]] static double relative(double a, double b);

  LineContactProblem problem_;
  EhlOptions o_;
  ContactState state_;
  double x_in_ = 0.0, x_out_ = 0.0;
  std::size_t coarsest_ = 0;  ///< nodes of the coarsest grid
  std::vector<std::unique_ptr<Level>> levels_;
  double H0_ = 0.0;
  double viscosity_exponent_ = 1.0;  ///< s of the start's homotopy η̄^s (1 after the start)
  /// Work by part: Σ nodes of every sweep, dense steps by their flops.
  EhlWork node_sweeps_;
  double iterating_sweeps_ = 0.0;  ///< of it, the cycles after the levels' full-multigrid cycles
  bool starting_ = false;          ///< start_on_coarsest is running
  double coarse_h_min_ = 0.0, coarse_p_max_ = 0.0, level_h_min_ = 0.0, level_p_max_ = 0.0;
  bool has_level_ = false;   ///< a full-multigrid level was recorded
  bool has_coarse_ = false;  ///< a solution on the next-coarser grid was recorded (full multigrid)
  /// The per-cycle factor ρ at which the last level that iterated to its error was accepted,
  /// and that level's nodes (fmg_cycle_reaches_error); ρ ≥ 1 until one has.
  double measured_factor_ = 1.0;
  std::size_t factor_nodes_ = 0;
  /// The factors the last two levels that iterated to their error measured from their own
  /// cycles, before any floor, newest last; the larger is the floor of the next level's ρ
  /// (iterate_to_error, level_factor_floor). 0 until a level has.
  std::array<double, 2> level_factors_{0.0, 0.0};
  [[nodiscard]] double level_factor_floor() const { return std::max(level_factors_[0], level_factors_[1]); }
  /// Why the iteration cannot go on (a coarsest grid without a Newton step); empty while it can.
  /// The solve then ends unconverged with this message: a status, not an exception.
  std::string failure_;
  /// The coarsest grid's factorized Newton matrix, kept across steps and visits.
  CoarsestNewton coarsest_newton_;
};

}  // namespace gearbench::ehl
