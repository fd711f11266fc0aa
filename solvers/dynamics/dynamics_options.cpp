// The case keys of the dynamics models (issue 21: one table per Options). Both models take
// the run keys (damping ratio, backlash, run length, integrator, friction, fillet) alike;
// their bearings, and the herringbone's groove coupling, mesh slicing and mesh-in impact, are
// their own.
#include <fmt/format.h>

#include "dynamics_options.h"
#include "herringbone12_dynamics.h"
#include "model/errors.h"
#include "spur6_dynamics.h"
#include "stiffness/mesh_stiffness.h"

namespace gearbench::dynamics {
namespace {

using model::Range;

/// A bearing stiffness may stand for a rigid support (1e16 N/m, 1e8 times a mesh's, is the
/// checks' rigid bearing), never zero (a free body has no static state).
constexpr double max_stiffness = 1e16;
constexpr double max_damping = 1e9;

/// The keys both models read alike, into members of the same names; `friction` and `fillet`
/// return where the model keeps them.
template <class O, class Friction, class Fillet>
void add_run_keys(model::OptionTable<O>& t, Friction friction, Fillet fillet) {
  t.number("mesh_damping_ratio", &O::mesh_damping_ratio, Range::closed(0.0, 1.0),
           {.description = "mesh damping ratio zeta_m: c_m = 2 zeta_m sqrt(k_mean m_e)"});
  t.section("friction", friction, FrictionLawOptions::table(),
            {.description = "the friction law and its parameters (the efficiency kind's section, every law but "
                            "\"ehl\"); the laws other than \"constant\" need the lubricant section"});
  t.include(fillet, stiffness::fillet_table());
  t.number("backlash_um", &O::backlash, Range{0.0, 1e4, true, false},
           {.description = "backlash along the line of action (herringbone12: along the normal, per half): the "
                           "flanks may part and strike the back flanks (docs/dynamics-model.md, \"Contact loss\"); "
                           "absent: the linear mesh",
            .unit = "um", .scale = 1e-6});
  t.integer("runup_cycles", &O::runup_cycles, 0, 1000000,
            {.description = "mesh cycles from the static state before recording (spur6 with a crack: rounded up to "
                            "whole revolutions)"});
  t.integer("record_cycles", &O::record_cycles, 2, 1000000,
            {.description = "mesh cycles recorded (spur6 with a crack: whole revolutions, at least two)"});
  t.integer("samples_per_cycle", &O::samples_per_cycle, 8, 4096,
            {.description = "samples of the recorded response per mesh cycle"});
  t.section("integrator", &O::integrator, IntegratorOptions::table(), {.description = "the time integrator"});
}

model::OptionTable<Spur6Options> make_spur6_bearings() {
  model::OptionTable<Spur6Options> t;
  t.number("stiffness_N_per_m", &Spur6Options::bearing_stiffness, Range::positive(max_stiffness),
           {.description = "bearing stiffness of each gear, x and y", .unit = "N/m"});
  t.number("damping_N_s_per_m", &Spur6Options::bearing_damping, Range::closed(0.0, max_damping),
           {.description = "bearing damping of each gear, x and y", .unit = "N*s/m"});
  return t;
}

model::OptionTable<Spur6Options> make_spur6_table() {
  model::OptionTable<Spur6Options> t;
  static const auto bearings = make_spur6_bearings();
  t.section("bearings", [](auto& o) -> auto& { return o; }, bearings, {.description = "the bearings of both gears"});
  add_run_keys(t, [](auto& o) -> auto& { return o.friction; }, [](auto& o) -> auto& { return o.fillet; });
  t.section("crack", &Spur6Options::crack, stiffness::crack_table(1),
            {.description = "a crack in one pinion tooth (the stiffness kind's section, gear 1 only); the response "
                            "then repeats once a revolution"});
  return t;
}

model::OptionTable<Herringbone12Options> make_herringbone_bearings() {
  model::OptionTable<Herringbone12Options> t;
  t.number("radial_stiffness_N_per_m", &Herringbone12Options::radial_stiffness, Range::positive(max_stiffness),
           {.description = "radial stiffness of each half's bearing, pinion and wheel", .unit = "N/m"});
  t.number("radial_damping_N_s_per_m", &Herringbone12Options::radial_damping, Range::closed(0.0, max_damping),
           {.description = "radial damping of each half's bearing", .unit = "N*s/m"});
  t.number("axial_stiffness_N_per_m", &Herringbone12Options::axial_stiffness, Range::positive(max_stiffness),
           {.description = "axial stiffness of the wheel halves (and of a pinion that does not float)", .unit = "N/m"});
  t.number("axial_damping_N_s_per_m", &Herringbone12Options::axial_damping, Range::closed(0.0, max_damping),
           {.description = "axial damping of the wheel halves (and of a pinion that does not float)",
            .unit = "N*s/m"});
  t.boolean("floating_pinion", &Herringbone12Options::floating_pinion,
            {.description = "the pinion has no axial bearing and centres itself between the halves (seed 000)"});
  return t;
}

model::OptionTable<Herringbone12Options> make_groove_coupling() {
  model::OptionTable<Herringbone12Options> t;
  t.number("axial_stiffness_N_per_m", &Herringbone12Options::groove_stiffness, Range::closed(0.0, max_stiffness),
           {.description = "axial coupling of the two halves of a gear", .unit = "N/m",
            .default_text = "E pi r_f^2 / groove: a solid shaft of the pinion's root radius over the groove"});
  t.number("axial_damping_N_s_per_m", &Herringbone12Options::groove_damping, Range::closed(0.0, max_damping),
           {.description = "axial damping between the halves", .unit = "N*s/m"});
  t.number("torsional_stiffness_N_m_per_rad", &Herringbone12Options::twist_stiffness,
           Range::closed(0.0, max_stiffness),
           {.description = "torsional coupling of the two halves of a gear", .unit = "N*m/rad",
            .default_text = "G pi r_f^4 / (2 groove): the same shaft in torsion"});
  t.number("torsional_damping_N_m_s_per_rad", &Herringbone12Options::twist_damping, Range::closed(0.0, max_damping),
           {.description = "torsional damping between the halves", .unit = "N*m*s/rad"});
  return t;
}

model::OptionTable<Herringbone12Options> make_herringbone_table() {
  model::OptionTable<Herringbone12Options> t;
  static const auto bearings = make_herringbone_bearings();
  static const auto groove = make_groove_coupling();
  t.section("bearings", [](auto& o) -> auto& { return o; }, bearings, {.description = "the bearings of each half"});
  t.section("groove_coupling", [](auto& o) -> auto& { return o; }, groove,
            {.description = "how the two halves of each gear are coupled across the groove"});
  t.section("mesh", &Herringbone12Options::mesh, HalfMeshOptions::table(),
            {.description = "the mesh excitation of a helical half"});
  add_run_keys(t, [](auto& o) -> auto& { return o.mesh.friction; }, [](auto& o) -> auto& { return o.mesh.fillet; });
  t.boolean("mesh_in_impact", &Herringbone12Options::mesh_in_impact,
            {.description = "seed 000 eq. 6 pulses at mesh-in, their peak that of eq. 6's mass and spring under the "
                            "entering corner's approach (docs/dynamics-model.md, \"Mesh-in impact\")"});
  t.boolean("mesh_in_impact_held_velocity", &Herringbone12Options::impact_held_velocity,
            {.description = "eq. 6 as printed: the closing speed held through the pulse (an overestimate, for "
                            "comparison)"});
  t.number("base_pitch_error_um", &Herringbone12Options::base_pitch_error, Range::closed(0.0, 100.0),
           {.description = "base pitch error f_pb, added to the loaded deflection the entering corner closes",
            .unit = "um", .scale = 1e-6});
  t.number("half_offset_cycles", &Herringbone12Options::half_offset, Range::closed(0.0, 1.0),
           {.description = "the right half's mesh lags the left one's by this fraction of a mesh cycle"});
  return t;
}

model::OptionTable<HalfMeshOptions> make_half_mesh_table() {
  model::OptionTable<HalfMeshOptions> t;
  t.integer("slices", &HalfMeshOptions::slices, 1, 10000, {.description = "face-width slices of a helical half"});
  t.integer("positions", &HalfMeshOptions::positions, 16, 100000,
            {.description = "points over one mesh cycle of the stiffness and friction-arm tables (helical)"});
  t.integer("harmonics", &HalfMeshOptions::harmonics, 1, 50000,
            {.description = "mesh harmonics kept of the tables (helical), below positions/2"});
  // A table of N points holds harmonics below N/2 only (Nyquist).
  t.rule([](const HalfMeshOptions& o, const std::string& prefix) {
    if (2 * o.harmonics >= o.positions)
      throw InputError(fmt::format("{}harmonics = {}: allowed range is [1, {}positions/2) = [1, {})", prefix,
                                   o.harmonics, prefix, (o.positions + 1) / 2));
  });
  return t;
}

model::OptionTable<ModelChoice> make_model_table() {
  model::OptionTable<ModelChoice> t;
  t.choice("model", &ModelChoice::model,
           std::vector<std::pair<std::string, ModelName>>{{"spur6", ModelName::spur6},
                                                          {"herringbone12", ModelName::herringbone12}},
           {.description = "6-DOF spur pair on bearings (seed 003), or 12-DOF bending-torsion-axial herringbone pair "
                           "(seed 000)"});
  return t;
}

}  // namespace

const model::OptionTable<Spur6Options>& Spur6Options::table() {
  static const auto t = make_spur6_table();
  return t;
}

const model::OptionTable<Herringbone12Options>& Herringbone12Options::table() {
  static const auto t = make_herringbone_table();
  return t;
}

const model::OptionTable<HalfMeshOptions>& HalfMeshOptions::table() {
  static const auto t = make_half_mesh_table();
  return t;
}

const model::OptionTable<ModelChoice>& ModelChoice::table() {
  static const auto t = make_model_table();
  return t;
}

}  // namespace gearbench::dynamics
