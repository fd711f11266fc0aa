// Tests of the 12-DOF herringbone model (solvers/dynamics/herringbone12_dynamics) and its
// independent RK4 (reference/ode/herringbone12_rk4): input validation with the case keys in
// the messages, the production static state as an equilibrium of the reference equations,
// the reference's observed order across the impact pulses, and the mesh tables.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "checks/dynamics_reference.h"
#include "closed_form/corner_contact.h"
#include "stiffness/cubic_spline.h"
#include "support/convergence.h"
#include "support/test_support.h"

namespace gearbench {
namespace {

using testing_support::input_error_of;

// Seed 000 (table 2): 17/44, m_n 6 mm, α_t 20°, β 24.43°, 55 mm per half, groove 58 mm.
model::GearPair seed000_pair() {
  model::GearPair g;
  g.teeth = {17, 44};
  g.normal_module = 6e-3;
  g.normal_pressure_angle = 18.334317 * std::numbers::pi / 180.0;
  g.helix_angle = 24.43 * std::numbers::pi / 180.0;
  g.face_width = 55e-3;
  g.herringbone = model::Herringbone{58e-3};
  return g;
}

const std::array<model::Material, 2> steel{model::Material{206e9, 0.3, 7850}, model::Material{206e9, 0.3, 7850}};
const model::OperatingPoint seed000_operating{2000.0 * std::numbers::pi / 30.0, 309.09, 313.15, {0.0, 0.0}};

dynamics::Herringbone12Options fast_options() {
  dynamics::Herringbone12Options o;
  o.mesh.slices = 40;
  o.mesh.positions = 180;
  o.mesh.friction.friction_coefficient = 0.05;
  return o;
}

using verification::herringbone_reference;
using verification::observed_order;

TEST(Herringbone12, RejectsBadInputNamingTheKey) {
  const geometry::GearPairGeometry herringbone(seed000_pair());
  const geometry::GearPairGeometry spur(testing_support::seed003_pair());
  auto error = [&](const geometry::GearPairGeometry& g, auto edit) {
    auto o = fast_options();
    edit(o);
    return input_error_of([&] { dynamics::Herringbone12Dynamics(g, steel, seed000_operating, o); });
  };
  EXPECT_NE(error(spur, [](auto&) {}).find("bearings.floating_pinion = true"), std::string::npos);
  EXPECT_NE(error(herringbone, [](auto& o) { o.mesh.harmonics = 90; }).find("mesh.harmonics = 90"), std::string::npos);
  EXPECT_NE(error(herringbone, [](auto& o) { o.half_offset = 1.5; }).find("half_offset_cycles = 1.5"), std::string::npos);
  EXPECT_NE(error(herringbone, [](auto& o) { o.base_pitch_error = 2e-4; }).find("base_pitch_error_um = 200"),
            std::string::npos);
  EXPECT_NE(error(herringbone, [](auto& o) { o.radial_stiffness = 0.0; }).find("bearings.radial_stiffness_N_per_m"),
            std::string::npos);
  EXPECT_NE(error(herringbone, [](auto& o) { o.mesh.friction.friction_coefficient = 0.9; }).find("friction.mu = 0.9"),
            std::string::npos);
  // A helical pair that is not a herringbone pair.
  const geometry::GearPairGeometry single(seed000_pair().one_mesh());
  EXPECT_NE(error(single, [](auto&) {}).find("gear_pair.herringbone: missing"), std::string::npos);
}

// Under the mean mesh (k̄, χ̄) and no pulses, the production static state (Eigen LU of the
// page's K·q = f) is at rest in the reference equations: every acceleration is at round-off.
TEST(Herringbone12, StaticStateIsAnEquilibriumOfTheReferenceEquations) {
  const geometry::GearPairGeometry g(seed000_pair());
  auto o = fast_options();
  o.mesh_in_impact = false;
  const dynamics::Herringbone12Dynamics d(g, steel, seed000_operating, o);
  auto p = herringbone_reference(d);
  const auto mean = d.mesh().mean();
  p.mesh = [mean](double) { return reference::HalfMeshValue{mean.stiffness, mean.chi_pinion, mean.chi_wheel}; };
  reference::Herringbone12State y{};
  const auto s = d.static_state();
  std::copy(s.begin(), s.begin() + 24, y.begin());
  const auto dy = reference::herringbone12_derivative(p, 0.0, y);
  const double force = d.parameters().static_force;
  double worst = 0.0;
  for (std::size_t i = 12; i < 24; ++i) {
    const std::size_t local = (i - 12) % 6;
    const double inertia = local == 2 ? p.I_p : local == 5 ? p.I_g : local < 3 ? p.m_p : p.m_g;
    const double scale = (local == 2 ? p.R_p : local == 5 ? p.R_g : 1.0) * force;  // force or torque scale
    worst = std::max(worst, std::abs(dy[i]) * inertia / scale);
  }
  std::printf("[ measured ] static state: largest |mass·acceleration| / (F̄ or R·F̄) = %.2e\n", worst);
  EXPECT_LT(worst, 1e-9);  // LU on a system with condition ~1e6: round-off ~1e-10 of the load
}

// Final states for dt = T/512, T/1024, T/2048 over two mesh cycles with impacts (pulse
// starts and ends stepped onto): differences must fall by 2⁴ per halving. The pulses of eq. 6
// as printed (3.7 times those under the approach) keep the differences far above round-off.
TEST(Herringbone12, ReferenceRk4HasOrderFourAcrossImpactPulses) {
  const geometry::GearPairGeometry g(seed000_pair());
  auto o = fast_options();
  o.mesh_in_impact = true;
  o.impact_held_velocity = true;
  const dynamics::Herringbone12Dynamics d(g, steel, seed000_operating, o);
  const auto p = herringbone_reference(d);
  reference::Herringbone12State y0{};
  const auto s = d.static_state();
  std::copy(s.begin(), s.begin() + 24, y0.begin());
  const double T = p.period;
  std::vector<double> delta;
  for (const double steps : {512.0, 1024.0, 2048.0})
    delta.push_back(reference::herringbone12_rk4(p, y0, 2 * T, T / steps, 2 * T).back().delta[0]);
  const double order = observed_order(delta[0], delta[1], delta[2]);
  std::printf("[ measured ] herringbone RK4 observed order %.3f (δ differences %.2e, %.2e m)\n", order,
              std::abs(delta[0] - delta[1]), std::abs(delta[1] - delta[2]));
  EXPECT_GE(order, 3.6);
  EXPECT_LE(order, 4.4);
}

// The mesh of a half: the arms summed here from the slices and MeshStiffness's slicing agree
// (same slices, same pair curve), and the truncated series keeps k̄.
TEST(Herringbone12, HalfMeshTablesAgreeWithTheSlicing) {
  const geometry::GearPairGeometry g(seed000_pair());
  // k_m (stiffness::MeshStiffness) and the arms (the half's own slices) on the same tooth,
  // whichever fillet the case names.
  auto circular = fast_options();
  circular.mesh.fillet = stiffness::Fillet::circular_arc;
  EXPECT_LT(dynamics::Herringbone12Dynamics(g, steel, seed000_operating, circular).mesh().slicing_consistency(), 1e-12);
  const dynamics::Herringbone12Dynamics d(g, steel, seed000_operating, fast_options());
  const auto& mesh = d.mesh();
  std::printf("[ measured ] slicing consistency %.2e, series−table deviation %.2e of k̄\n",
              mesh.slicing_consistency(), mesh.truncation());
  EXPECT_LT(mesh.slicing_consistency(), 1e-12);
  double mean = 0.0;
  for (int i = 0; i < 1000; ++i) mean += mesh.at(mesh.period() * i / 1000.0, 0.0).stiffness / 1000.0;
  EXPECT_NEAR(mean / mesh.mean_stiffness(), 1.0, 1e-12);  // the constant term is the table mean
  EXPECT_GT(mesh.mean().chi_pinion, 0.0);  // friction takes power out: the pinion arm opposes its torque
}

// The right-hand side evaluates k_m, its rate and the arms on one rotation (FourierSeries::
// evaluate): the values must be value()'s bit for bit, the rate the series' derivative
// (against a central difference at h = 1e-6 T, whose truncation is ~1e-12 relative).
TEST(Herringbone12, SeriesEvaluatedTogetherAreTheSeriesAlone) {
  const double period = 1.7e-3;
  std::vector<double> a(180), b(180);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double x = 2.0 * std::numbers::pi * static_cast<double>(i) / 180.0;
    a[i] = 1e9 * (1.0 + 0.1 * std::cos(x) + 0.03 * std::sin(3.0 * x) + 0.01 * std::cos(7.0 * x + 0.2));
    b[i] = 1e-3 * std::sin(2.0 * x) + 2e-4 * std::cos(5.0 * x);
  }
  const dynamics::FourierSeries fa(period, a, 24), fb(period, b, 24);
  const std::array<const dynamics::FourierSeries*, 2> both{&fa, &fb};
  for (const double t : {0.0, 0.3e-3, 1.1e-3, 5.0e-3}) {
    std::array<double, 2> v{};
    double rate = 0.0;
    dynamics::FourierSeries::evaluate(t, both, v, rate);
    EXPECT_EQ(v[0], fa.value(t));
    EXPECT_EQ(v[1], fb.value(t));
    const double h = 1e-6 * period;
    const double difference = (fa.value(t + h) - fa.value(t - h)) / (2.0 * h);
    EXPECT_NEAR(rate, difference, 1e3);  // the difference's rounding ε·k/h ≈ 1.4e2, against rates ~4e11
  }
  const dynamics::FourierSeries shorter(period, b, 12);
  const std::array<const dynamics::FourierSeries*, 2> mixed{&fa, &shorter};
  std::array<double, 2> v{};
  double rate = 0.0;
  EXPECT_THROW(dynamics::FourierSeries::evaluate(0.0, mixed, v, rate), std::logic_error);
}

// The spur pairs' rate dk/dt = u·dk/ds takes the spline's own derivative: against a central
// difference of the spline (O(h²) with h = 1e-6 of the span, rounding ~1e-10 relative); each
// pair slot evaluates through its own cursor.
TEST(Herringbone12, SplineDerivativeIsTheSplinesSlopeWithAnyCursor) {
  std::vector<double> x(101), y(101);
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = 0.01 * static_cast<double>(i);
    y[i] = std::exp(-x[i]) * std::sin(3.0 * x[i]);
  }
  const stiffness::CubicSpline spline(x, y);
  for (const double at : {0.0, 0.123, 0.5, 0.777, 1.0}) {
    const double h = 1e-6, lo = std::max(0.0, at - h), hi = std::min(1.0, at + h);
    EXPECT_NEAR(spline.derivative(at), (spline(hi) - spline(lo)) / (hi - lo), 1e-6) << at;
  }
  // A caller's own cursor, alternating between distant points as the pairs of a mesh do,
  // gives the same numbers as the spline's shared cache.
  std::array<stiffness::CubicSpline::Cursor, 2> cursors;
  for (int i = 0; i < 50; ++i) {
    const double near = 0.005 * i, far = 0.9 - 0.004 * i;
    EXPECT_EQ(spline(near, cursors[0]), spline(near));
    EXPECT_EQ(spline(far, cursors[1]), spline(far));
    EXPECT_EQ(spline.derivative(near, cursors[0]), spline.derivative(near));
  }
}

