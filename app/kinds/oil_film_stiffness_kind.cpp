// Case kind "oil_film_stiffness": the EHL film's stiffness along the path of contact of a
// spur pair, in series with the energy-method pair stiffness (seed 002, ordinary involute);
// with "tooth_form": "double_involute", the film stiffness over one mesh period of the
// stepped double-involute pair of the "double_involute" rack section and, side by side, of
// the ordinary involute pair with the same data (seed 002's comparison).
#include <fmt/format.h>

#include "case_schema.h"
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
            {"film_load_exponent", json::array()}, {"work_units", json::array()}};
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
    p["work_units"].push_back(q.work_units);
  }
  return p;
}

json instants_json(const ehl::MeshPeriodOilFilmResult& r) {
  json p = {{"time_s", json::array()}, {"contact_line_length_m", json::array()},
            {"load_per_length_N_per_m", json::array()}, {"film_stiffness_N_per_m", json::array()},
            {"pair2_root_length_m", json::array()}, {"pair2_tip_length_m", json::array()},
            {"pair2_film_stiffness_N_per_m", json::array()}, {"pair2_root_radius_m", json::array()},
            {"pair2_tip_radius_m", json::array()}, {"h_central_min_m", json::array()}, {"pairs", json::array()},
            {"work_units", json::array()}};
  for (const auto& m : r.instants) {
    p["time_s"].push_back(m.time);
    p["contact_line_length_m"].push_back(m.contact_length);
    p["load_per_length_N_per_m"].push_back(m.load_per_length);
    p["film_stiffness_N_per_m"].push_back(finite_or_null(m.film_stiffness));
    p["pair2_root_length_m"].push_back(m.pair2_root_length);
    p["pair2_tip_length_m"].push_back(m.pair2_tip_length);
    p["pair2_film_stiffness_N_per_m"].push_back(finite_or_null(m.pair2_film_stiffness));
    p["pair2_root_radius_m"].push_back(m.pair2_root_radius);
    p["pair2_tip_radius_m"].push_back(m.pair2_tip_radius);
    p["h_central_min_m"].push_back(finite_or_null(m.h_central_min));
    p["pairs"].push_back(m.pairs);
    p["work_units"].push_back(m.work_units);
  }
  return {{"instants", p}, {"mean_film_stiffness_N_per_m", finite_or_null(r.mean_film_stiffness)},
          {"ehl_solves", r.solves}, {"work_units", r.work_units}, {"seconds", r.seconds}};
}

json geometry_json(const geometry::DoubleInvolutePair& pair) {
  using geometry::ToothZone;
  const auto profile = geometry::rack_profile(pair.rack(), pair.geometry().pair());
  return {{"waist_radius_coef", profile.waist_radius},
          {"step_on_line_of_action_m", pair.step()},
          {"root_zone_m", {pair.zone(ToothZone::root).begin, pair.zone(ToothZone::root).end}},
          {"tip_zone_m", {pair.zone(ToothZone::tip).begin, pair.zone(ToothZone::tip).end}},
          {"root_zone_contact_ratio", pair.zone_contact_ratio(ToothZone::root)},
          {"tip_zone_contact_ratio", pair.zone_contact_ratio(ToothZone::tip)},
          {"rack_points_coef", {{"E", {profile.E.x, profile.E.y}}, {"D", {profile.D.x, profile.D.y}},
                                {"C", {profile.C.x, profile.C.y}}, {"B", {profile.B.x, profile.B.y}},
                                {"A", {profile.A.x, profile.A.y}}}}};
}

/// "tooth_form", which picks the other keys.
struct ToothFormChoice {
  std::string tooth_form = "involute";
  static const model::OptionTable<ToothFormChoice>& table() {
    static const auto table = [] {
      model::OptionTable<ToothFormChoice> t;
      t.choice("tooth_form", &ToothFormChoice::tooth_form, std::vector<std::string>{"involute", "double_involute"},
               {.description = "involute: the film stiffness along the path of contact; double_involute: over one "
                               "mesh period of the stepped pair of the double_involute rack, beside the ordinary "
                               "pair"});
      return t;
    }();
    return table;
  }
};

/// The keys of tooth_form "involute" beside the gear case.
using InvoluteCase = GearFluidCase<ehl::OilFilmStiffnessOptions>;

/// The keys of tooth_form "double_involute" beside the gear case.
struct DoubleInvoluteCase {
  model::DoubleInvoluteRack rack;
  ehl::MeshPeriodOilFilmOptions options;
  ehl::LineContactData fluid;
  static const model::OptionTable<DoubleInvoluteCase>& table() {
    static const auto table = [] {
      model::OptionTable<DoubleInvoluteCase> t;
      t.section("double_involute", &DoubleInvoluteCase::rack, ehl::double_involute_rack_table(),
                {.description = "the stepped double-involute basic rack", .required = true});
      t.include(&DoubleInvoluteCase::options, ehl::MeshPeriodOilFilmOptions::table());
      add_rheology_section(t);
      return t;
    }();
    return table;
  }
};

