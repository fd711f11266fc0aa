// Case kind "fe_stiffness": the deal.II finite-element tooth reference (reference/fe_tooth,
// docs/fe-tooth-model.md) along the path of contact of a spur pair: each gear's tooth
// compliance, the pair stiffness with Hertz added, the convergence of every solve, and
// optionally a VTU file (displacement, von Mises) of the first position's pinion solve.
// The optional "crack" section (the stiffness kind's keys, type "pitch") cracks one gear's
// loaded tooth as a slit in the mesh. Every key comes from the reference's Options tables
// (reference/fe_tooth/fe_tooth_options.cpp).
#include <cmath>
#include <fstream>

#include "case_schema.h"
#include "fe_tooth/fe_tooth_stiffness.h"
#include "kind_registry.h"
#include "model/case_reader.h"
#include "model/errors.h"

namespace gearbench::app {
namespace {

using nlohmann::json;
namespace fe = reference::fe;

/// The keys of an fe_stiffness case beside the gear pair and materials: the reference's
/// options and where to write the VTU file.
struct FeStiffnessCase {
  fe::FeToothOptions options;
  std::string vtu_output;  ///< empty: none

  static const model::OptionTable<FeStiffnessCase>& table() {
    static const auto table = [] {
      model::OptionTable<FeStiffnessCase> t;
      t.include(&FeStiffnessCase::options, fe::FeToothOptions::table());
      t.text("vtu_output", &FeStiffnessCase::vtu_output,
             {.description = "a VTU file to write of the first position's pinion solve (displacement, von Mises)",
              .default_text = "none"});
      return t;
    }();
    return table;
  }
};

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
  FeStiffnessCase k;
  FeStiffnessCase::table().read(root, k);
  root.finish();
  auto& options = k.options;
  options.vtu = !k.vtu_output.empty();

  const fe::FeToothStiffness model(gear_case.gear_pair, *gear_case.materials, options);
  const auto& path = model.path();
  const auto r = model.solve();
  if (options.vtu) {
    std::ofstream out(k.vtu_output);
    if (!(out << r.vtu)) throw InputError("vtu_output = " + k.vtu_output + ": cannot write the file");
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
  const auto& table = fe::FeToothOptions::table();
  json result = {{"kind", "fe_stiffness"},
                 {"plane", options.plane_stress ? "stress" : "strain"},
                 {"rigid_body", options.rigid_body},
                 {"crack", crack_json(model)},
                 {"path_of_contact_mm", {{"A", path.A * 1e3}, {"E", path.E * 1e3}, {"T1T2", path.t1t2 * 1e3}}},
                 {"path_position_mm", positions_mm},
                 {"gears", gears},
                 {"hertz_N_per_m", hertz},
                 {"pair_stiffness_N_per_m", pair},
                 {"pair_stiffness_fe_contact_N_per_m", pair_fe_contact},
                 {"converged", r.converged},
                 {"message", r.message},
                 {"summary", r.summary()},
                 {"options_given", table.to_json(r.options_given)},
                 {"options_used", table.to_json(r.options_used)},
                 {"seconds_per_position", seconds},
                 {"seconds", r.seconds},
                 {"vtu_output", k.vtu_output}};
  // The CLI's contract: a solve that did not converge exits 3, its figures written where asked.
  if (!r.converged) throw ConvergenceError("fe_stiffness: " + r.message, result.dump(2));
  return result;
}

std::vector<json> fe_stiffness_schema() {
  return {gear_case_schema({"materials"}), FeStiffnessCase::table().schema()};
}

const RegisterKind fe_stiffness_kind({"fe_stiffness",
                                      "deal.II finite-element tooth compliance and pair stiffness along A..E",
                                      run_fe_stiffness, fe_stiffness_schema});

}  // namespace
}  // namespace gearbench::app
