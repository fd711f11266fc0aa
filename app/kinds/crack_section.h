#pragma once
// The case section "crack": {"type": "pitch"|"root", "length_mm", "angle_deg", "gear"}, shared
// by the kinds that model cracked teeth.
#include <optional>

#include "model/json_reader.h"
#include "stiffness/pair_stiffness.h"

namespace gearbench::app {

/// Reads the optional "crack" section; `max_gear` is 2 where either gear may carry it.
std::optional<stiffness::GearCrack> read_crack(model::ObjectReader& root, int max_gear);

}  // namespace gearbench::app
