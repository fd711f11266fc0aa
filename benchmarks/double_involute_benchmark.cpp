// Double-involute pair of seed 002 (the pair, rack and oil of
// cases/seed002_double_involute_oil_film.json). Side-by-side ratios:
//  - BM_DoubleInvoluteContactLines/24 over its _baseline/24: the clipped contact lines of
//    solvers/geometry against the direct flank construction of reference/construction at
//    the same 24 instants of a mesh period (the speed-up of the closed form);
//  - BM_DoubleInvoluteOilFilmPeriod over its _baseline: the film stiffness over the whole
//    mesh period (8 instants, 2 Gauss points per piece, two EHL solves per point) of the
//    stepped pair against the ordinary involute pair with the same data (whose longer lines,
//    split at the pitch point into its two zones, take more solves: 120 against 104).
// The benchmarks keep their results alive with DoNotOptimize on the whole result object: on
// one double member of an lvalue (Google Benchmark 1.7.1, GCC 12, -O2) it overwrote the member
// (mean_film_stiffness read 1e-313 … 1e-14 instead of 1.51e11 N/m, fourteenth session).
#include <benchmark/benchmark.h>

#include <cmath>

#include "construction/double_involute_contact.h"
#include "ehl/oil_film_stiffness.h"
#include "geometry/double_involute.h"
#include "support/test_support.h"

namespace {

using namespace gearbench;

model::GearPair pair() {
  auto p = testing_support::spur_pair(25, 38, 3.0, 20.0, 40.0);
  p.helix_angle = 15.0 * M_PI / 180.0;
  return p;
}

model::DoubleInvoluteRack rack() { return {0.1, 0.1, 0.05, 0.3}; }

void BM_DoubleInvoluteContactLines(benchmark::State& state) {
  const geometry::GearPairGeometry g(pair());
  const geometry::DoubleInvolutePair di(g, rack());
  const auto n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += di.contact_line_length((i + 0.5) / n * g.base_pitch_transverse());
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_DoubleInvoluteContactLines)->Arg(24)->Unit(benchmark::kMicrosecond);

void BM_DoubleInvoluteContactLines_baseline(benchmark::State& state) {
  const reference::DoubleInvoluteConstruction construction(pair(), rack());
  const geometry::GearPairGeometry g(pair());
  const auto n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
      sum += construction
                 .at(construction.engagement_angle() +
                     (i + 0.5) / n * g.base_pitch_transverse() / construction.base_radius_pinion())
                 .total_length;
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_DoubleInvoluteContactLines_baseline)->Arg(24)->Unit(benchmark::kMicrosecond);

void oil_film_period(benchmark::State& state, const model::DoubleInvoluteRack& r) {
  const geometry::GearPairGeometry g(pair());
  const geometry::DoubleInvolutePair di(g, r);
  const std::array<model::Material, 2> steel{model::Material{206e9, 0.3, 7850}, model::Material{206e9, 0.3, 7850}};
  model::Lubricant oil;
  oil.viscosity = 0.03;
  oil.pressure_viscosity = 20e-9;
  model::OperatingPoint op;
  op.pinion_speed = 1000.0 * M_PI / 30.0;
  op.pinion_torque = 200.0;
  ehl::MeshPeriodOilFilmOptions o;
  o.samples = 8;
  o.points_per_piece = 2;
  const ehl::MeshPeriodOilFilm film(di, op, ehl::LineContactData::from_gear_media(steel, oil), o);
  ehl::MeshPeriodOilFilmResult result;
  for (auto _ : state) {
    result = film.solve();
    benchmark::DoNotOptimize(result);
  }
  state.counters["ehl_solves"] = result.solves;
  state.counters["mean_film_stiffness_N_per_um"] = result.mean_film_stiffness * 1e-6;
}

void BM_DoubleInvoluteOilFilmPeriod(benchmark::State& state) { oil_film_period(state, rack()); }
BENCHMARK(BM_DoubleInvoluteOilFilmPeriod)->Unit(benchmark::kMillisecond);  // one iteration: ~5 s CPU

void BM_DoubleInvoluteOilFilmPeriod_baseline(benchmark::State& state) { oil_film_period(state, {}); }
BENCHMARK(BM_DoubleInvoluteOilFilmPeriod_baseline)->Unit(benchmark::kMillisecond);

}  // namespace
