// Geometry benchmarks. The side-by-side ratio pairs the full geometry (construction,
// feasibility checks and a 101-point profile of curvature and sliding) with its simple
// baseline, the closed-form contact ratio alone, measured in the same run:
// `gearbench bench` reports BM_GeometryProfile / BM_GeometryProfile_baseline.
#include <benchmark/benchmark.h>

#include <cmath>

#include "closed_form/involute_closed_form.h"
#include "geometry/gear_pair_geometry.h"
#include "support/test_support.h"

namespace {

gearbench::model::GearPair seed004() { return gearbench::testing_support::seed004_pair(); }

void BM_GeometryProfile(benchmark::State& state) {
  const auto pair = seed004();
  const int points = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const gearbench::geometry::GearPairGeometry g(pair);
    double sum = 0.0;
    for (int i = 0; i < points; ++i)
      sum += g.kinematics(g.path().A + (g.path().E - g.path().A) * i / (points - 1), 100.0).slide_to_roll;
    benchmark::DoNotOptimize(sum);
  }
  state.counters["points"] = points;
  state.SetItemsProcessed(state.iterations() * points);
}
BENCHMARK(BM_GeometryProfile)->Arg(101);

void BM_GeometryProfile_baseline(benchmark::State& state) {
  const auto pair = seed004();
  for (auto _ : state) {
    auto r = gearbench::reference::involute_closed_form(pair);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_GeometryProfile_baseline);

void BM_HelicalContactLines(benchmark::State& state) {
  auto pair = seed004();
  pair.helix_angle = 15.0 * M_PI / 180.0;
  const gearbench::geometry::GearPairGeometry g(pair);
  const int positions = static_cast<int>(state.range(0));
  for (auto _ : state) {
    double sum = 0.0;
    for (int i = 0; i < positions; ++i)
      sum += g.contact_line_length(g.path().A + g.base_pitch_transverse() * i / positions);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * positions);
}
BENCHMARK(BM_HelicalContactLines)->Arg(1000);

}  // namespace

BENCHMARK_MAIN();
