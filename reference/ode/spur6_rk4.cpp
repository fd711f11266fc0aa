#include "ode/spur6_rk4.h"

#include "ode/fixed_step.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace gearbench::reference {

namespace {

// Where each coordinate sits in a Spur6State: q_i at i, its rate q̇_i at i + rate.
enum Coordinate : std::size_t { X1 = 0, Y1 = 1, TH1 = 2, X2 = 3, Y2 = 4, TH2 = 5 };
constexpr std::size_t rate = 6;

// ---- Input checks ---------------------------------------------------------------------

void require_positive(double value, const char* name) {
  if (!(value > 0.0))
    throw std::invalid_argument(std::string("spur6: ") + name + " must be positive, got " +
                                std::to_string(value));
}

// The parameters every function needs: what the equations divide by, and a path of
// contact that contact positions can be computed on.
void validate(const Spur6Parameters& p) {
  require_positive(p.m1, "m1");
  require_positive(p.m2, "m2");
  require_positive(p.I1, "I1");
  require_positive(p.I2, "I2");
  require_positive(p.rb1, "rb1");
  require_positive(p.rb2, "rb2");
  require_positive(p.mean_mesh_stiffness, "mean_mesh_stiffness");
  require_positive(p.pbt, "pbt");
  require_positive(p.contact_speed, "contact_speed");
  require_positive(p.E - p.A, "E - A");
  if (!p.pair_stiffness) throw std::invalid_argument("spur6: pair_stiffness is empty");
  if (!(p.backlash >= 0.0)) throw std::invalid_argument("spur6: backlash must be >= 0");
  if (p.benedict_kelley) {
    require_positive(p.benedict_kelley->viscosity, "benedict_kelley.viscosity");
    require_positive(p.benedict_kelley->face_width, "benedict_kelley.face_width");
    if (!(p.benedict_kelley->roughness_Ra >= 0.0 && p.benedict_kelley->roughness_Ra < 1.27e-6))
      throw std::invalid_argument("spur6: benedict_kelley.roughness_Ra must lie in [0, 1.27e-6) m");
  }
}

// ---- Section "Friction laws": Benedict & Kelley ----------------------------------------

// Benedict & Kelley, ASLE Trans. 4 (1961) 59, as quoted by Xu et al., J. Mech. Des. 129
// (2007) 58: μ = 0.0127·C_R·log10[3.17e8·W/(ν0·V_s·V_r²)], C_R = 50/(50 − S_avg), with W in
// lb/in, ν0 in cP, V in in/s, S_avg in µin. Converted here: W = w/175.127 (N/m → lb/in),
// V = v/0.0254 (m/s → in/s). The page caps μ at 0.15 (also where V_s = 0) and floors it at 0,
// and takes w ≥ 10 N/m.
double benedict_kelley(const Spur6Parameters::BenedictKelley& law, double w, double u1, double u2) {
  constexpr double newton_per_metre_per_lb_per_inch = 175.127, metre_per_inch = 0.0254, cap = 0.15;
  const double sliding = std::abs(u1 - u2) / metre_per_inch, rolling = (u1 + u2) / metre_per_inch;
  if (sliding == 0.0) return cap;
  const double load = std::max(w, 10.0) / newton_per_metre_per_lb_per_inch;
  const double centipoise = law.viscosity * 1e3;
  const double roughness_microinch = law.roughness_Ra / metre_per_inch * 1e6;
  const double c_r = 50.0 / (50.0 - roughness_microinch);
  const double mu = 0.0127 * c_r * std::log10(3.17e8 * load / (centipoise * sliding * rolling * rolling));
  return std::clamp(mu, 0.0, cap);
}

// μ_j of a pair at s carrying F_j: the constant μ, or Benedict–Kelley at w = |F_j|/b with
// the nominal surface speeds u1 = ω1·s, u2 = ω2·(T1T2 − s), ω_i = u/R_bi.
double pair_mu(const Spur6Parameters& p, double s, double force) {
  if (!p.benedict_kelley) return p.mu;
  const double u1 = p.contact_speed / p.rb1 * s, u2 = p.contact_speed / p.rb2 * (p.T1T2 - s);
  return benedict_kelley(*p.benedict_kelley, std::abs(force) / p.benedict_kelley->face_width, u1, u2);
}

// ---- Section "Mesh": the pairs in contact ---------------------------------------------

// mod(x, period) in [0, period).
double wrap(double x, double period) {
  const double r = std::fmod(x, period);
  return r < 0.0 ? r + period : r;
}

// One pair in contact: its index j and its friction sign λ_j (section "Friction").
struct Pair {
  int j;
  double lambda;
};

// A set of pairs in contact together with their positions as functions of time,
// s_j(t) = A + phase + u·(t − t_ref) + j·p_bt with phase = mod(u·t_ref, p_bt). At t = t_ref
// this is the page's s_j; on an interval without switches it is the same pair moving on.
struct ContactSet {
  double t_ref;
  double phase;
  std::vector<Pair> pairs;
};

// The page's pairs at time t: every j ≥ 0 with s_j ≤ E, and λ_j = −1 before the pitch
// point C, +1 after it, 0 on it.
ContactSet contact_set_at(const Spur6Parameters& p, double t) {
  ContactSet set{t, wrap(p.contact_speed * t, p.pbt), {}};
  for (int j = 0; p.A + set.phase + j * p.pbt <= p.E; ++j) {
    const double s = p.A + set.phase + j * p.pbt;
    set.pairs.push_back({j, s > p.C ? 1.0 : (s < p.C ? -1.0 : 0.0)});
  }
  return set;
}

// s_j(t) of a pair of the set; clamped to [A, E], which it can leave only by round-off at
// the ends of an interval.
double position(const Spur6Parameters& p, const ContactSet& set, const Pair& pair, double t) {
  const double s = p.A + set.phase + p.contact_speed * (t - set.t_ref) + pair.j * p.pbt;
  return std::clamp(s, p.A, p.E);
}

// c_m = 2·ζ_m·√(k̄·m_e) with m_e = I1·I2/(I1·R_b2² + I2·R_b1²).
double mesh_damping(const Spur6Parameters& p) {
  const double me = p.I1 * p.I2 / (p.I1 * p.rb2 * p.rb2 + p.I2 * p.rb1 * p.rb1);
  return 2.0 * p.zeta_mesh * std::sqrt(p.mean_mesh_stiffness * me);
}

// δ = x1 + R_b1·θ1 − x2 − R_b2·θ2, from the coordinates starting at `first` (0 for δ,
// `rate` for δ̇).
double transmission_error(const Spur6Parameters& p, const Spur6State& y, std::size_t first) {
  return y[first + X1] + p.rb1 * y[first + TH1] - y[first + X2] - p.rb2 * y[first + TH2];
}

// ---- Section "Contact loss": the contact modes ------------------------------------------

// +1 on the working flanks (δ > 0 and δ + τδ̇ > 0, τ = c_m/k̄: the flanks overlap and push),
// −1 on the back flanks (δ + b < 0 and δ + b + τδ̇ < 0), 0 otherwise. Without backlash +1 always.
int contact_mode(const Spur6Parameters& p, const Spur6State& y) {
  if (p.backlash == 0.0) return 1;
  const double delta = transmission_error(p, y, 0), tau_rate = mesh_damping(p) / p.mean_mesh_stiffness *
                                                               transmission_error(p, y, rate);
  if (delta > 0.0 && delta + tau_rate > 0.0) return 1;
  if (delta + p.backlash < 0.0 && delta + p.backlash + tau_rate < 0.0) return -1;
  return 0;
}

// The mesh's loads: F_m = Σ F_j (seed eq. 13) and, from section "Friction", the friction
// force F_f on the wheel and the friction moments M1 on the pinion and M2 on the wheel.
struct MeshLoads {
  double mesh = 0.0;
  double friction = 0.0;
  double moment1 = 0.0;
  double moment2 = 0.0;
};

MeshLoads mesh_loads(const Spur6Parameters& p, const ContactSet& set, int mode, double t,
                     const Spur6State& y) {
  if (mode == 0) return {};
  // The overlap of the flanks in contact: δ (working flanks), δ + b (back flanks).
  const double delta = transmission_error(p, y, 0) + (mode < 0 ? p.backlash : 0.0);
  const double delta_rate = transmission_error(p, y, rate);
  const double damping_per_stiffness = mesh_damping(p) / p.mean_mesh_stiffness;
  MeshLoads loads;
  for (const Pair& pair : set.pairs) {
    const double s = position(p, set, pair, t);
    const double k = p.pair_stiffness(s);
    const double force = k * delta + damping_per_stiffness * k * delta_rate;  // F_j
    const double friction = pair_mu(p, s, force) * pair.lambda * force;
    loads.mesh += force;
    loads.friction += friction;
    loads.moment1 += friction * s;               // arm ρ1 = s_j
    loads.moment2 += friction * (p.T1T2 - s);    // arm ρ2 = T1T2 − s_j
  }
  return loads;
}

// ---- Section "Loads": the quasi-static torque balance ----------------------------------

// F̄ = T1/(R_b1 + ā1) and T2 = F̄·(R_b2 + ā2), ā_i the mean over the N = 720 mesh positions
// u·t = (i + ½)·p_bt/N of Σμ_j·λ_j·k_j·ρ_ij / Σk_j with ρ_1j = s_j, ρ_2j = T1T2 − s_j, μ_j
// at the pair's share (T1/R_b1)·k_j/Σk_j of the nominal force.
using Loads = Spur6Loads;

Loads quasi_static_loads(const Spur6Parameters& p) {
  constexpr int positions = 720;
  double arm1 = 0.0, arm2 = 0.0;
  for (int i = 0; i < positions; ++i) {
    const double t = (i + 0.5) * p.pbt / positions / p.contact_speed;
    const ContactSet set = contact_set_at(p, t);
    double k = 0.0, k_arm1 = 0.0, k_arm2 = 0.0;
    for (const Pair& pair : set.pairs) k += p.pair_stiffness(position(p, set, pair, t));
    for (const Pair& pair : set.pairs) {
      const double s = position(p, set, pair, t);
      const double kj = p.pair_stiffness(s);
      const double mu = pair_mu(p, s, p.T1 / p.rb1 * kj / k);
      k_arm1 += mu * kj * pair.lambda * s;
      k_arm2 += mu * kj * pair.lambda * (p.T1T2 - s);
    }
    arm1 += k_arm1 / k / positions;
    arm2 += k_arm2 / k / positions;
  }
  const double force = p.T1 / (p.rb1 + arm1);
  return {force, force * (p.rb2 + arm2)};
}

// ---- Section "Equations of motion" (seed eq. 12) --------------------------------------

// −c·q̇ − k·q of a bearing coordinate.
double bearing_force(const Spur6State& y, std::size_t i, double k, double c) {
  return -c * y[i + rate] - k * y[i];
}

Spur6State equations_of_motion(const Spur6Parameters& p, const Loads& loads, const ContactSet& set, int mode,
                               double t, const Spur6State& y) {
  const MeshLoads f = mesh_loads(p, set, mode, t, y);
  const double T2 = loads.T2;
  Spur6State dy{};
  for (std::size_t i = 0; i < rate; ++i) dy[i] = y[i + rate];
  dy[X1 + rate] = (bearing_force(y, X1, p.k1, p.c1) - f.mesh) / p.m1;
  dy[Y1 + rate] = (bearing_force(y, Y1, p.k1, p.c1) - f.friction) / p.m1;
  dy[TH1 + rate] = (p.T1 - p.rb1 * f.mesh - f.moment1) / p.I1;
  dy[X2 + rate] = (bearing_force(y, X2, p.k2, p.c2) + f.mesh) / p.m2;
  dy[Y2 + rate] = (bearing_force(y, Y2, p.k2, p.c2) + f.friction) / p.m2;
  dy[TH2 + rate] = (p.rb2 * f.mesh + f.moment2 - T2) / p.I2;
  return dy;
}

// ---- Classical Runge–Kutta of order 4 -------------------------------------------------

// From a to b (no switch strictly inside) with the pair set of the midpoint: the
// right-hand limit of the pair set at a, the left-hand one at b; the contact mode held over
// every step and switched where it changes.
void integrate_interval(const Spur6Parameters& p, const Loads& loads, double a, double b, double dt, int& mode,
                        Spur6State& y) {
  const ContactSet set = contact_set_at(p, (a + b) / 2);
  const auto f = [&](int m, double t, const Spur6State& state) { return equations_of_motion(p, loads, set, m, t, state); };
  if (p.backlash == 0.0)
    ode::integrate_interval([&](double t, const Spur6State& state) { return f(1, t, state); }, a, b, dt, y);
  else
    ode::integrate_interval_with_modes(f, [&](const Spur6State& state) { return contact_mode(p, state); }, mode, a, b,
                                       dt, y);
}

// ---- The times the integrator steps onto ----------------------------------------------

// Where the right-hand side jumps, as phases mod(u·t, p_bt) of a mesh period (section
// "Mesh"): a pair enters at A, a pair leaves at E, a pair passes the pitch point C.
std::array<double, 3> switch_phases(const Spur6Parameters& p) {
  return {0.0, wrap(p.E - p.A, p.pbt), wrap(p.C - p.A, p.pbt)};
}

std::vector<ode::Breakpoint> breakpoints(const Spur6Parameters& p, double t_end, double dt, double sample_every) {
  std::vector<double> switches;
  for (double n = 0; n * p.pbt / p.contact_speed < t_end; ++n)
    for (double phase : switch_phases(p)) switches.push_back((n * p.pbt + phase) / p.contact_speed);
  return ode::breakpoints(switches, t_end, dt, sample_every);
}

Spur6Sample make_sample(const Spur6Parameters& p, double t, int mode, const Spur6State& y) {
  const MeshLoads f = mesh_loads(p, contact_set_at(p, t), mode, t, y);
  return {t, y, f.mesh, f.friction, transmission_error(p, y, 0), mode};
}

}  // namespace

