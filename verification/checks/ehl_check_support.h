#pragma once
// What the steady EHL checks share: Moes' film units, a grid series of one Moes point and the
// (M, L) map at the default settings (a series' observed order and Richardson value come from
// the convergence kit, support/convergence.h).
#include <algorithm>
#include <cmath>
#include <vector>

#include "check_registry.h"
#include "ehl/line_contact_problem.h"
#include "ehl/line_contact_solver.h"
#include "model/errors.h"
#include "support/convergence.h"

namespace gearbench::verification {

/// The report section of the steady isothermal solver's checks, whichever file holds them.
inline constexpr const char* steady_ehl_section = "Multigrid line-contact EHL (steady, isothermal)";

/// 1/(R·√U_Σ): metres to Moes' film H = (h/R)·U_Σ^(−1/2), U_Σ = η0(u1 + u2)/(E′R).
inline double moes_units(const ehl::LineContactData& d) { return 1.0 / d.moes_film_scale(); }

/// H_c, H_min (Moes units), p_max/p_h and work units on grids each twice as fine as the last.
struct GridSeries {
  std::vector<double> nodes, H_c, H_min, p_max, work_units;
};

/// The Moes point (M, L) on the given finest grids, each solved to 1 % of its own
/// discretisation-error estimate (a solve that does not converge throws, failing the check).
GridSeries grid_series(double M, double L, const std::vector<int>& nodes);

/// A contact's film converged in both the grid and the domain: 32769 nodes, the inlet at 1.5
/// times the default distance. The default inlet's film deficit is at most 1e-3 by its rule
/// (LineContactProblem::x_in), and the deficit falls as X_in⁻³ (it goes as g(X_in)^−1.5 and
/// the gap as X²), so ≤ 3e-4 here; the discretisation error on 32769 nodes is ≤ 1e-4 where the
/// default's is ≤ 5e-3 (H_c's falls as h²; H_min's at order 1.5–1.9 on the Moes map and
/// 1.0–1.4 at seed 004's Roelands contacts, ≤ 1.5e-4 there). At (5, 25) on twice the
/// inlet distance (X_in = −29.1) the solve on 16385 and 32769 nodes stalls at a force balance of
/// 1e-4: 1.5 times converges (eighteenth session). A reference may take the cycles it needs:
/// there the spike's slow mode contracts at ~0.5 a cycle on 32769 nodes, 52 cycles with two
/// pre-sweeps and 61 with the default's one (twenty-ninth session), past the default's cap.
struct ConvergedFilm {
  double h_central, h_min;  ///< [m]
};
ConvergedFilm converged_film(const ehl::LineContactProblem& p);

/// A default answer's relative errors of H_c and H_min against its converged film, with the
/// solve's own estimate.
struct FilmError {
  double M, L, nodes, H_c, H_min, estimate;
  [[nodiscard]] double worst() const { return std::max(std::abs(H_c), std::abs(H_min)); }
};

/// The largest error of `errors`, where it is, and every answer's figures.
CheckValue worst_film_error(const std::vector<FilmError>& errors);

/// One point of the (M, L) map: the default settings (grid chosen by the 1 % target).
struct MapPoint {
  double M = 0.0, L = 0.0;
  bool in_range = false;  ///< false: ᾱ = α·p_h > 40 with Barus, refused by the input validation
  /// The fixed grid does not resolve the film: refused by the grid's validation
  /// (ehl::refuse_grid_not_resolving_film), as `gearbench run` refuses it.
  bool refused = false;
  bool converged = false;
  int cycles = 0;
  double nodes = 0.0, work_units = 0.0, error_estimate = 0.0;
  double H = 0.0;         ///< film at dp/dx = 0, Moes units
  double H_c = 0.0, H_min = 0.0;  ///< central and minimum film, Moes units
};

/// M ∈ {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000} × L ∈ {0, 2.5, …, 25}, at the default settings
/// or (nodes > 0) on that fixed finest grid, solved once per process and grid (the report's maps
/// and the checks that hold them share the solves).
const std::vector<MapPoint>& moes_map(int nodes = 0);

/// Whether `gearbench run` accepts the fixed grid of `o` for this contact: the validator itself
/// (ehl::refuse_grid_not_resolving_film), so that the checks judge what a user gets.
inline bool grid_accepted(const ehl::LineContactProblem& p, const ehl::EhlOptions& o) {
  try {
    ehl::refuse_grid_not_resolving_film(p, o);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

/// The fixed grids issue 19 asks the whole map on.
inline constexpr int fixed_map_grids[] = {641, 2561, 16385};

/// The coarser grids of issue 19's range "every N from 257 to 16385" (2.5 s of solves in all:
/// fast tier, no report table).
inline constexpr int coarse_map_grids[] = {257, 513, 1025, 2049};

/// Richardson extrapolation of the two finest values of a series for a scheme of order p.
inline double richardson(const std::vector<double>& v, double p) { return richardson(v[v.size() - 2], v.back(), p); }

}  // namespace gearbench::verification
