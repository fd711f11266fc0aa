// Case kind "dynamics": 6-DOF spur-pair (model "spur6") and 12-DOF herringbone (model
// "herringbone12") dynamics (GSL rk8pd, or SUNDIALS CVODE or ARKODE, `integrator.method`),
// optionally swept over speed. Every key comes from the models' Options tables
// (solvers/dynamics/dynamics_options.cpp); this file composes them and writes the result.
#include <cmath>
#include <fmt/format.h>
#include <iostream>

#include "case_schema.h"
#include "dynamics/dynamics_options.h"
#include "dynamics/herringbone12_dynamics.h"
#include "dynamics/speed_sweep.h"
#include "dynamics/spur6_dynamics.h"
#include "efficiency/dynamic_efficiency.h"
#include "kind_registry.h"
#include "model/case_reader.h"
#include "model/errors.h"

namespace gearbench::app {
namespace {

using nlohmann::json;

/// The optional "dynamic_efficiency" section: the loss options of the efficiency kind
/// ("friction", "load_sharing", ...) plus "load_levels" and "phases" of the loss curves.
struct DynamicEfficiencySpec {
  efficiency::MeshLossOptions loss;
  efficiency::DynamicEfficiencyOptions curves;
};

const model::OptionTable<DynamicEfficiencySpec>& dynamic_efficiency_table() {
  static const auto table = [] {
    model::OptionTable<DynamicEfficiencySpec> t;
    t.include(&DynamicEfficiencySpec::loss, efficiency::MeshLossOptions::table());
    t.include(&DynamicEfficiencySpec::curves, efficiency::DynamicEfficiencyOptions::table());
    return t;
  }();
  return table;
}

/// The keys of a dynamics case beside "model" and the gear-pair sections: the model's
/// options, and what is computed from its run.
template <class Options>
struct DynamicsCase {
  Options options;
  std::optional<dynamics::SpeedSweepSpec> speed_sweep;
  std::optional<DynamicEfficiencySpec> dynamic_efficiency;

  static const model::OptionTable<DynamicsCase>& table() {
    static const auto table = [] {
      model::OptionTable<DynamicsCase> t;
      t.include(&DynamicsCase::options, Options::table());
      t.section("speed_sweep_rpm", &DynamicsCase::speed_sweep, dynamics::SpeedSweepSpec::table(),
                {.description = "runs the model again at equally spaced pinion speeds (dynamic factor and rms "
                                "transmission error per speed)"});
      t.section("dynamic_efficiency", &DynamicsCase::dynamic_efficiency, dynamic_efficiency_table(),
                {.description = "the dynamic efficiency (seed 000 eq. 12) of the recorded mesh forces, with the loss "
                                "keys of the efficiency kind"});
      return t;
    }();
    return table;
  }
};

json stats_json(const dynamics::ResponseStats& s) {
  return {{"mean", s.mean}, {"rms", s.rms}, {"peak_to_peak", s.peak_to_peak}};
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

/// What differs between the two models for run_model: options, result JSON and the series
/// that the dynamic efficiency and the speed sweep take.
struct Spur6Model {
  using Options = dynamics::Spur6Options;
  using Solver = dynamics::Spur6Dynamics;
  static constexpr auto result = spur6_result;
  static json notes(const Solver&) { return json::array(); }
  static constexpr std::size_t meshes = 1;
  static std::vector<std::vector<double>> forces(const dynamics::Spur6Result& r) { return {r.mesh_force}; }
  static double te_rms(const dynamics::Spur6Result& r) { return r.te.rms; }
  static dynamics::FrictionLawOptions& friction(Options& o) { return o.friction; }
};

struct Herringbone12Model {
  using Options = dynamics::Herringbone12Options;
  using Solver = dynamics::Herringbone12Dynamics;
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
  static dynamics::FrictionLawOptions& friction(Options& o) { return o.mesh.friction; }
};

/// How the run went: its status and message, the options given and used, the summary the
/// CLI prints on stderr; the message is a note where the figures are not the periodic response's.
template <class Model, class Result>
void add_run_report(json& result, const Result& r) {
  const auto& table = Model::Options::table();
  result["status"] = dynamics::status_name(r.status);
  result["message"] = r.message;
  result["summary"] = r.summary();
  result["options_given"] = table.to_json(r.options_given);
  result["options_used"] = table.to_json(r.options_used);
  if (r.status != dynamics::RunStatus::periodic) result["notes"].push_back(r.message);
}

/// Reads the model's keys and the sections computed from its run, solves, and adds the
/// dynamic efficiency and the speed sweep when asked.
template <class Model>
json run_model(model::ObjectReader& root, const model::GearCase& c, const geometry::GearPairGeometry& geometry) {
  using Case = DynamicsCase<typename Model::Options>;
  Case k;
  Case::table().read(root, k);
  root.finish();
  Model::friction(k.options).lubricant = c.lubricant;
  Case::table().validate(k);
  const auto& options = k.options;
  const typename Model::Solver solver(geometry, *c.materials, *c.operating, options);
  std::optional<efficiency::DynamicEfficiency> efficiency;  // before the integration: it checks the friction law's range
  if (k.dynamic_efficiency) efficiency.emplace(dynamic_efficiency(*k.dynamic_efficiency, c, Model::meshes));
  const auto r = solver.solve();
  json result = Model::result(solver, r);
  result["notes"] = json::array();
  add_run_report<Model>(result, r);
  for (const auto& note : Model::notes(solver)) result["notes"].push_back(note);
  result["friction_model"] = lubricant::friction_model_name(Model::friction(k.options).friction_model);
  result["contact_loss"] = contact_json(options.backlash, r);
  if (efficiency)
    result["dynamic_efficiency"] =
        dynamic_efficiency_json(efficiency->evaluate(r.time, Model::forces(r), r.mesh_frequency), *k.dynamic_efficiency);
  if (k.speed_sweep)
    result["speed_sweep"] = sweep_json(dynamics::speed_sweep(*k.speed_sweep, *c.operating, [&](const model::OperatingPoint& op) {
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
  dynamics::ModelChoice choice;
  dynamics::ModelChoice::table().read(root, choice);
  const geometry::GearPairGeometry geometry(gear_case.gear_pair);
  if (choice.model == dynamics::ModelName::spur6) return run_model<Spur6Model>(root, gear_case, geometry);
  return run_model<Herringbone12Model>(root, gear_case, geometry);
}

std::vector<json> dynamics_schema() {
  return {gear_case_schema({"materials", "operating"}), dynamics::ModelChoice::table().schema()};
}

/// Each model's keys, chosen by "model".
template <class Model>
KindSpec::SchemaVariant model_keys(const char* name) {
  return {name, [] { return std::vector<json>{DynamicsCase<typename Model::Options>::table().schema()}; }};
}

const RegisterKind dynamics_kind({"dynamics",
                                   "6-DOF spur-pair and 12-DOF herringbone dynamics (GSL rk8pd, SUNDIALS CVODE/ARKODE)",
                                   run_dynamics, dynamics_schema, "model",
                                   {model_keys<Spur6Model>("spur6"), model_keys<Herringbone12Model>("herringbone12")}});

}  // namespace
}  // namespace gearbench::app
