#pragma once
// JSON case sections → validated model structs. Key names are the stable contract of
// case files (units in the key); the structs hold SI values.
#include <array>
#include <nlohmann/json.hpp>
#include <optional>

#include "gear_pair.h"
#include "json_reader.h"
#include "materials.h"
#include "option_table.h"

namespace gearbench::model {

/// Tip radius ρ_fP* [m_n] of the rack when a case gives none: ISO 53 profile A's 0.38, or for
/// racks too narrow for it (pressure angles above about 22°, outside ISO 53) the full-round
/// tip radius, whose two rounds meet on the rack tooth's centre line.
double default_root_radius_coef(double dedendum_coef, double normal_pressure_angle);

/// The keys of the shared sections, one table each (option_table.h); the readers below and
/// `gearbench schema` come from them.
const OptionTable<GearPair>& gear_pair_table();
const OptionTable<Material>& material_table();
const OptionTable<OperatingPoint>& operating_table();
const OptionTable<Lubricant>& lubricant_table();
/// The thermal EHL kinds' "lubricant" (Roelands form or Walther form), "solids" and
/// "load_factors".
const OptionTable<ThermalLubricant>& thermal_lubricant_table();
const OptionTable<ThermalSolids>& thermal_solids_table();
const OptionTable<LoadFactors>& load_factors_table();

/// "load_sharing": how the load of a pair is shared where two pairs mesh, for every kind that
/// follows a contact along the path (the default is the member's).
template <class O, class Access>
void add_load_sharing(OptionTable<O>& t, Access access) {
  t.choice("load_sharing", access, std::vector<std::string>{"equal", "iso"},
           {.description = "load share of a pair where two mesh: half each (equal) or ISO/TR 15144-1's X_Y (iso)"});
}

/// "inlet_temperature_K", "lubricant" and "solids" of a thermal EHL case, in the members
/// `T0`, `lubricant` and `solids` of O.
template <class O>
void add_thermal_media(OptionTable<O>& t) {
  t.number("inlet_temperature_K", &O::inlet_temperature, Range::closed(200.0, 600.0),
           {.description = "inlet temperature T0 (lubricant and solids far from the contact)", .unit = "K",
            .required = true});
  t.section("lubricant", &O::lubricant, thermal_lubricant_table(),
            {.description = "the lubricant (viscosity at the inlet temperature or by nu40 and nu100)", .required = true});
  t.section("solids", &O::solids, thermal_solids_table(),
            {.description = "thermal data of the solids [pinion or surface 1, wheel or surface 2]", .required = true});
}

GearPair read_gear_pair(ObjectReader section);
/// `materials`: one object (both gears) or an array of two.
std::array<Material, 2> read_materials(ObjectReader& root);
OperatingPoint read_operating(ObjectReader section);
Lubricant read_lubricant(ObjectReader section);
/// The "lubricant" section of the thermal EHL kinds: "pressure_viscosity_1_per_GPa",
/// "density_kg_m3" (ρ15), "thermal_conductivity_W_per_mK", "specific_heat_J_per_kgK", and
/// either "viscosity_Pa_s" + "temperature_viscosity_1_per_K" or "nu40_mm2_s" + "nu100_mm2_s";
/// optional "eyring_stress_MPa".
ThermalLubricant read_thermal_lubricant(ObjectReader section);
/// "solids": {"thermal_conductivity_W_per_mK": [k1, k2], "specific_heat_J_per_kgK": [c1, c2],
/// "density_kg_m3": [ρ1, ρ2]}.
ThermalSolids read_thermal_solids(ObjectReader section);
/// "load_factors": {"K_A", "K_v", "K_H_alpha", "K_H_beta"}, each in [1, 10], default 1.
LoadFactors read_load_factors(ObjectReader section);

/// The physical data of a thermal EHL path case (kind "tehl_path").
struct ThermalPathCase {
  GearPair gear_pair;
  std::array<Material, 2> materials;
  OperatingPoint operating;
  LoadFactors load_factors;
  ThermalLubricant lubricant;
  ThermalSolids solids;
  double inlet_temperature = 0.0;     ///< T0 [K]
  std::string load_sharing = "iso";   ///< "iso" (ISO/TR 15144-1 X_Y) or "equal"
  /// The keys beside gear_pair, materials and operating.
  static const OptionTable<ThermalPathCase>& table();
};

/// Reads "gear_pair", "materials", "operating", "load_factors" (optional), "lubricant",
/// "solids", "inlet_temperature_K" and "load_sharing" (optional) of the root; the kind's
/// numerical sections are left to the caller.
ThermalPathCase read_thermal_path_case(ObjectReader& root);

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
