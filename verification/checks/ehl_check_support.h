#pragma once
// What the steady EHL checks share: Moes' film units and a grid series of one Moes point (its
// observed order and Richardson value come from the convergence kit, support/convergence.h).
#include <vector>

#include "ehl/line_contact_problem.h"
#include "support/convergence.h"

namespace gearbench::verification {

/// 1/(R·√U_Σ): metres to Moes' film H = (h/R)·U_Σ^(−1/2), U_Σ = η0(u1 + u2)/(E′R).
inline double moes_units(const ehl::LineContactData& d) { return 1.0 / d.moes_film_scale(); }

/// H_c, H_min (Moes units) and p_max/p_h on 6 grids, each twice as fine as the last.
struct GridSeries {
  std::vector<double> nodes, H_c, H_min, p_max;
};

/// The Moes point (M, L) on levels 4 … 9 above `coarsest_nodes`, by the default solver
/// (a solve that does not converge throws, failing the check).
GridSeries grid_series(double M, double L, int coarsest_nodes);

/// One point of the (M, L) convergence map: 641 nodes, the default solver with its fallbacks.
struct MapPoint {
  double M = 0.0, L = 0.0;
  bool in_range = false;  ///< false: ᾱ = α·p_h > 40 with Barus, refused by the input validation
  bool converged = false;
  int attempts = 0, cycles = 0;
  double H = 0.0;         ///< film at dp/dx = 0, Moes units
};

/// M ∈ {1, 2, 5, 10, 20, 50, 100, 300, 1000} × L ∈ {0, 5, 10, 15, 20, 22.5, 25}, solved once
/// per process (the report's map and the check that holds it share the solves).
const std::vector<MapPoint>& moes_map();

/// Richardson extrapolation of the two finest values of a series for the multigrid's
/// first-order scheme (docs/ehl-model.md).
inline double first_order_richardson(const std::vector<double>& v) {
  return richardson(v[v.size() - 2], v.back(), 1.0);
}

}  // namespace gearbench::verification
