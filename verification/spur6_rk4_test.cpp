// Tests of reference/ode/spur6_rk4, the RK4 reference for the 6-DOF spur pair of
// docs/dynamics-model.md: the page's pair set and friction signs, the static state staying
// static, the torsional natural frequency and the mesh damping ratio of free vibration, the
// observed order across stiffness switches, the energy balance and the decay to the static
// state. Measured figures are printed as "[ measured ]" lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "ode/spur6_rk4.h"
#include "support/convergence.h"

namespace gearbench::reference {
namespace {

using std::numbers::pi;
using verification::order_from_errors;

// Indices into a Spur6State: q = [x1, y1, θ1, x2, y2, θ2], then q̇.
constexpr std::size_t X1 = 0, Y1 = 1, TH1 = 2, X2 = 3, Y2 = 4, TH2 = 5, RATE = 6;

// ---- The test pair --------------------------------------------------------------------
// Seed 004's pair: 22/32 teeth, m = 2 mm, α = 25°, b = 20 mm, standard centre distance
// 54 mm (ε_α = 1.455), pinion at 1000 rpm under 100 N·m, blanks as the page's solid steel
// discs, bearings of 1e8 N/m and 500 N·s/m. The switch times fall at 0, 0.455 and 0.741 of
// a mesh period, off any step grid.

constexpr double alpha = 25.0 * pi / 180.0;

// Pair stiffness rising from 0 at A to K over the two-pair zone, holding K, and falling to
// 0 over the last two-pair zone: pairs enter, leave and change stiffness, but their sum is
// K at every instant (for any 1 < ε_α < 2), and k̄ = K.
void use_constant_total_stiffness(Spur6Parameters& p, double K) {
  const double A = p.A, E = p.E, ramp = p.E - p.A - p.pbt;
  p.pair_stiffness = [=](double s) {
    return K * std::min({1.0, (s - A) / ramp, (E - s) / ramp});
  };
  p.mean_mesh_stiffness = K;
}

// k_pair(s) = k0·(1 + 0.2·sin(2π(s − A)/(E − A))): the total jumps by k0 at every entry
// and exit; its mean over a mesh period is k̄ = ε_α·k0.
void use_sinusoidal_stiffness(Spur6Parameters& p, double k0) {
  const double A = p.A, length = p.E - p.A;
  p.pair_stiffness = [=](double s) {
    return k0 * (1.0 + 0.2 * std::sin(2 * pi * (s - A) / length));
  };
  p.mean_mesh_stiffness = k0 * length / p.pbt;
}

Spur6Parameters test_pair() {
  const double r1 = 22e-3, r2 = 32e-3, tip1 = 24e-3, tip2 = 34e-3;
  auto disc_mass = [](double r) { return 7850.0 * pi * r * r * 0.020; };  // ρ·π·r²·b
  Spur6Parameters p{};
  p.m1 = disc_mass(r1);
  p.I1 = p.m1 * r1 * r1 / 2;
  p.m2 = disc_mass(r2);
  p.I2 = p.m2 * r2 * r2 / 2;
  p.rb1 = r1 * std::cos(alpha);
  p.rb2 = r2 * std::cos(alpha);
  p.k1 = p.k2 = 1e8;
  p.c1 = p.c2 = 500.0;
  p.T1 = 100.0;
  p.mu = 0.0;
  p.zeta_mesh = 0.05;
  p.pbt = pi * 2e-3 * std::cos(alpha);
  p.T1T2 = 54e-3 * std::sin(alpha);
  p.A = p.T1T2 - std::sqrt(tip2 * tip2 - p.rb2 * p.rb2);
  p.E = std::sqrt(tip1 * tip1 - p.rb1 * p.rb1);
  p.C = r1 * std::sin(alpha);
  p.contact_speed = 1000.0 * 2 * pi / 60 * p.rb1;
  use_constant_total_stiffness(p, 3e8);
  return p;
}

double mesh_period(const Spur6Parameters& p) { return p.pbt / p.contact_speed; }

// The page's section "Loads": F̄ = T1/(R_b1 + ā1), T2 = F̄·(R_b2 + ā2), the arms ā_i the
// mean over u·t = (i + ½)·p_bt/720 of μ·Σλ_j·k_j·ρ_ij/Σk_j (pairs at A + frac·p_bt + j·p_bt ≤ E).
struct QuasiStatic {
  double force, T2;
};
QuasiStatic quasi_static(const Spur6Parameters& p) {
  double arm1 = 0, arm2 = 0;
  for (int i = 0; i < 720; ++i) {
    double k = 0, k1 = 0, k2 = 0;
    for (double s = p.A + (i + 0.5) / 720 * p.pbt; s <= p.E; s += p.pbt) {
      const double kj = p.pair_stiffness(s), lambda = s > p.C ? 1.0 : -1.0;
      k += kj;
      k1 += kj * lambda * s;
      k2 += kj * lambda * (p.T1T2 - s);
    }
    arm1 += p.mu * k1 / k / 720;
    arm2 += p.mu * k2 / k / 720;
  }
  const double force = p.T1 / (p.rb1 + arm1);
  return {force, force * (p.rb2 + arm2)};
}

// δ0 = F̄/k̄.
double static_deflection(const Spur6Parameters& p) {
  return quasi_static(p).force / p.mean_mesh_stiffness;
}

// √(K·(R_b1²/I1 + R_b2²/I2))/(2π): the torsional mode on rigid bearings.
double torsional_frequency(const Spur6Parameters& p) {
  const double K = p.mean_mesh_stiffness;
  return std::sqrt(K * (p.rb1 * p.rb1 / p.I1 + p.rb2 * p.rb2 / p.I2)) / (2 * pi);
}

// δ (first = 0) or δ̇ (first = RATE) of a state.
double transmission_error(const Spur6Parameters& p, const Spur6State& y, std::size_t first) {
  return y[first + X1] + p.rb1 * y[first + TH1] - y[first + X2] - p.rb2 * y[first + TH2];
}

// The static state with δ raised by 20 %, the wheel pushed along x and the pinion along y.
Spur6State perturbed_static_state(const Spur6Parameters& p) {
  Spur6State y = spur6_static_state(p);
  y[TH1] += 0.2 * static_deflection(p) / p.rb1;
  y[X2 + RATE] += 0.05;
  y[Y1] += 2e-6;
  return y;
}

// The largest deviation of y from a static state y_s: of δ and the bearing displacements
// [m], and of the rates with θ̇_i·R_bi [m/s]. The angles themselves are left out: the
// deviation coordinates have a neutral mode, both gears turning rigidly with δ fixed,
// which no force restores (round-off, or a transient, leaves it displaced).
struct Deviation {
  double displacement, rate;
};

Deviation deviation(const Spur6Parameters& p, const Spur6State& y, const Spur6State& ys) {
  Deviation d{};
  d.displacement = std::abs(transmission_error(p, y, 0) - transmission_error(p, ys, 0));
  for (std::size_t i : {X1, Y1, X2, Y2}) {
    d.displacement = std::max(d.displacement, std::abs(y[i] - ys[i]));
    d.rate = std::max(d.rate, std::abs(y[i + RATE] - ys[i + RATE]));
  }
  d.rate = std::max({d.rate, std::abs(p.rb1 * (y[TH1 + RATE] - ys[TH1 + RATE])),
                     std::abs(p.rb2 * (y[TH2 + RATE] - ys[TH2 + RATE]))});
  return d;
}

// ---- The page's pairs and friction signs ----------------------------------------------

// With k_pair = k and the state static: at u·t = f·p_bt the pairs sit at A + (f mod 1)·p_bt
// + j·p_bt ≤ E = A + 1.455·p_bt, with λ = −1 before C = A + 0.741·p_bt and +1 after it
// (the pinion flank slides ahead beyond C); each carries k·δ; T2 is the page's "Loads".
TEST(Spur6Rk4, DerivativeUsesThePagesPairsAndFrictionSigns) {
  Spur6Parameters p = test_pair();
  const double k = 2e8;
  p.pair_stiffness = [k](double) { return k; };
  p.mean_mesh_stiffness = k * (p.E - p.A) / p.pbt;
  p.mu = 0.1;
  const Spur6State y = spur6_static_state(p);
  const double F = k * static_deflection(p);
  const double T2 = quasi_static(p).T2;
  ASSERT_LT(T2, p.T1 * p.rb2 / p.rb1);  // friction takes power: less torque comes out

  struct Case {
    double fraction;
    std::vector<double> offsets;  // (s_j − A)/p_bt of the pairs in contact
  };
  for (const Case& c : {Case{0.0, {0.0, 1.0}}, Case{0.25, {0.25, 1.25}}, Case{0.6, {0.6}},
                        Case{0.9, {0.9}}, Case{1.25, {0.25, 1.25}}}) {
    double Fm = 0, Ff = 0, M1 = 0, M2 = 0;
    for (double offset : c.offsets) {
      const double s = p.A + offset * p.pbt;
      const double friction = p.mu * (s > p.C ? 1.0 : -1.0) * F;
      Fm += F;
      Ff += friction;
      M1 += friction * s;
      M2 += friction * (p.T1T2 - s);
    }
    const Spur6State d = spur6_derivative(p, c.fraction * mesh_period(p), y);
    SCOPED_TRACE(c.fraction);
    EXPECT_NEAR(d[X1 + RATE], (-p.k1 * y[X1] - Fm) / p.m1, 1e-9 * F / p.m1);
    EXPECT_NEAR(d[X2 + RATE], (-p.k2 * y[X2] + Fm) / p.m2, 1e-9 * F / p.m2);
    EXPECT_NEAR(d[Y1 + RATE], -Ff / p.m1, 1e-9 * F / p.m1);
    EXPECT_NEAR(d[Y2 + RATE], Ff / p.m2, 1e-9 * F / p.m2);
    EXPECT_NEAR(d[TH1 + RATE], (p.T1 - p.rb1 * Fm - M1) / p.I1, 1e-9 * p.T1 / p.I1);
    EXPECT_NEAR(d[TH2 + RATE], (p.rb2 * Fm + M2 - T2) / p.I2, 1e-9 * T2 / p.I2);
  }
}

// ---- (a) The static state stays static ------------------------------------------------

TEST(Spur6Rk4, StaticStateStaysStaticUnderConstantTotalStiffness) {
  Spur6Parameters p = test_pair();
  p.c1 = p.c2 = 0.0;  // damping in the mesh only
  const Spur6State y0 = spur6_static_state(p);
  const double delta0 = static_deflection(p), F0 = quasi_static(p).force;
  const double Tm = mesh_period(p);
  const std::vector<Spur6Sample> samples = spur6_rk4(p, y0, 3 * Tm, Tm / 200, Tm / 50);
  ASSERT_EQ(samples.size(), 151u);
  for (std::size_t i = 0; i + 1 < samples.size(); ++i)  // exactly on multiples, then t_end
    EXPECT_EQ(samples[i].t, static_cast<double>(i) * (Tm / 50));
  EXPECT_EQ(samples.back().t, 3 * Tm);

  double force_drift = 0;
  Deviation worst{};  // includes δ
  for (const Spur6Sample& s : samples) {
    force_drift = std::max(force_drift, std::abs(s.mesh_force - F0) / F0);
    const Deviation d = deviation(p, s.y, y0);
    worst = {std::max(worst.displacement, d.displacement), std::max(worst.rate, d.rate)};
  }
  const double rate_scale = 2 * pi * torsional_frequency(p) * delta0;
  std::printf("[ measured ] static state over 3 mesh periods: |F_m/F0 − 1| ≤ %.1e, "
              "δ and bearings within %.1e·δ0, rates within %.1e·ω·δ0\n",
              force_drift, worst.displacement / delta0, worst.rate / rate_scale);
  EXPECT_LT(force_drift, 1e-12);
  EXPECT_LT(worst.displacement, 1e-12 * delta0);
  EXPECT_LT(worst.rate, 1e-12 * rate_scale);
}

// ---- (b) Free vibration: the torsional frequency and the mesh damping ratio -----------
// Constant total stiffness K = k̄, μ = 0, bearings of 1e6·K without damping: the torsional
// mode is a single-DOF oscillator of equivalent mass m_e and damping ratio ζ_m, up to a
// coupling of order K/k_i = 1e-6.

Spur6Parameters free_vibration_pair(double zeta_mesh) {
  Spur6Parameters p = test_pair();
  p.k1 = p.k2 = 1e6 * p.mean_mesh_stiffness;
  p.c1 = p.c2 = 0.0;
  p.zeta_mesh = zeta_mesh;
  return p;
}

// From the static state with δ raised by 20 %, 8000 steps and 2000 samples a period.
std::vector<Spur6Sample> free_vibration(const Spur6Parameters& p, double periods) {
  Spur6State y0 = spur6_static_state(p);
  y0[TH1] += 0.2 * static_deflection(p) / p.rb1;
  const double period = 1 / torsional_frequency(p);
  return spur6_rk4(p, y0, periods * period, period / 8000, period / 2000);
}

// Times where δ − δ0 crosses zero upwards, by linear interpolation between samples.
std::vector<double> upward_crossings(const std::vector<Spur6Sample>& samples, double delta0) {
  std::vector<double> times;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const double a = samples[i - 1].transmission_error - delta0;
    const double b = samples[i].transmission_error - delta0;
    if (a < 0 && b >= 0)
      times.push_back(samples[i - 1].t + (samples[i].t - samples[i - 1].t) * a / (a - b));
  }
  return times;
}

// Local maxima of δ − δ0, refined by the parabola through the three samples around each.
std::vector<double> peaks(const std::vector<Spur6Sample>& samples, double delta0) {
  std::vector<double> values;
  for (std::size_t i = 1; i + 1 < samples.size(); ++i) {
    const double l = samples[i - 1].transmission_error - delta0;
    const double m = samples[i].transmission_error - delta0;
    const double r = samples[i + 1].transmission_error - delta0;
    if (m > 0 && m > l && m >= r)
      values.push_back(m + (r - l) * (r - l) / (8 * (2 * m - l - r)));
  }
  return values;
}

TEST(Spur6Rk4, FreeVibrationHasTheTorsionalFrequency) {
  const Spur6Parameters p = free_vibration_pair(0.0);
  const std::vector<Spur6Sample> samples = free_vibration(p, 20.5);
  const std::vector<double> crossings = upward_crossings(samples, static_deflection(p));
  ASSERT_EQ(crossings.size(), 20u);
  const double measured = static_cast<double>(crossings.size() - 1) /
                          (crossings.back() - crossings.front());
  const double expected = torsional_frequency(p);
  const double error = measured / expected - 1;
  std::printf("[ measured ] torsional frequency %.3f Hz, closed form %.3f Hz, relative "
              "error %.2e\n", measured, expected, error);
  EXPECT_LT(std::abs(error), 1e-4);
}

// Successive peaks of a damped mode fall by exp(−2πζ/√(1 − ζ²)) per period.
TEST(Spur6Rk4, FreeVibrationDecaysWithTheMeshDampingRatio) {
  const double zeta = 0.02;
  const Spur6Parameters p = free_vibration_pair(zeta);
  const std::vector<Spur6Sample> samples = free_vibration(p, 10.5);
  const std::vector<double> maxima = peaks(samples, static_deflection(p));
  ASSERT_EQ(maxima.size(), 10u);
  const double decrement = std::log(maxima.front() / maxima.back()) /
                           static_cast<double>(maxima.size() - 1) / (2 * pi);
  const double measured = decrement / std::sqrt(1 + decrement * decrement);
  std::printf("[ measured ] mesh damping ratio %.7f from the log decrement, ζ_m = %.7f, "
              "relative error %.2e\n", measured, zeta, measured / zeta - 1);
  EXPECT_NEAR(measured / zeta, 1.0, 1e-4);
}

// ---- (c) Switches: observed order and where they fall ---------------------------------
// A jumping total stiffness and friction (λ jumps at C): seed 004's pair with the
// sinusoidal pair stiffness and μ = 0.05, from the static state over two mesh periods.

Spur6Parameters switching_pair() {
  Spur6Parameters p = test_pair();
  use_sinusoidal_stiffness(p, 2e8);
  p.mu = 0.05;
  return p;
}

// Each coordinate's largest magnitude along a trajectory.
Spur6State coordinate_scale(const std::vector<Spur6Sample>& samples) {
  Spur6State scale{};
  for (const Spur6Sample& s : samples)
    for (std::size_t i = 0; i < scale.size(); ++i)
      scale[i] = std::max(scale[i], std::abs(s.y[i]));
  return scale;
}

// max_i |a_i − b_i|/scale_i.
double scaled_difference(const Spur6State& a, const Spur6State& b, const Spur6State& scale) {
  double worst = 0;
  for (std::size_t i = 0; i < scale.size(); ++i)
    worst = std::max(worst, std::abs(a[i] - b[i]) / scale[i]);
  return worst;
}

// The final states for dt, dt/2 and dt/4: differences fall by 2⁴ per halving only if the
// right-hand side is smooth on every step, i.e. every switch is stepped onto.
TEST(Spur6Rk4, ObservedOrderIsFourAcrossStiffnessSwitches) {
  const Spur6Parameters p = switching_pair();
  const Spur6State y0 = spur6_static_state(p);
  const double Tm = mesh_period(p), t_end = 2 * Tm;
  std::vector<Spur6State> finals;
  for (double steps_per_period : {2048.0, 4096.0, 8192.0})
    finals.push_back(spur6_rk4(p, y0, t_end, Tm / steps_per_period, t_end).back().y);
  const Spur6State scale = coordinate_scale(spur6_rk4(p, y0, t_end, Tm / 2048, Tm / 64));
  const double coarse = scaled_difference(finals[0], finals[1], scale);
  const double fine = scaled_difference(finals[1], finals[2], scale);
  const double order = order_from_errors(coarse, fine);
  std::printf("[ measured ] observed order %.3f (scaled differences %.2e, %.2e; "
              "dt = Tm/2048, Tm/4096, Tm/8192)\n", order, coarse, fine);
  EXPECT_GE(order, 3.7);
  EXPECT_LE(order, 4.3);
}

// RK4 on spur6_derivative with `steps` equal steps: the page's pair set at every stage, so
// only first order across switches.
Spur6State plain_rk4(const Spur6Parameters& p, const Spur6State& y0, double t_end, int steps) {
  auto advanced = [](const Spur6State& q, double step, const Spur6State& dq) {
    Spur6State r;
    for (std::size_t i = 0; i < q.size(); ++i) r[i] = q[i] + step * dq[i];
    return r;
  };
  const double h = t_end / steps;
  const Spur6Loads loads = spur6_loads(p);
  Spur6State y = y0;
  for (int n = 0; n < steps; ++n) {
    const double t = n * h;
    const Spur6State d1 = spur6_derivative(p, loads, t, y);
    const Spur6State d2 = spur6_derivative(p, loads, t + h / 2, advanced(y, h / 2, d1));
    const Spur6State d3 = spur6_derivative(p, loads, t + h / 2, advanced(y, h / 2, d2));
    const Spur6State d4 = spur6_derivative(p, loads, t + h, advanced(y, h, d3));
    for (std::size_t i = 0; i < y.size(); ++i)
      y[i] += h / 6 * (d1[i] + 2 * d2[i] + 2 * d3[i] + d4[i]);
  }
  return y;
}

// Contact loss (the page's section "Contact loss"): the switching pair with a 5 µm backlash,
// released from twice its static deflection with 2 m/s of closing speed the wrong way, so
// that the flanks part, cross the backlash and strike the back flanks. The contact mode
// holds over each step and the step is bisected where it changes: the final states for
// dt, dt/2 and dt/4 still converge at order 4 (a step through the switch, unlocated, would
// leave first order).
TEST(Spur6Rk4, ObservedOrderIsFourAcrossContactLoss) {
  Spur6Parameters p = switching_pair();
  p.backlash = 5e-6;
  Spur6State y0 = spur6_static_state(p);
  y0[TH1] += static_deflection(p) / p.rb1;
  y0[TH1 + RATE] -= 2.0 / p.rb1;
  const double Tm = mesh_period(p), t_end = 2 * Tm;
  std::vector<Spur6State> finals;
  for (double steps_per_period : {2048.0, 4096.0, 8192.0})
    finals.push_back(spur6_rk4(p, y0, t_end, Tm / steps_per_period, t_end).back().y);
  const auto run = spur6_rk4(p, y0, t_end, Tm / 2048, Tm / 256);
  int parted = 0, back = 0;
  for (const Spur6Sample& s : run) {
    parted += s.contact == 0;
    back += s.contact < 0;
    EXPECT_GE(s.contact >= 0 ? s.mesh_force : -s.mesh_force, 0.0);  // the flanks push, never pull
  }
  const Spur6State scale = coordinate_scale(run);
  const double coarse = scaled_difference(finals[0], finals[1], scale);
  const double fine = scaled_difference(finals[1], finals[2], scale);
  const double order = order_from_errors(coarse, fine);
  std::printf("[ measured ] contact loss: %d of %zu samples parted, %d on the back flanks; observed order %.3f "
              "(scaled differences %.2e, %.2e)\n", parted, run.size(), back, order, coarse, fine);
  EXPECT_GT(parted, 0);
  EXPECT_GT(back, 0);
  EXPECT_GE(order, 3.6);
  EXPECT_LE(order, 4.4);
}

// The plain RK4 converges at first order to spur6_rk4's solution: its distance from it
// halves with the step. A pair set held past a switch (one not stepped onto) would make
// spur6_rk4 converge, at order 4, to another solution, and the distance would stall.
TEST(Spur6Rk4, PlainRk4OnThePagesDerivativeConvergesToIt) {
  const Spur6Parameters p = switching_pair();
  const Spur6State y0 = spur6_static_state(p);
  const double Tm = mesh_period(p), t_end = 2 * Tm;
  const std::vector<Spur6Sample> samples = spur6_rk4(p, y0, t_end, Tm / 2048, Tm / 64);
  auto distance = [&](int steps) {
    return scaled_difference(plain_rk4(p, y0, t_end, steps), samples.back().y,
                             coordinate_scale(samples));
  };
  const double coarse = distance(1 << 16), fine = distance(1 << 17);
  std::printf("[ measured ] plain RK4 at dt = Tm/32768, Tm/65536 against spur6_rk4: scaled "
              "differences %.2e, %.2e (order %.3f)\n", coarse, fine, order_from_errors(coarse, fine));
  EXPECT_LT(fine, 2e-3);
  EXPECT_NEAR(order_from_errors(coarse, fine), 1.0, 0.2);
}

// ---- (d) Energy balance and decay ------------------------------------------------------
// With μ = 0 and Σ k_j = k̄ at every instant, the energy in deviation coordinates
//   E = ½Σ m·q̇² + ½Σ I·θ̇² + ½k_i(x_i² + y_i²) + ½k̄·δ² − T1·θ1 + T2·θ2
// changes as dE/dt = −D with D = c1(ẋ1² + ẏ1²) + c2(ẋ2² + ẏ2²) + c_m·δ̇² (Σ c_j = c_m).

double energy(const Spur6Parameters& p, const Spur6State& y) {
  auto square = [](double v) { return v * v; };
  const double kinetic = p.m1 * (square(y[X1 + RATE]) + square(y[Y1 + RATE])) +
                         p.m2 * (square(y[X2 + RATE]) + square(y[Y2 + RATE])) +
                         p.I1 * square(y[TH1 + RATE]) + p.I2 * square(y[TH2 + RATE]);
  const double elastic = p.k1 * (square(y[X1]) + square(y[Y1])) +
                         p.k2 * (square(y[X2]) + square(y[Y2])) +
                         p.mean_mesh_stiffness * square(transmission_error(p, y, 0));
  return (kinetic + elastic) / 2 - p.T1 * y[TH1] + p.T1 * p.rb2 / p.rb1 * y[TH2];
}

double dissipation(const Spur6Parameters& p, const Spur6State& y) {
  auto square = [](double v) { return v * v; };
  const double me = p.I1 * p.I2 / (p.I1 * p.rb2 * p.rb2 + p.I2 * p.rb1 * p.rb1);
  const double cm = 2 * p.zeta_mesh * std::sqrt(p.mean_mesh_stiffness * me);
  return p.c1 * (square(y[X1 + RATE]) + square(y[Y1 + RATE])) +
         p.c2 * (square(y[X2 + RATE]) + square(y[Y2 + RATE])) +
         cm * square(transmission_error(p, y, RATE));
}

TEST(Spur6Rk4, EnergyBalanceOverAMeshPeriod) {
  const Spur6Parameters p = test_pair();
  const double Tm = mesh_period(p);
  const std::vector<Spur6Sample> samples =
      spur6_rk4(p, perturbed_static_state(p), Tm, Tm / 4000, Tm / 4000);
  ASSERT_EQ(samples.size(), 4001u);

  double dissipated = 0;  // composite Simpson
  for (std::size_t i = 0; i + 2 < samples.size(); i += 2)
    dissipated += (samples[i + 2].t - samples[i].t) / 6 *
                  (dissipation(p, samples[i].y) + 4 * dissipation(p, samples[i + 1].y) +
                   dissipation(p, samples[i + 2].y));
  const double released = energy(p, samples.front().y) - energy(p, samples.back().y);
  const double imbalance = (released - dissipated) / dissipated;
  std::printf("[ measured ] energy over a mesh period: released %.6e J, dissipated %.6e J, "
              "relative imbalance %.2e\n", released, dissipated, imbalance);
  EXPECT_GT(dissipated, 0.5 * (energy(p, samples.front().y) -
                               energy(p, spur6_static_state(p))));
  EXPECT_LT(std::abs(imbalance), 1e-6);
}

TEST(Spur6Rk4, DampedMotionDecaysToTheStaticState) {
  const Spur6Parameters p = test_pair();
  const Spur6State y_static = spur6_static_state(p);
  const Spur6State y0 = perturbed_static_state(p);
  const double Tm = mesh_period(p);
  const std::vector<Spur6Sample> samples = spur6_rk4(p, y0, 20 * Tm, Tm / 200, 20 * Tm);
  const Deviation initial = deviation(p, y0, y_static);
  const Deviation remaining = deviation(p, samples.back().y, y_static);
  std::printf("[ measured ] after 20 mesh periods: displacements %.2e → %.2e m, rates "
              "%.2e → %.2e m/s\n", initial.displacement, remaining.displacement, initial.rate,
              remaining.rate);
  EXPECT_LT(remaining.displacement, 1e-8 * initial.displacement);
  EXPECT_LT(remaining.rate, 1e-8 * initial.rate);
}

// ---- Input checks ---------------------------------------------------------------------

TEST(Spur6Rk4, RejectsNonPositiveMassesInertiasAndStep) {
  const Spur6Parameters good = test_pair();
  const Spur6State y0 = spur6_static_state(good);
  using P = Spur6Parameters;
  for (double P::*member : {&P::m1, &P::m2, &P::I1, &P::I2}) {
    Spur6Parameters bad = good;
    bad.*member = 0.0;
    EXPECT_THROW(spur6_static_state(bad), std::invalid_argument);
    EXPECT_THROW(spur6_derivative(bad, 0.0, y0), std::invalid_argument);
    EXPECT_THROW(spur6_rk4(bad, y0, 1e-3, 1e-6, 1e-4), std::invalid_argument);
  }
  EXPECT_THROW(spur6_rk4(good, y0, 1e-3, 0.0, 1e-4), std::invalid_argument);
  EXPECT_THROW(spur6_rk4(good, y0, 1e-3, -1e-6, 1e-4), std::invalid_argument);
}

}  // namespace
}  // namespace gearbench::reference
