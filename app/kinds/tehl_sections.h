#pragma once
// Case sections of the thermal EHL kinds (tehl_point, tehl_path): the temperature-dependent
// lubricant, the solids' thermal data, the "thermal" numerical options, and the result JSON
// of one thermal contact.
#include <nlohmann/json.hpp>

#include "ehl/thermal_line_contact.h"
#include "lubricant/thermal_rheology.h"
#include "model/json_reader.h"

namespace gearbench::app {

/// "lubricant": {"pressure_viscosity_1_per_GPa", "density_kg_m3" (at 15 °C),
/// "thermal_conductivity_W_per_mK", "specific_heat_J_per_kgK", and either
/// "viscosity_Pa_s" + "temperature_viscosity_1_per_K" or "nu40_mm2_s" + "nu100_mm2_s";
/// optional "eyring_stress_MPa"}. The Eyring stress goes to `eyring_stress` (Pa).
lubricant::ThermalLubricantData read_thermal_lubricant(model::ObjectReader& root, double inlet_temperature,
                                                       std::optional<double>& eyring_stress);

/// "solids": {"thermal_conductivity_W_per_mK": [k1, k2], "specific_heat_J_per_kgK": [c1, c2],
/// "density_kg_m3": [ρ1, ρ2]}.
ehl::SolidThermalData read_solids(model::ObjectReader& root);

/// The optional "thermal" section over the defaults, and the optional "grid" section.
ehl::ThermalEhlOptions read_thermal_options(model::ObjectReader& root);

/// Figures, diagnostics and (with `fields`) the p, h and temperature fields of one contact.
nlohmann::json thermal_result_json(const ehl::ThermalEhlResult& r, bool fields);

}  // namespace gearbench::app
