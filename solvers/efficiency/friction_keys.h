#pragma once
// The keys of a case's "friction" section, declared once for every Options that holds a
// friction law in the members friction_model, friction_coefficient, boundary_friction and
// lubricant_factor: the mesh-loss solver's (efficiency::MeshLossOptions) and the dynamics
// models' (dynamics::FrictionLawOptions). Each holder offers the laws it can evaluate.
#include <fmt/format.h>
#include <string>
#include <utility>
#include <vector>

#include "lubricant/friction_laws.h"
#include "model/errors.h"
#include "model/option_table.h"

namespace gearbench::efficiency {

namespace detail {
/// What a law is, for the key's description.
inline std::string friction_law_text(lubricant::FrictionModel m) {
  using lubricant::FrictionModel;
  switch (m) {
    case FrictionModel::constant: return "a constant mu";
    case FrictionModel::xu_kahraman: return "Xu-Kahraman";
    case FrictionModel::benedict_kelley: return "Benedict-Kelley";
    case FrictionModel::iso14179: return "ISO/TR 14179-2";
    case FrictionModel::mixed: return "the mixed law of seed 000";
    case FrictionModel::ehl: return "the isothermal EHL solver with Eyring traction";
    case FrictionModel::ehl_thermal: return "the thermal EHL solver with a Ree-Eyring film (tau0 from the lubricant)";
  }
  return lubricant::friction_model_name(m);
}
}  // namespace detail

/// Adds "model" (one of `laws`), "mu", "mu_boundary" and "lubricant_factor" to `t`, and the
/// rule that "mu" belongs to the constant law alone.
template <class O>
void add_friction_keys(model::OptionTable<O>& t, const std::vector<lubricant::FrictionModel>& laws) {
  using model::Range;
  std::vector<std::pair<std::string, lubricant::FrictionModel>> names;
  std::string texts;
  for (const auto m : laws) {
    names.emplace_back(lubricant::friction_model_name(m), m);
    texts += (texts.empty() ? "" : ", ") + detail::friction_law_text(m);
  }
  t.choice("model", &O::friction_model, names, {.description = "friction law: " + texts});
  t.number("mu", &O::friction_coefficient, Range::closed(0.0, 0.5),
           {.description = "the constant friction coefficient; required with model \"constant\", refused with the "
                           "others"});
  t.number("mu_boundary", &O::boundary_friction, Range::closed(0.07, 0.15),
           {.description = "boundary friction mu_BL of the mixed law (seed 000: measured 0.07-0.15)"});
  t.number("lubricant_factor", &O::lubricant_factor, Range{0.0, 2.0, true, false},
           {.description = "X_L of ISO/TR 14179-2 (mineral oil 1)"});
  // Which keys a law takes depends on the law: mu belongs to the constant law alone, given or
  // not (the holder's default stands only while no friction section is written).
  t.after_read([](model::ObjectReader& r, const O& o) {
    const bool constant = o.friction_model == lubricant::FrictionModel::constant;
    const auto name = lubricant::friction_model_name(o.friction_model);
    if (constant && !r.has("mu")) throw InputError(r.key_path("mu") + ": missing, required for friction.model = constant");
    if (!constant && r.has("mu"))
      throw InputError(fmt::format("{} = {}: applies to friction.model = constant only (model is {})", r.key_path("mu"),
                                   model::format_value(o.friction_coefficient), name));
  });
}

}  // namespace gearbench::efficiency