// ---- Public interface -----------------------------------------------------------------

Spur6State spur6_static_state(const Spur6Parameters& p) {
  validate(p);
  require_positive(p.k1, "k1");
  require_positive(p.k2, "k2");
  const double F0 = quasi_static_loads(p).force;
  const double delta0 = F0 / p.mean_mesh_stiffness;
  Spur6State y{};
  y[X1] = -F0 / p.k1;
  y[X2] = F0 / p.k2;
  y[TH1] = (delta0 - y[X1] + y[X2]) / p.rb1;
  return y;
}

double spur6_benedict_kelley(const Spur6Parameters& p, double s, double load_per_length) {
  validate(p);
  if (!p.benedict_kelley) throw std::invalid_argument("spur6: benedict_kelley parameters are not set");
  const double u1 = p.contact_speed / p.rb1 * s, u2 = p.contact_speed / p.rb2 * (p.T1T2 - s);
  return benedict_kelley(*p.benedict_kelley, load_per_length, u1, u2);
}

Spur6Loads spur6_loads(const Spur6Parameters& p) {
  validate(p);
  return quasi_static_loads(p);
}

Spur6State spur6_derivative(const Spur6Parameters& p, double t, const Spur6State& y) {
  return spur6_derivative(p, spur6_loads(p), t, y);
}

