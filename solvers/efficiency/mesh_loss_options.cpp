// The case keys of the mesh-loss solver (issue 21: one table per Options).
#include <fmt/format.h>

#include "ehl_friction.h"
#include "friction_keys.h"
#include "mesh_loss.h"
#include "model/errors.h"

namespace gearbench::efficiency {
namespace {

using lubricant::FrictionModel;
using model::Range;

model::OptionTable<MeshLossOptions> make_friction_table() {
  model::OptionTable<MeshLossOptions> t;
  add_friction_keys(t, {FrictionModel::constant, FrictionModel::xu_kahraman, FrictionModel::benedict_kelley,
                        FrictionModel::iso14179, FrictionModel::mixed, FrictionModel::ehl,
                        FrictionModel::ehl_thermal});
  t.number("eyring_stress_MPa", &MeshLossOptions::eyring_stress, EhlFriction::eyring_stress_range(),
           {.description = "Eyring stress tau0 of the \"ehl\" law; required there, refused elsewhere", .unit = "MPa",
            .scale = 1e6});
  t.rule([](const MeshLossOptions& o, const std::string& prefix) {
    const bool ehl = o.friction_model == FrictionModel::ehl;
    if (ehl && !o.eyring_stress)
      throw InputError(prefix + "eyring_stress_MPa: missing, required by friction.model = \"ehl\"");
    if (!ehl && o.eyring_stress)
      throw InputError(prefix + "eyring_stress_MPa: applies to friction.model = \"ehl\" only" +
                       (o.friction_model == FrictionModel::ehl_thermal
                            ? std::string(" (the \"ehl_thermal\" film takes its tau0 from lubricant.eyring_stress_MPa)")
                            : std::string()));
  });
  return t;
}

model::OptionTable<MeshLossOptions> make_table() {
  model::OptionTable<MeshLossOptions> t;
  static const auto friction = make_friction_table();
  t.section("friction", [](auto& o) -> auto& { return o; }, friction,
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

const model::OptionTable<MeshLossOptions>& MeshLossOptions::table() {
  static const auto t = make_table();
  return t;
}

}  // namespace gearbench::efficiency
