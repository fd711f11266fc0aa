#pragma once
// The result JSON of one thermal contact of the thermal EHL kinds (tehl_point, tehl_path). Their
// keys are tables': ehl::ThermalEhlOptions::table() ("grid", "rheology", "thermal") and the
// model's thermal tables (model::add_thermal_media, model::ThermalPathCase::table()).
#include <nlohmann/json.hpp>

#include "ehl/thermal_line_contact.h"
#include "model/json_reader.h"

namespace gearbench::app {

/// Figures, diagnostics and (with `fields`) the p, h and temperature fields of one contact.
nlohmann::json thermal_result_json(const ehl::ThermalEhlResult& r, bool fields);

}  // namespace gearbench::app
