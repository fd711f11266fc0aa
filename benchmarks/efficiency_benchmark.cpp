// Efficiency benchmarks: static mesh efficiency over one mesh period
//  - spur (seed 004, 22/32) with 200 positions, Xu–Kahraman friction and film, against the
//    same integration with a constant μ (BM_EfficiencySpur over BM_EfficiencySpur_baseline:
//    the cost of the regression and the film per contact point);
//  - helical (the seed 000 herringbone pair, both halves) with 200 positions × every contact
//    line × 20 points, mixed friction, against constant μ;
//  - one contact's friction coefficient from the regression against the EHL solver's
//    (BM_ContactFriction over BM_ContactFriction_baseline: regression time / EHL time, the
//    saving that makes a regression usable inside the loss integral);
//  - seed 004's path (cases/efficiency_seed004_ehl_thermal.json, 40 positions and the mean's
//    Gauss points) with the thermal Ree–Eyring law "ehl_thermal" against the isothermal "ehl"
//    law with the same τ0 (BM_EfficiencySeed004EhlThermal over its _baseline: the cost of the
//    thermal film per path, measured in the same run). A fresh MeshLoss per iteration, so the
//    laws' memory of solved contacts does not answer.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "efficiency/ehl_friction.h"
#include "efficiency/mesh_loss.h"
#include "ehl/line_contact_solver.h"
#include "lubricant/friction_laws.h"
#include "model/case_reader.h"
#include "model/json_reader.h"
#include "support/test_support.h"

