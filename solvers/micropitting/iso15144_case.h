#pragma once
// The "micropitting" section of a gear-pair case: the data ISO/TR 15144-1 method B needs
// beyond "gear_pair", "materials" and "operating" (K factors, oil, thermal data of the
// solids, lubrication method) and the reference test that rates the oil (FZG C-GF/8.3/90 at
// its failure load stage), read into the reference's Inputs.
//
// "micropitting": {
//   "K_A", "K_v", "K_Halpha", "K_Hbeta": factors ≥ 1 (default 1),
//   "lubrication_method": "dip" | "spray" | "submerged" (default "dip"),
//   "tip_relief_factor_XCa" (default 1), "accuracy_grade" (ISO 1328, default 7),
//   "buttressing": "on" | "off" (default "on"), "material_factor_WW" (default 1),
//   "oil": {"base": "mineral" | "polyalphaolefin" | "polyglycol", "nu40_mm2_s", "nu100_mm2_s",
//           "density_15C_kg_m3", "lubricant_factor_XL" (default 1 / 0.8 / 0.7 by base)},
//   "solids": {"thermal_conductivity_W_per_mK": [λ1, λ2], "specific_heat_J_per_kgK": [c1, c2],
//              "density_kg_m3": [ρ1, ρ2]},
//   "reference_test": {"name", "failure_load_stage", "gear_pair": {... with center_distance_mm},
//                      "pinion_torque_Nm", "pitch_line_speed_m_s" (at the working pitch
//                      circle), "oil_temperature_C", "roughness_Ra_um": [Ra1, Ra2],
//                      "lubrication_method" (default "dip"), "accuracy_grade" (default 7)}
// }
// The test gear runs the same oil, materials and solids as the gear, with K factors of 1.
#include <string>

#include "micropitting/iso15144_micropitting.h"
#include "model/case_reader.h"
#include "model/json_reader.h"
#include "model/option_table.h"

namespace gearbench::micropitting {

struct MicropittingCase {
  micropitting::iso15144::Inputs gear;
  micropitting::iso15144::Inputs test;
  double material_factor = 1.0;
  int failure_load_stage = 0;
  std::string test_name = "reference test";
  double test_pitch_line_speed = 0.0;  ///< v at the test pair's working pitch circle [m/s]
  model::ThermalSolids solids;         ///< "solids" as given, for both the gear and the test

  /// The keys of the "micropitting" section, their units, ranges and defaults (the member
  /// initialisers of this struct and of iso15144::Inputs).
  static const model::OptionTable<MicropittingCase>& table();
  /// The section as the method uses it: an accuracy grade better than 7 counts as 7 in the
  /// load sharing (ISO/TR 15144-1 (46)-(48)).
  [[nodiscard]] MicropittingCase used() const;
};

/// "micropitting.solids": the thermal data of the gear bodies, per key [gear 1, gear 2].
const model::OptionTable<model::ThermalSolids>& solids_table();

/// Reads "micropitting" (required) with the case's "materials" and "operating" (required).
/// InputError names the key, the value and the allowed range.
MicropittingCase read_micropitting(model::ObjectReader& root, const model::GearCase& c,
                                   const std::string& kind);

}  // namespace gearbench::micropitting
