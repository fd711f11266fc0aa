// Case kind "stiffness": energy-method mesh stiffness over one mesh cycle, healthy or
// cracked, with the ISO 6336-1 method B figures beside it for comparison.
#include <cmath>

#include "closed_form/iso6336_stiffness.h"
#include "case_schema.h"
#include "kind_registry.h"
#include "model/case_reader.h"
#include "model/errors.h"
#include "stiffness/mesh_stiffness.h"

namespace gearbench::app {
namespace {

using nlohmann::json;

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
  stiffness::MeshStiffnessOptions::table().read(root, options);
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
      {"options_given", stiffness::MeshStiffnessOptions::table().to_json(r.options_given)},
      {"options_used", stiffness::MeshStiffnessOptions::table().to_json(r.options_used)},
      {"iso6336", {{"q_prime", iso.q_prime},
                   {"c_prime_N_per_mm_um", iso.c_prime},
                   {"c_gamma_alpha_N_per_mm_um", iso.c_gamma_alpha},
                   {"c_gamma_beta_N_per_mm_um", iso.c_gamma_beta},
                   {"z_n", {iso.z_n1, iso.z_n2}}}},
      {"warnings", warnings},
  };
}

std::vector<json> stiffness_schema() {
  return {gear_case_schema({"materials"}), stiffness::MeshStiffnessOptions::table().schema()};
}

const RegisterKind stiffness_kind({"stiffness", "energy-method mesh stiffness over a mesh cycle",
                                   run_stiffness, stiffness_schema});

}  // namespace
}  // namespace gearbench::app
