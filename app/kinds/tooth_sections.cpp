#include "tooth_sections.h"

#include <numbers>

namespace gearbench::app {

std::optional<stiffness::GearCrack> read_crack(model::ObjectReader& root, int max_gear) {
  if (!root.has("crack")) return std::nullopt;
  auto c = root.object("crack");
  stiffness::GearCrack crack;
  crack.crack.type = c.string("type", {"pitch", "root"}) == "pitch" ? stiffness::Crack::Type::pitch
                                                                     : stiffness::Crack::Type::root;
  crack.crack.length = c.number("length_mm", model::Range::closed(0.0, 1e4), "mm") * 1e-3;
  crack.crack.angle = c.number("angle_deg", {0.0, 90.0, true, true}, "deg") * std::numbers::pi / 180.0;
  crack.gear = c.optional_integer("gear", 1, max_gear).value_or(1) - 1;
  c.finish();
  return crack;
}

stiffness::Fillet read_fillet(model::ObjectReader& root) {
  const auto name = root.optional_string("fillet", {"trochoid", "circular_arc"}).value_or("trochoid");
  return name == "circular_arc" ? stiffness::Fillet::circular_arc : stiffness::Fillet::trochoid;
}

}  // namespace gearbench::app
