#pragma once
// Case sections of the thermal EHL kinds (tehl_point, tehl_path): the "thermal" numerical
// options and the result JSON of one thermal contact. The lubricant and solids sections are
// model data (model::read_thermal_lubricant, model::read_thermal_solids).
#include <nlohmann/json.hpp>

#include "ehl/thermal_line_contact.h"
#include "model/json_reader.h"

namespace gearbench::app {

/// The optional "thermal" section over the defaults, the optional "grid" section and the
/// top-level "rheology" ("newtonian", default, or "eyring": τ0 from lubricant.eyring_stress_MPa).
ehl::ThermalEhlOptions read_thermal_options(model::ObjectReader& root);

/// Figures, diagnostics and (with `fields`) the p, h and temperature fields of one contact.
nlohmann::json thermal_result_json(const ehl::ThermalEhlResult& r, bool fields);

}  // namespace gearbench::app
