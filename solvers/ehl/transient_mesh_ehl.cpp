#include "transient_mesh_ehl.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "fas_multigrid.h"
#include "geometry/load_sharing.h"
#include "model/errors.h"

namespace gearbench::ehl {

EhlOptions TransientMeshOptions::default_grid() {
  EhlOptions o;
  o.nodes = 641;         // the seed 004 pitch-point case changes < 1 % from 321
  o.max_cycles = 100;    // per time step, after its full multigrid
  o.tolerance = 1e-6;    // per step; the time discretisation error is far larger
  // W on two levels above the coarsest grid, not the steady default's three: the steps start
  // warm on 641 nodes, where a third W level only adds visits of 41–161-node grids. Seed 004's
  // 200 steps: 66 WU and 5.4 ms a step against 83 WU and 6.7 ms, every step converged
  // (twenty-eighth session; 125 WU and 5.5 ms before that session's coarsest grid and mixing).
  o.w_cycle_levels = 2;
  return o;
}

std::string TransientMeshResult::summary() const {
  return fmt::format("{} steps, {} cycles, {:.1f} work units, {:.2f} s; p_max {:.4e} Pa, h_min {:.4e} m{}",
                     steps.size(), total_cycles, work_units, seconds, p_max, h_min,
                     converged ? "" : fmt::format(" (step {} did not converge)", failed_step));
}

TransientMeshEhl::TransientMeshEhl(const geometry::GearPairGeometry& geometry,
                                   const model::OperatingPoint& operating, const LineContactData& lubricant,
                                   TransientMeshOptions options)
    : geometry_(geometry), operating_(operating), lubricant_(lubricant), options_(std::move(options)) {
  options_.validate();
  if (geometry_.base_helix_angle() != 0.0)
    throw InputError("gear_pair.helix_angle_deg: ehl_transient follows one spur contact; the pair is helical");
  if (!(operating_.pinion_speed > 0.0))
    throw InputError(fmt::format("operating.pinion_speed_rpm = {}: must be positive", operating_.pinion_speed));
  if (!(operating_.pinion_torque > 0.0))
    throw InputError(fmt::format("operating.pinion_torque_Nm = {}: must be positive", operating_.pinion_torque));
}

double TransientMeshEhl::normal_load_per_length() const {
  return operating_.pinion_torque / geometry_.radii(0).base / geometry_.pair().face_width;
}

LineContactData TransientMeshEhl::pitch_contact() const {
  const auto k = geometry_.kinematics(geometry_.path().C, operating_.pinion_speed);
  LineContactData d = lubricant_;
  d.reduced_radius = k.reduced_radius;
  d.load_per_length = normal_load_per_length();
  d.u1 = k.u1;
  d.u2 = k.u2;
  return d;
}

namespace {

/// Dimensionless state of the contact at s relative to the pitch point (seed 004's C_R,
/// C_u, C_w), with the instantaneous data for the output.
struct Instant {
  TransientMeshStep step;
  ContactState state;
};

/// What decides whether a step's discretisation-error estimate carries to another step: its
/// time step and the contact's load, curvature and speed.
struct ContactScales {
  double time_step = 0.0, load = 0.0, curvature = 0.0, speed = 0.0;
  explicit ContactScales(const ContactState& s)
      : time_step(s.time_step), load(s.load), curvature(s.curvature), speed(s.speed) {}
  ContactScales() = default;
};

/// Whether a warm-started step may carry the discretisation-error estimate of the step solved by
/// full multigrid at `estimated`: the same problem (the steady first step's is not a transient
/// step's), its load, curvature and speed all within a tenth of that step's. The load jumps
/// where the pair count changes (× 2 at B) are not.
bool within_carry(const ContactScales& now, const ContactScales& estimated) {
  constexpr double carry = 0.1;
  const auto near = [](double a, double b) { return std::abs(a - b) <= carry * std::abs(b); };
  return now.time_step == estimated.time_step && near(now.load, estimated.load) &&
         near(now.curvature, estimated.curvature) && near(now.speed, estimated.speed);
}

/// The next step's start: the last solution extrapolated linearly in time from the one before
/// it (equal steps), P kept ≥ 0; the last alone where there is none before it. From the last
/// alone, the warm iteration's error lags the motion, always with one sign, and the squeeze term
/// carries it into the next steps: on seed 004 it grew to 1.3e-3 of H_c, 1.5 × full multigrid's
/// largest, against 8.7e-4 extrapolated.
WarmStart extrapolated(const WarmStart& last, const WarmStart& before) {
  if (before.P.size() != last.P.size()) return last;
  WarmStart next = last;
  for (std::size_t i = 0; i < next.P.size(); ++i) next.P[i] = std::max(0.0, 2.0 * last.P[i] - before.P[i]);
  next.H0 = 2.0 * last.H0 - before.H0;
  return next;
}

TransientMeshProfile make_profile(const std::string& name, double position, const EhlResult& r,
                                  const LineContactProblem& p) {
  TransientMeshProfile out{name, position, {}, {}, {}};
  for (std::size_t i = 0; i < r.X.size(); ++i) {
    out.x.push_back(r.X[i] * p.length_scale());
    out.p.push_back(r.P[i] * p.pressure_scale());
    out.h.push_back(r.H[i] * p.film_scale());
  }
  return out;
}

}  // namespace

TransientMeshResult TransientMeshEhl::run() const {
  const auto start = std::chrono::steady_clock::now();
  const LineContactData reference = pitch_contact();
  const LineContactProblem problem(reference);
  const auto sharing = geometry::make_load_sharing(options_.load_sharing, "load_sharing");
  const auto& path = geometry_.path();
  const double base_speed = geometry_.radii(0).base * operating_.pinion_speed;  // ds/dt

  TransientMeshResult out;
  out.reference_radius = reference.reduced_radius;
  out.reference_load = reference.load_per_length;
  out.reference_entrainment = reference.mean_speed();
  out.reference_half_width = problem.hertz_half_width();
  out.reference_pressure = problem.hertz_pressure();
  out.time_step = (path.E - path.A) / base_speed / options_.steps;
  out.dimensionless_time_step = out.time_step * reference.mean_speed() / problem.length_scale();

  const auto instant = [&](int n) {
    Instant in;
    // The last step sits a hair inside E, where the pair still carries load.
    const double s = std::min(path.A + base_speed * out.time_step * n, path.E - 1e-9 * (path.E - path.A));
    const auto k = geometry_.kinematics(s, operating_.pinion_speed);
    auto& st = in.step;
    st.time = out.time_step * n;
    st.position = s;
    st.roll_angle = s / geometry_.radii(0).base;
    st.reduced_radius = k.reduced_radius;
    st.entrainment = k.entrainment;
    st.sliding = k.sliding;
    st.load_per_length = sharing->share(geometry_, s) * reference.load_per_length;
    st.hertz_pressure = std::sqrt(st.load_per_length * reference.reduced_modulus / (2.0 * std::numbers::pi * st.reduced_radius));
    in.state.curvature = reference.reduced_radius / k.reduced_radius;
    in.state.speed = k.entrainment / reference.mean_speed();
    in.state.load = problem.load() * st.load_per_length / reference.load_per_length;
    in.state.time_step = n == 0 ? 0.0 : out.dimensionless_time_step;
    return in;
  };

  // Named points: the step nearest to each.
  const std::vector<std::pair<std::string, double>> named{
      {"A", path.A}, {"B", path.B}, {"C", path.C}, {"D", path.D}, {"E", path.E}};
  const auto nearest_step = [&](double s) {
    return static_cast<int>(std::lround((s - path.A) / (base_speed * out.time_step)));
  };

  // A step starts from the previous steps' solution on the finest grid and stops at the error
  // rule with the estimate of the last step solved by full multigrid, while the contact stays
  // near that step's (within_carry); else, and always under the residual rule, by full
  // multigrid, its coarsest grid started from the previous step. The previous step's ρ̄H is data
  // of the squeeze term on every grid. Seed 004 (641 nodes, 201 steps; thirty-first session):
  // 45.5 → 19.1 WU a step, 7 steps by full multigrid; against every step solved to a residual
  // of 1e-10, the largest difference in H_c, H_min and p_max 8.7e-4, 6.6e-4 and 8.5e-4 (full
  // multigrid at every step: 8.7e-4, 8.7e-4, 2.4e-3); over 161–1281 nodes, 50–400 steps and both
  // load sharings docs/ehl-model.md has the table. (Eleventh session: a warm start under the
  // residual rule stalled where the load jumps, at B; with full multigrid at each step the old
  // solver then spent 454 WU a step.)
  const bool error_rule = options_.grid.stop == StopRule::discretisation_error;
  std::vector<double> rho_h_old;
  WarmStart previous, before;  // the last two steps' solutions; `before` empty across a jump
  ContactScales estimated_at;  // the contact of the last step solved by full multigrid
  for (int n = 0; n <= options_.steps; ++n) {
    Instant in = instant(n);
    in.state.rho_h_old = rho_h_old;
    const bool warm = error_rule && n > 0 && within_carry(ContactScales(in.state), estimated_at);
    if (!warm) {
      in.state.nearby = previous;
      estimated_at = ContactScales(in.state);
    }
    FasMultigrid mg(problem, options_.grid, in.state);
    auto r = warm ? mg.solve(extrapolated(previous, before)) : mg.solve();
    out.total_cycles += r.cycles;
    out.work_units += r.work_units;
    out.work_by_part += r.work_by_part;
    out.work_units_iterating += r.work_units_iterating;
    if (!r.converged) {
      out.failed_step = n;
      out.failed_residual_history = r.residual_history;
      out.failed_force_history = r.force_history;
      // The step's own message names its rule: the error rule's bound or grid.tolerance.
      out.fail(fmt::format("transient EHL: time step {} of {} did not converge in {} cycles (grid.max_cycles = {}): {}",
                           n, options_.steps, r.residual_history.size(), options_.grid.max_cycles, r.message));
      break;
    }
    rho_h_old = mg.rho_h();
    before = warm ? previous : WarmStart{};
    previous = WarmStart{r.P, r.H0, r.error_estimate, r.rule_factor};
    auto& st = in.step;
    st.h_central = r.h_central;
    st.h_min = r.h_min;
    st.p_max = r.p_max;
    st.cycles = r.cycles;
    st.residual = r.residual_history.empty() ? 0.0 : r.residual_history.back();
    st.work_units = r.work_units;
    st.full_multigrid = !warm;
    out.full_multigrid_steps += warm ? 0 : 1;
    out.steps.push_back(st);
    for (const auto& [name, s] : named)
      if (nearest_step(s) == n) out.profiles.push_back(make_profile(name, st.position, r, problem));
  }

  const auto& steps = out.steps;
  if (!steps.empty()) {
    const auto pmax = std::max_element(steps.begin(), steps.end(), [](auto& a, auto& b) { return a.p_max < b.p_max; });
    const auto hmin = std::min_element(steps.begin(), steps.end(), [](auto& a, auto& b) { return a.h_min < b.h_min; });
    out.p_max = pmax->p_max;
    out.p_max_position = pmax->position;
    out.h_min = hmin->h_min;
    out.h_min_position = hmin->position;
    const auto [hc_lo, hc_hi] = std::minmax_element(steps.begin(), steps.end(),
                                                    [](auto& a, auto& b) { return a.h_central < b.h_central; });
    out.h_central_min = hc_lo->h_central;
    out.h_central_max = hc_hi->h_central;
  }
  if (out.failed_step < 0)
    out.succeed(fmt::format("converged: all {} time steps from A to E met grid.tolerance = {:.1e} within "
                            "grid.max_cycles = {}", options_.steps + 1, options_.grid.tolerance,
                            options_.grid.max_cycles));
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace gearbench::ehl
