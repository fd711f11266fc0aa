#include "micropitting/tehl_micropitting.h"

#include "geometry/gear_pair_geometry.h"

namespace gearbench::micropitting {

namespace iso = iso15144;

TehlMicropitting compare_with_iso(const ehl::ThermalPathResult& path, const model::ThermalPathCase& c,
                                  const MicropittingCase& m, const ehl::ThermalEhlOptions& options) {
  TehlMicropitting t;
  t.iso = iso::assess(m.gear, m.test, m.material_factor);

  // The test gear: same oil and solids, its own gears, speed, torque and oil temperature, K = 1.
  const geometry::GearPairGeometry test_geometry(m.test.pair);
  model::OperatingPoint test_operating;
  test_operating.pinion_speed = m.test.pinion_speed;
  test_operating.pinion_torque = m.test.pinion_torque;
  const lubricant::ThermalRheology test_oil(c.lubricant, m.test.oil_temperature);
  const ehl::ThermalMeshPath test_path(test_geometry, test_operating, c.materials, test_oil, c.solids,
                                       model::LoadFactors{}, "iso", options);
  t.reference_point = test_path.solve_point("A");
  const double Ra_ref = 0.5 * (m.test.roughness_Ra[0] + m.test.roughness_Ra[1]);
  t.lambda_GFT = t.reference_point.result.h_min / Ra_ref;
  t.lambda_GFP = iso::permissible_lambda(t.lambda_GFT, m.material_factor);

  const double Ra = 0.5 * (m.gear.roughness_Ra[0] + m.gear.roughness_Ra[1]);
  for (std::size_t i = 0; i < path.points.size() && i < t.lambda.size(); ++i) {
    t.lambda[i] = path.points[i].result.h_min / Ra;
    if (i == 0 || t.lambda[i] < t.lambda_min) {
      t.lambda_min = t.lambda[i];
      t.lambda_min_at = path.points[i].name;
    }
  }
  t.S_lambda = t.lambda_min / t.lambda_GFP;
  return t;
}

nlohmann::json micropitting_json(const TehlMicropitting& t) {
  nlohmann::json points = nlohmann::json::array();
  for (std::size_t i = 0; i < t.iso.gear.points.size(); ++i) {
    const auto& y = t.iso.gear.points[i];
    points.push_back({{"point", y.name}, {"iso_h_m", y.h}, {"iso_lambda_GF", y.lambda},
                      {"iso_p_dyn_Pa", y.p_dyn}, {"iso_flash_temperature_K", y.flash_temperature},
                      {"tehl_lambda_GF", t.lambda[i]}});
  }
  const auto& ref = t.reference_point;
  return {{"points", points},
          {"iso", {{"lambda_min", t.iso.gear.lambda_min}, {"lambda_min_at", t.iso.gear.lambda_min_at},
                   {"lambda_GFT", t.iso.lambda_GFT}, {"lambda_GFP", t.iso.lambda_GFP},
                   {"S_lambda", t.iso.S_lambda}}},
          {"tehl", {{"lambda_min", t.lambda_min}, {"lambda_min_at", t.lambda_min_at},
                    {"reference_test_h_min_m", ref.result.h_min},
                    {"reference_test_hertz_pressure_Pa", ref.hertz_pressure},
                    {"reference_test_temperature_rise_max_K", ref.result.temperature_rise_max},
                    {"lambda_GFT", t.lambda_GFT}, {"lambda_GFP", t.lambda_GFP}, {"S_lambda", t.S_lambda}}}};
}

}  // namespace gearbench::micropitting
