#include "ode/herringbone12_rk4.h"

#include "ode/fixed_step.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace gearbench::reference {

namespace {

constexpr double pi = 3.14159265358979323846;

// One body of a half: its translational coordinates along the line of action (y) and the
// axis (z) and its rotation θ, as offsets into a half's six coordinates.
struct Body {
  std::size_t y, z, theta;
};
constexpr Body pinion{0, 1, 2};
constexpr Body wheel{3, 4, 5};
constexpr std::size_t half_size = 6;
constexpr std::size_t rates = 12;

void require_positive(double value, const char* name) {
  if (!(value > 0.0))
    throw std::invalid_argument(std::string("herringbone12: ") + name + " must be positive, got " +
                                std::to_string(value));
}

void validate(const Herringbone12Parameters& p) {
  require_positive(p.m_p, "m_p");
  require_positive(p.m_g, "m_g");
  require_positive(p.I_p, "I_p");
  require_positive(p.I_g, "I_g");
  require_positive(p.R_p, "R_p");
  require_positive(p.R_g, "R_g");
  require_positive(p.mean_mesh_stiffness, "mean_mesh_stiffness");
  require_positive(p.period, "period");
  if (!p.mesh) throw std::invalid_argument("herringbone12: mesh is empty");
  if (p.impact_force > 0.0 && !(p.impact_duration > 0.0 && p.impact_duration < p.period))
    throw std::invalid_argument("herringbone12: impact_duration must lie in (0, period)");
}

// The page's hand of each half: the left half's axial mesh component is +sin β_b, the right's −sin β_b.
double hand(std::size_t half) { return half == 0 ? 1.0 : -1.0; }

// Section "Mesh-in impact": F_s = F_peak·sin(π·r/τ) while the half's clock r = mod(t + offset, T) < τ.
// `inside` says which side of a pulse boundary the step belongs to.
double pulse(const Herringbone12Parameters& p, std::size_t half, double t, double t_inside) {
  if (!(p.impact_force > 0.0)) return 0.0;
  const double clock_inside = t_inside + p.clock_offset[half];
  const double n = std::floor(clock_inside / p.period);
  if (clock_inside - n * p.period >= p.impact_duration) return 0.0;
  const double r = std::clamp(t + p.clock_offset[half] - n * p.period, 0.0, p.impact_duration);
  return p.impact_force * std::sin(pi * r / p.impact_duration);
}

// Section "Mesh force per half": δ = cos β_b (y_p − y_g + R_p θ_p − R_g θ_g) + σ sin β_b (z_p − z_g).
double normal_approach(const Herringbone12Parameters& p, const double* q, std::size_t half) {
  return std::cos(p.beta_b) * (q[pinion.y] - q[wheel.y] + p.R_p * q[pinion.theta] - p.R_g * q[wheel.theta]) +
         hand(half) * std::sin(p.beta_b) * (q[pinion.z] - q[wheel.z]);
}

struct MeshLoad {
  double delta, force, chi_p, chi_g;
};

MeshLoad mesh_load(const Herringbone12Parameters& p, double t, const Herringbone12State& y, std::size_t half) {
  const double* q = y.data() + half * half_size;
  const double* v = y.data() + rates + half * half_size;
  const HalfMeshValue m = p.mesh(t + p.clock_offset[half]);
  const double delta = normal_approach(p, q, half);
  const double delta_rate = normal_approach(p, v, half);
  const double force = m.k * delta + p.mesh_damping * m.k / p.mean_mesh_stiffness * delta_rate;
  return {delta, force, m.chi_p, m.chi_g};
}

// Section "Equations of motion" of the page, one half at a time; `other` is the other
// half's coordinate index offset for the groove couplings.
Herringbone12State equations(const Herringbone12Parameters& p, double t, double t_inside,
                             const Herringbone12State& y) {
  Herringbone12State dy{};
  for (std::size_t i = 0; i < rates; ++i) dy[i] = y[rates + i];
  const double c = std::cos(p.beta_b), s = std::sin(p.beta_b);
  for (std::size_t h = 0; h < 2; ++h) {
    const std::size_t self = h * half_size, other = (1 - h) * half_size;
    auto q = [&](std::size_t base, std::size_t i) { return y[base + i]; };
    auto v = [&](std::size_t base, std::size_t i) { return y[rates + base + i]; };
    auto coupling = [&](std::size_t i, double k, double damping) {
      return -k * (q(self, i) - q(other, i)) - damping * (v(self, i) - v(other, i));
    };
    const MeshLoad load = mesh_load(p, t, y, h);
    const double F = load.force;
    const double Fs = pulse(p, h, t, t_inside);
    double* a = dy.data() + rates + self;
    a[pinion.y] = (-c * F - p.k_radial * q(self, pinion.y) - p.c_radial * v(self, pinion.y)) / p.m_p;
    a[pinion.z] = (-hand(h) * s * F - p.k_axial_p * q(self, pinion.z) - p.c_axial_p * v(self, pinion.z) +
                   coupling(pinion.z, p.k_groove, p.c_groove)) / p.m_p;
    a[pinion.theta] = (p.T_p - p.R_p * c * F - F * load.chi_p - p.R_p * Fs +
                       coupling(pinion.theta, p.k_twist, p.c_twist)) / p.I_p;
    a[wheel.y] = (c * F - p.k_radial * q(self, wheel.y) - p.c_radial * v(self, wheel.y)) / p.m_g;
    a[wheel.z] = (hand(h) * s * F - p.k_axial_g * q(self, wheel.z) - p.c_axial_g * v(self, wheel.z) +
                  coupling(wheel.z, p.k_groove, p.c_groove)) / p.m_g;
    a[wheel.theta] = (p.R_g * c * F + F * load.chi_g - p.T_g + p.R_g * Fs +
                      coupling(wheel.theta, p.k_twist, p.c_twist)) / p.I_g;
  }
  return dy;
}

std::vector<ode::Breakpoint> breakpoints(const Herringbone12Parameters& p, double t_end, double dt,
                                         double sample_every) {
  std::vector<double> switches;  // the impact pulses start and end
  if (p.impact_force > 0.0)
    for (std::size_t h = 0; h < 2; ++h)
      for (double n = std::floor(p.clock_offset[h] / p.period) - 1; (n * p.period - p.clock_offset[h]) < t_end; ++n)
        for (const double tau : {n * p.period, n * p.period + p.impact_duration})
          switches.push_back(tau - p.clock_offset[h]);
  return ode::breakpoints(switches, t_end, dt, sample_every);
}

Herringbone12Sample sample(const Herringbone12Parameters& p, double t, const Herringbone12State& y) {
  Herringbone12Sample s{t, {}, {}};
  for (std::size_t h = 0; h < 2; ++h) {
    const MeshLoad load = mesh_load(p, t, y, h);
    s.delta[h] = load.delta;
    s.force[h] = load.force;
  }
  return s;
}

}  // namespace

