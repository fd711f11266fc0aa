#include "involute.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gearbench::geometry {

double involute(double alpha) { return std::tan(alpha) - alpha; }

double inverse_involute(double value) {
  if (!(value >= 0.0) || value > involute(85.0 * M_PI / 180.0))
    throw std::domain_error("inverse_involute: argument outside [0, inv 85 deg]");
  if (value == 0.0) return 0.0;
  // Both starts lie above the root (inv α > α³/3, and tan α = value + α < value + π/2),
  // and f is convex and increasing, so Newton descends monotonically onto the root.
  double alpha = std::min(std::cbrt(3.0 * value), std::atan(value + M_PI / 2.0));
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double t = std::tan(alpha);
    const double step = (t - alpha - value) / (t * t);
    alpha -= step;
    if (std::abs(step) <= 1e-15 * alpha) return alpha;
  }
  return alpha;  // Newton converges quadratically from the series start; 50 is a guard.
}

}  // namespace gearbench::geometry
