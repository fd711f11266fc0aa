// The Options tables (issue 21): validate() names the key, the value and the allowed range as
// the reader does; a value read at a bound passes; what a table records reads back the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "dynamics/herringbone12_dynamics.h"
#include "dynamics/speed_sweep.h"
#include "dynamics/spur6_dynamics.h"
#include "efficiency/efficiency_sweep.h"
#include "ehl/ehl_tables.h"
#include "ehl/thermal_line_contact.h"
#include "ehl/transient_mesh_ehl.h"
#include "efficiency/mesh_loss.h"
#include "micropitting/iso15144_case.h"
#include "model/case_reader.h"
#include "stiffness/mesh_stiffness.h"
#include "support/test_support.h"

namespace gearbench {
namespace {

using nlohmann::json;
using testing_support::input_error_of;

TEST(OptionTable, ValidateNamesKeyValueAndRange) {
  stiffness::MeshStiffnessOptions o;
  o.positions = 1;
  EXPECT_EQ(input_error_of([&] { o.validate(); }), "positions = 1: allowed range is [2, 100000]");
  o = {};
  o.crack = stiffness::GearCrack{{stiffness::Crack::Type::pitch, 1e-3, 0.5}, 2};  // gear index 2 is gear 3
  EXPECT_EQ(input_error_of([&] { o.validate(); }), "crack.gear = 3: allowed range is [1, 2]");
  o.crack->gear = 0;
  o.crack->crack.length = 20.0;  // m: 20000 mm
  EXPECT_EQ(input_error_of([&] { o.validate(); }), "crack.length_mm = 20000: allowed range is [0, 10000] mm");

  efficiency::MeshLossOptions l;
  l.friction_coefficient = 0.7;
  EXPECT_EQ(input_error_of([&] { l.validate(); }), "friction.mu = 0.7: allowed range is [0, 0.5]");
  l = {};
  l.friction_model = lubricant::FrictionModel::ehl;
  EXPECT_EQ(input_error_of([&] { l.validate(); }),
            "friction.eyring_stress_MPa: missing, required by friction.model = \"ehl\"");
  l.eyring_stress = 2e9;
  EXPECT_EQ(input_error_of([&] { l.validate(); }), "friction.eyring_stress_MPa = 2000: allowed range is (0, 1000] MPa");

  efficiency::SweepSpec s{{50.0, -1.0}, {}, {}};
  EXPECT_EQ(input_error_of([&] { s.validate(); }), "sweep.torque_Nm[1] = -1: allowed range is (0, 1000000000] N*m");
  EXPECT_EQ(input_error_of([] { efficiency::SweepSpec{}.validate(); }),
            "sweep: give at least one of torque_Nm, speed_rpm, pressure_angle_deg");
}

// The dynamics models' options (issue 21): what was validated only when the integrator was
// built, after the mesh tables (tolerances, steps), or not at all (the sweep's points), is now
// refused by validate() up front, naming the key, the value and the range.
TEST(OptionTable, DynamicsValidateNamesKeyValueAndRange) {
  const auto spur6 = [](auto edit) {
    dynamics::Spur6Options o;
    edit(o);
    return input_error_of([&] { o.validate(); });
  };
  EXPECT_EQ(spur6([](auto& o) { o.integrator.max_steps = 0; }),
            "integrator.max_steps = 0: allowed range is [1, 1000000000]");
  EXPECT_EQ(spur6([](auto& o) { o.integrator.absolute_tolerance = 1.0; }),
            "integrator.atol = 1: allowed range is [1e-20, 0.01]");
  EXPECT_EQ(spur6([](auto& o) { o.integrator.relative_tolerance = 1e-15; }),
            "integrator.rtol = 1e-15: allowed range is [1e-14, 0.01]");
  EXPECT_EQ(spur6([](auto& o) { o.bearing_stiffness = 0.0; }),
            "bearings.stiffness_N_per_m = 0: allowed range is (0, 1e+16] N/m");
  EXPECT_EQ(spur6([](auto& o) { o.crack = stiffness::GearCrack{{stiffness::Crack::Type::pitch, 1e-3, 0.5}, 1}; }),
            "crack.gear = 2: allowed range is [1, 1]");
  EXPECT_EQ(spur6([](auto& o) { o.friction.boundary_friction = 0.2; }),
            "friction.mu_boundary = 0.2: allowed range is [0.07, 0.15]");
  EXPECT_EQ(spur6([](auto& o) { o.friction.friction_model = lubricant::FrictionModel::mixed; }),
            "lubricant: missing, needed for friction.model = mixed");
  dynamics::Herringbone12Options h;
  h.groove_stiffness = -1.0;
  EXPECT_EQ(input_error_of([&] { h.validate(); }),
            "groove_coupling.axial_stiffness_N_per_m = -1: allowed range is [0, 1e+16] N/m");
  h = {};
  h.mesh.positions = 90;
  h.mesh.harmonics = 45;  // a table of 90 points holds 44 harmonics
  EXPECT_EQ(input_error_of([&] { h.validate(); }), "mesh.harmonics = 45: allowed range is [1, mesh.positions/2) = [1, 45)");
  EXPECT_EQ(input_error_of([] { dynamics::SpeedSweepSpec{1000.0, 2000.0, 1}.validate(); }),
            "speed_sweep_rpm.points = 1: allowed range is [2, 10000]");
  EXPECT_EQ(input_error_of([] { dynamics::SpeedSweepSpec{1000.0, 500.0, 3}.validate(); }),
            "speed_sweep_rpm.to = 500: must be above speed_sweep_rpm.from = 1000");
}

// One friction section, a default μ per model that holds it: the schema shows each model's.
TEST(OptionTable, ASectionsSchemaDefaultsAreItsHolders) {
  const auto mu = [](const json& schema) { return schema["properties"]["friction"]["properties"]["mu"]["default"]; };
  EXPECT_EQ(mu(dynamics::Spur6Options::table().schema()), 0.06);
  EXPECT_EQ(mu(dynamics::Herringbone12Options::table().schema()), 0.0);
  EXPECT_EQ(mu(efficiency::MeshLossOptions::table().schema()), 0.05);
}

// The work-precision study's methods (Verner, Fehlberg) may be set through the C++ API and
// are recorded, but a case may not name them, and the schema does not offer them.
TEST(OptionTable, StudyOnlyMethodsAreValidButNotReadNorOffered) {
  const auto& t = dynamics::IntegratorOptions::table();
  dynamics::IntegratorOptions o;
  o.method = dynamics::IntegratorMethod::verner;
  EXPECT_NO_THROW(o.validate());
  EXPECT_EQ(t.to_json(o)["method"], "verner");
  const auto offered = t.schema()["properties"]["method"]["enum"];
  EXPECT_EQ(std::count(offered.begin(), offered.end(), "verner"), 0);
  EXPECT_EQ(std::count(offered.begin(), offered.end(), "rk8pd"), 1);
  const json section = {{"method", "verner"}};
  model::ObjectReader r(section, "integrator");
  EXPECT_NE(input_error_of([&] { t.read(r, o); }).find("integrator.method = \"verner\""), std::string::npos);
}

// The reader converts a case value to SI (× scale + offset); validate() converts the bounds the
// same way, so a value read exactly at a bound is not refused by rounding.
TEST(OptionTable, AValueReadAtABoundPassesValidate) {
  const auto c = json::parse(R"({"pinion_speed_rpm": 1e6, "pinion_torque_Nm": 1e-6, "oil_temperature_C": 400,
                                  "roughness_Ra_um": [0, 100]})");
  model::ObjectReader r(c, "operating");
  model::OperatingPoint op;
  model::operating_table().read(r, op);
  EXPECT_NO_THROW(model::operating_table().validate(op, "operating."));
  op.oil_temperature = 400.0 + 273.15 + 1e-9;
  EXPECT_NE(input_error_of([&] { model::operating_table().validate(op, "operating."); })
                .find("operating.oil_temperature_C = 400"), std::string::npos);
}

// to_json writes the options in case keys and units: read back, they are the same options.
TEST(OptionTable, WhatATableRecordsReadsBackTheSame) {
  stiffness::MeshStiffnessOptions o;
  o.beam_start = stiffness::BeamStart::improved;
  o.fillet = stiffness::Fillet::circular_arc;
  o.positions = 90;
  o.bore_radius = std::array<double, 2>{0.01, 0.02};
  o.crack = stiffness::GearCrack{{stiffness::Crack::Type::root, 2.5e-3, 0.7}, 1};
  const auto& t = stiffness::MeshStiffnessOptions::table();
  const json recorded = t.to_json(o);
  EXPECT_EQ(recorded["bore_diameter_mm"], json::array({20.0, 40.0}));
  EXPECT_EQ(recorded["crack"]["gear"], 2);
  model::ObjectReader r(recorded, "");
  stiffness::MeshStiffnessOptions back;
  t.read(r, back);
  r.finish();
  EXPECT_EQ(t.to_json(back), recorded);
  EXPECT_EQ(back.crack->gear, 1);
  EXPECT_DOUBLE_EQ(back.crack->crack.length, 2.5e-3);
}

TEST(OptionTable, SchemaDefaultsAreTheMemberInitialisers) {
  const auto schema = efficiency::MeshLossOptions::table().schema();
  EXPECT_EQ(schema["properties"]["positions"]["default"], efficiency::MeshLossOptions{}.positions);
  EXPECT_EQ(schema["properties"]["rolling_loss_constant_Pa"]["default"], 6.2053e8);
  EXPECT_EQ(schema["properties"]["friction"]["properties"]["mu_boundary"]["minimum"], 0.07);
  EXPECT_EQ(schema["additionalProperties"], false);
  // A default that depends on other keys is said in words, never given as a number.
  const auto oil = micropitting::MicropittingCase::table().schema()["properties"]["oil"]["anyOf"][0];
  EXPECT_FALSE(oil["properties"]["lubricant_factor_XL"].contains("default"));
  EXPECT_NE(oil["properties"]["lubricant_factor_XL"]["description"].get<std::string>().find("by base"),
            std::string::npos);
}

// The EHL grid (one table for every EHL solver): an absent nodes, levels or domain is a value
// the table knows as "the solver chooses", valid and left out of the record; any other value
// is held to the range the case reader uses, named with its section; the relaxation settings
// the C++ API alone sets are held to theirs; the thermal lubricant's 1/GPa converts by division.
TEST(OptionTable, EhlGridUnsetValuesAndRanges) {
  ehl::EhlOptions o;
  EXPECT_NO_THROW(o.validate());
  EXPECT_FALSE(ehl::EhlOptions::table().to_json(o).contains("nodes"));
  o.nodes = 5;
  EXPECT_EQ(input_error_of([&] { o.validate(); }), "grid.nodes = 5: allowed range is [9, 1048577]");
  o = {};
  o.x_in = -3.0;
  EXPECT_EQ(input_error_of([&] { o.validate(); }), "grid.x_in = -3, grid.x_out = 0: give both or neither");
  o = {};
  o.pre_sweeps = 21;
  EXPECT_EQ(input_error_of([&] { o.validate(); }), "grid.pre_sweeps = 21: allowed range is [0, 20]");
  ehl::TransientMeshOptions t;
  t.grid.nodes = 0;  // the transient follows the contact on one fixed grid
  EXPECT_NE(input_error_of([&] { t.validate(); }).find("grid.nodes: ehl_transient needs a fixed grid"),
            std::string::npos);
  ehl::ThermalEhlOptions thermal;
  thermal.factor_relaxation = 0.0;
  EXPECT_EQ(input_error_of([&] { thermal.validate(); }), "thermal.factor_relaxation = 0: allowed range is (0, 1]");

  const json lubricant = {{"pressure_viscosity_1_per_GPa", 10.556}, {"density_kg_m3", 900},
                          {"thermal_conductivity_W_per_mK", 0.14}, {"specific_heat_J_per_kgK", 2000},
                          {"nu40_mm2_s", 320}, {"nu100_mm2_s", 20}};
  const auto l = model::read_thermal_lubricant(model::ObjectReader(lubricant, "lubricant"));
  EXPECT_EQ(l.pressure_viscosity, 10.556 / 1e9);
  EXPECT_EQ(model::thermal_lubricant_table().to_json(l)["pressure_viscosity_1_per_GPa"], 10.556);
}

}  // namespace
}  // namespace gearbench
