// Case kind "dynamics": 6-DOF spur-pair dynamics on SUNDIALS CVODE (model "spur6").
#include <cmath>
#include <fmt/format.h>

#include "dynamics/spur6_dynamics.h"
#include "crack_section.h"
#include "kind_registry.h"
#include "model/case_reader.h"
#include "model/errors.h"

namespace gearbench::app {
namespace {

using nlohmann::json;
using model::Range;

dynamics::Spur6Options read_options(model::ObjectReader& root) {
  dynamics::Spur6Options o;
  root.optional_string("model", {"spur6"});
  if (root.has("bearings")) {
    auto b = root.object("bearings");
    o.bearing_stiffness = b.optional_number("stiffness_N_per_m", Range::positive(1e15), "N/m").value_or(o.bearing_stiffness);
    o.bearing_damping = b.optional_number("damping_N_s_per_m", Range::closed(0.0, 1e9), "N*s/m").value_or(o.bearing_damping);
    b.finish();
  }
  o.mesh_damping_ratio = root.optional_number("mesh_damping_ratio", Range::closed(0.0, 1.0)).value_or(o.mesh_damping_ratio);
  if (root.has("friction")) {
    auto f = root.object("friction");
    o.friction_coefficient = f.number("mu", Range::closed(0.0, 0.5));
    f.finish();
  }
  o.crack = read_crack(root, 1);
  o.runup_cycles = root.optional_integer("runup_cycles", 0, 1000000).value_or(o.runup_cycles);
  o.record_cycles = root.optional_integer("record_cycles", 2, 1000000).value_or(o.record_cycles);
  o.samples_per_cycle = root.optional_integer("samples_per_cycle", 8, 4096).value_or(o.samples_per_cycle);
  if (root.has("integrator")) {
    auto i = root.object("integrator");
    o.integrator.method = i.optional_string("method", {"adams", "bdf"}).value_or("adams") == "bdf"
                              ? dynamics::CvodeMethod::bdf : dynamics::CvodeMethod::adams;
    o.integrator.relative_tolerance = i.optional_number("rtol", {1e-14, 1e-2}).value_or(o.integrator.relative_tolerance);
    o.integrator.absolute_tolerance = i.optional_number("atol", {1e-20, 1e-2}).value_or(o.integrator.absolute_tolerance);
    i.finish();
  }
  return o;
}

json stats_json(const dynamics::Spur6Result::Stats& s) {
  return {{"mean", s.mean}, {"rms", s.rms}, {"peak_to_peak", s.peak_to_peak}};
}

json run_dynamics(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  const auto gear_case = model::read_gear_case(root);
  if (!gear_case.materials) throw InputError("materials: missing required key (kind dynamics)");
  if (!gear_case.operating) throw InputError("operating: missing required key (kind dynamics)");
  auto options = read_options(root);
  root.finish();

  const geometry::GearPairGeometry geometry(gear_case.gear_pair);
  const dynamics::Spur6Dynamics solver(geometry, *gear_case.materials, *gear_case.operating, options);
  const auto r = solver.solve();
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
      {"parameters", {{"masses_kg", {p.m1, p.m2}}, {"inertias_kg_m2", {p.I1, p.I2}},
                      {"mean_mesh_stiffness_N_per_m", p.mean_mesh_stiffness},
                      {"mesh_damping_N_s_per_m", p.mesh_damping}}},
      {"diagnostics", {{"steps", r.steps}, {"rhs_evaluations", r.rhs_evaluations}, {"seconds", r.seconds},
                       {"periodicity", r.periodicity}}},
  };
}

const RegisterKind dynamics_kind({"dynamics", "6-DOF spur-pair dynamics on SUNDIALS CVODE", run_dynamics});

}  // namespace
}  // namespace gearbench::app
