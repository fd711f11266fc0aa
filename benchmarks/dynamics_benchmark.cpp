// Dynamics benchmarks: 100 mesh cycles of the 6-DOF spur model (seed 003 pair, 996 rpm,
// 50 N·m), SUNDIALS CVODE (Adams, rtol 1e-8) against the independent fixed-step RK4 at
// equal accuracy: both land within ~1e-6 of the transmission error's peak-to-peak of an
// RK4 run at 8192 steps per cycle (CVODE 8e-7; RK4 at 2048 steps 9.5e-6, at 4096 ~6e-7).
// `gearbench bench` reports the time ratio.
#include <benchmark/benchmark.h>

#include <cmath>

#include "dynamics/spur6_dynamics.h"
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
  std::copy(s0.begin(), s0.end(), y0.begin());
  for (auto _ : state) benchmark::DoNotOptimize(reference::spur6_rk4(r, y0, 100.0 * T, T / 4096.0, T / 64.0).size());
  state.counters["mesh_cycles_per_s"] = benchmark::Counter(100.0 * static_cast<double>(state.iterations()),
                                                           benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Spur6Dynamics_baseline)->Unit(benchmark::kMillisecond);

}  // namespace
