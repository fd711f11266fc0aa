#pragma once
// The "ehl" friction law: the friction coefficient of a gear contact point computed by the
// isothermal line-contact EHL solver with Eyring traction (ehl/traction.h), in place of a
// regression. Each distinct contact (load, radius, speeds) is solved once and remembered,
// so a mesh period costs one EHL solve per contact point of the series.
#include <map>
#include <mutex>
#include <tuple>

#include "ehl/line_contact_solver.h"
#include "lubricant/friction_laws.h"

namespace gearbench::efficiency {

class EhlFriction {
 public:
  /// `fluid`: E′, η0, α (or z), rheology models; `eyring_stress`: τ0 [Pa]; `grid`: the EHL
  /// grid (161 nodes by default: the traction changes by < 1 % to 641 nodes, see the tests).
  EhlFriction(const ehl::LineContactData& fluid, double eyring_stress, ehl::EhlOptions grid = default_grid());
  /// |μ| at the contact; throws ConvergenceError naming the contact when the solve fails.
  [[nodiscard]] double coefficient(const lubricant::ContactState& c) const;
  [[nodiscard]] int solves() const { return static_cast<int>(cache_.size()); }

  static ehl::EhlOptions default_grid();

 private:
  ehl::LineContactData fluid_;
  double eyring_stress_ = 0.0;
  ehl::EhlOptions grid_;
  mutable std::map<std::tuple<double, double, double, double>, double> cache_;
  mutable std::mutex mutex_;
};

}  // namespace gearbench::efficiency
