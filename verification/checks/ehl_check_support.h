#pragma once
// What the steady EHL checks share: Moes' film units, a grid series of one Moes point, and the
// observed order and Richardson value of such a series.
#include <cmath>
#include <vector>

#include "ehl/line_contact_problem.h"

namespace gearbench::verification {

/// 1/(R·√U_Σ): metres to Moes' film H = (h/R)·U_Σ^(−1/2), U_Σ = η0(u1 + u2)/(E′R).
inline double moes_units(const ehl::LineContactData& d) {
  return 1.0 / (d.reduced_radius * std::sqrt(d.viscosity * (d.u1 + d.u2) / (d.reduced_modulus * d.reduced_radius)));
}

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

/// log2 of the ratio of the last two changes of a series on grids halving h.
inline double observed_order(const std::vector<double>& v) {
  const std::size_t n = v.size();
  return std::log2((v[n - 3] - v[n - 2]) / (v[n - 2] - v[n - 1]));
}

/// Richardson extrapolation of the two finest values for a first-order scheme.
inline double richardson(const std::vector<double>& v) { return 2.0 * v.back() - v[v.size() - 2]; }

}  // namespace gearbench::verification
