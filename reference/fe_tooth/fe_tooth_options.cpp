// The case keys of the FE tooth reference (issue 21: one table per Options). Outside the
// deal.II plugin, which links nothing of ours: its callers validate before they call it.
#include <fmt/format.h>
#include <numbers>

#include "fe_tooth_stiffness.h"
#include "model/errors.h"
#include "model/option_table.h"

namespace gearbench::reference::fe {
namespace {

using model::Range;

model::OptionTable<ElasticOptions> make_elastic_table() {
  model::OptionTable<ElasticOptions> t;
  t.integer("degree", &ElasticOptions::degree, 1, 4, {.description = "polynomial degree of the Lagrange elements"});
  t.integer("max_cycles", &ElasticOptions::max_cycles, 3, 20,
            {.description = "solves at most, the first on the initial mesh, each later one on a Kelly-refined mesh"});
  t.number("refine_fraction", &ElasticOptions::refine_fraction, Range{0.0, 1.0, true, true},
           {.description = "share of the cells the Kelly estimator marks for refinement per cycle"});
  t.number("tolerance", &ElasticOptions::tolerance, Range{0.0, 0.5, true, true},
           {.description = "converged when the last two relative changes of the probed displacement are below it"});
  return t;
}

/// The keys of the energy method's "crack" section, as this reference models them: a pitch
/// crack, meshed as a slit.
model::OptionTable<ToothCrack> make_crack_table() {
  model::OptionTable<ToothCrack> t;
  t.choice("type", &ToothCrack::type, std::vector<std::pair<std::string, ToothCrack::Type>>{{"pitch", ToothCrack::Type::pitch}},
           {.description = "where the crack starts: at the pitch point (seed 003; the slit models no other)",
            .required = true});
  t.number("length_mm", &ToothCrack::length, Range::closed(0.0, 1e4),
           {.description = "crack depth q along its path", .unit = "mm", .scale = 1e-3, .required = true});
  t.number("angle_deg", &ToothCrack::angle, Range{0.0, 90.0, true, true},
           {.description = "angle of the crack path to the tooth's centre line", .unit = "deg",
            .scale = std::numbers::pi / 180.0, .required = true});
  // Gears are numbered 1, 2 in a case and 0, 1 in the code.
  t.integer("gear", &ToothCrack::gear, 1, 2,
            {.description = "the gear whose loaded tooth carries the crack (1 pinion, 2 wheel)", .offset = -1.0});
  return t;
}

model::OptionTable<FeToothOptions> make_mesh_table() {
  model::OptionTable<FeToothOptions> t;
  t.number("near_size_modules", &FeToothOptions::near_size_modules, Range{0.01, 1.0, true, false},
           {.description = "initial element size at the loaded tooth, in normal modules"});
  t.number("far_size_modules", &FeToothOptions::far_size_modules, Range{0.01, 5.0, true, false},
           {.description = "largest initial element size, in normal modules, at least near_size_modules"});
  t.rule([](const FeToothOptions& o, const std::string& prefix) {
    if (o.far_size_modules < o.near_size_modules)
      throw InputError(fmt::format("{}far_size_modules = {}: must be at least {}near_size_modules = {}", prefix,
                                   model::format_value(o.far_size_modules), prefix,
                                   model::format_value(o.near_size_modules)));
  });
  return t;
}

model::OptionTable<FeToothOptions> make_table() {
  model::OptionTable<FeToothOptions> t;
  t.boolean("plane_stress", &FeToothOptions::plane_stress,
            {.description = "plane stress (the energy method's E and G) instead of plane strain"});
  t.number("bore_diameter_mm", &FeToothOptions::bore_radius, Range::positive(1e7),
           {.description = "bore diameter per gear, below the root diameter; the bore is clamped", .unit = "mm",
            .scale = 0.5e-3, .default_text = "half the root diameter"});
  t.number("load_N_per_mm", &FeToothOptions::load_per_width, Range::positive(1e5),
           {.description = "normal force per face width (it sets the Hertzian width of the load patch)",
            .unit = "N/mm", .scale = 1e3});
  t.integer("positions", &FeToothOptions::positions, 1, 200,
            {.description = "mesh positions, equally spaced along the path of contact A..E (one: its middle)"});
  static const auto mesh = make_mesh_table();
  t.section("mesh", [](auto& o) -> auto& { return o; }, mesh, {.description = "the initial mesh of each gear"});
  t.boolean("rigid_body", &FeToothOptions::rigid_body,
            {.description = "diagnostic: the body inside the root circle 1000 times stiffer, so that the probe sees "
                            "the tooth alone"});
  t.section("fe", &FeToothOptions::fe, ElasticOptions::table(), {.description = "the adaptive finite-element solve"});
  static const auto crack = make_crack_table();
  t.section("crack", &FeToothOptions::crack, crack,
            {.description = "a pitch crack in one gear's loaded tooth, meshed as a slit (the stiffness kind's keys)"});
  return t;
}

}  // namespace

const model::OptionTable<ElasticOptions>& ElasticOptions::table() {
  static const auto t = make_elastic_table();
  return t;
}

void ElasticOptions::validate() const { table().validate(*this, "fe."); }

const model::OptionTable<FeToothOptions>& FeToothOptions::table() {
  static const auto t = make_table();
  return t;
}

}  // namespace gearbench::reference::fe
