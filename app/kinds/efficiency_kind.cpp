// Case kind "efficiency": sliding loss and mesh efficiency over one mesh period (constant μ
// for now), with Ohlendorf's H_V and the AGMA 6011 figure beside it.
#include <cmath>
#include <numbers>

#include "closed_form/efficiency_closed_form.h"
#include "efficiency/mesh_loss.h"
#include "kind_registry.h"
#include "model/case_reader.h"
#include "model/errors.h"

namespace gearbench::app {
namespace {

using nlohmann::json;

json run_efficiency(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  const auto gear_case = model::read_gear_case(root);
  if (!gear_case.operating) throw InputError("operating: missing required key (kind efficiency)");
  efficiency::MeshLossOptions options;
  if (root.has("friction")) {
    auto f = root.object("friction");
    f.optional_string("model", {"constant"});  // the regression and EHL laws are still to come
    options.friction_coefficient = f.number("mu", model::Range::closed(0.0, 0.5));
    f.finish();
  }
  options.load_sharing = root.optional_string("load_sharing", {"equal", "iso"}).value_or("equal");
  options.positions = root.optional_integer("positions", 2, 1000000).value_or(options.positions);
  options.points_per_line = root.optional_integer("points_per_line", 1, 100000).value_or(options.points_per_line);
  root.finish();

  const geometry::GearPairGeometry geometry(gear_case.gear_pair);
  const auto r = efficiency::MeshLoss(geometry, *gear_case.operating, options).solve();
  const auto hv = reference::ohlendorf_loss_factor(gear_case.gear_pair);
  const double alpha_n_deg = gear_case.gear_pair.normal_pressure_angle * 180.0 / std::numbers::pi;
  return {
      {"kind", "efficiency"},
      {"efficiency_mean", r.efficiency_mean},
      {"efficiency_min", r.efficiency_min},
      {"efficiency_max", r.efficiency_max},
      {"power_loss_mean_W", r.sliding_loss_mean},
      {"sliding_loss_mean_W", r.sliding_loss_mean},
      {"input_power_W", r.input_power},
      {"friction_coefficient_mean", r.friction_coefficient_mean},
      {"loss_factor_numeric", r.loss_factor_numeric},
      {"ohlendorf_HV", hv.H_V},
      {"agma6011_efficiency", reference::agma6011_efficiency(gear_case.gear_pair.teeth[0],
                                                             gear_case.gear_pair.teeth[1], alpha_n_deg)},
      {"mesh_position_rad", r.mesh_position},
      {"efficiency", r.efficiency},
      {"sliding_loss_W", r.sliding_loss},
      {"notes", json::array({"constant friction coefficient; no rolling loss yet (it needs the film thickness)",
                             "agma6011_efficiency uses the normal pressure angle in seed 000 eq. 13"})},
  };
}

const RegisterKind efficiency_kind({"efficiency", "sliding loss and mesh efficiency over a mesh period",
                                    run_efficiency});

}  // namespace
}  // namespace gearbench::app