/// Reads the case's keys over the fluid of its gear case.
template <class Case>
Case read_case(model::ObjectReader& root, const model::GearCase& gear_case) {
  Case k;
  k.fluid = gear_fluid(gear_case, "oil_film_stiffness");
  Case::table().read(root, k);
  root.finish();
  Case::table().validate(k);
  return k;
}

json run_double_involute(model::ObjectReader& root, const model::GearCase& gear_case) {
  const auto k = read_case<DoubleInvoluteCase>(root, gear_case);
  const auto& rack = k.rack;
  const auto& options = k.options;
  const auto& fluid = k.fluid;

  const geometry::GearPairGeometry geometry(gear_case.gear_pair);
  const geometry::DoubleInvolutePair stepped(geometry, rack), ordinary(geometry, {});
  const auto rs = ehl::MeshPeriodOilFilm(stepped, *gear_case.operating, fluid, options).try_solve();
  const auto ro = ehl::MeshPeriodOilFilm(ordinary, *gear_case.operating, fluid, options).try_solve();
  // Both pairs' solves, as one status: converged when both are, the message of the one that is not.
  model::SolveStatus status;
  if (!rs.converged) status.fail("double involute: " + rs.message);
  else if (!ro.converged) status.fail("involute: " + ro.message);
  else status.succeed("converged: the double-involute and the involute pair (" + rs.message + ")");
  json out = {{"kind", "oil_film_stiffness"},
          {"tooth_form", "double_involute"},
          {"perturbation", options.perturbation},
          {"mesh_period_s", rs.period},
          {"geometry", geometry_json(stepped)},
          {"double_involute", instants_json(rs)},
          {"involute", instants_json(ro)},
          {"mean_film_stiffness_ratio", finite_or_null(rs.mean_film_stiffness / ro.mean_film_stiffness)},
          {"notes", json::array({"w = F_bn/L(t): the normal force spread uniformly over the contact lines",
                                 "k_oil = −Δw/Δh_c by a central difference at loads w(1 ± perturbation); a pair's film "
                                 "stiffness is ∫k_oil dl along its contact line",
                                 "involute: the ordinary pair with the same gear data (a zero step)"})},
          {"diagnostics", {{"seconds", rs.seconds + ro.seconds}, {"ehl_solves", rs.solves + ro.solves},
                           {"work_units", rs.work_units + ro.work_units}}},
          {"options_given", ehl::MeshPeriodOilFilmOptions::table().to_json(options)},
          {"options_used", ehl::MeshPeriodOilFilmOptions::table().to_json(options)}};
  out["converged"] = status.converged;
  out["message"] = status.message;
  out["summary"] = "double involute: " + rs.summary() + "; involute: " + ro.summary();
  throw_unless_converged(status, out);
  return out;
}

json run_oil_film_stiffness(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  ToothFormChoice form;
  ToothFormChoice::table().read(root, form);
  const auto gear_case = model::read_gear_case(root);
  if (form.tooth_form == "double_involute") return run_double_involute(root, gear_case);
  if (root.has("double_involute"))
    throw InputError("double_involute: the rack section is read only with tooth_form \"double_involute\" "
                     "(tooth_form is \"involute\")");
  const auto k = read_case<InvoluteCase>(root, gear_case);
  const auto& options = k.options;
  const auto& fluid = k.fluid;

  const geometry::GearPairGeometry geometry(gear_case.gear_pair);
  const auto r = ehl::OilFilmStiffness(geometry, *gear_case.materials, *gear_case.operating, fluid, options).try_solve();
  json out = {{"kind", "oil_film_stiffness"},
          {"face_width_m", r.face_width},
          {"perturbation", options.perturbation},
          {"points", points_json(r)},
          {"notes", json::array({"k_oil = −Δw/Δh_c by a central difference at loads w(1 ± perturbation)",
                                 "stiffness_with_film: the pair stiffness and b·k_oil in series"})},
          {"diagnostics", {{"seconds", r.seconds}, {"work_units", r.work_units}}},
          {"options_given", ehl::OilFilmStiffnessOptions::table().to_json(options)},
          {"options_used", ehl::OilFilmStiffnessOptions::table().to_json(options)}};
  add_solve_status(out, r);
  throw_unless_converged(r, out);
  return out;
}

std::vector<json> oil_film_schema() {
  return {gear_case_schema({"materials", "operating", "lubricant"}), ToothFormChoice::table().schema()};
}

template <class Case>
KindSpec::SchemaVariant form_keys(const char* name) {
  return {name, [] { return std::vector<json>{Case::table().schema()}; }};
}

const RegisterKind oil_film_kind({"oil_film_stiffness", "EHL oil-film stiffness along the path of contact (seed 002)",
                                  run_oil_film_stiffness, oil_film_schema, "tooth_form",
                                  {form_keys<InvoluteCase>("involute"),
                                   form_keys<DoubleInvoluteCase>("double_involute")}});

}  // namespace
}  // namespace gearbench::app
