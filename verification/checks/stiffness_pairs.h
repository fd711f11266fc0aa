#pragma once
// Spur pairs shared by the stiffness checks (energy method, GSL reference, ISO 6336, FE):
// ISO 53 profile A rack (the model's defaults), 20°, steel of ISO 6336's E_st.
#include <array>
#include <cmath>

#include "model/gear_pair.h"
#include "model/materials.h"

namespace gearbench::verification {

inline model::GearPair spur_pair(int z1, int z2, double module_mm, double width_mm, double x1 = 0.0,
                                 double x2 = 0.0) {
  model::GearPair g;
  g.teeth = {z1, z2};
  g.normal_module = module_mm * 1e-3;
  g.normal_pressure_angle = 20.0 * M_PI / 180.0;
  g.face_width = width_mm * 1e-3;
  g.profile_shift = {x1, x2};
  return g;
}

/// E_st = 206 GPa (ISO 6336-1), ν 0.3.
inline const std::array<model::Material, 2> steel206{model::Material{206e9, 0.3, 7850},
                                                     model::Material{206e9, 0.3, 7850}};

}  // namespace gearbench::verification
