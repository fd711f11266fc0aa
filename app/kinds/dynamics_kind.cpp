// Case kind "dynamics": 6-DOF spur-pair (model "spur6") and 12-DOF herringbone (model
// "herringbone12") dynamics on SUNDIALS (CVODE or ARKODE, `integrator.method`), optionally swept over speed.
#include <cmath>
#include <fmt/format.h>
#include <iostream>

#include "tooth_sections.h"
#include "dynamics/herringbone12_dynamics.h"
#include "dynamics/speed_sweep.h"
#include "dynamics/spur6_dynamics.h"
#include "efficiency/dynamic_efficiency.h"
#include "efficiency_sections.h"
#include "kind_registry.h"
#include "model/case_reader.h"
#include "model/errors.h"

namespace gearbench::app {
namespace {

using nlohmann::json;
using model::Range;

dynamics::IntegratorOptions read_integrator(model::ObjectReader& root, dynamics::IntegratorOptions o) {
  if (!root.has("integrator")) return o;
  auto i = root.object("integrator");
  std::vector<std::string> keys;
  for (const auto& m : dynamics::integrator_methods())
    if (m.offered) keys.emplace_back(m.key);
  if (const auto method = i.optional_string("method", keys)) o.method = dynamics::integrator_method(*method);
  o.relative_tolerance = i.optional_number("rtol", {1e-14, 1e-2}).value_or(o.relative_tolerance);
  o.absolute_tolerance = i.optional_number("atol", {1e-20, 1e-2}).value_or(o.absolute_tolerance);
  i.finish();
  return o;
}

/// An optional true/false key of `object` (read through `reader`, which then knows it).
std::optional<bool> optional_bool(model::ObjectReader& reader, const json& object, const std::string& key) {
  if (!reader.has(key)) return std::nullopt;
  reader.accept(key);
  if (!object.at(key).is_boolean())
    throw InputError(fmt::format("{} = {}: must be true or false", reader.key_path(key), model::shown_value(object.at(key))));
  return object.at(key).get<bool>();
}

/// The keys both models read alike: mesh damping, friction (the efficiency kind's section),
/// backlash, run length and integrator. `mu` and `law` are where the model keeps its friction.
template <class Options>
void read_common_options(model::ObjectReader& root, const model::GearCase& c, Options& o, double& mu,
                         dynamics::FrictionLawOptions& law) {
  o.mesh_damping_ratio = root.optional_number("mesh_damping_ratio", Range::closed(0.0, 1.0)).value_or(o.mesh_damping_ratio);
  efficiency::MeshLossOptions friction;
  friction.friction_coefficient = mu;
  read_friction_section(root, friction);
  mu = friction.friction_coefficient;
  law.model = friction.friction_model;
  law.boundary_mu = friction.boundary_friction;
  law.lubricant_factor = friction.lubricant_factor;
  law.lubricant = c.lubricant;
  if (const auto b = root.optional_number("backlash_um", Range::positive(1e4), "um")) o.backlash = *b * 1e-6;
  o.runup_cycles = root.optional_integer("runup_cycles", 0, 1000000).value_or(o.runup_cycles);
  o.record_cycles = root.optional_integer("record_cycles", 2, 1000000).value_or(o.record_cycles);
  o.samples_per_cycle = root.optional_integer("samples_per_cycle", 8, 4096).value_or(o.samples_per_cycle);
  o.integrator = read_integrator(root, o.integrator);
}

dynamics::Spur6Options read_spur6_options(model::ObjectReader& root, const json&, const model::GearCase& c) {
  dynamics::Spur6Options o;
  if (root.has("bearings")) {
    auto b = root.object("bearings");
    o.bearing_stiffness = b.optional_number("stiffness_N_per_m", Range::positive(1e15), "N/m").value_or(o.bearing_stiffness);
    o.bearing_damping = b.optional_number("damping_N_s_per_m", Range::closed(0.0, 1e9), "N*s/m").value_or(o.bearing_damping);
    b.finish();
  }
  read_common_options(root, c, o, o.friction_coefficient, o.friction_law);
  o.crack = read_crack(root, 1);
  o.fillet = read_fillet(root);
  return o;
}

dynamics::Herringbone12Options read_herringbone_options(model::ObjectReader& root, const json& case_json,
                                                       const model::GearCase& c) {
  dynamics::Herringbone12Options o;
  if (root.has("bearings")) {
    auto b = root.object("bearings");
    o.radial_stiffness = b.optional_number("radial_stiffness_N_per_m", Range::positive(1e15), "N/m").value_or(o.radial_stiffness);
    o.radial_damping = b.optional_number("radial_damping_N_s_per_m", Range::closed(0.0, 1e9), "N*s/m").value_or(o.radial_damping);
    o.axial_stiffness = b.optional_number("axial_stiffness_N_per_m", Range::positive(1e15), "N/m").value_or(o.axial_stiffness);
    o.axial_damping = b.optional_number("axial_damping_N_s_per_m", Range::closed(0.0, 1e9), "N*s/m").value_or(o.axial_damping);
    o.floating_pinion = optional_bool(b, case_json.at("bearings"), "floating_pinion").value_or(o.floating_pinion);
    b.finish();
  }
  if (root.has("groove_coupling")) {
    auto g = root.object("groove_coupling");
    o.groove_stiffness = g.optional_number("axial_stiffness_N_per_m", Range::closed(0.0, 1e15), "N/m");
    o.groove_damping = g.optional_number("axial_damping_N_s_per_m", Range::closed(0.0, 1e9), "N*s/m").value_or(o.groove_damping);
    o.twist_stiffness = g.optional_number("torsional_stiffness_N_m_per_rad", Range::closed(0.0, 1e15), "N*m/rad");
    o.twist_damping = g.optional_number("torsional_damping_N_m_s_per_rad", Range::closed(0.0, 1e9), "N*m*s/rad")
                          .value_or(o.twist_damping);
    g.finish();
  }
  if (root.has("mesh")) {
    auto m = root.object("mesh");
    o.mesh.slices = m.optional_integer("slices", 1, 10000).value_or(o.mesh.slices);
    o.mesh.positions = m.optional_integer("positions", 16, 100000).value_or(o.mesh.positions);
    o.mesh.harmonics = m.optional_integer("harmonics", 1, 50000).value_or(o.mesh.harmonics);
    m.finish();
  }
  read_common_options(root, c, o, o.mesh.friction_coefficient, o.mesh.friction_law);
  o.mesh.fillet = read_fillet(root);
  o.mesh_in_impact = optional_bool(root, case_json, "mesh_in_impact").value_or(o.mesh_in_impact);
  o.impact_held_velocity =
      optional_bool(root, case_json, "mesh_in_impact_held_velocity").value_or(o.impact_held_velocity);
  o.base_pitch_error = 1e-6 * root.optional_number("base_pitch_error_um", Range::closed(0.0, 100.0)).value_or(0.0);
  o.half_offset = root.optional_number("half_offset_cycles", Range::closed(0.0, 1.0)).value_or(o.half_offset);
  return o;
}

json stats_json(const dynamics::ResponseStats& s) {
  return {{"mean", s.mean}, {"rms", s.rms}, {"peak_to_peak", s.peak_to_peak}};
}

/// "speed_sweep_rpm": {"from", "to", "points"}, pinion speeds, equally spaced.
std::optional<dynamics::SpeedSweepSpec> read_sweep(model::ObjectReader& root) {
  if (!root.has("speed_sweep_rpm")) return std::nullopt;
  auto s = root.object("speed_sweep_rpm");
  dynamics::SpeedSweepSpec w{s.number("from", Range::positive(1e6), "rpm"), s.number("to", Range::positive(1e6), "rpm"),
                             s.integer("points", 2, 10000)};
  s.finish();
  w.validate();
  return w;
}

json energy_json(const dynamics::EnergyBalance& e) {
  return {{"input", e.input}, {"output", e.output}, {"damping", e.damping}, {"friction", e.friction},
          {"parametric", e.parametric}, {"impact", e.impact}, {"energy_change", e.energy_change},
          {"relative_residual", e.residual}};
}

/// The contact-loss figures of a run with backlash; null without.
template <class Result>
json contact_json(const std::optional<double>& backlash, const Result& r) {
  if (!backlash) return nullptr;
  return {{"backlash_m", *backlash}, {"separation_fraction", r.contact_loss_fraction},
          {"back_contact_fraction", r.back_contact_fraction}, {"root_events", r.contact_events}};
}

json spur6_result(const dynamics::Spur6Dynamics& solver, const dynamics::Spur6Result& r) {
  const auto& p = solver.parameters();
  return {
      {"kind", "dynamics"},
      {"model", "spur6"},
      {"time_s", r.time},
      {"transmission_error_m", r.transmission_error},
      {"mesh_force_N", r.mesh_force},
      {"friction_force_N", r.friction_force},
      {"bearing_force_x1_N", r.bearing_force_x1},
      {"statistics", {{"transmission_error_m", stats_json(r.te)}, {"mesh_force_N", stats_json(r.force)},
                      {"friction_force_N", stats_json(r.friction)}}},
      {"static_mesh_force_N", r.static_mesh_force},
      {"dynamic_factor", r.dynamic_factor},
      {"mesh_frequency_Hz", r.mesh_frequency},
      {"natural_frequencies_Hz", r.natural_frequencies},
      {"spectrum", {{"frequency_Hz", r.spectrum_frequency}, {"transmission_error_amplitude_m", r.spectrum_te}}},
      {"energy_balance_J", energy_json(r.energy)},
      {"load_torque_Nm", p.T2},
      {"parameters", {{"masses_kg", {p.m1, p.m2}}, {"inertias_kg_m2", {p.I1, p.I2}},
                      {"mean_mesh_stiffness_N_per_m", p.mean_mesh_stiffness},
                      {"mesh_damping_N_s_per_m", p.mesh_damping}}},
      {"diagnostics", {{"steps", r.steps}, {"rhs_evaluations", r.rhs_evaluations}, {"seconds", r.seconds},
                       {"periodicity", r.periodicity}}},
  };
}

json herringbone12_result(const dynamics::Herringbone12Dynamics& solver, const dynamics::Herringbone12Result& r) {
  const auto& p = solver.parameters();
  return {
      {"kind", "dynamics"},
      {"model", "herringbone12"},
      {"time_s", r.time},
      {"transmission_error_m", {{"left", r.transmission_error[0]}, {"right", r.transmission_error[1]}}},
      {"mesh_force_N", {{"left", r.mesh_force[0]}, {"right", r.mesh_force[1]}}},
      {"friction_torque_pinion_Nm", {{"left", r.friction_torque[0]}, {"right", r.friction_torque[1]}}},
      {"axial_float_m", r.axial_float},
      {"bearing_force_pinion_left_N", r.bearing_force_pinion},
      {"statistics", {{"transmission_error_left_m", stats_json(r.te[0])}, {"transmission_error_right_m", stats_json(r.te[1])},
                      {"mesh_force_left_N", stats_json(r.force[0])}, {"mesh_force_right_N", stats_json(r.force[1])},
                      {"axial_float_m", stats_json(r.float_stats)}}},
      {"static_mesh_force_per_half_N", r.static_mesh_force},
      {"dynamic_factor", r.dynamic_factor},
      {"load_torque_Nm", r.load_torque},
      {"mesh_frequency_Hz", r.mesh_frequency},
      {"natural_frequencies_Hz", r.natural_frequencies},
      {"mode_shapes", r.mode_shapes},
      {"spectrum", {{"frequency_Hz", r.spectrum_frequency}, {"transmission_error_left_amplitude_m", r.spectrum_te}}},
      {"energy_balance_J", energy_json(r.energy)},
      {"parameters", {{"masses_per_half_kg", {p.m_p, p.m_g}}, {"inertias_per_half_kg_m2", {p.I_p, p.I_g}},
                      {"base_helix_angle_deg", p.beta_b * 180.0 / M_PI},
                      {"mean_mesh_stiffness_per_half_N_per_m", p.mean_mesh_stiffness},
                      {"mesh_damping_N_s_per_m", p.mesh_damping}, {"groove_axial_stiffness_N_per_m", p.k_groove},
                      {"groove_torsional_stiffness_N_m_per_rad", p.k_twist},
                      {"impact", {{"velocity_m_per_s", p.impact_velocity}, {"peak_force_N", p.impact_force},
                                  {"held_velocity_peak_force_N", p.impact_held_force},
                                  {"stiffness_N_per_m", p.impact_stiffness}, {"duration_s", p.impact_duration},
                                  {"approach_time_s", p.impact_approach_time},
                                  {"compression_ratio", p.impact_compression_ratio},
                                  {"entry_fraction", p.impact_entry_fraction}}}}},
      {"diagnostics", {{"steps", r.steps}, {"rhs_evaluations", r.rhs_evaluations}, {"seconds", r.seconds},
                       {"periodicity", r.periodicity}, {"slicing_consistency", solver.mesh().slicing_consistency()},
                       {"harmonic_truncation", solver.mesh().truncation()}}},
  };
}

/// The speed sweep's figures; its progress goes to stderr, one line per point.
json sweep_json(const dynamics::SpeedSweepResult& s) {
  json skipped = json::array();
  for (const auto& k : s.skipped) skipped.push_back({{"speed_rpm", k.speed_rpm}, {"reason", k.reason}});
  return {{"speed_rpm", s.speed_rpm}, {"mesh_frequency_Hz", s.mesh_frequency}, {"dynamic_factor", s.dynamic_factor},
          {"transmission_error_rms_m", s.te_rms}, {"skipped", skipped}};
}

void print_progress(const std::string& line) { std::cerr << "gearbench: " << line << std::endl; }

/// The optional "dynamic_efficiency" section: the loss options of the efficiency kind
/// ("friction", "load_sharing", ...) plus "load_levels" and "phases" of the loss curves.
struct DynamicEfficiencySpec {
  efficiency::MeshLossOptions loss;
  efficiency::DynamicEfficiencyOptions curves;
};

std::optional<DynamicEfficiencySpec> read_dynamic_efficiency(model::ObjectReader& root) {
  if (!root.has("dynamic_efficiency")) return std::nullopt;
  auto section = root.object("dynamic_efficiency");
  DynamicEfficiencySpec spec{read_mesh_loss_options(section), {}};
  spec.curves.load_levels = section.optional_integer("load_levels", 2, 100).value_or(spec.curves.load_levels);
  spec.curves.phases = section.optional_integer("phases", 4, 100000).value_or(spec.curves.phases);
  section.finish();
  return spec;
}

/// η_D(t) of the recorded window (seed 000 eq. 12) beside the static efficiency on the same
/// phase grid. A herringbone pair is passed as one helical half with a force series per half.
/// Constructed before the integration: the static loss at the nominal force, computed then,
/// refuses a contact out of the friction law's range (e.g. its Hertz pressure) at once, not
/// after the run.
efficiency::DynamicEfficiency dynamic_efficiency(const DynamicEfficiencySpec& spec, const model::GearCase& c,
                                                 std::size_t meshes) {
  return {geometry::GearPairGeometry(c.gear_pair.one_mesh()), *c.operating, spec.loss, {c.materials, c.lubricant},
          meshes, spec.curves};
}

json dynamic_efficiency_json(const efficiency::DynamicEfficiencyResult& r, const DynamicEfficiencySpec& spec) {
  return {{"mean", r.mean}, {"static_mean", r.static_mean}, {"efficiency", r.efficiency},
          {"load_levels_N", r.load_levels}, {"friction_model", lubricant::friction_model_name(spec.loss.friction_model)}};
}

/// What differs between the two models for run_model: reading, result JSON and the series
/// that the dynamic efficiency and the speed sweep take.
struct Spur6Model {
  using Solver = dynamics::Spur6Dynamics;
  static constexpr auto read = read_spur6_options;
  static constexpr auto result = spur6_result;
  static json notes(const Solver&) { return json::array(); }
  static constexpr std::size_t meshes = 1;
  static std::vector<std::vector<double>> forces(const dynamics::Spur6Result& r) { return {r.mesh_force}; }
  static double te_rms(const dynamics::Spur6Result& r) { return r.te.rms; }
  static const dynamics::FrictionLawOptions& law(const dynamics::Spur6Options& o) { return o.friction_law; }
};

struct Herringbone12Model {
  using Solver = dynamics::Herringbone12Dynamics;
  static constexpr auto read = read_herringbone_options;
  static constexpr auto result = herringbone12_result;
  /// What the mesh-in pulse stands for (docs/dynamics-model.md, "Mesh-in impact").
  static json notes(const Solver& solver) {
    const auto& p = solver.parameters();
    json notes = json::array();
    if (p.impact_compression_ratio > 1.0 && p.impact_force == p.impact_held_force)
      notes.push_back(fmt::format(
          "mesh_in_impact_held_velocity: eq. 6 as printed compresses the mesh by {:.3g} times the gap that the "
          "entering tooth's approach closes (parameters.impact.compression_ratio; it holds where that is <= 1, here "
          "below about {:.0f} rpm), so it overstates the dynamic factor",
          p.impact_compression_ratio, p.impact_premise_speed() * 30.0 / M_PI));
    if (p.impact_entry_fraction > 0.0)
      notes.push_back(fmt::format(
          "mesh_in_impact: the pulse engages the whole helical half at once, while its entering contact sweeps across "
          "the face ({:.2g} % of the face width in premature contact at a time, parameters.impact.entry_fraction): an "
          "upper estimate of the mesh-in impact",
          100.0 * p.impact_entry_fraction));
    return notes;
  }
  static constexpr std::size_t meshes = 2;  ///< the halves
  static std::vector<std::vector<double>> forces(const dynamics::Herringbone12Result& r) {
    return {r.mesh_force[0], r.mesh_force[1]};
  }
  static double te_rms(const dynamics::Herringbone12Result& r) { return r.te[0].rms; }
  static const dynamics::FrictionLawOptions& law(const dynamics::Herringbone12Options& o) { return o.mesh.friction_law; }
};

/// Above this periodicity (the last recorded period against the one before, relative to
/// the peak-to-peak transmission error) the run has not reached its periodic response: 6e-8
/// at the seed's 1000 rpm, 1.5e-2 at 1e6 rpm.
constexpr double max_periodicity = 1e-3;

/// Notes of a result whose figures are not those of the periodic response.
json periodicity_notes(double periodicity) {
  if (periodicity <= max_periodicity) return json::array();
  return json::array({fmt::format("not periodic: successive periods differ by {:.2g} of the peak-to-peak transmission error "
                      "(more than {:.0e}), so the dynamic factor is that of a transient; raise runup_cycles",
                      periodicity, max_periodicity)});
}

/// Reads the model's options and the shared sections, solves, and adds the dynamic
/// efficiency and the speed sweep when asked.
template <class Model>
json run_model(model::ObjectReader& root, const json& case_json, const model::GearCase& c,
               const geometry::GearPairGeometry& geometry) {
  const auto options = Model::read(root, case_json, c);
  const auto sweep = read_sweep(root);
  const auto efficiency_spec = read_dynamic_efficiency(root);
  root.finish();
  const typename Model::Solver solver(geometry, *c.materials, *c.operating, options);
  std::optional<efficiency::DynamicEfficiency> efficiency;  // before the integration: it checks the friction law's range
  if (efficiency_spec) efficiency.emplace(dynamic_efficiency(*efficiency_spec, c, Model::meshes));
  const auto r = solver.solve();
  json result = Model::result(solver, r);
  result["notes"] = periodicity_notes(r.periodicity);
  for (const auto& note : Model::notes(solver)) result["notes"].push_back(note);
  result["friction_model"] = lubricant::friction_model_name(Model::law(options).model);
  result["contact_loss"] = contact_json(options.backlash, r);
  if (efficiency)
    result["dynamic_efficiency"] =
        dynamic_efficiency_json(efficiency->evaluate(r.time, Model::forces(r), r.mesh_frequency), *efficiency_spec);
  if (sweep)
    result["speed_sweep"] = sweep_json(dynamics::speed_sweep(*sweep, *c.operating, [&](const model::OperatingPoint& op) {
      const auto point = typename Model::Solver(geometry, *c.materials, op, options).solve();
      return dynamics::SpeedPoint{point.mesh_frequency, point.dynamic_factor, Model::te_rms(point)};
    }, print_progress));
  return result;
}

json run_dynamics(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  const auto gear_case = model::read_gear_case(root);
  if (!gear_case.materials) throw InputError("materials: missing required key (kind dynamics)");
  if (!gear_case.operating) throw InputError("operating: missing required key (kind dynamics)");
  const std::string model_name = root.optional_string("model", {"spur6", "herringbone12"}).value_or("spur6");
  const geometry::GearPairGeometry geometry(gear_case.gear_pair);
  if (model_name == "spur6") return run_model<Spur6Model>(root, case_json, gear_case, geometry);
  return run_model<Herringbone12Model>(root, case_json, gear_case, geometry);
}

const RegisterKind dynamics_kind(
    {"dynamics", "6-DOF spur-pair and 12-DOF herringbone dynamics on SUNDIALS CVODE/ARKODE", run_dynamics});

}  // namespace
}  // namespace gearbench::app
