#pragma once
// Case keys of the energy-method tooth, shared by the kinds that build one: the section
// "crack": {"type": "pitch"|"root", "length_mm", "angle_deg", "gear"} and the key
// "fillet": "trochoid" (default) | "circular_arc" (docs/stiffness-model.md).
#include <optional>

#include "model/json_reader.h"
#include "stiffness/pair_stiffness.h"

namespace gearbench::app {

/// Reads the optional "crack" section; `max_gear` is 2 where either gear may carry it.
std::optional<stiffness::GearCrack> read_crack(model::ObjectReader& root, int max_gear);

/// Reads the optional "fillet" key.
stiffness::Fillet read_fillet(model::ObjectReader& root);

}  // namespace gearbench::app
