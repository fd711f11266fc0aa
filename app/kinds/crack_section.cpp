#include "crack_section.h"

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

}  // namespace gearbench::app
