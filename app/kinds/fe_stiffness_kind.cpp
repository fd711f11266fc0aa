// Case kind "fe_stiffness": the deal.II finite-element tooth reference (reference/fe_tooth,
// docs/fe-tooth-model.md) along the path of contact of a spur pair: each gear's tooth
// compliance, the pair stiffness with Hertz added, the convergence of every solve, and
// optionally a VTU file (displacement, von Mises) of the first position's pinion solve.
// The optional "crack" section (the stiffness kind's keys, type "pitch") cracks one gear's
// loaded tooth as a slit in the mesh.
#include <cmath>
#include <fstream>

#include "tooth_sections.h"
#include "fe_tooth/fe_tooth_stiffness.h"
#include "kind_registry.h"
#include "model/case_reader.h"
#include "model/errors.h"

namespace gearbench::app {
namespace {

using nlohmann::json;
namespace fe = reference::fe;

fe::ElasticOptions read_fe_options(model::ObjectReader& root) {
  fe::ElasticOptions o;
  if (!root.has("fe")) return o;
  auto s = root.object("fe");
  o.degree = s.optional_integer("degree", 1, 4).value_or(o.degree);
  o.max_cycles = s.optional_integer("max_cycles", 3, 20).value_or(o.max_cycles);
  o.refine_fraction = s.optional_number("refine_fraction", {0.0, 1.0, true, true}).value_or(o.refine_fraction);
  o.tolerance = s.optional_number("tolerance", {0.0, 0.5, true, true}).value_or(o.tolerance);
  s.finish();
  return o;
}

/// The stiffness kind's "crack" section; the FE slit models seed 003's pitch crack.
std::optional<fe::ToothCrack> read_fe_crack(model::ObjectReader& root) {
  const auto c = read_crack(root, 2);
  if (!c) return std::nullopt;
  if (c->crack.type != stiffness::Crack::Type::pitch)
    throw InputError("crack.type = root: kind fe_stiffness models the pitch crack (seed 003) only");
  return fe::ToothCrack{c->gear, c->crack.length, c->crack.angle};
}

fe::FeToothOptions read_options(model::ObjectReader& root, const json& case_json) {
  fe::FeToothOptions o;
  if (root.has("plane_stress")) {
    if (!case_json["plane_stress"].is_boolean())
      throw InputError("plane_stress = " + model::shown_value(case_json["plane_stress"]) + ": must be true or false");
    o.plane_strain = !case_json["plane_stress"].get<bool>();
  }
  if (auto bore = root.optional_number_pair("bore_diameter_mm", model::Range::positive(1e7), "mm"))
    o.bore_radius = std::array<double, 2>{0.5e-3 * (*bore)[0], 0.5e-3 * (*bore)[1]};
  o.load_per_width = root.optional_number("load_N_per_mm", model::Range::positive(1e5), "N/mm").value_or(100.0) * 1e3;
  if (root.has("mesh")) {
    auto m = root.object("mesh");
    o.near_size_modules = m.optional_number("near_size_modules", {0.01, 1.0, true, false}).value_or(o.near_size_modules);
    o.far_size_modules = m.optional_number("far_size_modules", {0.01, 5.0, true, false}).value_or(o.far_size_modules);
    m.finish();
  }
  if (root.has("rigid_body")) {
    if (!case_json["rigid_body"].is_boolean())
      throw InputError("rigid_body = " + model::shown_value(case_json["rigid_body"]) + ": must be true or false");
    o.rigid_body = case_json["rigid_body"].get<bool>();
  }
  o.fe = read_fe_options(root);
  o.crack = read_fe_crack(root);
  return o;
}

json convergence_json(const fe::ElasticResult& r) {
  json rows = json::array();
  for (const auto& c : r.cycles)
    rows.push_back({{"cycle", c.cycle}, {"cells", c.cells}, {"dofs", c.dofs}, {"displacement_m", c.value},
                    {"relative_change", c.change}, {"observed_rate", c.rate},
                    {"load_patch_displacement_m", c.load_displacement}});
  return {{"converged", r.converged}, {"observed_rate", r.observed_rate}, {"seconds", r.seconds},
          {"cycles", rows}, {"table", r.table}};
}

/// The slit as meshed (tooth coordinates, mm), or null for healthy teeth.
json crack_json(const fe::FeToothStiffness& model) {
  for (int g = 0; g < 2; ++g)
    if (const auto& s = model.slit(g))
      return {{"gear", g + 1},
              {"mouth_mm", {s->mouth[0] * 1e3, s->mouth[1] * 1e3}},
              {"tip_mm", {s->tip[0] * 1e3, s->tip[1] * 1e3}}};
  return nullptr;
}

json run_fe_stiffness(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  const auto gear_case = model::read_gear_case(root);
  if (!gear_case.materials) throw InputError("materials: missing required key (kind fe_stiffness)");
  const int count = root.optional_integer("positions", 1, 200).value_or(5);
  auto options = read_options(root, case_json);
  const auto vtu_path = root.optional_string("vtu_output");
  options.vtu = vtu_path.has_value();
  root.finish();

  const fe::FeToothStiffness model(gear_case.gear_pair, *gear_case.materials, options);
  const auto& path = model.path();
  std::vector<double> s;
  for (int i = 0; i < count; ++i) s.push_back(count == 1 ? 0.5 * (path.A + path.E) : path.A + (path.E - path.A) * i / (count - 1));
  const auto r = model.solve(s);
  if (vtu_path) {
    std::ofstream out(*vtu_path);
    if (!(out << r.vtu)) throw InputError("vtu_output = " + *vtu_path + ": cannot write the file");
  }

  json positions_mm = json::array(), pair = json::array(), pair_fe_contact = json::array(),
       hertz = json::array(), seconds = json::array();
  std::array<json, 2> compliance{json::array(), json::array()}, contact{json::array(), json::array()},
      convergence{json::array(), json::array()}, probe_to_crack{json::array(), json::array()},
      crack_compliance{json::array(), json::array()};
  for (const auto& p : r.positions) {
    positions_mm.push_back(p.path_position * 1e3);
    pair.push_back(p.pair_stiffness);
    pair_fe_contact.push_back(p.pair_stiffness_fe_contact);
    hertz.push_back(1.0 / p.hertz_compliance);
    double t = 0.0;
    for (std::size_t g = 0; g < 2; ++g) {
      compliance[g].push_back(p.tooth[g].compliance);
      contact[g].push_back(p.tooth[g].contact_compliance);
      convergence[g].push_back(convergence_json(p.tooth[g].fe));
      probe_to_crack[g].push_back(p.tooth[g].probe_to_crack * 1e3);
      crack_compliance[g].push_back(p.tooth[g].crack_compliance);
      t += p.tooth[g].seconds;
    }
    seconds.push_back(t);
  }
  json gears = json::array();
  for (std::size_t g = 0; g < 2; ++g)
    gears.push_back({{"tooth_compliance_m_per_N", compliance[g]},
                     {"cracked", model.slit(static_cast<int>(g)).has_value()},
                     {"crack_compliance_m_per_N", crack_compliance[g]},
                     {"probe_to_crack_mm", probe_to_crack[g]},
                     {"load_patch_compliance_m_per_N", contact[g]},
                     {"root_radius_mm", r.radii[g].root * 1e3},
                     {"tip_radius_mm", r.radii[g].tip * 1e3},
                     {"bore_radius_mm", r.bore_radius[g] * 1e3},
                     {"initial_cells", r.initial_cells[g]},
                     {"convergence", convergence[g]}});
  return {{"kind", "fe_stiffness"},
          {"plane", options.plane_strain ? "strain" : "stress"},
          {"rigid_body", options.rigid_body},
          {"crack", crack_json(model)},
          {"path_of_contact_mm", {{"A", path.A * 1e3}, {"E", path.E * 1e3}, {"T1T2", path.t1t2 * 1e3}}},
          {"path_position_mm", positions_mm},
          {"gears", gears},
          {"hertz_N_per_m", hertz},
          {"pair_stiffness_N_per_m", pair},
          {"pair_stiffness_fe_contact_N_per_m", pair_fe_contact},
          {"converged", r.converged},
          {"seconds_per_position", seconds},
          {"seconds", r.seconds},
          {"vtu_output", vtu_path.value_or("")}};
}

const RegisterKind fe_stiffness_kind({"fe_stiffness",
                                      "deal.II finite-element tooth compliance and pair stiffness along A..E",
                                      run_fe_stiffness});

}  // namespace
}  // namespace gearbench::app
