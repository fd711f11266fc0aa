#pragma once
// One check per integrator offered in `integrator.method`, for each dynamics model: the
// model's agreement with its independent RK4 reference at a tight tolerance.
#include <fmt/format.h>

#include <functional>
#include <string>

#include "check_registry.h"
#include "dynamics/integrator.h"

namespace gearbench::verification {

/// Registers `<prefix>.rk4.<method>` for every offered method: `agreement` run at rtol 1e-8
/// (atol 1e-14), within 1e-5 of the peak-to-peak. Returns true (for a static initialiser).
inline bool register_rk4_per_method(
    const std::string& prefix, const std::string& section, const std::string& reference,
    const std::string& quantity,
    const std::function<CheckValue(const CheckContext&, const dynamics::IntegratorOptions&)>& agreement) {
  for (const auto& m : dynamics::integrator_methods())
    if (m.offered) RegisterCheck(CheckSpec{
        .id = fmt::format("{}.rk4.{}", prefix, m.key), .section = section, .solver = "dynamics",
        .reference = reference, .quantity = fmt::format("{}, {}", quantity, m.description), .unit = "-",
        .tolerance = {1e-5, 0},
        .justification = "rtol 1e-8 gives every method ~1e-7 of the peak-to-peak or better in the work–precision "
                         "study (100 cycles); 1e-5 leaves room for the local-to-global error growth",
        .tier = Tier::fast, .run = [method = m.method, agreement](const CheckContext& ctx) {
          dynamics::IntegratorOptions i;
          i.method = method;
          i.relative_tolerance = 1e-8;
          i.absolute_tolerance = 1e-14;
          return agreement(ctx, i);
        }});
  return true;
}

}  // namespace gearbench::verification
