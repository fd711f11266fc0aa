#pragma once
// The thermal EHL example shared by the tests, the checks and the benchmarks: a steel line
// contact (R 20 mm, 300 kN/m, E′ 220 GPa, ū 2 m/s) lubricated by a mineral oil (η0 0.05 Pa·s
// and β 0.03 1/K at 40 °C, α 20 1/GPa), as cases/tehl_point_sliding.json.
#include "ehl/ehl_tables.h"
#include "ehl/line_contact_problem.h"
#include "model/materials.h"

namespace gearbench::testing_support {

inline constexpr double mineral_oil_inlet_temperature = 313.15;  ///< [K]
inline constexpr double mineral_oil_beta = 0.03;                 ///< viscosity–temperature coefficient [1/K]

inline model::ThermalLubricant mineral_oil() {
  model::ThermalLubricant d;
  d.density_15C = 870.0;
  d.pressure_viscosity = 20e-9;
  d.viscosity = 0.05;
  d.temperature_viscosity = mineral_oil_beta;
  d.thermal_conductivity = 0.14;
  d.specific_heat = 2000.0;
  return d;
}

inline model::ThermalSolids steel_solids() {
  model::ThermalSolids s;
  s.conductivity = {46.0, 46.0};
  s.specific_heat = {470.0, 470.0};
  s.density = {7850.0, 7850.0};
  return s;
}

/// The contact at slide-to-roll ratio (u1 − u2)/ū around ū = 2 m/s.
inline ehl::LineContactData sliding_contact(double slide_to_roll) {
  ehl::LineContactData c;
  c.reduced_radius = 0.02;
  c.load_per_length = 3e5;
  c.reduced_modulus = 2.2e11;
  c.u1 = 2.0 * (1.0 + 0.5 * slide_to_roll);
  c.u2 = 2.0 * (1.0 - 0.5 * slide_to_roll);
  return c;
}

/// The dimensional "contact" section of a case (R, w, [u1, u2], E'), read by its case table.
inline ehl::LineContactData case_contact(model::ObjectReader& root) {
  auto section = root.object("contact");
  ehl::ContactInput input;
  ehl::ContactInput::table().read(section, input);
  ehl::LineContactData d;
  input.apply(d);
  return d;
}

}  // namespace gearbench::testing_support