Herringbone12State herringbone12_derivative(const Herringbone12Parameters& p, double t,
                                            const Herringbone12State& y) {
  validate(p);
  return equations(p, t, t, y);
}

std::vector<Herringbone12Sample> herringbone12_rk4(const Herringbone12Parameters& p, const Herringbone12State& y0,
                                                   double t_end, double dt, double sample_every) {
  validate(p);
  require_positive(dt, "dt");
  require_positive(sample_every, "sample_every");
  if (!(t_end >= 0.0)) throw std::invalid_argument("herringbone12: t_end must be non-negative");
  Herringbone12State y = y0;
  std::vector<Herringbone12Sample> samples{sample(p, 0.0, y)};
  if (t_end == 0.0) return samples;
  const auto points = breakpoints(p, t_end, dt, sample_every);
  for (std::size_t i = 1; i < points.size(); ++i) {
    // Every stage of the interval sees the pulse state of its midpoint.
    const double inside = 0.5 * (points[i - 1].t + points[i].t);
    ode::integrate_interval([&](double t, const Herringbone12State& state) { return equations(p, t, inside, state); },
                            points[i - 1].t, points[i].t, dt, y);
    if (points[i].sample) samples.push_back(sample(p, points[i].t, y));
  }
  return samples;
}

}  // namespace gearbench::reference
