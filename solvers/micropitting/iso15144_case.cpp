// The "micropitting" case section (key list in the header).
#include "micropitting/iso15144_case.h"

#include <numbers>

#include "model/errors.h"

namespace gearbench::micropitting {
namespace {

namespace iso = iso15144;
using model::Range;

iso::LubricationMethod read_method(model::ObjectReader& s) {
  const auto m = s.optional_string("lubrication_method", {"dip", "spray", "submerged"}).value_or("dip");
  return m == "spray" ? iso::LubricationMethod::spray
         : m == "submerged" ? iso::LubricationMethod::submerged
                            : iso::LubricationMethod::dip;
}

iso::Oil read_oil(model::ObjectReader s) {
  iso::Oil o;
  const auto base = s.string("base", {"mineral", "polyalphaolefin", "polyglycol"});
  o.base = base == "polyalphaolefin" ? iso::OilBase::polyalphaolefin
           : base == "polyglycol"    ? iso::OilBase::polyglycol
                                     : iso::OilBase::mineral;
  o.nu40 = s.number("nu40_mm2_s", Range::positive(1e4), "mm2/s") * 1e-6;
  o.nu100 = s.number("nu100_mm2_s", Range::positive(1e4), "mm2/s") * 1e-6;
  o.rho15 = s.number("density_15C_kg_m3", Range::closed(700.0, 1300.0), "kg/m3");
  // X_L, TR table (as the port and ISO/TR 13989 give it): mineral 1.0, PAO 0.8, non-water-
  // soluble polyglycol 0.7 (water-soluble 0.6, traction fluid 1.5, phosphate ester 1.3 only
  // through the key).
  const double by_base = o.base == iso::OilBase::polyalphaolefin ? 0.8
                         : o.base == iso::OilBase::polyglycol   ? 0.7
                                                                : 1.0;
  o.lubricant_factor = s.optional_number("lubricant_factor_XL", Range::positive(3.0)).value_or(by_base);
  s.finish();
  return o;
}

std::array<iso::Solid, 2> read_solids(model::ObjectReader s) {
  const auto k = s.number_pair("thermal_conductivity_W_per_mK", Range::positive(1e3), "W/(m*K)");
  const auto c = s.number_pair("specific_heat_J_per_kgK", Range::positive(1e5), "J/(kg*K)");
  const auto rho = s.number_pair("density_kg_m3", Range::closed(100.0, 1e5), "kg/m3");
  s.finish();
  return {iso::Solid{k[0], rho[0], c[0]}, iso::Solid{k[1], rho[1], c[1]}};
}

void read_test(model::ObjectReader s, MicropittingCase& mc) {
  auto& t = mc.test;
  t.operating_section = "micropitting.reference_test";
  mc.test_name = s.optional_string("name").value_or("reference test");
  mc.failure_load_stage = s.integer("failure_load_stage", 1, 14);
  t.pair = model::read_gear_pair(s.object("gear_pair"));
  if (!t.pair.center_distance)
    throw InputError(s.key_path("gear_pair.center_distance_mm") +
                     ": missing required key (the pitch line speed refers to the working pitch circle)");
  t.pinion_torque = s.number("pinion_torque_Nm", Range::positive(1e7), "N*m");
  const double v = s.number("pitch_line_speed_m_s", Range::positive(200.0), "m/s");
  const double r_w1 = *t.pair.center_distance * t.pair.teeth[0] / (t.pair.teeth[0] + t.pair.teeth[1]);
  t.pinion_speed = v / r_w1;
  t.oil_temperature = s.number("oil_temperature_C", Range::closed(-20.0, 200.0), "degC") + 273.15;
  const auto ra = s.number_pair("roughness_Ra_um", Range::positive(10.0), "um");
  t.roughness_Ra = {ra[0] * 1e-6, ra[1] * 1e-6};
  t.method = read_method(s);
  t.accuracy_grade = s.optional_integer("accuracy_grade", 1, 12).value_or(7);
  s.finish();
}

}  // namespace

MicropittingCase read_micropitting(model::ObjectReader& root, const model::GearCase& c,
                                   const std::string& kind) {
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
  const Range factor = Range::closed(1.0, 10.0);
  g.K_A = s.optional_number("K_A", factor).value_or(1.0);
  g.K_v = s.optional_number("K_v", factor).value_or(1.0);
  g.K_Halpha = s.optional_number("K_Halpha", factor).value_or(1.0);
  g.K_Hbeta = s.optional_number("K_Hbeta", factor).value_or(1.0);
  g.method = read_method(s);
  g.tip_relief_factor = s.optional_number("tip_relief_factor_XCa", Range::closed(1.0, 3.0)).value_or(1.0);
  g.accuracy_grade = s.optional_integer("accuracy_grade", 1, 12).value_or(7);
  g.buttressing = s.optional_string("buttressing", {"on", "off"}).value_or("on") == "on";
  mc.material_factor = s.optional_number("material_factor_WW", Range::positive(5.0)).value_or(1.0);
  g.oil = read_oil(s.object("oil"));
  g.solids = read_solids(s.object("solids"));
  read_test(s.object("reference_test"), mc);
  s.finish();

  mc.test.materials = g.materials;
  mc.test.solids = g.solids;
  mc.test.oil = g.oil;
  g.validate();
  mc.test.validate();
  return mc;
}

}  // namespace gearbench::micropitting
