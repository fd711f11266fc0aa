// The loss options of a case, read by the mesh-loss solver's tables: shared by the efficiency
// kind and the dynamics kind's dynamic efficiency.
#include "efficiency_sections.h"

namespace gearbench::app {

void read_friction_section(model::ObjectReader& root, efficiency::MeshLossOptions& options) {
  if (!root.has("friction")) return;
  auto f = root.object("friction");
  efficiency::MeshLossOptions::friction_table().read(f, options);
  f.finish();
}

efficiency::MeshLossOptions read_mesh_loss_options(model::ObjectReader& root) {
  efficiency::MeshLossOptions options;
  efficiency::MeshLossOptions::table().read(root, options);
  return options;
}

}  // namespace gearbench::app
