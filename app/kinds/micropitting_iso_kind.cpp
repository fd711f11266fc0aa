// Case kind "micropitting_iso": ISO/TR 15144-1 method B at A, AB, B, C, D, DE, E of a gear
// pair, the reference test that rates the oil by the same method, and S_λ.
#include <fmt/format.h>
#include <numbers>

#include "geometry/gear_pair_geometry.h"
#include "micropitting/iso15144_case.h"
#include "case_schema.h"
#include "kind_registry.h"
#include "model/case_reader.h"
#include "model/errors.h"

namespace gearbench::app {
namespace {

using nlohmann::json;
namespace iso = micropitting::iso15144;
using micropitting::read_micropitting;
constexpr double to_deg = 180.0 / std::numbers::pi;

json point_json(const iso::PointResult& y) {
  return {{"point", y.name},
          {"position_from_T1_mm", y.position * 1e3},
          {"rho1_mm", y.rho1 * 1e3},
          {"rho2_mm", y.rho2 * 1e3},
          {"rho_n_mm", y.rho_n * 1e3},
          {"buttressing_factor", y.buttressing},
          {"load_sharing_factor", y.load_share},
          {"p_dyn_MPa", y.p_dyn * 1e-6},
          {"v_r1_m_s", y.v_r1},
          {"v_r2_m_s", y.v_r2},
          {"v_sum_m_s", y.v_sum},
          {"v_g_m_s", y.v_g},
          {"flash_temperature_K", y.flash_temperature},
          {"contact_temperature_K", y.contact_temperature},
          {"nu_B_mm2_s", y.nu_B * 1e6},
          {"eta_B_Pa_s", y.eta_B},
          {"alpha_B_1_per_GPa", y.alpha_B * 1e9},
          {"sliding_parameter", y.sliding_parameter},
          {"speed_parameter", y.U},
          {"load_parameter", y.W},
          {"h_m", y.h},
          {"h_um", y.h * 1e6},
          {"lambda_GF", y.lambda}};
}

json result_json(const iso::Result& r) {
  json points = json::array();
  for (const auto& y : r.points) points.push_back(point_json(y));
  return {{"transverse_pressure_angle_deg", r.transverse_pressure_angle * to_deg},
          {"working_pressure_angle_deg", r.working_pressure_angle * to_deg},
          {"base_helix_angle_deg", r.base_helix_angle * to_deg},
          {"center_distance_mm", r.center_distance * 1e3},
          {"contact_ratio_transverse", r.contact_ratio_transverse},
          {"contact_ratio_overlap", r.contact_ratio_overlap},
          {"addendum_contact_ratio", r.addendum_contact_ratio},
          {"reduced_modulus_GPa", r.reduced_modulus * 1e-9},
          {"Ra_um", r.Ra * 1e6},
          {"tangential_force_N", r.tangential_force},
          {"power_kW", r.power * 1e-3},
          {"helical_load_factor_KBgamma", r.helical_load_factor},
          {"roughness_factor_XR", r.roughness_factor},
          {"eta_oil_Pa_s", r.eta_oil},
          {"friction_coefficient_mean", r.friction_coefficient},
          {"loss_factor_HV", r.loss_factor},
          {"bulk_temperature_K", r.bulk_temperature},
          {"nu_M_mm2_s", r.nu_M * 1e6},
          {"eta_M_Pa_s", r.eta_M},
          {"alpha_38_1_per_GPa", r.alpha_38 * 1e9},
          {"alpha_M_1_per_GPa", r.alpha_M * 1e9},
          {"materials_parameter_GM", r.materials_parameter},
          {"thermal_contact_coefficient", r.thermal_contact_coefficient},
          {"lambda_GF_min", r.lambda_min},
          {"lambda_GF_min_at", r.lambda_min_at},
          {"points", points}};
}

/// The oil laws of the TR (Walther viscosity, linear density) describe a liquid oil; past
/// 500 °C no gear oil is one, and far past it the density turns negative and the film NaN
/// (1e5 rpm or 1e9 N·m once ended in an internal error). Refused as bad input, naming the
/// section whose speed and torque get there.
constexpr double max_contact_temperature_C = 500.0;

void check_oil_laws_hold(const iso::Result& r, const iso::Inputs& in) {
  for (const auto& y : r.points) {
    const double celsius = y.contact_temperature - 273.15;
    if (celsius <= max_contact_temperature_C) continue;  // a NaN fails too
    throw InputError(fmt::format(
        "{}: the contact temperature reaches {:.0f} °C at point {} (pinion speed {} rpm, torque {} N*m), beyond "
        "the {:.0f} °C to which the oil laws of ISO/TR 15144-1 hold; lower the speed or the torque",
        in.operating_section, celsius, y.name, model::format_value(in.pinion_speed * 30.0 / std::numbers::pi),
        model::format_value(in.pinion_torque), max_contact_temperature_C));
  }
}

json run_micropitting(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  const auto gear_case = model::read_gear_case(root);
  const auto mc = read_micropitting(root, gear_case, "micropitting_iso");
  root.finish();
  // The pair gets the validation every kind applies (undercut, pointed teeth, centre
  // distance against the shifts, contact ratio): the ISO/TR method assumes a sound pair.
  static_cast<void>(geometry::GearPairGeometry(gear_case.gear_pair));

  const auto a = iso::assess(mc.gear, mc.test, mc.material_factor);
  check_oil_laws_hold(a.gear, mc.gear);
  check_oil_laws_hold(a.reference_test, mc.test);
  return {{"kind", "micropitting_iso"},
          {"method", "ISO/TR 15144-1:2014 method B (unmodified profiles); see docs/iso15144.md for "
                     "the coefficients not confirmed at the source"},
          {"S_lambda", a.S_lambda},
          {"lambda_GF_min", a.gear.lambda_min},
          {"lambda_GF_min_at", a.gear.lambda_min_at},
          {"lambda_GFT", a.lambda_GFT},
          {"lambda_GFP", a.lambda_GFP},
          {"material_factor_WW", mc.material_factor},
          {"reference_test_name", mc.test_name},
          {"reference_test_failure_load_stage", mc.failure_load_stage},
          {"options_given", micropitting::MicropittingCase::table().to_json(mc)},
          {"options_used", micropitting::MicropittingCase::table().to_json(mc.used())},
          {"gear", result_json(a.gear)},
          {"reference_test", result_json(a.reference_test)}};
}

std::vector<json> micropitting_schema() {
  return {gear_case_schema({"materials", "operating"}),
          section_part("micropitting",
                       micropitting::MicropittingCase::table().schema("what ISO/TR 15144-1 method B needs beyond the "
                                                                      "pair, materials and operating point"),
                       true)};
}

const RegisterKind micropitting_kind({"micropitting_iso",
                                      "ISO/TR 15144-1 method B: local film, flash temperature, S_lambda",
                                      run_micropitting, micropitting_schema});

}  // namespace
}  // namespace gearbench::app
