// The "micropitting" case section (key list in the header), read by one table (issue 21).
#include "micropitting/iso15144_case.h"

#include <algorithm>
#include <numbers>

#include "lubricant/lubricant_section.h"
#include "model/errors.h"

namespace gearbench::micropitting {
namespace {

namespace iso = iso15144;
using model::Range;

// Declared once, used for the gear and for its reference test.
const std::vector<std::pair<std::string, iso::LubricationMethod>> methods = {
    {"dip", iso::LubricationMethod::dip}, {"spray", iso::LubricationMethod::spray},
    {"submerged", iso::LubricationMethod::submerged}};
const model::KeySpec method_spec{.description = "lubrication method, selecting X_S of the bulk temperature (84)"};
const model::KeySpec grade_spec{.description = "ISO 1328 accuracy grade Q of the spur load sharing (46)-(48); "
                                               "better than 7 counts as 7"};
constexpr int best_grade = 1, worst_grade = 12, grade_floor = 7;

model::OptionTable<iso::Oil> make_oil_table() {
  model::OptionTable<iso::Oil> t;
  t.choice("base", &iso::Oil::base,
           std::vector<std::pair<std::string, iso::OilBase>>{{"mineral", iso::OilBase::mineral},
                                                             {"polyalphaolefin", iso::OilBase::polyalphaolefin},
                                                             {"polyglycol", iso::OilBase::polyglycol}},
           {.description = "base oil, selecting the pressure-viscosity formula (9)-(11)", .required = true});
  t.number("nu40_mm2_s", &iso::Oil::nu40, Range::positive(1e4),
           {.description = "kinematic viscosity at 40 degC", .unit = "mm2/s", .scale = 1e-6, .required = true});
  t.number("nu100_mm2_s", &iso::Oil::nu100, Range::positive(1e4),
           {.description = "kinematic viscosity at 100 degC", .unit = "mm2/s", .scale = 1e-6, .required = true});
  t.number("density_15C_kg_m3", &iso::Oil::rho15, Range::closed(700.0, 1300.0),
           {.description = "density at 15 degC", .unit = "kg/m3", .required = true});
  t.number("lubricant_factor_XL", &iso::Oil::lubricant_factor, Range::positive(3.0),
           {.description = "X_L of the friction coefficient (86)",
            .default_text = "by base: mineral 1, polyalphaolefin 0.8, polyglycol 0.7"});
  // X_L, TR table (as the port and ISO/TR 13989 give it): mineral 1.0, PAO 0.8, non-water-
  // soluble polyglycol 0.7 (water-soluble 0.6, traction fluid 1.5, phosphate ester 1.3 only
  // through the key).
  t.after_read([](model::ObjectReader& r, iso::Oil& o) {
    if (r.has("lubricant_factor_XL")) return;
    o.lubricant_factor = o.base == iso::OilBase::polyalphaolefin ? 0.8 : o.base == iso::OilBase::polyglycol ? 0.7 : 1.0;
  });
  return t;
}

model::OptionTable<model::ThermalSolids> make_solids_table() {
  model::OptionTable<model::ThermalSolids> t;
  t.number("thermal_conductivity_W_per_mK", &model::ThermalSolids::conductivity, Range::positive(1e3),
           {.description = "lambda_M per gear (82)", .unit = "W/(m*K)", .required = true});
  t.number("specific_heat_J_per_kgK", &model::ThermalSolids::specific_heat, Range::positive(1e5),
           {.description = "c_M per gear (82)", .unit = "J/(kg*K)", .required = true});
  t.number("density_kg_m3", &model::ThermalSolids::density, Range::closed(100.0, 1e5),
           {.description = "rho_M per gear (82)", .unit = "kg/m3", .required = true});
  return t;
}

model::OptionTable<MicropittingCase> make_test_table() {
  model::OptionTable<MicropittingCase> t;
  t.text("name", &MicropittingCase::test_name, {.description = "the test's name, shown in the output"});
  t.integer("failure_load_stage", &MicropittingCase::failure_load_stage, 1, 14,
            {.description = "FZG load stage at which the oil failed the test", .required = true});
  t.external("gear_pair", model::gear_pair_table().schema("the test gear pair, with center_distance_mm"),
             {.required = true});
  t.number("pinion_torque_Nm", [](auto& c) -> auto& { return c.test.pinion_torque; }, Range::positive(1e7),
           {.description = "pinion torque at the failure load stage", .unit = "N*m", .required = true});
  t.number("pitch_line_speed_m_s", &MicropittingCase::test_pitch_line_speed, Range::positive(200.0),
           {.description = "speed at the working pitch circle", .unit = "m/s", .required = true});
  t.number("oil_temperature_C", [](auto& c) -> auto& { return c.test.oil_temperature; }, Range::closed(-20.0, 200.0),
           {.description = "oil temperature of the test", .unit = "degC", .offset = 273.15, .required = true});
  t.number("roughness_Ra_um", [](auto& c) -> auto& { return c.test.roughness_Ra; }, Range::positive(10.0),
           {.description = "Ra per flank of the test gears", .unit = "um", .scale = 1e-6, .required = true});
  t.choice("lubrication_method", [](auto& c) -> auto& { return c.test.method; }, methods, method_spec);
  t.integer("accuracy_grade", [](auto& c) -> auto& { return c.test.accuracy_grade; }, best_grade, worst_grade,
            grade_spec);
  t.after_read([](model::ObjectReader& s, MicropittingCase& mc) {
    auto& p = mc.test.pair;
    p = model::read_gear_pair(s.object("gear_pair"));
    if (!p.center_distance)
      throw InputError(s.key_path("gear_pair.center_distance_mm") +
                       ": missing required key (the pitch line speed refers to the working pitch circle)");
    const double r_w1 = *p.center_distance * p.teeth[0] / (p.teeth[0] + p.teeth[1]);
    mc.test.pinion_speed = mc.test_pitch_line_speed / r_w1;
    mc.test.operating_section = "micropitting.reference_test";
  });
  return t;
}

model::OptionTable<iso::Inputs> make_inputs_table() {
  model::OptionTable<iso::Inputs> t;
  const Range factor = Range::closed(1.0, 10.0);
  t.number("K_A", &iso::Inputs::K_A, factor, {.description = "application factor"});
  t.number("K_v", &iso::Inputs::K_v, factor, {.description = "dynamic factor"});
  t.number("K_Halpha", &iso::Inputs::K_Halpha, factor, {.description = "transverse load factor"});
  t.number("K_Hbeta", &iso::Inputs::K_Hbeta, factor, {.description = "face load factor"});
  t.choice("lubrication_method", &iso::Inputs::method, methods, method_spec);
  t.number("tip_relief_factor_XCa", &iso::Inputs::tip_relief_factor, Range::closed(1.0, 3.0),
           {.description = "X_Ca of the bulk temperature (84); 1 for unmodified profiles"});
  t.integer("accuracy_grade", &iso::Inputs::accuracy_grade, best_grade, worst_grade, grade_spec);
  t.choice("buttressing", &iso::Inputs::buttressing, std::vector<std::pair<std::string, bool>>{{"on", true}, {"off", false}},
           {.description = "buttressing factor X_but at A and E of helical gears"});
  static const auto oil = make_oil_table();
  t.section("oil", &iso::Inputs::oil, oil,
            {.description = "the oil, explicit or named from the catalogue (gearbench lubricants)", .required = true},
            lubricant::named_or_explicit_schema);
  return t;
}

model::OptionTable<MicropittingCase> make_table() {
  model::OptionTable<MicropittingCase> t;
  t.include([](auto& c) -> auto& { return c.gear; }, iso::Inputs::table());
  t.number("material_factor_WW", &MicropittingCase::material_factor, Range::positive(5.0),
           {.description = "W_W of lambda_GFP (2014 edition; unconfirmed, 1 keeps the 2010 form)"});
  static const auto test = make_test_table();
  t.section("solids", &MicropittingCase::solids, solids_table(),
            {.description = "thermal data of the gear bodies", .required = true});
  t.section("reference_test", [](auto& c) -> auto& { return c; }, test,
            {.description = "the test that rates the oil, evaluated by the same method", .required = true});
  return t;
}

}  // namespace

const model::OptionTable<model::ThermalSolids>& solids_table() {
  static const auto t = make_solids_table();
  return t;
}

const model::OptionTable<iso::Inputs>& iso::Inputs::table() {
  static const auto t = make_inputs_table();
  return t;
}

const model::OptionTable<MicropittingCase>& MicropittingCase::table() {
  static const auto t = make_table();
  return t;
}

MicropittingCase MicropittingCase::used() const {
  MicropittingCase u = *this;
  u.gear.accuracy_grade = std::max(gear.accuracy_grade, grade_floor);
  u.test.accuracy_grade = std::max(test.accuracy_grade, grade_floor);
  return u;
}

MicropittingCase read_micropitting(model::ObjectReader& root, const model::GearCase& c, const std::string& kind) {
  if (!c.operating) throw InputError("operating: missing required key (kind " + kind + ")");
  if (!c.materials) throw InputError("materials: missing required key (kind " + kind + ")");
  if (!root.has("micropitting")) throw InputError("micropitting: missing required key (kind " + kind + ")");
  auto s = root.object("micropitting");
  MicropittingCase mc;
  auto& g = mc.gear;
  g.pair = c.gear_pair;
  g.materials = *c.materials;
  g.pinion_speed = c.operating->pinion_speed;
  g.pinion_torque = c.operating->pinion_torque;
  g.oil_temperature = c.operating->oil_temperature;
  g.roughness_Ra = c.operating->roughness_Ra;
  MicropittingCase::table().read(s, mc);
  s.finish();

  // The test gear runs the same oil, materials and solids as the gear.
  for (std::size_t i = 0; i < 2; ++i)
    g.solids[i] = iso::Solid{mc.solids.conductivity[i], mc.solids.density[i], mc.solids.specific_heat[i]};
  mc.test.materials = g.materials;
  mc.test.solids = g.solids;
  mc.test.oil = g.oil;
  g.validate();
  mc.test.validate();
  return mc;
}

}  // namespace gearbench::micropitting
