#include "load_sharing.h"

#include <algorithm>
#include <fmt/format.h>

#include "model/errors.h"

namespace gearbench::geometry {

double IsoLoadSharing::spur_share(const GearPairGeometry& g, double s) {
  const auto& p = g.path();
  if (s < p.A || s > p.E) return 0.0;
  // ε_α ≥ 2 has no single-contact zone: B lies beyond D. The ISO rule is defined for
  // 1 ≤ ε_α < 2; beyond it, fall back to equal sharing.
  if (p.B >= p.D) return 1.0 / g.pairs_in_contact(s);
  if (s < p.B) return 1.0 / 3.0 + (s - p.A) / (3.0 * (p.B - p.A));
  if (s <= p.D) return 1.0;
  return 1.0 / 3.0 + (p.E - s) / (3.0 * (p.E - p.D));
}

double IsoLoadSharing::share(const GearPairGeometry& g, double s) const {
  const double eps_beta = g.contact_ratio_overlap();
  const double helical = 1.0 / g.contact_ratio_transverse();
  if (eps_beta >= 1.0) return (s < g.path().A || s > g.path().E) ? 0.0 : helical;
  return (1.0 - eps_beta) * spur_share(g, s) +
         eps_beta * ((s < g.path().A || s > g.path().E) ? 0.0 : helical);
}

double EqualLoadSharing::share(const GearPairGeometry& g, double s) const {
  if (s < g.path().A || s > g.path().E) return 0.0;
  return 1.0 / std::max(1, g.pairs_in_contact(s));
}

std::unique_ptr<LoadSharing> make_load_sharing(const std::string& name, const std::string& key) {
  if (name == "iso") return std::make_unique<IsoLoadSharing>();
  if (name == "equal") return std::make_unique<EqualLoadSharing>();
  throw InputError(fmt::format("{} = \"{}\": allowed values are iso, equal", key, name));
}

}  // namespace gearbench::geometry
