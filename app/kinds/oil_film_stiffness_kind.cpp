// Case kind "oil_film_stiffness": the EHL film's stiffness along the path of contact of a
// spur pair, in series with the energy-method pair stiffness (seed 002, ordinary involute).
#include <fmt/format.h>

#include "ehl/oil_film_stiffness.h"
#include "ehl_sections.h"
#include "kind_registry.h"
#include "model/case_reader.h"
#include "model/errors.h"

namespace gearbench::app {
namespace {

using nlohmann::json;

json points_json(const ehl::OilFilmStiffnessResult& r) {
  json p = {{"position_m", json::array()}, {"load_per_length_N_per_m", json::array()},
            {"reduced_radius_m", json::array()}, {"entrainment_m_per_s", json::array()},
            {"h_central_m", json::array()}, {"h_min_m", json::array()}, {"p_max_Pa", json::array()},
            {"oil_film_stiffness_per_length_N_per_m2", json::array()}, {"oil_film_stiffness_N_per_m", json::array()},
            {"pair_stiffness_N_per_m", json::array()}, {"stiffness_with_film_N_per_m", json::array()},
            {"film_compliance_share", json::array()}, {"moes_M", json::array()}, {"moes_L", json::array()},
            {"film_load_exponent", json::array()}};
  for (const auto& q : r.points) {
    p["position_m"].push_back(q.position);
    p["load_per_length_N_per_m"].push_back(q.load_per_length);
    p["reduced_radius_m"].push_back(q.reduced_radius);
    p["entrainment_m_per_s"].push_back(q.entrainment);
    p["h_central_m"].push_back(finite_or_null(q.h_central));
    p["h_min_m"].push_back(finite_or_null(q.h_min));
    p["p_max_Pa"].push_back(finite_or_null(q.p_max));
    p["oil_film_stiffness_per_length_N_per_m2"].push_back(finite_or_null(q.stiffness_per_length));
    p["oil_film_stiffness_N_per_m"].push_back(finite_or_null(q.stiffness));
    p["pair_stiffness_N_per_m"].push_back(finite_or_null(q.pair_stiffness));
    p["stiffness_with_film_N_per_m"].push_back(finite_or_null(q.stiffness_with_film));
    p["film_compliance_share"].push_back(finite_or_null(q.film_share));
    p["moes_M"].push_back(q.moes_M);
    p["moes_L"].push_back(q.moes_L);
    p["film_load_exponent"].push_back(finite_or_null(q.film_load_exponent));
  }
  return p;
}

json run_oil_film_stiffness(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  const auto gear_case = model::read_gear_case(root);
  const auto fluid = read_gear_fluid(root, gear_case, "oil_film_stiffness");
  ehl::OilFilmStiffnessOptions options;
  options.positions = root.optional_integer("positions", 1, 10000).value_or(options.positions);
  options.perturbation =
      root.optional_number("perturbation", {0.0, 0.2, true, false}).value_or(options.perturbation);
  options.load_sharing = root.optional_string("load_sharing", {"equal", "iso"}).value_or(options.load_sharing);
  options.grid = read_ehl_grid(root, options.grid);
  root.finish();

  const geometry::GearPairGeometry geometry(gear_case.gear_pair);
  const auto r = ehl::OilFilmStiffness(geometry, *gear_case.materials, *gear_case.operating, fluid, options).solve();
  return {{"kind", "oil_film_stiffness"},
          {"face_width_m", r.face_width},
          {"perturbation", options.perturbation},
          {"points", points_json(r)},
          {"notes", json::array({"k_oil = −Δw/Δh_c by a central difference at loads w(1 ± perturbation)",
                                 "stiffness_with_film: the pair stiffness and b·k_oil in series"})},
          {"diagnostics", {{"seconds", r.seconds}}}};
}

const RegisterKind oil_film_kind({"oil_film_stiffness", "EHL oil-film stiffness along the path of contact (seed 002)",
                                  run_oil_film_stiffness});

}  // namespace
}  // namespace gearbench::app
