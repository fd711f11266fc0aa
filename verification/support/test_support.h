#pragma once
// Small helpers shared by the GoogleTest suites and the benchmarks: the seed gear pairs as
// model data, and the message of an InputError.
#include <functional>
#include <numbers>
#include <string>

#include "model/errors.h"
#include "model/case_reader.h"
#include "model/gear_pair.h"

namespace gearbench::testing_support {

/// An unshifted spur pair on the ISO 53 rack, SI units from mm and degrees.
inline model::GearPair spur_pair(int z1, int z2, double module_mm, double pressure_angle_deg,
                                 double face_width_mm) {
  model::GearPair g;
  g.teeth = {z1, z2};
  g.normal_module = module_mm * 1e-3;
  g.normal_pressure_angle = pressure_angle_deg * std::numbers::pi / 180.0;
  g.face_width = face_width_mm * 1e-3;
  g.root_radius_coef = model::default_root_radius_coef(g.dedendum_coef, g.normal_pressure_angle);  // as a case file
  return g;
}

/// Seed 003 (Xu et al. 2022): 20/25, m 2 mm, α 20°, b 20 mm.
inline model::GearPair seed003_pair() { return spur_pair(20, 25, 2.0, 20.0, 20.0); }
/// Seed 004 (Liu et al. 2019): 22/32, m 2 mm, α 25°, b 20 mm.
inline model::GearPair seed004_pair() { return spur_pair(22, 32, 2.0, 25.0, 20.0); }

/// The message of the InputError `f` throws, or "" if it throws none.
inline std::string input_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace gearbench::testing_support
