// Case kind "geometry": the involute geometry of a gear pair, its path of contact and the
// profiles of curvature, speed and sliding along it.
#include <cmath>
#include <numbers>

#include "geometry/gear_pair_geometry.h"
#include "geometry/load_sharing.h"
#include "case_schema.h"
#include "kind_registry.h"
#include "model/case_reader.h"

namespace gearbench::app {
namespace {

using nlohmann::json;
constexpr double to_mm = 1e3;
constexpr double to_deg = 180.0 / std::numbers::pi;

json pair_mm(double a, double b) { return json::array({a * to_mm, b * to_mm}); }

json path_json(const geometry::PathOfContact& p) {
  return {{"T1", 0.0},         {"T2", p.T2 * to_mm}, {"A", p.A * to_mm}, {"AB", p.AB * to_mm},
          {"B", p.B * to_mm},  {"C", p.C * to_mm},   {"D", p.D * to_mm}, {"DE", p.DE * to_mm},
          {"E", p.E * to_mm}};
}

/// What the kind prints beyond the geometry itself: the resolution of the profiles.
struct GeometryOutput {
  int profile_points = 51;
  static const model::OptionTable<GeometryOutput>& table() {
    static const auto t = [] {
      model::OptionTable<GeometryOutput> table;
      table.integer("profile_points", &GeometryOutput::profile_points, 3, 100001,
                {.description = "points of the profiles along the path of contact (and along each contact line)"});
      return table;
    }();
    return t;
  }
};

json profile_json(const geometry::GearPairGeometry& g, int points, double pinion_speed,
                  bool with_speeds) {
  const geometry::IsoLoadSharing iso;
  const geometry::EqualLoadSharing equal;
  std::map<std::string, json> columns;
  const auto& p = g.path();
  for (int i = 0; i < points; ++i) {
    const double s = p.A + (p.E - p.A) * i / (points - 1);
    const auto k = g.kinematics(s, pinion_speed);
    columns["position_mm"].push_back(s * to_mm);
    columns["pinion_radius_mm"].push_back(k.pinion_radius * to_mm);
    columns["rho1_mm"].push_back(k.rho1 * to_mm);
    columns["rho2_mm"].push_back(k.rho2 * to_mm);
    columns["reduced_radius_mm"].push_back(k.reduced_radius * to_mm);
    columns["reduced_radius_normal_mm"].push_back(k.reduced_radius_normal * to_mm);
    columns["slide_to_roll"].push_back(k.slide_to_roll);
    columns["specific_sliding_pinion"].push_back(k.specific_sliding1);
    columns["specific_sliding_wheel"].push_back(k.specific_sliding2);
    columns["pairs_in_contact"].push_back(g.pairs_in_contact(s));
    columns["load_share_iso"].push_back(iso.share(g, s));
    columns["load_share_equal"].push_back(equal.share(g, s));
    if (with_speeds) {
      columns["u1_m_s"].push_back(k.u1);
      columns["u2_m_s"].push_back(k.u2);
      columns["entrainment_m_s"].push_back(k.entrainment);
      columns["sliding_m_s"].push_back(k.sliding);
    }
  }
  return json(columns);
}

json contact_lines_json(const geometry::GearPairGeometry& g, int points) {
  json position = json::array(), length = json::array();
  const double pb = g.base_pitch_transverse();
  for (int i = 0; i < points; ++i) {
    const double s0 = g.path().A + pb * i / (points - 1);
    position.push_back(s0 * to_mm);
    length.push_back(g.contact_line_length(s0) * to_mm);
  }
  return {{"mesh_position_mm", position}, {"length_mm", length}};
}

json run_geometry(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  const auto gear_case = model::read_gear_case(root);
  GeometryOutput output;
  GeometryOutput::table().read(root, output);
  const int points = output.profile_points;
  root.finish();

  const geometry::GearPairGeometry g(gear_case.gear_pair);
  const auto& r1 = g.radii(0);
  const auto& r2 = g.radii(1);
  double single = 0.0, dbl = 0.0, more = 0.0;
  json zones = json::array();
  for (const auto& z : g.contact_zones()) {
    zones.push_back({{"begin_mm", z.begin * to_mm}, {"end_mm", z.end * to_mm}, {"pairs", z.pairs}});
    (z.pairs == 1 ? single : z.pairs == 2 ? dbl : more) += z.end - z.begin;
  }
  const bool with_speeds = gear_case.operating.has_value();
  const double omega = with_speeds ? gear_case.operating->pinion_speed : 1.0;

  json out = {
      {"kind", "geometry"},
      {"center_distance_mm", g.center_distance() * to_mm},
      {"zero_backlash_center_distance_mm", g.zero_backlash_center_distance() * to_mm},
      {"transverse_module_mm", g.transverse_module() * to_mm},
      {"transverse_pressure_angle_deg", g.transverse_pressure_angle() * to_deg},
      {"working_pressure_angle_deg", g.working_pressure_angle() * to_deg},
      {"base_helix_angle_deg", g.base_helix_angle() * to_deg},
      {"base_pitch_transverse_mm", g.base_pitch_transverse() * to_mm},
      {"contact_ratio_transverse", g.contact_ratio_transverse()},
      {"contact_ratio_overlap", g.contact_ratio_overlap()},
      {"contact_ratio_total", g.contact_ratio_total()},
      {"line_of_action_mm", path_json(g.path())},
      {"reference_radius_mm", pair_mm(r1.reference, r2.reference)},
      {"base_radius_mm", pair_mm(r1.base, r2.base)},
      {"tip_radius_mm", pair_mm(r1.tip, r2.tip)},
      {"root_radius_mm", pair_mm(r1.root, r2.root)},
      {"working_pitch_radius_mm", pair_mm(r1.working, r2.working)},
      {"form_radius_mm", pair_mm(r1.form, r2.form)},
      {"single_contact_length_mm", single * to_mm},
      {"double_contact_length_mm", dbl * to_mm},
      {"multiple_contact_length_mm", more * to_mm},  // three or more pairs (ε_α ≥ 2)
      {"contact_zones", zones},
      {"profile", profile_json(g, points, omega, with_speeds)},
      {"warnings", g.warnings()},
  };
  if (g.contact_ratio_overlap() > 0.0) out["contact_lines"] = contact_lines_json(g, points);
  if (!with_speeds)
    out["notes"] = json::array({"no \"operating\" section: speeds omitted (slide-to-roll is speed-independent)"});
  return out;
}

const RegisterKind geometry_kind({"geometry",
                                  "involute geometry, path of contact, curvature and sliding",
                                  run_geometry, [] {
                                    return std::vector<json>{gear_case_schema({}), GeometryOutput::table().schema()};
                                  }});

}  // namespace
}  // namespace gearbench::app
