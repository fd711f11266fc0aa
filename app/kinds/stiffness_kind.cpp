// Case kind "stiffness": energy-method mesh stiffness over one mesh cycle, healthy or
// cracked, with the ISO 6336-1 method B figures beside it for comparison.
#include <cmath>

#include "closed_form/iso6336_stiffness.h"
#include "tooth_sections.h"
#include "kind_registry.h"
#include "model/case_reader.h"
#include "model/errors.h"
#include "stiffness/mesh_stiffness.h"

namespace gearbench::app {
namespace {

using nlohmann::json;

stiffness::BeamStart read_beam_start(model::ObjectReader& root) {
  const auto name = root.optional_string("beam_start", {"improved", "straight", "base_circle"})
                        .value_or("improved");
  if (name == "straight") return stiffness::BeamStart::straight;
  if (name == "base_circle") return stiffness::BeamStart::base_circle;
  return stiffness::BeamStart::improved;
}

json vector_json(const std::vector<double>& v, double scale = 1.0) {
  json out = json::array();
  for (double x : v) out.push_back(x * scale);
  return out;
}

json run_stiffness(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  const auto gear_case = model::read_gear_case(root);
  if (!gear_case.materials) throw InputError("materials: missing required key (kind stiffness)");
  stiffness::MeshStiffnessOptions options;
  options.beam_start = read_beam_start(root);
  if (root.has("fillet") && options.beam_start != stiffness::BeamStart::improved)
    throw InputError("fillet = " + model::shown_value(case_json["fillet"]) +
                     ": allowed only with beam_start \"improved\" (the other beams have no fillet)");
  options.fillet = read_fillet(root);
  options.positions = root.optional_integer("positions", 2, 100000).value_or(360);
  options.path_points = root.optional_integer("path_points", 2, 100000).value_or(201);
  options.slices = root.optional_integer("slices", 1, 10000).value_or(50);
  if (root.has("foundation")) {
    if (!case_json["foundation"].is_boolean())
      throw InputError("foundation = " + model::shown_value(case_json["foundation"]) + ": must be true or false");
    options.foundation = case_json["foundation"].get<bool>();
  }
  if (auto bore = root.optional_number_pair("bore_diameter_mm", model::Range::positive(1e7), "mm"))
    options.bore_radius = std::array<double, 2>{0.5e-3 * (*bore)[0], 0.5e-3 * (*bore)[1]};
  options.crack = read_crack(root, 2);
  root.finish();

  const geometry::GearPairGeometry geometry(gear_case.gear_pair);
  const stiffness::MeshStiffness solver(geometry, *gear_case.materials, options);
  const auto r = solver.solve();
  const auto iso = reference::iso6336_stiffness(gear_case.gear_pair);

  json components = json::object();
  for (std::size_t g = 0; g < 2; ++g)
    components[g == 0 ? "gear1" : "gear2"] = {{"bending_N_per_m", vector_json(r.bending[g])},
                                              {"shear_N_per_m", vector_json(r.shear[g])},
                                              {"axial_N_per_m", vector_json(r.axial[g])},
                                              {"foundation_N_per_m", vector_json(r.foundation[g])}};
  json warnings = r.warnings;
  for (const auto& w : iso.warnings) warnings.push_back(w);
  return {
      {"kind", "stiffness"},
      {"mesh_position_rad", vector_json(r.mesh_position)},
      {"mesh_stiffness_N_per_m", vector_json(r.mesh_stiffness)},
      {"mesh_stiffness_mean_N_per_m", r.mean},
      {"healthy_mesh_stiffness_N_per_m", vector_json(r.healthy_mesh_stiffness)},
      {"mesh_stiffness_min_N_per_m", r.min},
      {"mesh_stiffness_max_N_per_m", r.max},
      {"mesh_stiffness_mean_N_per_mm_um", r.mean_per_face_width()},
      {"single_pair_position_mm", vector_json(r.path_position, 1e3)},
      {"single_pair_stiffness_N_per_m", vector_json(r.single_pair_stiffness)},
      {"components", components},
      {"hertz_N_per_m", r.hertz},
      {"slices", r.slices},
      {"iso6336", {{"q_prime", iso.q_prime},
                   {"c_prime_N_per_mm_um", iso.c_prime},
                   {"c_gamma_alpha_N_per_mm_um", iso.c_gamma_alpha},
                   {"c_gamma_beta_N_per_mm_um", iso.c_gamma_beta},
                   {"z_n", {iso.z_n1, iso.z_n2}}}},
      {"warnings", warnings},
  };
}

const RegisterKind stiffness_kind({"stiffness", "energy-method mesh stiffness over a mesh cycle",
                                   run_stiffness});

}  // namespace
}  // namespace gearbench::app