namespace {

using namespace gearbench;

constexpr double rpm = std::numbers::pi / 30.0;
const model::Material steel{206e9, 0.3, 7850};

efficiency::MeshLossMedia media(double viscosity, double alpha) {
  model::Lubricant oil;
  oil.viscosity = viscosity;
  oil.pressure_viscosity = alpha;
  return {std::array<model::Material, 2>{steel, steel}, oil};
}

model::GearPair seed000_pair() {
  auto p = testing_support::spur_pair(17, 44, 6.0, 18.334317, 55.0);
  p.helix_angle = 24.43 * std::numbers::pi / 180.0;
  p.herringbone = model::Herringbone{0.058};
  return p;
}

void run_mesh_loss(benchmark::State& state, const model::GearPair& pair, const model::OperatingPoint& op,
                   lubricant::FrictionModel law, const efficiency::MeshLossMedia& m) {
  const geometry::GearPairGeometry g(pair);
  efficiency::MeshLossOptions o;
  o.friction_model = law;
  o.positions = 200;
  o.points_per_line = 20;
  const efficiency::MeshLoss solver(g, op, o, m);
  for (auto _ : state) benchmark::DoNotOptimize(solver.solve().efficiency_mean);
  state.counters["positions_per_s"] = benchmark::Counter(200.0 * static_cast<double>(state.iterations()),
                                                         benchmark::Counter::kIsRate);
}

const model::OperatingPoint seed004_op{1000 * rpm, 100.0, 313.15, {0.4e-6, 0.4e-6}};
const model::OperatingPoint seed000_op{2000 * rpm, 309.09, 313.15, {0.4e-6, 0.4e-6}};

void BM_EfficiencySpur(benchmark::State& state) {
  run_mesh_loss(state, testing_support::seed004_pair(), seed004_op, lubricant::FrictionModel::xu_kahraman,
                media(0.08, 24.8e-9));
}
BENCHMARK(BM_EfficiencySpur)->Unit(benchmark::kMillisecond);

void BM_EfficiencySpur_baseline(benchmark::State& state) {
  run_mesh_loss(state, testing_support::seed004_pair(), seed004_op, lubricant::FrictionModel::constant, {});
}
BENCHMARK(BM_EfficiencySpur_baseline)->Unit(benchmark::kMillisecond);

void BM_EfficiencyHelical(benchmark::State& state) {
  run_mesh_loss(state, seed000_pair(), seed000_op, lubricant::FrictionModel::mixed, media(0.044, 22e-9));
}
BENCHMARK(BM_EfficiencyHelical)->Unit(benchmark::kMillisecond);

void BM_EfficiencyHelical_baseline(benchmark::State& state) {
  run_mesh_loss(state, seed000_pair(), seed000_op, lubricant::FrictionModel::constant, {});
}
BENCHMARK(BM_EfficiencyHelical_baseline)->Unit(benchmark::kMillisecond);

/// Seed 004 contact a tenth of the way from A to the pitch point, half the load (double
/// contact): SR ≈ 0.6, so both the regression and the EHL traction see real sliding.
struct ContactSetup {
  ContactSetup() {
    const geometry::GearPairGeometry g(testing_support::seed004_pair());
    const double s = g.path().A + 0.1 * (g.path().C - g.path().A);
    const auto k = g.kinematics(s, seed004_op.pinion_speed);
    data.reduced_radius = k.reduced_radius;
    data.load_per_length = 0.5 * seed004_op.pinion_torque / g.radii(0).base / g.pair().face_width;
    data.u1 = k.u1;
    data.u2 = k.u2;
    data.reduced_modulus = steel.youngs_modulus / (1.0 - steel.poisson_ratio * steel.poisson_ratio);  // equal steels
    data.viscosity = 0.08;
    data.pressure_viscosity = 24.8e-9;
    data.roelands_z = 0.68;
    state.load_per_length = data.load_per_length;
    state.reduced_radius = data.reduced_radius;
    state.u1 = k.u1;
    state.u2 = k.u2;
    state.hertz_pressure = std::sqrt(data.load_per_length * data.reduced_modulus / (2.0 * M_PI * data.reduced_radius));
    state.viscosity = 0.08;
    state.roughness_Ra = 0.4e-6;
  }
  ehl::LineContactData data;
  lubricant::ContactState state;
};

void BM_ContactFriction(benchmark::State& state) {
  const ContactSetup s;
  for (auto _ : state) benchmark::DoNotOptimize(lubricant::xu_kahraman(lubricant::XuKahramanInputs::from_si(s.state)));
}
BENCHMARK(BM_ContactFriction)->Unit(benchmark::kMicrosecond);

/// The "ehl" law at the same contact: isothermal EHL (161 nodes) with Eyring traction, a
/// fresh law each time so that its memory of solved contacts does not answer.
void BM_ContactFriction_baseline(benchmark::State& state) {
  const ContactSetup s;
  for (auto _ : state) benchmark::DoNotOptimize(efficiency::EhlFriction(s.data, 5e6).coefficient(s.state));
}
BENCHMARK(BM_ContactFriction_baseline)->Unit(benchmark::kMillisecond);

/// The seed 004 case of the thermal law, read once.
struct Seed004Thermal {
  Seed004Thermal() {
    const auto j = model::read_json_file(std::string(GEARBENCH_SOURCE_DIR) + "/cases/efficiency_seed004_ehl_thermal.json");
    model::ObjectReader root(j, "");
    c = model::read_gear_case(root);
    efficiency::MeshLossOptions::table().read(root, options);
  }
  model::GearCase c;
  efficiency::MeshLossOptions options;
};

void run_seed004_path(benchmark::State& state, lubricant::FrictionModel law) {
  static const Seed004Thermal s;
  const geometry::GearPairGeometry g(s.c.gear_pair);
  auto o = s.options;
  o.friction_model = law;
  if (law == lubricant::FrictionModel::ehl) o.eyring_stress = s.c.lubricant->eyring_stress;
  int solves = 0;
  for (auto _ : state) {
    const efficiency::MeshLoss loss(g, *s.c.operating, o, {s.c.materials, s.c.lubricant});
    benchmark::DoNotOptimize(loss.solve().efficiency_min);
    solves = loss.ehl_solves();
  }
  state.counters["contact_solves"] = solves;
}

void BM_EfficiencySeed004EhlThermal(benchmark::State& state) {
  run_seed004_path(state, lubricant::FrictionModel::ehl_thermal);
}
BENCHMARK(BM_EfficiencySeed004EhlThermal)->Unit(benchmark::kSecond);

void BM_EfficiencySeed004EhlThermal_baseline(benchmark::State& state) {
  run_seed004_path(state, lubricant::FrictionModel::ehl);
}
BENCHMARK(BM_EfficiencySeed004EhlThermal_baseline)->Unit(benchmark::kSecond);

}  // namespace
