// The loss options of a case: friction law, load sharing, rolling-loss constant and the
// resolution of the mesh period, shared by the efficiency kind and the dynamics kind's
// dynamic efficiency.
#include "efficiency_sections.h"

#include <fmt/format.h>

#include "model/errors.h"

namespace gearbench::app {

void read_friction_section(model::ObjectReader& root, efficiency::MeshLossOptions& options) {
  if (!root.has("friction")) return;
  auto f = root.object("friction");
  const auto name = f.optional_string("model", {"constant", "xu_kahraman", "benedict_kelley", "iso14179", "mixed", "ehl"})
                        .value_or("constant");
  options.friction_model = lubricant::parse_friction_model(name, "friction.model");
  const auto mu = f.optional_number("mu", model::Range::closed(0.0, 0.5));
  const bool constant = options.friction_model == lubricant::FrictionModel::constant;
  if (constant && !mu) throw InputError("friction.mu: missing, required for friction.model = constant");
  if (!constant && mu)
    throw InputError(fmt::format("friction.mu = {}: applies to friction.model = constant only (model is {})", *mu, name));
  if (mu) options.friction_coefficient = *mu;
  options.boundary_friction =
      f.optional_number("mu_boundary", model::Range::closed(0.07, 0.15)).value_or(options.boundary_friction);
  options.lubricant_factor =
      f.optional_number("lubricant_factor", model::Range::closed(0.1, 2.0)).value_or(options.lubricant_factor);
  if (auto tau = f.optional_number("eyring_stress_MPa", model::Range::positive(1e3), "MPa"))
    options.eyring_stress = *tau * 1e6;
  f.finish();
}

efficiency::MeshLossOptions read_mesh_loss_options(model::ObjectReader& root) {
  efficiency::MeshLossOptions options;
  read_friction_section(root, options);
  options.load_sharing = root.optional_string("load_sharing", {"equal", "iso", "stiffness"}).value_or("equal");
  options.rolling_loss_constant = root.optional_number("rolling_loss_constant_Pa", model::Range::closed(0.0, 1e11), "Pa")
                                      .value_or(options.rolling_loss_constant);
  options.positions = root.optional_integer("positions", 2, 1000000).value_or(options.positions);
  options.points_per_line = root.optional_integer("points_per_line", 1, 100000).value_or(options.points_per_line);
  return options;
}

}  // namespace gearbench::app
