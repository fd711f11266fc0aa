// The gear kinds' EHL fluid and NaN-free JSON output.
#include "ehl_sections.h"

#include <cmath>
#include <fmt/format.h>

#include "model/errors.h"

namespace gearbench::app {

/// Non-finite numbers become null: diagnostics of a failed solve may hold them.
nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
bool newtonian_friction_in_range(double mu) { return std::abs(mu) <= 1.0; }

std::string withheld_friction_note(double mu, const std::string& whose) {
  return fmt::format("{}Newtonian traction would exceed the normal load (friction coefficient {:.3g}): outside "
                     "the Newtonian model, so no friction is given; the film figures stand (a lubricant's shear "
                     "stress is limited: the efficiency kind's \"ehl\" law and the thermal kinds' "
                     "lubricant.eyring_stress_MPa limit it by an Eyring stress)",
                     whose.empty() ? "the " : whose + " ", mu);
}

nlohmann::json work_by_part_json(const ehl::EhlWork& w) {
  return {{"start", w.start},       {"relaxation", w.relaxation},       {"restriction", w.restriction},
          {"coarsest", w.coarsest}, {"spike", w.spike},                 {"free_boundary", w.free_boundary},
          {"interpolation", w.interpolation}, {"acceleration", w.acceleration}};
}

nlohmann::json finite_vector(const std::vector<double>& v, double scale) {
  nlohmann::json out = nlohmann::json::array();
  for (double x : v) out.push_back(finite_or_null(x * scale));
  return out;
}

ehl::LineContactData gear_fluid(const model::GearCase& c, const std::string& kind) {
  if (!c.operating) throw InputError("operating: missing required key (kind " + kind + ")");
  if (!c.materials) throw InputError("materials: missing required key (kind " + kind + ")");
  if (!c.lubricant) throw InputError("lubricant: missing required key (kind " + kind + ")");
  return ehl::LineContactData::from_gear_media(*c.materials, *c.lubricant);
}

}  // namespace gearbench::app
