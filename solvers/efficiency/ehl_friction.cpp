#include "ehl_friction.h"

#include <cmath>
#include <fmt/format.h>

#include "ehl/traction.h"
#include "model/errors.h"

namespace gearbench::efficiency {

ehl::EhlOptions EhlFriction::default_grid() {
  ehl::EhlOptions o;
  o.nodes = 161;
  return o;
}

EhlFriction::EhlFriction(const ehl::LineContactData& fluid, double eyring_stress, ehl::EhlOptions grid)
    : fluid_(fluid), eyring_stress_(eyring_stress), grid_(std::move(grid)) {
  if (!(eyring_stress > 0.0 && eyring_stress <= 1e9))
    throw InputError(fmt::format("friction.eyring_stress_MPa = {}: allowed range is (0, 1000]", eyring_stress * 1e-6));
  grid_.validate();
}

double EhlFriction::coefficient(const lubricant::ContactState& c) const {
  const auto key = std::make_tuple(c.load_per_length, c.reduced_radius, c.u1, c.u2);
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
  }
  ehl::LineContactData d = fluid_;
  d.load_per_length = c.load_per_length;
  d.reduced_radius = c.reduced_radius;
  d.u1 = c.u1;
  d.u2 = c.u2;
  const ehl::LineContactProblem problem(d);
  ehl::EhlResult r;
  try {
    r = ehl::LineContactSolver(problem, grid_).solve();
  } catch (const ConvergenceError& e) {
    throw ConvergenceError(fmt::format("friction.model = \"ehl\": the EHL solve at w {:.4g} N/m, R {:.4g} m, "
                                       "u [{:.4g}, {:.4g}] m/s (Moes M {:.3g}, L {:.3g}) failed: {}",
                                       d.load_per_length, d.reduced_radius, d.u1, d.u2, d.moes_M(), d.moes_L(),
                                       e.what()));
  }
  const double mu = std::abs(ehl::eyring_traction(problem, r, eyring_stress_).coefficient);
  const std::lock_guard<std::mutex> lock(mutex_);
  cache_.emplace(key, mu);
  return mu;
}

}  // namespace gearbench::efficiency
