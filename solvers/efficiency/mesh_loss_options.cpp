// The case keys of the mesh-loss solver (issue 21: one table per Options).
#include <fmt/format.h>

#include "mesh_loss.h"
#include "model/errors.h"

namespace gearbench::efficiency {
namespace {

using lubricant::FrictionModel;
using model::Range;

model::OptionTable<MeshLossOptions> make_friction_table() {
  model::OptionTable<MeshLossOptions> t;
  std::vector<std::pair<std::string, FrictionModel>> models;
  for (const auto m : {FrictionModel::constant, FrictionModel::xu_kahraman, FrictionModel::benedict_kelley,
                       FrictionModel::iso14179, FrictionModel::mixed, FrictionModel::ehl})
    models.emplace_back(lubricant::friction_model_name(m), m);
  t.choice("model", &MeshLossOptions::friction_model, models,
           {.description = "friction law: a constant mu, Xu-Kahraman, Benedict-Kelley, ISO/TR 14179-2, the mixed "
                           "law of seed 000, or the isothermal EHL solver with Eyring traction"});
  t.number("mu", &MeshLossOptions::friction_coefficient, Range::closed(0.0, 0.5),
           {.description = "the constant friction coefficient; required with model \"constant\", refused with the others"});
  t.number("mu_boundary", &MeshLossOptions::boundary_friction, Range::closed(0.07, 0.15),
           {.description = "boundary friction mu_BL of the mixed law (seed 000: measured 0.07-0.15)"});
  t.number("lubricant_factor", &MeshLossOptions::lubricant_factor, Range{0.0, 2.0, true, false},
           {.description = "X_L of ISO/TR 14179-2 (mineral oil 1)"});
  t.number("eyring_stress_MPa", &MeshLossOptions::eyring_stress, Range{0.0, 1e3, true, false},
           {.description = "Eyring stress tau0 of the \"ehl\" law; required there, refused elsewhere", .unit = "MPa",
            .scale = 1e6});
  // Which keys a law takes depends on the law: mu belongs to the constant law alone, given or
  // not (the default 0.05 stands only while no friction section is written).
  t.after_read([](model::ObjectReader& r, const MeshLossOptions& o) {
    const bool constant = o.friction_model == FrictionModel::constant;
    const auto name = lubricant::friction_model_name(o.friction_model);
    if (constant && !r.has("mu")) throw InputError(r.key_path("mu") + ": missing, required for friction.model = constant");
    if (!constant && r.has("mu"))
      throw InputError(fmt::format("{} = {}: applies to friction.model = constant only (model is {})", r.key_path("mu"),
                                   model::format_value(o.friction_coefficient), name));
  });
  t.rule([](const MeshLossOptions& o, const std::string& prefix) {
    const bool ehl = o.friction_model == FrictionModel::ehl;
    if (ehl && !o.eyring_stress)
      throw InputError(prefix + "eyring_stress_MPa: missing, required by friction.model = \"ehl\"");
    if (!ehl && o.eyring_stress)
      throw InputError(prefix + "eyring_stress_MPa: applies to friction.model = \"ehl\" only");
  });
  return t;
}

model::OptionTable<MeshLossOptions> make_table() {
  model::OptionTable<MeshLossOptions> t;
  t.section("friction", [](auto& o) -> auto& { return o; }, MeshLossOptions::friction_table(),
            {.description = "the friction law and its parameters"});
  t.choice("load_sharing", &MeshLossOptions::load_sharing, {"equal", "iso", "stiffness"},
           {.description = "load sharing between the pairs in contact: equal (Ohlendorf), iso (ISO 6336 / TR "
                           "15144-1 X_Y) or stiffness (energy-method pair stiffness); helical pairs: equal only"});
  t.number("rolling_loss_constant_Pa", &MeshLossOptions::rolling_loss_constant, Range::closed(0.0, 1e11),
           {.description = "C_r of the rolling loss P_r = C_r h_min u_mean l cos(alpha_wt) (seed 004 eq. 9; "
                           "9e9 reads the equation as printed)", .unit = "Pa"});
  t.integer("positions", &MeshLossOptions::positions, 2, 1000000,
            {.description = "mesh positions over one mesh period (the output series)"});
  t.integer("points_per_line", &MeshLossOptions::points_per_line, 1, 100000,
            {.description = "helical pairs: midpoints along every contact line"});
  return t;
}

}  // namespace

const model::OptionTable<MeshLossOptions>& MeshLossOptions::friction_table() {
  static const auto t = make_friction_table();
  return t;
}

const model::OptionTable<MeshLossOptions>& MeshLossOptions::table() {
  static const auto t = make_table();
  return t;
}

}  // namespace gearbench::efficiency
