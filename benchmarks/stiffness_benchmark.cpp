// Mesh-stiffness benchmarks: one mesh cycle at 360 positions (seed 003 pair). The side-by-
// side baseline is the GSL reference evaluating the same tooth integrals at the same
// positions (`gearbench bench` reports BM_StiffnessSpurCycle / ..._baseline).
// Targets from the issue: spur cycle < 5 ms, helical with 50 slices < 50 ms.
#include <benchmark/benchmark.h>

#include <cmath>

#include "quadrature/energy_quadrature.h"
#include "stiffness/mesh_stiffness.h"
#include "support/test_support.h"

namespace {

using namespace gearbench;

model::GearPair seed003(double helix_deg = 0.0) {
  auto g = testing_support::seed003_pair();
  g.helix_angle = helix_deg * M_PI / 180.0;
  return g;
}

const std::array<model::Material, 2> steel{model::Material{212e9, 0.289, 7850},
                                           model::Material{212e9, 0.289, 7850}};

void BM_StiffnessSpurCycle(benchmark::State& state) {
  const geometry::GearPairGeometry g(seed003());
  stiffness::MeshStiffnessOptions o;
  o.positions = 360;
  o.path_points = 2;
  for (auto _ : state) {
    const stiffness::MeshStiffness solver(g, steel, o);
    benchmark::DoNotOptimize(solver.solve().mean);
  }
  state.counters["positions"] = 360;
}
BENCHMARK(BM_StiffnessSpurCycle)->Unit(benchmark::kMillisecond);

// The same 360 positions, every pair in contact, both teeth, on the same tooth as the
// production default (the generated trochoid fillet): the GSL integrals only (no
// foundation), so the ratio is a lower bound on production's advantage.
void BM_StiffnessSpurCycle_baseline(benchmark::State& state) {
  const auto pair = seed003();
  const geometry::GearPairGeometry g(pair);
  const auto& p = g.path();
  const double pb = g.base_pitch_transverse();
  for (auto _ : state) {
    double sum = 0.0;
    for (int i = 0; i < 360; ++i)
      for (double s = p.A + pb * i / 360.0; s <= p.E; s += pb)
        for (int gear = 0; gear < 2; ++gear) {
          const auto c = reference::energy_compliance_quadrature(
              pair, steel[static_cast<std::size_t>(gear)], gear, s,
              reference::QuadBeamStart::trochoid, {}, pair.face_width);
          sum += c.bending + c.shear + c.axial;
        }
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_StiffnessSpurCycle_baseline)->Unit(benchmark::kMillisecond);

void BM_StiffnessHelicalCycle(benchmark::State& state) {
  const geometry::GearPairGeometry g(seed003(15.0));
  stiffness::MeshStiffnessOptions o;
  o.positions = 360;
  o.path_points = 2;
  o.slices = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const stiffness::MeshStiffness solver(g, steel, o);
    benchmark::DoNotOptimize(solver.solve().mean);
  }
  state.counters["slices"] = static_cast<double>(o.slices);
}
BENCHMARK(BM_StiffnessHelicalCycle)->Arg(50)->Unit(benchmark::kMillisecond);

}  // namespace
