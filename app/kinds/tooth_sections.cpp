#include "tooth_sections.h"

#include "stiffness/mesh_stiffness.h"

#include <numbers>

namespace gearbench::app {

std::optional<stiffness::GearCrack> read_crack(model::ObjectReader& root, int max_gear) {
  if (!root.has("crack")) return std::nullopt;
  auto c = root.object("crack");
  stiffness::GearCrack crack;
  stiffness::crack_table(max_gear).read(c, crack);
  c.finish();
  return crack;
}

stiffness::Fillet read_fillet(model::ObjectReader& root) {
  const auto name = root.optional_string("fillet", {"trochoid", "circular_arc"}).value_or("trochoid");
  return name == "circular_arc" ? stiffness::Fillet::circular_arc : stiffness::Fillet::trochoid;
}

}  // namespace gearbench::app
