// Case kind "ehl_transient": transient isothermal EHL of one spur contact travelling from A
// to E (seed 004), from a gear-pair case with materials, operating point and lubricant.
#include <cmath>
#include <fmt/format.h>

#include "case_schema.h"
#include "ehl/transient_mesh_ehl.h"
#include "ehl_sections.h"
#include "kind_registry.h"
#include "model/case_reader.h"
#include "model/errors.h"

namespace gearbench::app {
namespace {

using nlohmann::json;

json step_series(const ehl::TransientMeshResult& r) {
  json s = {{"time_s", json::array()}, {"position_m", json::array()}, {"roll_angle_rad", json::array()},
            {"reduced_radius_m", json::array()}, {"entrainment_m_per_s", json::array()},
            {"sliding_m_per_s", json::array()}, {"load_per_length_N_per_m", json::array()},
            {"hertz_pressure_Pa", json::array()}, {"h_central_m", json::array()}, {"h_min_m", json::array()},
            {"p_max_Pa", json::array()}, {"cycles", json::array()},
            {"work_units", json::array()}, {"full_multigrid", json::array()}};
  for (const auto& st : r.steps) {
    s["time_s"].push_back(st.time);
    s["position_m"].push_back(st.position);
    s["roll_angle_rad"].push_back(st.roll_angle);
    s["reduced_radius_m"].push_back(st.reduced_radius);
    s["entrainment_m_per_s"].push_back(st.entrainment);
    s["sliding_m_per_s"].push_back(st.sliding);
    s["load_per_length_N_per_m"].push_back(st.load_per_length);
    s["hertz_pressure_Pa"].push_back(st.hertz_pressure);
    s["h_central_m"].push_back(finite_or_null(st.h_central));
    s["h_min_m"].push_back(finite_or_null(st.h_min));
    s["p_max_Pa"].push_back(finite_or_null(st.p_max));
    s["cycles"].push_back(st.cycles);
    s["work_units"].push_back(st.work_units);
    s["full_multigrid"].push_back(st.full_multigrid);
  }
  return s;
}

json result_json(const ehl::TransientMeshResult& r) {
  json profiles = json::object();
  for (const auto& p : r.profiles)
    profiles[p.point] = {{"position_m", p.position}, {"x_m", finite_vector(p.x)}, {"p_Pa", finite_vector(p.p)},
                         {"h_m", finite_vector(p.h)}};
  return {
      {"kind", "ehl_transient"},
      {"p_max_Pa", finite_or_null(r.p_max)},
      {"p_max_position_m", r.p_max_position},
      {"h_min_m", finite_or_null(r.h_min)},
      {"h_min_position_m", r.h_min_position},
      {"h_central_range_m", {finite_or_null(r.h_central_min), finite_or_null(r.h_central_max)}},
      {"reference", {{"reduced_radius_m", r.reference_radius}, {"load_per_length_N_per_m", r.reference_load},
                     {"entrainment_m_per_s", r.reference_entrainment}, {"hertz_half_width_m", r.reference_half_width},
                     {"hertz_pressure_Pa", r.reference_pressure}}},
      {"time_step_s", r.time_step},
      {"dimensionless_time_step", r.dimensionless_time_step},
      {"steps", step_series(r)},
      {"profiles", profiles},
      {"diagnostics", {{"converged", r.converged}, {"failed_step", r.failed_step},
                       {"failed_residual_history", finite_vector(r.failed_residual_history)},
                       {"failed_force_balance_history", finite_vector(r.failed_force_history)},
                       {"total_cycles", r.total_cycles}, {"work_units", r.work_units},
                       {"work_units_by_part", work_by_part_json(r.work_by_part)},
                       {"work_units_iterating", r.work_units_iterating},
                       {"full_multigrid_steps", r.full_multigrid_steps}, {"seconds", r.seconds}}},
  };
}

/// The keys of an ehl_transient case beside the gear pair, materials, operating point and
/// lubricant: the solver's options and the film's rheology.
using TransientCase = GearFluidCase<ehl::TransientMeshOptions>;

json run_ehl_transient(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  const auto gear_case = model::read_gear_case(root);
  TransientCase k;
  k.fluid = gear_fluid(gear_case, "ehl_transient");
  TransientCase::table().read(root, k);
  root.finish();
  TransientCase::table().validate(k);
  const auto& options = k.options;
  const auto& fluid = k.fluid;

  const geometry::GearPairGeometry geometry(gear_case.gear_pair);
  const auto r = ehl::TransientMeshEhl(geometry, *gear_case.operating, fluid, options).run();
  auto out = result_json(r);
  add_solve_status(out, r);
  add_options_record(out, ehl::TransientMeshOptions::table(), options, options);
  throw_unless_converged(r, out);
  return out;
}

std::vector<json> ehl_transient_schema() {
  return {gear_case_schema({"materials", "operating", "lubricant"}), TransientCase::table().schema()};
}

const RegisterKind ehl_transient_kind({"ehl_transient", "transient EHL of a spur contact from A to E (seed 004)",
                                       run_ehl_transient, ehl_transient_schema});

}  // namespace
}  // namespace gearbench::app
