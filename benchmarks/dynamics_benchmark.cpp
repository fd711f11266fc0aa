// Dynamics benchmarks: 100 mesh cycles of the 6-DOF spur model (seed 003 pair, 996 rpm,
// 50 N·m), SUNDIALS CVODE (Adams, rtol 1e-8) against the independent fixed-step RK4 at
// equal accuracy: both land within ~1e-6 of the transmission error's peak-to-peak of an
// RK4 run at 8192 steps per cycle (CVODE 8e-7; RK4 at 2048 steps 9.5e-6, at 4096 ~6e-7).
// `gearbench bench` reports the time ratio.
// 100 mesh cycles of the 12-DOF herringbone model (seed 000 case: 2000 rpm, 309 N·m, μ 0.05,
// mesh-in impacts), CVODE Adams at rtol 1e-8, against the independent RK4 at 2048 steps per
// cycle (the step of the check herringbone12.rk4, which agrees with CVODE to ~1e-5 of the
// transmission error's peak-to-peak or better). Target: 100 cycles in under 1 s.
#include <benchmark/benchmark.h>

#include <cmath>

#include "dynamics/herringbone12_dynamics.h"
#include "dynamics/spur6_dynamics.h"
#include "ode/herringbone12_rk4.h"
#include "ode/spur6_rk4.h"
#include "support/test_support.h"

namespace {

using namespace gearbench;

struct Setup {
  geometry::GearPairGeometry geometry{testing_support::seed003_pair()};
  std::array<model::Material, 2> materials{model::Material{212e9, 0.289, 7850}, model::Material{212e9, 0.289, 7850}};
  model::OperatingPoint operating{996.0 * M_PI / 30.0, 50.0, 313.15, {0.0, 0.0}};
};

void BM_Spur6Dynamics(benchmark::State& state) {
  const Setup s;
  dynamics::Spur6Options o;
  o.runup_cycles = 0;
  o.record_cycles = 100;
  const dynamics::Spur6Dynamics d(s.geometry, s.materials, s.operating, o);
  for (auto _ : state) benchmark::DoNotOptimize(d.solve().te.rms);
  state.counters["mesh_cycles_per_s"] = benchmark::Counter(100.0 * static_cast<double>(state.iterations()),
                                                           benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Spur6Dynamics)->Unit(benchmark::kMillisecond);

void BM_Spur6Dynamics_baseline(benchmark::State& state) {
  const Setup s;
  const dynamics::Spur6Dynamics d(s.geometry, s.materials, s.operating, dynamics::Spur6Options{});
  const auto& p = d.parameters();
  reference::Spur6Parameters r{p.m1, p.m2, p.I1, p.I2, p.rb1, p.rb2, p.k_bearing, p.k_bearing,
                               p.c_bearing, p.c_bearing, p.T1, p.mu, p.zeta_mesh, p.mean_mesh_stiffness,
                               p.A, p.C, p.E, p.T1T2, p.pbt, p.contact_speed,
                               [&d](double x) { return d.pair_stiffness(x); }};
  const double T = p.pbt / p.contact_speed;
  reference::Spur6State y0{};
  const auto s0 = d.static_state();
  std::copy(s0.begin(), s0.begin() + 12, y0.begin());
  for (auto _ : state) benchmark::DoNotOptimize(reference::spur6_rk4(r, y0, 100.0 * T, T / 4096.0, T / 64.0).size());
  state.counters["mesh_cycles_per_s"] = benchmark::Counter(100.0 * static_cast<double>(state.iterations()),
                                                           benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Spur6Dynamics_baseline)->Unit(benchmark::kMillisecond);

struct HerringboneSetup {
  model::GearPair pair = [] {
    model::GearPair g;
    g.teeth = {17, 44};
    g.normal_module = 6e-3;
    g.normal_pressure_angle = 18.334317 * M_PI / 180.0;
    g.helix_angle = 24.43 * M_PI / 180.0;
    g.face_width = 55e-3;
    g.herringbone = model::Herringbone{58e-3};
    return g;
  }();
  geometry::GearPairGeometry geometry{pair};
  std::array<model::Material, 2> materials{model::Material{206e9, 0.3, 7850}, model::Material{206e9, 0.3, 7850}};
  model::OperatingPoint operating{2000.0 * M_PI / 30.0, 309.09, 313.15, {0.0, 0.0}};
  dynamics::Herringbone12Options options() const {
    dynamics::Herringbone12Options o;
    o.mesh.friction_coefficient = 0.05;
    o.runup_cycles = 0;
    o.record_cycles = 100;
    return o;
  }
};

void BM_Herringbone12Dynamics(benchmark::State& state) {
  const HerringboneSetup s;
  const dynamics::Herringbone12Dynamics d(s.geometry, s.materials, s.operating, s.options());
  for (auto _ : state) benchmark::DoNotOptimize(d.solve().te[0].rms);
  state.counters["mesh_cycles_per_s"] = benchmark::Counter(100.0 * static_cast<double>(state.iterations()),
                                                           benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Herringbone12Dynamics)->Unit(benchmark::kMillisecond);

void BM_Herringbone12Dynamics_baseline(benchmark::State& state) {
  const HerringboneSetup s;
  const dynamics::Herringbone12Dynamics d(s.geometry, s.materials, s.operating, s.options());
  const auto& p = d.parameters();
  const auto& mesh = d.mesh();
  const reference::Herringbone12Parameters r{
      p.m_p, p.m_g, p.I_p, p.I_g, p.R_p, p.R_g, p.beta_b, p.k_radial, p.c_radial, p.k_axial_p, p.c_axial_p,
      p.k_axial_g, p.c_axial_g, p.k_groove, p.c_groove, p.k_twist, p.c_twist, p.T_p, p.T_g,
      p.mean_mesh_stiffness, p.mesh_damping, p.impact_force, p.impact_duration, p.period, p.clock_offset,
      [&mesh](double tau) {
        const auto m = mesh.at(tau, tau);
        return reference::HalfMeshValue{m.stiffness, m.chi_pinion, m.chi_wheel};
      }};
  reference::Herringbone12State y0{};
  const auto s0 = d.static_state();
  std::copy(s0.begin(), s0.begin() + 24, y0.begin());
  for (auto _ : state)
    benchmark::DoNotOptimize(reference::herringbone12_rk4(r, y0, 100.0 * p.period, p.period / 2048.0, p.period / 64.0).size());
  state.counters["mesh_cycles_per_s"] = benchmark::Counter(100.0 * static_cast<double>(state.iterations()),
                                                           benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Herringbone12Dynamics_baseline)->Unit(benchmark::kMillisecond);

}  // namespace
