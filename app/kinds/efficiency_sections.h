#pragma once
// Case keys of the mesh-loss solver, read from the case root (kind efficiency) or from a
// section of it (the dynamics kind's "dynamic_efficiency").
#include "efficiency/mesh_loss.h"
#include "model/json_reader.h"

namespace gearbench::app {

/// "friction": {"model", "mu", "mu_boundary", "lubricant_factor"}, "load_sharing",
/// "rolling_loss_constant_Pa", "positions", "points_per_line".
efficiency::MeshLossOptions read_mesh_loss_options(model::ObjectReader& root);

/// The "friction" section alone into the friction fields of `options` (the dynamics kind
/// reads it too); nothing when the section is absent.
void read_friction_section(model::ObjectReader& root, efficiency::MeshLossOptions& options);

}  // namespace gearbench::app