// The impact velocity v_s and the approach time Δt = 2δ̄/v_s of the model (docs/dynamics-model.md,
// "Mesh-in impact") are first order in the rotation γ of the flank normal at first contact;
// the exact construction of the corner contact (reference/closed_form/corner_contact) at the
// model's own δ̄ must agree to that order: γ ∝ √δ̄, so the error shrinks as √δ̄ from the seed
// load to a quarter of it, and stays below 10 % (γ ≈ 3.5 % at the seed load).
TEST(Herringbone12, ImpactVelocityIsTheExactCornerContactToFirstOrder) {
  const auto pair = seed000_pair();
  const geometry::GearPairGeometry g(pair);
  auto o = fast_options();
  o.mesh_in_impact = true;
  std::array<double, 2> velocity_error{}, time_error{}, deflection{};
  for (std::size_t i = 0; i < 2; ++i) {
    auto operating = seed000_operating;
    operating.pinion_torque /= i == 0 ? 1.0 : 4.0;
    const auto p = dynamics::Herringbone12Dynamics(g, steel, operating, o).parameters();
    deflection[i] = p.static_force / p.mean_mesh_stiffness;
    const auto exact = reference::corner_contact(pair, operating.pinion_speed, deflection[i]);
    velocity_error[i] = p.impact_velocity / exact.approach_velocity - 1.0;
    time_error[i] = p.impact_approach_time / exact.lead_time - 1.0;
    std::printf("[ measured ] δ̄ %.3e m: v_s %.4f m/s (exact %.4f, %+.2e), Δt %.3e s (exact %.3e, %+.2e), r %.3f\n",
                deflection[i], p.impact_velocity, exact.approach_velocity, velocity_error[i], p.impact_approach_time,
                exact.lead_time, time_error[i], p.impact_compression_ratio);
  }
  const double order = std::sqrt(deflection[0] / deflection[1]);
  for (const auto& e : {velocity_error, time_error}) {
    EXPECT_LT(std::abs(e[0]), 0.1);
    EXPECT_NEAR(e[0] / e[1], order, 0.25 * order);
  }
}

