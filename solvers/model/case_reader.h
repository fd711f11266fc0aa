#pragma once
// JSON case sections → validated model structs. Key names are the stable contract of
// case files (units in the key); the structs hold SI values.
#include <array>
#include <nlohmann/json.hpp>
#include <optional>

#include "gear_pair.h"
#include "json_reader.h"
#include "materials.h"

namespace gearbench::model {

GearPair read_gear_pair(ObjectReader section);
/// `materials`: one object (both gears) or an array of two.
std::array<Material, 2> read_materials(ObjectReader& root);
OperatingPoint read_operating(ObjectReader section);
Lubricant read_lubricant(ObjectReader section);

/// The sections shared by every gear-pair case kind. Sections a kind does not need are
/// still validated when present, so one case file can serve several kinds.
struct GearCase {
  GearPair gear_pair;
  std::optional<std::array<Material, 2>> materials;
  std::optional<OperatingPoint> operating;
  std::optional<Lubricant> lubricant;
};

/// Reads "gear_pair" (required) and the optional "materials", "operating", "lubricant".
GearCase read_gear_case(ObjectReader& root);

}  // namespace gearbench::model
