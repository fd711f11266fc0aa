#pragma once
// The gear pair, materials and operating point of a dynamics case file, as the dynamics
// checks construct their solvers from them.
#include <array>
#include <string>

#include "check_registry.h"

namespace gearbench::verification {

struct DynamicsCase {
  model::GearPair pair;
  std::array<model::Material, 2> materials;
  model::OperatingPoint operating;
};

inline DynamicsCase dynamics_case(const CheckContext& ctx, const std::string& file) {
  const auto c = ctx.gear_case(file);
  return {c.gear_pair, *c.materials, *c.operating};
}

}  // namespace gearbench::verification