// The pulse's peak F_s·(√(1+φ²) − 1)/φ (docs/dynamics-model.md, "Mesh-in impact") is seed eq. 6's
// v_s·√(m_e/q_s) where the approach is long against the pulse (φ = 2/r large: 20 rpm, r ≈ 0.03), and
// k·δ where it is short (φ → 0: at 2000 rpm and a hundredth of the torque, r ≈ 34); the reference's
// entering pair under the exact approach is eq. 6 in the first limit. A base-pitch error f_pb
// adds to the gap the corner closes: v_s ∝ √(δ̄ + f_pb).
TEST(Herringbone12, ImpactPeakIsEquationSixUnderTheApproach) {
  const auto pair = seed000_pair();
  const geometry::GearPairGeometry g(pair);
  auto o = fast_options();
  o.mesh_in_impact = true;
  auto slow = seed000_operating;
  slow.pinion_speed = 20.0 * std::numbers::pi / 30.0;
  const auto p = dynamics::Herringbone12Dynamics(g, steel, slow, o).parameters();
  const double me = p.I_p * p.I_g / (p.I_p * p.R_g * p.R_g + p.I_g * p.R_p * p.R_p);
  const double deflection = p.static_force / p.mean_mesh_stiffness;
  const double reference_peak =
      reference::entering_pair_peak_force(pair, slow.pinion_speed, deflection, me, p.impact_stiffness);
  const double exact_held =  // eq. 6 at the exact corner contact's closing speed
      reference::corner_contact(pair, slow.pinion_speed, deflection).approach_velocity * std::sqrt(me * p.impact_stiffness);
  std::printf("[ measured ] 20 rpm: r %.4f, F_s %.1f N, eq. 6 %.1f N; reference %.1f N, eq. 6 exact v_s %.1f N\n",
              p.impact_compression_ratio, p.impact_force, p.impact_held_force, reference_peak, exact_held);
  EXPECT_LT(p.impact_compression_ratio, 0.05);
  EXPECT_NEAR(p.impact_force / p.impact_held_force, 1.0, 0.03);  // 1 − r/2 to first order
  EXPECT_NEAR(reference_peak / exact_held, 1.0, 0.03);
  // Short approach: the peak tends to k·δ (the corner closes δ before the spring responds).
  auto light = seed000_operating;
  light.pinion_torque /= 100.0;
  const auto q = dynamics::Herringbone12Dynamics(g, steel, light, o).parameters();
  const double gap = q.static_force / q.mean_mesh_stiffness;
  std::printf("[ measured ] 1/100 torque: r %.2f, F_s %.1f N, k·δ %.1f N\n", q.impact_compression_ratio,
              q.impact_force, q.impact_stiffness * gap);
  EXPECT_GT(q.impact_compression_ratio, 30.0);
  EXPECT_NEAR(q.impact_force / (q.impact_stiffness * gap), 1.0, 0.05);
  // Base-pitch error.
  o.base_pitch_error = 3.0 * deflection;
  const auto e = dynamics::Herringbone12Dynamics(g, steel, slow, o).parameters();
  EXPECT_NEAR(e.impact_velocity / p.impact_velocity,
              std::sqrt((e.static_force / e.mean_mesh_stiffness + o.base_pitch_error) / deflection), 1e-3);
}

}  // namespace
}  // namespace gearbench
