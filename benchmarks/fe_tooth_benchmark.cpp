// FE against energy method: the time for one mesh position (both teeth and the pair) of the
// seed 003 pair. BM_PairComplianceOnePosition is the energy method (solvers/stiffness);
// its _baseline is the deal.II FE reference at the converged mesh (Kelly cycles to the
// 0.5 % criterion, plane stress), whose ratio is the speed-up that justifies the energy
// method. The gear meshes (gmsh) are built once, outside the timed loop, as the kind does.
// BM_CrackedPairCompliance is the same with seed 003's 2.5 mm pitch crack in the pinion at
// A + p_b (the energy method's limiting line against the FE slit: its healthy companion
// solve and the slit solve of the pinion, and the wheel).
#include <benchmark/benchmark.h>

#include <cmath>

#include "fe_tooth/fe_tooth_stiffness.h"
#include "stiffness/pair_stiffness.h"
#include "support/test_support.h"

namespace {

using namespace gearbench;

const std::array<model::Material, 2> steel{model::Material{212e9, 0.289, 7850},
                                           model::Material{212e9, 0.289, 7850}};

void BM_PairComplianceOnePosition(benchmark::State& state) {
  const geometry::GearPairGeometry g(testing_support::seed003_pair());
  const stiffness::PairStiffness pair(g, steel, stiffness::ToothModel{},
                                      {0.5 * g.radii(0).root, 0.5 * g.radii(1).root}, std::nullopt, true);
  const double s = 0.5 * (g.path().A + g.path().E);
  for (auto _ : state) benchmark::DoNotOptimize(pair.compliance(s).total());
}
BENCHMARK(BM_PairComplianceOnePosition)->Unit(benchmark::kMicrosecond);

void BM_PairComplianceOnePosition_baseline(benchmark::State& state) {
  reference::fe::FeToothOptions o;
  o.plane_stress = true;
  const reference::fe::FeToothStiffness fe(testing_support::seed003_pair(), steel, o);
  const double s = 0.5 * (fe.path().A + fe.path().E);
  for (auto _ : state) benchmark::DoNotOptimize(fe.at(s).pair_stiffness);
}
// One iteration: a solve takes seconds, and its cost does not vary between runs.
BENCHMARK(BM_PairComplianceOnePosition_baseline)->Unit(benchmark::kMillisecond);  // one iteration: ~6 s

const double crack_angle = 45.0 * M_PI / 180.0;  // seed 003, section 1.3

void BM_CrackedPairCompliance(benchmark::State& state) {
  const geometry::GearPairGeometry g(testing_support::seed003_pair());
  const stiffness::GearCrack crack{{stiffness::Crack::Type::pitch, 2.5e-3, crack_angle}, 0};
  const stiffness::PairStiffness pair(g, steel, stiffness::ToothModel{},
                                      {0.5 * g.radii(0).root, 0.5 * g.radii(1).root}, crack, true);
  const double s = g.path().A + g.base_pitch_transverse();
  for (auto _ : state) benchmark::DoNotOptimize(pair.compliance(s).total());
}
BENCHMARK(BM_CrackedPairCompliance)->Unit(benchmark::kMicrosecond);

void BM_CrackedPairCompliance_baseline(benchmark::State& state) {
  reference::fe::FeToothOptions o;
  o.plane_stress = true;
  o.crack = reference::fe::ToothCrack{0, 2.5e-3, crack_angle};
  const reference::fe::FeToothStiffness fe(testing_support::seed003_pair(), steel, o);
  const double s = fe.path().A + fe.path().base_pitch;
  for (auto _ : state) benchmark::DoNotOptimize(fe.at(s).pair_stiffness);
}
BENCHMARK(BM_CrackedPairCompliance_baseline)->Unit(benchmark::kMillisecond);  // one iteration: ~10 s

}  // namespace
