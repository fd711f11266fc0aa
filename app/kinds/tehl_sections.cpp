// The result JSON of the thermal EHL kinds.
#include "tehl_sections.h"

#include <fmt/format.h>

#include "ehl_sections.h"
#include "model/errors.h"

namespace gearbench::app {

using nlohmann::json;

json thermal_result_json(const ehl::ThermalEhlResult& r, bool fields) {
  json out = {
      {"rheology", r.rheology == lubricant::ShearRheology::eyring ? "eyring" : "newtonian"},
      {"h_central_m", finite_or_null(r.h_central)},
      {"h_min_m", finite_or_null(r.h_min)},
      {"x_h_min_m", finite_or_null(r.x_h_min)},
      {"p_max_Pa", finite_or_null(r.p_max)},
      {"temperature_rise_max_K", finite_or_null(r.temperature_rise_max)},
      {"x_temperature_rise_max_m", finite_or_null(r.x_temperature_rise_max)},
      {"wall_temperature_rise_max_K", {finite_or_null(r.wall_temperature_rise_max[0]),
                                       finite_or_null(r.wall_temperature_rise_max[1])}},
      {"friction_coefficient", finite_or_null(r.friction_coefficient)},
      {"friction_force_per_length_N_per_m", finite_or_null(r.friction_force)},
      {"isothermal", {{"h_central_m", finite_or_null(r.isothermal_h_central)},
                      {"h_min_m", finite_or_null(r.isothermal_h_min)},
                      {"p_max_Pa", finite_or_null(r.isothermal_p_max)},
                      {"friction_coefficient", finite_or_null(r.isothermal_friction_coefficient)}}},
      {"heat_balance_W_per_m", {{"shear_heating", finite_or_null(r.heat.shear_heating)},
                                {"compression", finite_or_null(r.heat.compression)},
                                {"film_outflow", finite_or_null(r.heat.film_outflow)},
                                {"solid_outflow", {finite_or_null(r.heat.solid_outflow[0]),
                                                   finite_or_null(r.heat.solid_outflow[1])}},
                                {"depth_loss", {finite_or_null(r.heat.depth_loss[0]),
                                                finite_or_null(r.heat.depth_loss[1])}}}},
      {"diagnostics", {{"converged", r.converged}, {"iterations", r.iterations},
                       {"coarse_grid_iterations", r.coarse_grid_iterations},
                       {"stop", {{"film_tolerance_used", finite_or_null(r.film_tolerance_used)},
                                 {"temperature_tolerance_used_K", finite_or_null(r.temperature_tolerance_used)},
                                 {"h_min_error_estimate", r.h_min_error_estimate
                                                              ? finite_or_null(*r.h_min_error_estimate)
                                                              : json(nullptr)}}},
                       {"temperature_change_history_K", finite_vector(r.temperature_change_history)},
                       {"h_min_history_m", finite_vector(r.h_min_history)},
                       {"pressure_cycles", r.pressure_cycles}, {"work_units", r.work_units},
                       {"work_units_by_part", work_by_part_json(r.work_by_part)},
                       {"solid_depth_m", r.depth}, {"nodes", r.x.size()},
                       {"film_nodes", r.zeta.size()}, {"solid_nodes", r.solid_depth.size()},
                       {"seconds", r.seconds}}},
  };
  if (r.friction_coefficient_eyring) out["friction_coefficient_eyring"] = finite_or_null(*r.friction_coefficient_eyring);
  json notes = json::array();
  if (!newtonian_friction_in_range(r.friction_coefficient)) {
    notes.push_back(withheld_friction_note(r.friction_coefficient, ""));
    out["friction_coefficient"] = out["friction_force_per_length_N_per_m"] = nullptr;
  }
  if (!newtonian_friction_in_range(r.isothermal_friction_coefficient)) {
    notes.push_back(withheld_friction_note(r.isothermal_friction_coefficient, "the isothermal solution's"));
    out["isothermal"]["friction_coefficient"] = nullptr;
  }
  if (!notes.empty()) out["notes"] = notes;
  if (fields) {
    json film = json::array();
    for (const auto& column : r.film_temperature) film.push_back(finite_vector(column));
    std::array<json, 2> solids{json::array(), json::array()};
    for (int b = 0; b < 2; ++b)
      for (const auto& column : r.solid_temperature[static_cast<std::size_t>(b)]) solids[static_cast<std::size_t>(b)].push_back(finite_vector(column));
    out["profile"] = {{"x_m", finite_vector(r.x)}, {"p_Pa", finite_vector(r.p)}, {"h_m", finite_vector(r.h)}};
    out["temperature_field"] = {{"zeta", finite_vector(r.zeta)}, {"solid_depth_m", finite_vector(r.solid_depth)},
                                {"film_K", film}, {"solid_a_K", solids[0]}, {"solid_b_K", solids[1]}};
  }
  return out;
}

}  // namespace gearbench::app
