// Thermal EHL (issue #4): one sliding contact and seed 001's whole path (A, AB, B, C, D, DE,
// E) with the default grids (641 nodes, 10 across the film, 14 in each solid), each against
// the isothermal solution of the same contacts as its baseline (the side-by-side ratio is the
// price of the temperature field), and the sliding contact with a Ree–Eyring film (issue 26:
// ≤ 10× its isothermal solve). Target: the whole path under 2 s.
#include <benchmark/benchmark.h>

#include "ehl/thermal_mesh_path.h"
#include "model/case_reader.h"
#include "model/json_reader.h"
#include "support/thermal_fixtures.h"

namespace {

using namespace gearbench;

model::ThermalPathCase seed001() {
  const auto j = model::read_json_file(std::string(GEARBENCH_SOURCE_DIR) + "/cases/seed001_tehl_path.json");
  model::ObjectReader root(j, "");
  return model::read_thermal_path_case(root);
}

/// The sliding contact of cases/tehl_point_sliding.json (SRR 0.5).
ehl::LineContactData sliding_contact() { return testing_support::sliding_contact(0.5); }
using testing_support::mineral_oil;
model::ThermalSolids steel() { return testing_support::steel_solids(); }

void BM_TehlPoint(benchmark::State& state) {
  const lubricant::ThermalRheology rheology(mineral_oil(), 313.15);
  ehl::ThermalEhlResult r;
  for (auto _ : state) {
    r = ehl::ThermalLineContact(sliding_contact(), rheology, steel(), {}).solve();
    benchmark::DoNotOptimize(r);
  }
  state.counters["thermal_iterations"] = r.iterations;
  state.counters["work_units"] = r.work_units;
}
BENCHMARK(BM_TehlPoint)->Unit(benchmark::kMillisecond);

/// The same contact with a Ree–Eyring film (τ0 5 MPa, issue 26): against the same baseline.
void BM_TehlPointEyring(benchmark::State& state) {
  auto oil = mineral_oil();
  oil.eyring_stress = 5e6;
  const lubricant::ThermalRheology rheology(oil, 313.15);
  ehl::ThermalEhlOptions o;
  o.film.rheology = lubricant::ShearRheology::eyring;
  ehl::ThermalEhlResult r;
  for (auto _ : state) {
    r = ehl::ThermalLineContact(sliding_contact(), rheology, steel(), o).solve();
    benchmark::DoNotOptimize(r);
  }
  state.counters["thermal_iterations"] = r.iterations;
  state.counters["work_units"] = r.work_units;
}
BENCHMARK(BM_TehlPointEyring)->Unit(benchmark::kMillisecond);

void BM_TehlPoint_baseline(benchmark::State& state) {
  const lubricant::ThermalRheology rheology(mineral_oil(), 313.15);
  const ehl::ThermalLineContact contact(sliding_contact(), rheology, steel(), {});
  const ehl::LineContactProblem problem(contact.isothermal_data());
  ehl::EhlResult r;
  for (auto _ : state) {
    r = ehl::LineContactSolver(problem, ehl::ThermalEhlOptions{}.grid).solve();
    benchmark::DoNotOptimize(r);
  }
  state.counters["work_units"] = r.work_units;
}
BENCHMARK(BM_TehlPoint_baseline)->Unit(benchmark::kMillisecond);

void BM_TehlPath(benchmark::State& state) {
  const auto c = seed001();
  const geometry::GearPairGeometry g(c.gear_pair);
  const lubricant::ThermalRheology rheology(c.lubricant, c.inlet_temperature);
  const ehl::ThermalMeshPath path(g, c.operating, c.materials, rheology, c.solids, c.load_factors, c.load_sharing, {});
  for (auto _ : state) benchmark::DoNotOptimize(path.run().points.size());
  state.counters["points"] = 7;
}
BENCHMARK(BM_TehlPath)->Unit(benchmark::kMillisecond);

/// The same seven contacts, isothermal at the inlet temperature.
void BM_TehlPath_baseline(benchmark::State& state) {
  const auto c = seed001();
  const geometry::GearPairGeometry g(c.gear_pair);
  const lubricant::ThermalRheology rheology(c.lubricant, c.inlet_temperature);
  const ehl::ThermalMeshPath path(g, c.operating, c.materials, rheology, c.solids, c.load_factors, c.load_sharing, {});
  std::vector<ehl::LineContactData> contacts;
  for (const auto& p : path.contacts())
    contacts.push_back(ehl::ThermalLineContact(p.contact, rheology, c.solids, {}).isothermal_data());
  for (auto _ : state)
    for (const auto& d : contacts) {
      const ehl::LineContactProblem problem(d);
      benchmark::DoNotOptimize(ehl::LineContactSolver(problem, ehl::ThermalEhlOptions{}.grid).solve().h_min);
    }
  state.counters["points"] = 7;
}
BENCHMARK(BM_TehlPath_baseline)->Unit(benchmark::kMillisecond);

}  // namespace