Spur6State spur6_derivative(const Spur6Parameters& p, const Spur6Loads& loads, double t, const Spur6State& y) {
  validate(p);
  return equations_of_motion(p, loads, contact_set_at(p, t), contact_mode(p, y), t, y);
}

std::vector<Spur6Sample> spur6_rk4(const Spur6Parameters& p, const Spur6State& y0,
                                   double t_end, double dt, double sample_every) {
  validate(p);
  require_positive(dt, "dt");
  require_positive(sample_every, "sample_every");
  if (!(t_end >= 0.0))
    throw std::invalid_argument("spur6: t_end must be non-negative, got " +
                                std::to_string(t_end));

  Spur6State y = y0;
  int mode = contact_mode(p, y);
  std::vector<Spur6Sample> samples{make_sample(p, 0.0, mode, y)};
  if (t_end == 0.0) return samples;
  const std::vector<ode::Breakpoint> points = breakpoints(p, t_end, dt, sample_every);
  const Loads loads = quasi_static_loads(p);
  for (std::size_t i = 1; i < points.size(); ++i) {
    integrate_interval(p, loads, points[i - 1].t, points[i].t, dt, mode, y);
    if (points[i].sample) samples.push_back(make_sample(p, points[i].t, mode, y));
  }
  return samples;
}

}  // namespace gearbench::reference
