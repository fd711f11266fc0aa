#include "case_reader.h"

#include "errors.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace gearbench::model {

// A full-round rack's two tip rounds meet on the tooth's centre line, tangent to the flanks:
// π/4 − h_fP tan α = ρ(1/cos α − tan α), the largest tip radius that fits.
double default_root_radius_coef(double dedendum_coef, double normal_pressure_angle) {
  const double full_round = std::max(0.0, std::numbers::pi / 4.0 - dedendum_coef * std::tan(normal_pressure_angle)) /
                            (1.0 / std::cos(normal_pressure_angle) - std::tan(normal_pressure_angle));
  return std::min(0.38, full_round);
}

GearPair read_gear_pair(ObjectReader s) {
  GearPair g;
  gear_pair_table().read(s, g);
  s.finish();
  return g;
}

namespace {
Material read_material(ObjectReader s) {
  Material m;
  material_table().read(s, m);
  s.finish();
  return m;
}
}  // namespace

std::array<Material, 2> read_materials(ObjectReader& root) {
  const auto pair = root.object_or_pair("materials");
  return {read_material(ObjectReader(pair.objects[0], pair.paths[0])),
          read_material(ObjectReader(pair.objects[1], pair.paths[1]))};
}

OperatingPoint read_operating(ObjectReader s) {
  OperatingPoint op;
  operating_table().read(s, op);
  s.finish();
  return op;
}

Lubricant read_lubricant(ObjectReader s) {
  Lubricant l;
  lubricant_table().read(s, l);
  s.finish();
  return l;
}

ThermalLubricant read_thermal_lubricant(ObjectReader l) {
  ThermalLubricant d;
  thermal_lubricant_table().read(l, d);
  l.finish();
  return d;
}

ThermalSolids read_thermal_solids(ObjectReader s) {
  ThermalSolids d;
  thermal_solids_table().read(s, d);
  s.finish();
  return d;
}

LoadFactors read_load_factors(ObjectReader f) {
  LoadFactors k;
  load_factors_table().read(f, k);
  f.finish();
  return k;
}

ThermalPathCase read_thermal_path_case(ObjectReader& root) {
  ThermalPathCase c;
  c.gear_pair = read_gear_pair(root.object("gear_pair"));
  if (!root.has("materials")) throw InputError("materials: missing required key");
  c.materials = read_materials(root);
  if (!root.has("operating")) throw InputError("operating: missing required key");
  c.operating = read_operating(root.object("operating"));
  ThermalPathCase::table().read(root, c);
  return c;
}

GearCase read_gear_case(ObjectReader& root) {
  GearCase c;
  c.gear_pair = read_gear_pair(root.object("gear_pair"));
  if (root.has("materials")) c.materials = read_materials(root);
  if (root.has("operating")) c.operating = read_operating(root.object("operating"));
  if (root.has("lubricant")) c.lubricant = read_lubricant(root.object("lubricant"));
  return c;
}

}  // namespace gearbench::model
