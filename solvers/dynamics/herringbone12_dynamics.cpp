#include "herringbone12_dynamics.h"

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <utility>

#include "model/errors.h"

namespace gearbench::dynamics {

namespace {
constexpr double pi = std::numbers::pi;
// Coordinates of half h start at 6h: y_p, z_p, θ_p, y_g, z_g, θ_g; rates at 12 + i;
// the work accumulators (damping, friction, parametric, impact) at 24..27.
enum Local : int { YP = 0, ZP = 1, TP = 2, YG = 3, ZG = 4, TG = 5 };
constexpr int rate = 12;
constexpr int work = 24;
constexpr double hand[2] = {1.0, -1.0};  // σ_h: the halves are of opposite hand

int index(int half, Local c) { return 6 * half + c; }

using Matrix12 = Eigen::Matrix<double, 12, 12>;
using Vector12 = Eigen::Matrix<double, 12, 1>;

/// Bearings, groove coupling (axial) and shaft twist of both halves: the stiffness of
/// everything but the mesh (docs/dynamics-model.md, "12-DOF").
Matrix12 support_stiffness(const Herringbone12Parameters& p) {
  Matrix12 K = Matrix12::Zero();
  for (int h = 0; h < 2; ++h) {
    K(index(h, YP), index(h, YP)) += p.k_radial;
    K(index(h, YG), index(h, YG)) += p.k_radial;
    K(index(h, ZP), index(h, ZP)) += p.k_axial_p + p.k_groove;
    K(index(h, ZG), index(h, ZG)) += p.k_axial_g + p.k_groove;
    K(index(h, ZP), index(1 - h, ZP)) -= p.k_groove;
    K(index(h, ZG), index(1 - h, ZG)) -= p.k_groove;
    for (const Local c : {TP, TG}) {
      K(index(h, c), index(h, c)) += p.k_twist;
      K(index(h, c), index(1 - h, c)) -= p.k_twist;
    }
  }
  return K;
}

/// ∂δ_h/∂q: the mesh deflection of half h along the normal as a linear form in q.
Vector12 mesh_direction(const Herringbone12Parameters& p, int h) {
  const double cb = std::cos(p.beta_b), sb = std::sin(p.beta_b);
  Vector12 v = Vector12::Zero();
  v(index(h, YP)) = cb, v(index(h, ZP)) = hand[h] * sb, v(index(h, TP)) = cb * p.R_p;
  v(index(h, YG)) = -cb, v(index(h, ZG)) = -hand[h] * sb, v(index(h, TG)) = -cb * p.R_g;
  return v;
}

}  // namespace

Herringbone12Dynamics::Herringbone12Dynamics(const geometry::GearPairGeometry& geometry,
                                             const std::array<model::Material, 2>& materials,
                                             const model::OperatingPoint& operating, Herringbone12Options options)
    : options_((options.validate(), std::move(options))),
      mesh_(geometry, materials, operating, options_.mesh) {
  const auto& pair = geometry.pair();
  if (pair.helix_angle > 0.0 && !pair.herringbone)
    throw InputError("gear_pair.herringbone: missing; model \"herringbone12\" needs a herringbone pair "
                     "(or a spur pair, helix_angle_deg 0)");
  p_.beta_b = geometry.base_helix_angle();
  if (options_.floating_pinion && p_.beta_b == 0.0)
    throw InputError("bearings.floating_pinion = true: a spur pair (helix_angle_deg 0) cannot hold a floating "
                     "pinion axially; set it false");
  if (geometry.contact_ratio_transverse() >= 2.0)
    throw InputError(fmt::format("gear_pair: transverse contact ratio {:.4f}; model \"herringbone12\" allows "
                                 "[1, 2)", geometry.contact_ratio_transverse()));
  // One half's blank: a solid disc of the reference diameter and the half's face width.
  auto disc = [&](int gear, double& m, double& I) {
    const double r = geometry.radii(gear).reference;
    m = materials[static_cast<std::size_t>(gear)].density * pi * r * r * pair.face_width;
    I = 0.5 * m * r * r;
  };
  disc(0, p_.m_p, p_.I_p);
  disc(1, p_.m_g, p_.I_g);
  p_.R_p = geometry.radii(0).base;
  p_.R_g = geometry.radii(1).base;
  p_.k_radial = options_.radial_stiffness;
  p_.c_radial = options_.radial_damping;
  p_.k_axial_g = options_.axial_stiffness;
  p_.c_axial_g = options_.axial_damping;
  p_.k_axial_p = options_.floating_pinion ? 0.0 : options_.axial_stiffness;
  p_.c_axial_p = options_.floating_pinion ? 0.0 : options_.axial_damping;
  // Default groove coupling: a solid shaft of the pinion's root radius over the groove
  // width, axially E·A/L and in torsion G·J/L (gearbench choice: the seed gives no value).
  const double groove = pair.herringbone ? pair.herringbone->groove_width : 0.0;
  const double r_f = geometry.radii(0).root;
  if ((!options_.groove_stiffness || !options_.twist_stiffness) && !(groove > 0.0))
    throw InputError("groove_coupling: axial_stiffness_N_per_m and torsional_stiffness_N_m_per_rad are required "
                     "without a herringbone groove");
  const double E = materials[0].youngs_modulus, G = E / (2.0 * (1.0 + materials[0].poisson_ratio));
  p_.k_groove = options_.groove_stiffness.value_or(E * pi * r_f * r_f / groove);
  p_.k_twist = options_.twist_stiffness.value_or(G * 0.5 * pi * std::pow(r_f, 4) / groove);
  p_.c_groove = options_.groove_damping;
  p_.c_twist = options_.twist_damping;
  p_.omega_p = operating.pinion_speed;
  p_.omega_g = operating.pinion_speed * p_.R_p / p_.R_g;
  p_.period = mesh_.period();
  p_.clock_offset = {0.0, -options_.half_offset * p_.period};
  p_.mean_mesh_stiffness = mesh_.mean_stiffness();
  const double me = p_.I_p * p_.I_g / (p_.I_p * p_.R_g * p_.R_g + p_.I_g * p_.R_p * p_.R_p);
  p_.mesh_damping = 2.0 * options_.mesh_damping_ratio * std::sqrt(p_.mean_mesh_stiffness * me);
  // Quasi-static torque balance of a half under the mean arms and the mean impact pulse
  // F̄_s = (2/π)·F_s·τ/T (docs, "Loads"): T_p = F̄(R_p cos β_b + χ̄_p) + R_p F̄_s,
  // T_g = F̄(R_g cos β_b + χ̄_g) + R_g F̄_s. F_s grows with √F̄: a fixed-point iteration.
  const double cb = std::cos(p_.beta_b);
  p_.T_p = 0.5 * operating.pinion_torque;
  p_.static_force = p_.T_p / (p_.R_p * cb + mesh_.mean().chi_pinion);
  double mean_impact = 0.0;
  if (options_.mesh_in_impact) {
    // Mesh-in impact (seed 000 eq. 6) with the first-order corner-contact approach of the page: the corner
    // closes the gap δ = δ̄ + f_pb (loaded deflection and base-pitch error) in Δt, v_s = 2δ/Δt =
    // ω_g·√(2·δ·T1T2·ρ_2A/ρ_1A); q_s = 1/k_m at mesh-in. Eq. 6 holds v_s through the pulse: its peak
    // v_s·√(m_e/q_s) times (√(1+φ²) − 1)/φ, φ = ω_s·Δt, is the peak of the same mass and spring under the
    // approach, whose closing speed falls from v_s to zero at A (docs, "Mesh-in impact").
    const auto& path = geometry.path();
    p_.impact_stiffness = mesh_.at(0.0, 1e-9 * p_.period).stiffness;
    const double omega_s = std::sqrt(p_.impact_stiffness / me);
    p_.impact_duration = pi / omega_s;
    const auto speed = [&] { return fmt::format("operating.pinion_speed_rpm = {:.6g}", operating.pinion_speed * 30.0 / pi); };
    if (p_.impact_duration >= p_.period)
      throw InputError(fmt::format("mesh_in_impact = true: at {} the pulse lasts {:.4g} s, longer than a mesh cycle "
                                   "({:.4g} s); set mesh_in_impact false",
                                   speed(), p_.impact_duration, p_.period));
    for (int iteration = 0; iteration < 50; ++iteration) {
      const double gap = p_.static_force / p_.mean_mesh_stiffness + options_.base_pitch_error;
      p_.impact_velocity = p_.omega_g * std::sqrt(2.0 * gap * path.T2 * (path.T2 - path.A) / path.A);
      p_.impact_approach_time = 2.0 * gap / p_.impact_velocity;
      p_.impact_held_force = p_.impact_velocity * std::sqrt(me * p_.impact_stiffness);
      const double phi = omega_s * p_.impact_approach_time;
      p_.impact_force = options_.impact_held_velocity ? p_.impact_held_force
                                                      : p_.impact_held_force * (std::sqrt(1.0 + phi * phi) - 1.0) / phi;
      p_.impact_compression_ratio = p_.impact_held_force / p_.impact_stiffness / gap;  // = 2/φ
      mean_impact = 2.0 / pi * p_.impact_force * p_.impact_duration / p_.period;
      p_.static_force = (p_.T_p - p_.R_p * mean_impact) / (p_.R_p * cb + mesh_.mean().chi_pinion);
      if (!(p_.static_force > 0.0))
        throw InputError(fmt::format("mesh_in_impact = true: at {}, operating.pinion_torque_Nm = {:.6g} and "
                                     "base_pitch_error_um = {:.6g} the mean impact pulse ({:.4g} N) would carry the "
                                     "whole load; set mesh_in_impact false",
                                     speed(), operating.pinion_torque, 1e6 * options_.base_pitch_error, mean_impact));
    }
    // A helical half's entering contact sweeps across the face: the slices in premature contact at
    // one instant span R_p·Ω_p·Δt of the path, i.e. R_p·Ω_p·Δt/tan β_b of the face width.
    if (p_.beta_b > 0.0)
      p_.impact_entry_fraction = std::min(
          1.0, p_.R_p * p_.omega_p * p_.impact_approach_time / (std::tan(p_.beta_b) * pair.face_width));
  }
  p_.mean_impact_force = mean_impact;
  p_.T_g = p_.static_force * (p_.R_g * cb + mesh_.mean().chi_wheel) + p_.R_g * mean_impact;
}

double Herringbone12Dynamics::impact_force(int half, double t, double t_mid) const {
  if (!options_.mesh_in_impact) return 0.0;
  const double offset = p_.clock_offset[static_cast<std::size_t>(half)];
  const double n = std::floor((t_mid + offset) / p_.period);
  if (t_mid + offset - n * p_.period >= p_.impact_duration) return 0.0;
  const double r = std::clamp(t + offset - n * p_.period, 0.0, p_.impact_duration);
  return p_.impact_force * std::sin(pi * r / p_.impact_duration);
}

// docs/dynamics-model.md, "Mesh force per half" (seed 000 eq. 7, base helix angle):
// δ_h = cos β_b·(y_p − y_g + R_p θ_p − R_g θ_g) + σ_h sin β_b·(z_p − z_g).
double Herringbone12Dynamics::delta(int h, const double* y, int first) const {
  const double cb = std::cos(p_.beta_b), sb = std::sin(p_.beta_b);
  return cb * (y[first + index(h, YP)] - y[first + index(h, YG)] + p_.R_p * y[first + index(h, TP)] -
               p_.R_g * y[first + index(h, TG)]) +
         hand[h] * sb * (y[first + index(h, ZP)] - y[first + index(h, ZG)]);
}

Herringbone12Dynamics::HalfState Herringbone12Dynamics::half_state(int h, double t, double t_mid,
                                                                 const double* y) const {
  HalfState s;
  const double offset = p_.clock_offset[static_cast<std::size_t>(h)];
  s.mesh = mesh_.at(t + offset, t_mid + offset);
  s.delta = delta(h, y, 0);
  s.delta_rate = delta(h, y, rate);
  s.stiffness = s.mesh.stiffness;
  s.damping = p_.mesh_damping * s.stiffness / p_.mean_mesh_stiffness;
  s.force = s.stiffness * s.delta + s.damping * s.delta_rate;
  s.penetration = s.delta;
  s.mesh_dissipation = s.damping * s.delta_rate * s.delta_rate;
  if (options_.backlash) {
    // Contact loss (docs, "Contact loss"): the flanks overlap by p = δ or δ + b and push, never pull.
    const double b = *options_.backlash;
    s.back = s.delta < -b;
    s.penetration = s.delta > 0.0 ? s.delta : (s.back ? s.delta + b : 0.0);
    const double pushed = s.stiffness * s.penetration + s.damping * s.delta_rate;
    s.force = s.delta > 0.0 ? std::max(0.0, pushed) : (s.back ? std::min(0.0, pushed) : 0.0);
    // (F_n − k·p)·δ̇: c·δ̇² while the flanks push, −k·p·δ̇ ≥ 0 while they separate, 0 in the backlash.
    if (s.force == 0.0) s.mesh_dissipation = -s.stiffness * s.penetration * s.delta_rate;
  }
  if (mesh_.load_dependent_friction()) {
    const auto arms = mesh_.arms(t + offset, t_mid + offset, s.force);
    s.mesh.chi_pinion = arms[0];
    s.mesh.chi_wheel = arms[1];
  }
  s.impact = impact_force(h, t, t_mid);
  // With contact loss the pulse needs the working flanks in contact: the entering pair meets
  // early only by the loaded deflection (docs, "Contact loss").
  if (options_.backlash && !(s.delta > 0.0)) s.impact = 0.0;
  return s;
}

void Herringbone12Dynamics::contact_functions(const double* y, double* g) const {
  const double b = *options_.backlash, tau = p_.mesh_damping / p_.mean_mesh_stiffness;
  for (int h = 0; h < 2; ++h) {
    const double d = delta(h, y, 0), tau_rate = tau * delta(h, y, rate);
    double* gh = g + 4 * h;
    gh[0] = d;
    gh[1] = d + b;
    gh[2] = d + tau_rate;
    gh[3] = d + b + tau_rate;
  }
}

// docs/dynamics-model.md, "Equations of motion" (seed 000 eqs 1–4).
void Herringbone12Dynamics::derivative(double t, double t_mid, const double* y, double* dydt) const {
  const double cb = std::cos(p_.beta_b), sb = std::sin(p_.beta_b);
  for (int i = 0; i < 12; ++i) dydt[i] = y[rate + i];
  double damping = 0.0, friction = 0.0, parametric = 0.0, impact = 0.0;
  for (int h = 0; h < 2; ++h) {
    const int o = 1 - h;  // the other half
    const HalfState s = half_state(h, t, t_mid, y);
    const double Fy = cb * s.force, Fz = hand[h] * sb * s.force;
    auto v = [&](int half, Local c) { return y[rate + index(half, c)]; };
    auto q = [&](int half, Local c) { return y[index(half, c)]; };
    dydt[rate + index(h, YP)] = (-Fy - p_.c_radial * v(h, YP) - p_.k_radial * q(h, YP)) / p_.m_p;
    dydt[rate + index(h, ZP)] = (-Fz - p_.c_axial_p * v(h, ZP) - p_.k_axial_p * q(h, ZP) -
                                 p_.c_groove * (v(h, ZP) - v(o, ZP)) - p_.k_groove * (q(h, ZP) - q(o, ZP))) / p_.m_p;
    dydt[rate + index(h, TP)] = (p_.T_p - p_.R_p * Fy - s.force * s.mesh.chi_pinion - p_.R_p * s.impact -
                                 p_.c_twist * (v(h, TP) - v(o, TP)) - p_.k_twist * (q(h, TP) - q(o, TP))) / p_.I_p;
    dydt[rate + index(h, YG)] = (Fy - p_.c_radial * v(h, YG) - p_.k_radial * q(h, YG)) / p_.m_g;
    dydt[rate + index(h, ZG)] = (Fz - p_.c_axial_g * v(h, ZG) - p_.k_axial_g * q(h, ZG) -
                                 p_.c_groove * (v(h, ZG) - v(o, ZG)) - p_.k_groove * (q(h, ZG) - q(o, ZG))) / p_.m_g;
    dydt[rate + index(h, TG)] = (p_.R_g * Fy + s.force * s.mesh.chi_wheel - p_.T_g + p_.R_g * s.impact -
                                 p_.c_twist * (v(h, TG) - v(o, TG)) - p_.k_twist * (q(h, TG) - q(o, TG))) / p_.I_g;
    // Powers of the page's energy balance (section "Energy balance").
    damping += p_.c_radial * (v(h, YP) * v(h, YP) + v(h, YG) * v(h, YG)) + p_.c_axial_p * v(h, ZP) * v(h, ZP) +
               p_.c_axial_g * v(h, ZG) * v(h, ZG) + s.mesh_dissipation;
    friction += s.force * (s.mesh.chi_pinion * (p_.omega_p + v(h, TP)) - s.mesh.chi_wheel * (p_.omega_g + v(h, TG)));
    parametric += 0.5 * s.mesh.rate * s.penetration * s.penetration;
    impact += s.impact * (p_.R_g * v(h, TG) - p_.R_p * v(h, TP));
  }
  for (const Local c : {ZP, ZG, TP, TG}) {
    const double dv = y[rate + index(0, c)] - y[rate + index(1, c)];
    damping += (c == ZP || c == ZG ? p_.c_groove : p_.c_twist) * dv * dv;
  }
  dydt[work + 0] = damping;
  dydt[work + 1] = friction;
  dydt[work + 2] = parametric;
  dydt[work + 3] = impact;
}

// E = ½Σm·q̇² + ½Σ I(Ω + θ̇)² + ½Σ k·q² (bearings, groove) + ½Σ_h k_h(t)·p_h² (p_h = δ_h
// without contact loss).
double Herringbone12Dynamics::energy(double t, double t_mid, const double* y) const {
  double e = 0.0;
  for (int h = 0; h < 2; ++h) {
    auto v = [&](Local c) { return y[rate + index(h, c)]; };
    auto q = [&](Local c) { return y[index(h, c)]; };
    e += p_.m_p * (v(YP) * v(YP) + v(ZP) * v(ZP)) + p_.m_g * (v(YG) * v(YG) + v(ZG) * v(ZG));
    e += p_.I_p * (p_.omega_p + v(TP)) * (p_.omega_p + v(TP)) + p_.I_g * (p_.omega_g + v(TG)) * (p_.omega_g + v(TG));
    e += p_.k_radial * (q(YP) * q(YP) + q(YG) * q(YG)) + p_.k_axial_p * q(ZP) * q(ZP) + p_.k_axial_g * q(ZG) * q(ZG);
    const HalfState s = half_state(h, t, t_mid, y);
    e += s.stiffness * s.penetration * s.penetration;
  }
  for (const Local c : {ZP, ZG, TP, TG}) {
    const double dq = y[index(0, c)] - y[index(1, c)];
    e += (c == ZP || c == ZG ? p_.k_groove : p_.k_twist) * dq * dq;
  }
  return 0.5 * e;
}

// K·q = f under the mean stiffness and arms with θ_g = 0 in the left half (the rigid-body
// rotation; with uncoupled halves, in both), solved by Eigen's full-pivot LU.
std::vector<double> Herringbone12Dynamics::static_state() const {
  Matrix12 K = support_stiffness(p_);
  Vector12 f = Vector12::Zero();
  for (int h = 0; h < 2; ++h) {
    const Vector12 v = mesh_direction(p_, h);
    Vector12 load = v;
    load(index(h, TP)) += mesh_.mean().chi_pinion;
    load(index(h, TG)) -= mesh_.mean().chi_wheel;
    K += p_.mean_mesh_stiffness * load * v.transpose();
    f(index(h, TP)) = p_.T_p - p_.R_p * p_.mean_impact_force;
    f(index(h, TG)) = -p_.T_g + p_.R_g * p_.mean_impact_force;
  }
  std::vector<int> keep;
  for (int i = 0; i < 12; ++i)
    if (i != index(0, TG) && (i != index(1, TG) || p_.k_twist > 0.0)) keep.push_back(i);
  const auto n = static_cast<Eigen::Index>(keep.size());
  Eigen::MatrixXd Kr(n, n);
  Eigen::VectorXd fr(n);
  for (Eigen::Index a = 0; a < n; ++a) {
    fr(a) = f(keep[static_cast<std::size_t>(a)]);
    for (Eigen::Index b = 0; b < n; ++b) Kr(a, b) = K(keep[static_cast<std::size_t>(a)], keep[static_cast<std::size_t>(b)]);
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(Kr);
  if (lu.rank() < n)
    throw InputError("bearings: the static problem is singular (an axial coordinate is unrestrained: a floating "
                     "pinion needs a helical pair)");
  const Eigen::VectorXd qr = lu.solve(fr);
  std::vector<double> y(state_size(), 0.0);
  for (Eigen::Index a = 0; a < n; ++a) y[static_cast<std::size_t>(keep[static_cast<std::size_t>(a)])] = qr(a);
  return y;
}

std::vector<double> Herringbone12Dynamics::natural_frequencies(std::vector<std::vector<double>>* shapes) const {
  Matrix12 M = Matrix12::Zero(), K = support_stiffness(p_);
  for (int h = 0; h < 2; ++h) {
    M(index(h, YP), index(h, YP)) = M(index(h, ZP), index(h, ZP)) = p_.m_p;
    M(index(h, YG), index(h, YG)) = M(index(h, ZG), index(h, ZG)) = p_.m_g;
    M(index(h, TP), index(h, TP)) = p_.I_p;
    M(index(h, TG), index(h, TG)) = p_.I_g;
    const Vector12 v = mesh_direction(p_, h);
    K += p_.mean_mesh_stiffness * v * v.transpose();
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix<double, 12, 12>> solver(K, M);
  std::vector<double> f;
  const double scale = solver.eigenvalues().maxCoeff();
  for (int i = 0; i < 12; ++i) {
    if (solver.eigenvalues()(i) <= 1e-10 * scale) continue;
    f.push_back(std::sqrt(solver.eigenvalues()(i)) / (2.0 * pi));
    if (shapes) {
      const auto column = solver.eigenvectors().col(i);
      shapes->emplace_back(column.data(), column.data() + 12);
    }
  }
  return f;
}

std::vector<double> Herringbone12Dynamics::break_times(double t0, double t1) const {
  std::vector<double> times;
  for (int h = 0; h < 2; ++h) {
    const double offset = p_.clock_offset[static_cast<std::size_t>(h)];
    for (const double tau : mesh_.switch_times(t0 + offset, t1 + offset)) times.push_back(tau - offset);
    if (!options_.mesh_in_impact) continue;
    for (double base = std::floor((t0 + offset) / p_.period) * p_.period; base < t1 + offset + p_.period;
         base += p_.period)
      for (const double tau : {base, base + p_.impact_duration})
        if (tau - offset > t0 && tau - offset < t1) times.push_back(tau - offset);
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end(),
                          [this](double a, double b) { return std::abs(a - b) < 1e-12 * p_.period; }),
              times.end());
  return times;
}

Herringbone12Result Herringbone12Dynamics::solve() const {
  const auto start = std::chrono::steady_clock::now();
  const double T = p_.period;
  MarchPlan plan;
  plan.t_record = options_.runup_cycles * T;
  plan.t_end = (options_.runup_cycles + options_.record_cycles) * T;
  plan.sample_interval = T / options_.samples_per_cycle;
  plan.samples = static_cast<std::size_t>(options_.record_cycles * options_.samples_per_cycle) + 1;
  plan.longest_call = T;
  Herringbone12Result r;
  r.options_given = r.options_used = options_;
  r.options_used.groove_stiffness = p_.k_groove;
  r.options_used.twist_stiffness = p_.k_twist;
  r.static_mesh_force = p_.static_force;
  r.mesh_frequency = 1.0 / T;
  r.load_torque = 2.0 * p_.T_g;
  const auto m = march(*this, options_.integrator, plan, static_state(), [&](double t, double t_mid, const std::vector<double>& y) {
    r.time.push_back(t - plan.t_record);
    for (int h = 0; h < 2; ++h) {
      const HalfState s = half_state(h, t, t_mid, y.data());
      r.transmission_error[static_cast<std::size_t>(h)].push_back(s.delta);
      r.mesh_force[static_cast<std::size_t>(h)].push_back(s.force);
      r.friction_torque[static_cast<std::size_t>(h)].push_back(s.force * s.mesh.chi_pinion);
      if (s.force == 0.0) r.contact_loss_fraction += 0.5;
      if (s.back) r.back_contact_fraction += 0.5;
    }
    r.axial_float.push_back(0.5 * (y[index(0, ZP)] + y[index(1, ZP)]));
    r.bearing_force_pinion.push_back(p_.k_radial * y[index(0, YP)] + p_.c_radial * y[rate + index(0, YP)]);
  });
  r.steps = m.steps;
  r.rhs_evaluations = m.rhs_evaluations;
  r.contact_events = m.contact_events;
  // Energy balance of the recorded window (docs, "Energy balance").
  auto& e = r.energy;
  const double window = plan.t_end - plan.t_record;
  for (int h = 0; h < 2; ++h) {
    e.input += p_.T_p * (p_.omega_p * window + m.y_end[index(h, TP)] - m.y_record[index(h, TP)]);
    e.output += p_.T_g * (p_.omega_g * window + m.y_end[index(h, TG)] - m.y_record[index(h, TG)]);
  }
  e.damping = m.y_end[work + 0] - m.y_record[work + 0];
  e.friction = m.y_end[work + 1] - m.y_record[work + 1];
  e.parametric = m.y_end[work + 2] - m.y_record[work + 2] + m.jumps;
  e.impact = m.y_end[work + 3] - m.y_record[work + 3];
  e.energy_change = m.energy_end - m.energy_record;
  e.residual = e.relative_residual();

  for (std::size_t h = 0; h < 2; ++h) {
    r.te[h] = statistics(r.transmission_error[h]);
    r.force[h] = statistics(r.mesh_force[h]);
    r.dynamic_factor = std::max(r.dynamic_factor, *std::max_element(r.mesh_force[h].begin(), r.mesh_force[h].end()) /
                                                      r.static_mesh_force);
  }
  r.float_stats = statistics(r.axial_float);
  r.contact_loss_fraction /= static_cast<double>(r.time.size());
  r.back_contact_fraction /= static_cast<double>(r.time.size());
  // The spectrum and periodicity over whole cycles: the closing sample repeats the first phase.
  std::vector<double> te(r.transmission_error[0].begin(), r.transmission_error[0].end() - 1);
  amplitude_spectrum(te, plan.sample_interval, r.spectrum_frequency, r.spectrum_te);
  r.natural_frequencies = natural_frequencies(&r.mode_shapes);
  r.periodicity = periodicity(te, static_cast<std::size_t>(options_.samples_per_cycle));
  auto [status, message] = run_status(r.periodicity);
  r.status = status;
  r.message = std::move(message);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::string Herringbone12Result::summary() const { return run_summary("herringbone12", *this); }

}  // namespace gearbench::dynamics
