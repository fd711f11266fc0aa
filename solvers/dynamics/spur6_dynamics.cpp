#include "spur6_dynamics.h"

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <fmt/format.h>
#include <numbers>
#include <numeric>
#include <utility>

#include "model/errors.h"

namespace gearbench::dynamics {

namespace {
constexpr double pi = std::numbers::pi;
// The state: q = [x1, y1, θ1, x2, y2, θ2] (docs/dynamics-model.md), their rates at rate + i,
// then the work accumulators of the energy balance.
enum Coordinate : int { X1 = 0, Y1 = 1, TH1 = 2, X2 = 3, Y2 = 4, TH2 = 5 };
constexpr int rate = 6;
enum Work : int { DAMPING = 12, FRICTION = 13, PARAMETRIC = 14 };

/// δ = x1 + R_b1·θ1 − x2 − R_b2·θ2 (first = 0) or its rate (first = rate).
double line_of_action(const Spur6Parameters& p, const double* y, int first) {
  return y[first + X1] + p.rb1 * y[first + TH1] - y[first + X2] - p.rb2 * y[first + TH2];
}
}  // namespace

Spur6Dynamics::Spur6Dynamics(const geometry::GearPairGeometry& geometry,
                             const std::array<model::Material, 2>& materials,
                             const model::OperatingPoint& operating, Spur6Options options)
    : geometry_(geometry),
      options_((options.validate(), std::move(options))),
      friction_(geometry, materials, operating, options_.friction),
      mesh_(geometry, materials, operating.pinion_speed, options_.fillet, options_.crack) {
  if (geometry_.base_helix_angle() > 0.0)
    throw InputError(fmt::format("gear_pair.helix_angle_deg = {:.6g}: model \"spur6\" needs 0 (a spur pair)",
                                 geometry_.pair().helix_angle * 180.0 / pi));
  const auto& pair = geometry_.pair();
  // Solid discs of the reference diameter (docs/dynamics-model.md, inertia of the blanks).
  auto disc = [&](int gear, double& m, double& I) {
    const double r = geometry_.radii(gear).reference;
    m = materials[static_cast<std::size_t>(gear)].density * pi * r * r * pair.face_width;
    I = 0.5 * m * r * r;
  };
  disc(0, p_.m1, p_.I1);
  disc(1, p_.m2, p_.I2);
  p_.rb1 = geometry_.radii(0).base;
  p_.rb2 = geometry_.radii(1).base;
  p_.k_bearing = options_.bearing_stiffness;
  p_.c_bearing = options_.bearing_damping;
  p_.T1 = operating.pinion_torque;
  p_.mu = options_.friction.friction_coefficient;
  p_.zeta_mesh = options_.mesh_damping_ratio;
  const auto& path = geometry_.path();
  p_.A = path.A;
  p_.C = path.C;
  p_.E = path.E;
  p_.T1T2 = path.T2;
  p_.pbt = geometry_.base_pitch_transverse();
  p_.contact_speed = mesh_.contact_speed();
  p_.z1 = pair.teeth[0];
  p_.face_width = pair.face_width;
  p_.backlash = options_.backlash.value_or(0.0);
  p_.crack_mouth = mesh_.crack_mouth();
  if (geometry_.contact_ratio_transverse() >= 2.0)
    throw InputError(fmt::format("gear_pair: transverse contact ratio {:.4f}; model \"spur6\" allows [1, 2) "
                                 "(one or two pairs in contact)", geometry_.contact_ratio_transverse()));
  p_.mean_mesh_stiffness = mesh_.mean_stiffness();
  // Quasi-static torque balance under the mean friction arms ā_i (docs/dynamics-model.md,
  // "Loads"), μ_j of a law at the pair's share of the nominal force T1/R_b1.
  const auto arms = mesh_.mean_arms(friction_, p_.T1 / p_.rb1);
  p_.static_force = p_.T1 / (p_.rb1 + arms[0]);
  p_.T2 = p_.static_force * (p_.rb2 + arms[1]);
  const double me = p_.I1 * p_.I2 / (p_.I1 * p_.rb2 * p_.rb2 + p_.I2 * p_.rb1 * p_.rb1);
  p_.mesh_damping = 2.0 * p_.zeta_mesh * std::sqrt(p_.mean_mesh_stiffness * me);
}

// The pairs of the interval holding t_mid (docs/dynamics-model.md, "Mesh", SpurMesh), each
// carrying F_j = k_j·δ + c_j·δ̇ (c_j = c_m·k_j/k̄) and its friction.
Spur6Dynamics::MeshState Spur6Dynamics::mesh(double t, double t_mid, const double* y) const {
  const double delta = line_of_action(p_, y, 0);
  const double delta_rate = line_of_action(p_, y, rate);
  MeshState m;
  m.delta = delta;
  m.delta_rate = delta_rate;
  m.penetration = delta;
  // Contact loss (docs, "Contact loss"): the flanks overlap by p = δ (working flanks) or
  // δ + b (back flanks) and push, never pull.
  const bool loss = options_.backlash.has_value();
  if (loss) {
    m.back = delta < -p_.backlash;
    m.penetration = delta > 0.0 ? delta : (m.back ? delta + p_.backlash : 0.0);
  }
  for (const SpurPair& pair : mesh_.pairs(t, t_mid)) {
    const double k = pair.stiffness;
    const double c = p_.mesh_damping * k / p_.mean_mesh_stiffness;
    double force = k * delta + c * delta_rate;
    if (loss) {
      const double pushed = k * m.penetration + c * delta_rate;
      force = delta > 0.0 ? std::max(0.0, pushed) : (m.back ? std::min(0.0, pushed) : 0.0);
    }
    m.stiffness += k;
    m.damping += c;
    m.stiffness_rate += pair.rate;
    // μ of the law at the pair's own load; the constant μ bit for bit.
    const double mu = friction_.coefficient(pair.s, std::abs(force) / p_.face_width);
    m.force += force;
    m.friction += mu * pair.lambda * force;
    m.moment1 += mu * pair.lambda * force * pair.s;
    m.moment2 += mu * pair.lambda * force * (p_.T1T2 - pair.s);
  }
  // (F_m − Σk_j·p)·δ̇: Σc_j·δ̇² while the flanks push, −Σk_j·p·δ̇ ≥ 0 while they separate faster
  // than the damper allows (F_m = 0 at p ≠ 0), 0 in the backlash.
  m.mesh_dissipation = m.force != 0.0 || !loss ? m.damping * delta_rate * delta_rate
                                                : -m.stiffness * m.penetration * delta_rate;
  return m;
}

// docs/dynamics-model.md, "Equations of motion" (seed 003 eq. 12).
void Spur6Dynamics::derivative(double t, double t_mid, const double* y, double* dydt) const {
  const MeshState m = mesh(t, t_mid, y);
  const double* v = y + rate;
  for (int i = 0; i < 6; ++i) dydt[i] = v[i];
  double* a = dydt + rate;
  a[X1] = (-m.force - p_.c_bearing * v[X1] - p_.k_bearing * y[X1]) / p_.m1;
  a[Y1] = (-m.friction - p_.c_bearing * v[Y1] - p_.k_bearing * y[Y1]) / p_.m1;
  a[TH1] = (p_.T1 - p_.rb1 * m.force - m.moment1) / p_.I1;
  a[X2] = (m.force - p_.c_bearing * v[X2] - p_.k_bearing * y[X2]) / p_.m2;
  a[Y2] = (m.friction - p_.c_bearing * v[Y2] - p_.k_bearing * y[Y2]) / p_.m2;
  a[TH2] = (p_.rb2 * m.force + m.moment2 - p_.T2) / p_.I2;
  // The works of the energy balance (docs/dynamics-model.md, "Energy balance").
  const double w1 = p_.contact_speed / p_.rb1, w2 = w1 * p_.rb1 / p_.rb2;
  double bearings = 0.0;
  for (const int i : {X1, Y1, X2, Y2}) bearings += p_.c_bearing * v[i] * v[i];
  dydt[DAMPING] = bearings + m.mesh_dissipation;
  dydt[FRICTION] = m.moment1 * (w1 + v[TH1]) - m.moment2 * (w2 + v[TH2]) - m.friction * (v[Y2] - v[Y1]);
  dydt[PARAMETRIC] = 0.5 * m.stiffness_rate * m.penetration * m.penetration;
}

// E = ½Σm·q̇² + ½Σ I·(Ω + θ̇)² + ½k_b·Σq² + ½Σk_j·p² (p = δ without contact loss).
double Spur6Dynamics::energy(double t, double t_mid, const double* y) const {
  const double w1 = p_.contact_speed / p_.rb1, w2 = w1 * p_.rb1 / p_.rb2;
  const MeshState m = mesh(t, t_mid, y);
  const double* v = y + rate;
  double e = p_.m1 * (v[X1] * v[X1] + v[Y1] * v[Y1]) + p_.m2 * (v[X2] * v[X2] + v[Y2] * v[Y2]);
  e += p_.I1 * (w1 + v[TH1]) * (w1 + v[TH1]) + p_.I2 * (w2 + v[TH2]) * (w2 + v[TH2]);
  for (const int i : {X1, Y1, X2, Y2}) e += p_.k_bearing * y[i] * y[i];
  return 0.5 * (e + m.stiffness * m.penetration * m.penetration);
}

void Spur6Dynamics::contact_functions(const double* y, double* g) const {
  const double delta = line_of_action(p_, y, 0), tau_rate = p_.mesh_damping / p_.mean_mesh_stiffness * line_of_action(p_, y, rate);
  g[0] = delta;
  g[1] = delta + p_.backlash;
  g[2] = delta + tau_rate;
  g[3] = delta + p_.backlash + tau_rate;
}

std::vector<double> Spur6Dynamics::static_state() const {
  const double F0 = p_.static_force;
  const double delta0 = F0 / p_.mean_mesh_stiffness;
  std::vector<double> y(state_size(), 0.0);
  y[X1] = -F0 / p_.k_bearing;
  y[X2] = F0 / p_.k_bearing;
  y[TH1] = (delta0 - y[X1] + y[X2]) / p_.rb1;
  return y;
}

std::vector<double> Spur6Dynamics::break_times(double t0, double t1) const { return mesh_.break_times(t0, t1); }

std::vector<double> Spur6Dynamics::natural_frequencies() const {
  Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero(), K = M;
  M.diagonal() << p_.m1, p_.m1, p_.I1, p_.m2, p_.m2, p_.I2;
  K.diagonal() << p_.k_bearing, p_.k_bearing, 0.0, p_.k_bearing, p_.k_bearing, 0.0;
  Eigen::Matrix<double, 6, 1> v;
  v << 1.0, 0.0, p_.rb1, -1.0, 0.0, -p_.rb2;  // δ = v·q
  K += p_.mean_mesh_stiffness * v * v.transpose();
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> solver(K, M);
  std::vector<double> f;
  const double scale = solver.eigenvalues().maxCoeff();
  for (int i = 0; i < 6; ++i)
    if (solver.eigenvalues()(i) > 1e-10 * scale) f.push_back(std::sqrt(solver.eigenvalues()(i)) / (2.0 * pi));
  return f;
}

Spur6Result Spur6Dynamics::solve() const {
  const auto start = std::chrono::steady_clock::now();
  const bool cracked = options_.crack && options_.crack->crack.length > 0.0;
  const double T_mesh = p_.pbt / p_.contact_speed;
  // With a cracked tooth the response repeats once per revolution (z1 mesh cycles).
  const int period_cycles = cracked ? p_.z1 : 1;
  const int runup = (options_.runup_cycles + period_cycles - 1) / period_cycles * period_cycles;
  const int record = (std::max(options_.record_cycles, 2 * period_cycles) + period_cycles - 1) / period_cycles * period_cycles;
  MarchPlan plan;
  plan.t_record = runup * T_mesh;
  plan.t_end = (runup + record) * T_mesh;
  plan.sample_interval = T_mesh / options_.samples_per_cycle;
  plan.samples = static_cast<std::size_t>(record) * static_cast<std::size_t>(options_.samples_per_cycle);
  plan.longest_call = T_mesh;

  Spur6Result r;
  r.options_given = r.options_used = options_;
  r.options_used.runup_cycles = runup;
  r.options_used.record_cycles = record;
  r.static_mesh_force = p_.static_force;
  r.mesh_frequency = 1.0 / T_mesh;
  const auto m = march(*this, options_.integrator, plan, static_state(), [&](double t, double t_mid, const std::vector<double>& y) {
    const MeshState mesh_state = mesh(t, t_mid, y.data());
    r.time.push_back(t - plan.t_record);
    r.transmission_error.push_back(mesh_state.delta);
    r.mesh_force.push_back(mesh_state.force);
    r.friction_force.push_back(mesh_state.friction);
    r.bearing_force_x1.push_back(p_.k_bearing * y[X1] + p_.c_bearing * y[rate + X1]);
    if (mesh_state.force == 0.0) r.contact_loss_fraction += 1.0;
    if (mesh_state.back) r.back_contact_fraction += 1.0;
  });
  r.steps = m.steps;
  r.rhs_evaluations = m.rhs_evaluations;
  r.contact_events = m.contact_events;

  auto& e = r.energy;
  const double w1 = p_.contact_speed / p_.rb1, w2 = w1 * p_.rb1 / p_.rb2, window = plan.t_end - plan.t_record;
  e.input = p_.T1 * (w1 * window + m.y_end[TH1] - m.y_record[TH1]);
  e.output = p_.T2 * (w2 * window + m.y_end[TH2] - m.y_record[TH2]);
  e.damping = m.y_end[DAMPING] - m.y_record[DAMPING];
  e.friction = m.y_end[FRICTION] - m.y_record[FRICTION];
  e.parametric = m.y_end[PARAMETRIC] - m.y_record[PARAMETRIC] + m.jumps;
  e.energy_change = m.energy_end - m.energy_record;
  e.residual = e.relative_residual();
  r.te = statistics(r.transmission_error);
  r.force = statistics(r.mesh_force);
  r.friction = statistics(r.friction_force);
  r.contact_loss_fraction /= static_cast<double>(r.time.size());
  r.back_contact_fraction /= static_cast<double>(r.time.size());
  r.dynamic_factor = *std::max_element(r.mesh_force.begin(), r.mesh_force.end()) / r.static_mesh_force;
  amplitude_spectrum(r.transmission_error, plan.sample_interval, r.spectrum_frequency, r.spectrum_te);
  r.natural_frequencies = natural_frequencies();
  r.periodicity = periodicity(r.transmission_error, static_cast<std::size_t>(period_cycles * options_.samples_per_cycle));
  auto [status, message] = run_status(r.periodicity);
  r.status = status;
  r.message = std::move(message);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::string Spur6Result::summary() const { return run_summary("spur6", *this); }

}  // namespace gearbench::dynamics
