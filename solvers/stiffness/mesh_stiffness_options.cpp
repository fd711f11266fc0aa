// The case keys of the energy-method mesh stiffness (issue 21: one table per Options).
#include <fmt/format.h>
#include <numbers>

#include "mesh_stiffness.h"
#include "model/errors.h"

namespace gearbench::stiffness {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

model::OptionTable<GearCrack> make_crack_table(int max_gear) {
  model::OptionTable<GearCrack> t;
  t.choice("type", [](auto& c) -> auto& { return c.crack.type; },
           std::vector<std::pair<std::string, Crack::Type>>{{"pitch", Crack::Type::pitch}, {"root", Crack::Type::root}},
           {.description = "where the crack starts: at the pitch point or at the root (seed 003)", .required = true});
  t.number("length_mm", [](auto& c) -> auto& { return c.crack.length; }, model::Range::closed(0.0, 1e4),
           {.description = "crack depth q along its path", .unit = "mm", .scale = 1e-3, .required = true});
  t.number("angle_deg", [](auto& c) -> auto& { return c.crack.angle; }, model::Range{0.0, 90.0, true, true},
           {.description = "angle of the crack path to the tooth's centre line", .unit = "deg", .scale = deg,
            .required = true});
  // Gears are numbered 1, 2 in a case and 0, 1 in the code.
  t.integer("gear", &GearCrack::gear, 1, max_gear,
            {.description = "the gear that carries the crack (1 pinion, 2 wheel)", .offset = -1.0});
  return t;
}

model::OptionTable<Fillet> make_fillet_table() {
  model::OptionTable<Fillet> t;
  t.choice("fillet", [](auto& f) -> auto& { return f; },
           std::vector<std::pair<std::string, Fillet>>{{"trochoid", Fillet::trochoid},
                                                       {"circular_arc", Fillet::circular_arc}},
           {.description = "root fillet of the energy-method tooth's improved beam: the trochoid the rack cutter "
                           "generates, or seed 003's circular arc (docs/stiffness-model.md); kind stiffness: only "
                           "with beam_start \"improved\""});
  return t;
}

model::OptionTable<MeshStiffnessOptions> make_table() {
  model::OptionTable<MeshStiffnessOptions> t;
  t.choice("beam_start", &MeshStiffnessOptions::beam_start,
           std::vector<std::pair<std::string, BeamStart>>{
               {"improved", BeamStart::improved}, {"straight", BeamStart::straight}, {"base_circle", BeamStart::base_circle}},
           {.description = "where the cantilever beam starts: root circle with fillet (improved), root circle with "
                           "constant thickness below the base circle (straight), or the base circle"});
  t.include(&MeshStiffnessOptions::fillet, fillet_table());
  t.integer("positions", &MeshStiffnessOptions::positions, 2, 100000,
            {.description = "mesh positions over one mesh cycle (with a crack: over the cracked tooth's engagement)"});
  t.integer("path_points", &MeshStiffnessOptions::path_points, 2, 100000,
            {.description = "points of the single-pair curve along the path of contact A..E"});
  t.integer("slices", &MeshStiffnessOptions::slices, 1, 10000,
            {.description = "face-width slices of a helical pair (a spur pair is always one slice)"});
  t.integer("spline_nodes", &MeshStiffnessOptions::spline_nodes, 4, 1000000,
            {.description = "helical pairs: nodes of the cubic spline of the single-pair stiffness along A..E"});
  t.boolean("foundation", &MeshStiffnessOptions::foundation,
            {.description = "include the fillet-foundation compliance (Sainsot et al. 2004)"});
  t.number("bore_diameter_mm", &MeshStiffnessOptions::bore_radius, model::Range::positive(1e7),
           {.description = "bore diameter per gear, below the root diameter", .unit = "mm", .scale = 0.5e-3,
            .default_text = "half the root diameter"});
  t.section("crack", &MeshStiffnessOptions::crack, crack_table(2),
            {.description = "a crack in one tooth (spur pairs only); absent: healthy teeth"});
  // The straight and base-circle beams have no fillet, so a fillet given with them says
  // the case expects a model it does not get.
  t.after_read([](model::ObjectReader& r, const MeshStiffnessOptions& o) {
    if (r.has("fillet") && o.beam_start != BeamStart::improved)
      throw InputError(fmt::format("fillet = \"{}\": allowed only with beam_start \"improved\" (the other beams "
                                   "have no fillet)", o.fillet == Fillet::trochoid ? "trochoid" : "circular_arc"));
  });
  return t;
}

}  // namespace

const model::OptionTable<GearCrack>& crack_table(int max_gear) {
  static const auto pinion_only = make_crack_table(1);
  static const auto either = make_crack_table(2);
  return max_gear == 1 ? pinion_only : either;
}

const model::OptionTable<Fillet>& fillet_table() {
  static const auto t = make_fillet_table();
  return t;
}

const model::OptionTable<MeshStiffnessOptions>& MeshStiffnessOptions::table() {
  static const auto t = make_table();
  return t;
}

}  // namespace gearbench::stiffness
