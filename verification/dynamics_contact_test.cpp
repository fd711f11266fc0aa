// Tests of the friction laws and the contact loss inside the dynamics models
// (docs/dynamics-model.md, "Friction laws" and "Contact loss"): the reference's own
// Benedict–Kelley against the production law, the ISO and mixed laws, the helical arms'
// interpolation between load levels, a heavily loaded pair whose contact is never
// lost (no root fires, the result is the linear model's bit for bit), and the herringbone
// pair whose mesh-in impact pulls its mesh force below zero unless contact may be lost.
// Also the integrators under the march (solvers/dynamics/integrator.h): every method of the
// work–precision study on an oscillator with a restart, the method keys, and the compiled
// serial vector kernels against SUNDIALS' own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "checks/dynamics_reference.h"
#include "dynamics/integrator.h"
#include "dynamics/serial_kernels.h"
#include "model/errors.h"
#include "dynamics/pair_friction.h"
#include "dynamics/response_analysis.h"
#include "efficiency/mesh_loss.h"
#include "support/test_support.h"

namespace gearbench {
namespace {

using verification::spur6_reference;

const std::array<model::Material, 2> steel{model::Material{212e9, 0.289, 7850}, model::Material{212e9, 0.289, 7850}};
// Seed 003's operating point (cases/seed003_spur_dynamics.json) with flanks of Ra 0.4 µm.
const model::OperatingPoint seed003_operating{996.0 * std::numbers::pi / 30.0, 50.0, 313.15, {0.4e-6, 0.4e-6}};
// The oil of cases/seed000_herringbone_dynamics.json.
const model::Lubricant oil{0.044, 22e-9, {}, {}, {}, {}, {}, {}};

// The production law (solvers/lubricant through dynamics::PairFriction) and the reference's
// own Benedict–Kelley, coded from the published imperial form, along the path and over two
// decades of load. They differ by the SI constant only: 29.66 against 3.17e8·0.0254³/175.127
// = 29.6626, a factor 1.00009 in the logarithm's argument, i.e. 5e-7 in μ.
TEST(DynamicsFriction, ReferenceBenedictKelleyMatchesTheProductionLaw) {
  const geometry::GearPairGeometry g(testing_support::seed003_pair());
  dynamics::Spur6Options o;
  o.friction.friction_model = lubricant::FrictionModel::benedict_kelley;
  o.friction.lubricant = oil;
  const dynamics::PairFriction production(g, steel, seed003_operating, o.friction);
  const dynamics::Spur6Dynamics d(g, steel, seed003_operating, o);
  auto p = spur6_reference(d);
  p.benedict_kelley = reference::Spur6Parameters::BenedictKelley{oil.viscosity, 0.4e-6, g.pair().face_width};
  double worst = 0.0, smallest = 1.0, largest = 0.0;
  for (int i = 0; i <= 40; ++i) {
    const double s = p.A + (p.E - p.A) * i / 40.0;
    for (const double w : {1e4, 1e5, 1e6}) {
      const double mu = production.coefficient(s, w);
      worst = std::max(worst, std::abs(mu - reference::spur6_benedict_kelley(p, s, w)));
      smallest = std::min(smallest, mu);
      largest = std::max(largest, mu);
    }
  }
  std::printf("[ measured ] Benedict–Kelley μ from %.4f to %.4f on the path; largest difference %.2e\n", smallest,
              largest, worst);
  EXPECT_LT(worst, 2e-6);
  EXPECT_LT(smallest, largest);  // the law is not a constant along the path
}

// ISO/TR 14179-2 is a mean coefficient of the pair (the efficiency solver's, at its nominal
// load): the same μ at every contact and load. The mixed law blends the full-film
// Xu–Kahraman coefficient with μ_BL by the fluid share of the film: it lies between them.
TEST(DynamicsFriction, IsoIsTheMeanCoefficientAndMixedLiesBetweenItsLaws) {
  const geometry::GearPairGeometry g(testing_support::seed003_pair());
  auto with = [&](lubricant::FrictionModel model) {
    dynamics::FrictionLawOptions law;
    law.friction_model = model;
    law.lubricant = oil;
    return dynamics::PairFriction(g, steel, seed003_operating, law);
  };
  efficiency::MeshLossOptions iso_options;
  iso_options.friction_model = lubricant::FrictionModel::iso14179;
  const double iso_mu =
      efficiency::MeshLoss(g, seed003_operating, iso_options, {steel, oil}).iso14179_coefficient();
  const auto iso = with(lubricant::FrictionModel::iso14179), mixed = with(lubricant::FrictionModel::mixed),
             full_film = with(lubricant::FrictionModel::xu_kahraman);
  const auto& path = g.path();
  for (const double s : {path.A, 0.5 * (path.A + path.C), 0.5 * (path.C + path.E), path.E})
    for (const double w : {1e3, 1e5, 1e6}) {
      EXPECT_EQ(iso.coefficient(s, w), iso_mu);
      const double lo = std::min(full_film.coefficient(s, w), 0.1), hi = std::max(full_film.coefficient(s, w), 0.1);
      EXPECT_GE(mixed.coefficient(s, w), lo);
      EXPECT_LE(mixed.coefficient(s, w), hi);
    }
}

// The helical arms under a friction law are interpolated linearly between the load levels
// (l/4)·F_nom. A second half mesh whose nominal force is 1.125·F_nom has a table at exactly
// that force (its level 4): against it the interpolation midway between levels 4 and 5 of the
// first shows its error. For μ ∝ w^0.52 (Xu–Kahraman: P_h^1.03 with P_h ∝ √w) the midpoint
// error of linear interpolation on [1, 1.25] is 1.6e-3 of the value; twice that, 3e-3 of the
// largest arm, leaves room for the law's exponential terms in P_h.
TEST(DynamicsFriction, HelicalArmsInterpolateBetweenLoadLevels) {
  model::GearPair pair;
  pair.teeth = {17, 44};
  pair.normal_module = 6e-3;
  pair.normal_pressure_angle = 18.334317 * std::numbers::pi / 180.0;
  pair.helix_angle = 24.43 * std::numbers::pi / 180.0;
  pair.face_width = 55e-3;
  pair.herringbone = model::Herringbone{58e-3};
  const geometry::GearPairGeometry g(pair);
  const std::array<model::Material, 2> s0{model::Material{206e9, 0.3, 7850}, model::Material{206e9, 0.3, 7850}};
  dynamics::HalfMeshOptions o;
  o.slices = 40;
  o.positions = 180;
  o.friction.friction_model = lubricant::FrictionModel::xu_kahraman;
  o.friction.lubricant = oil;
  model::OperatingPoint operating{2000.0 * std::numbers::pi / 30.0, 309.09, 313.15, {0.4e-6, 0.4e-6}};
  const double nominal = operating.pinion_torque / 2.0 / (g.radii(0).base * std::cos(g.base_helix_angle()));
  const dynamics::HalfMesh coarse(g, s0, operating, o);
  operating.pinion_torque *= 1.125;
  const dynamics::HalfMesh exact(g, s0, operating, o);
  const double force = 1.125 * nominal;  // midway between levels 4 and 5 of `coarse`, level 4 of `exact`
  double worst = 0.0, largest = 0.0;
  for (int i = 0; i < 100; ++i) {
    const double t = coarse.period() * i / 100.0;
    const auto a = coarse.arms(t, t, force), b = exact.arms(t, t, force);
    worst = std::max({worst, std::abs(a[0] - b[0]), std::abs(a[1] - b[1])});
    largest = std::max({largest, std::abs(b[0]), std::abs(b[1])});
  }
  std::printf("[ measured ] arms midway between load levels: largest deviation %.2e of the largest arm %.3e m\n",
              worst / largest, largest);
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(worst / largest, 3e-3);
}

// The seed 003 pair under its 50 N·m: the static deflection (~25 µm) dwarfs the dynamic
// fluctuation, δ and δ + τδ̇ stay positive, no contact function has a root and the run with
// a 100 µm backlash is the linear model's bit for bit (the root functions do not alter
// CVODE's steps).
TEST(DynamicsContactLoss, NoRootFiresUnderAHeavyLoadAndTheResultIsTheLinearOne) {
  const geometry::GearPairGeometry g(testing_support::seed003_pair());
  dynamics::Spur6Options o;
  o.runup_cycles = 10;
  o.record_cycles = 4;
  const auto linear = dynamics::Spur6Dynamics(g, steel, seed003_operating, o).solve();
  o.backlash = 100e-6;
  const auto lossy = dynamics::Spur6Dynamics(g, steel, seed003_operating, o).solve();
  std::printf("[ measured ] heavy load: %ld roots, δ from %.3e to %.3e m\n", lossy.contact_events,
              lossy.te.mean - 0.5 * lossy.te.peak_to_peak, lossy.te.mean + 0.5 * lossy.te.peak_to_peak);
  EXPECT_EQ(lossy.contact_events, 0);
  EXPECT_EQ(lossy.contact_loss_fraction, 0.0);
  EXPECT_EQ(lossy.transmission_error, linear.transmission_error);
  EXPECT_EQ(lossy.mesh_force, linear.mesh_force);
  EXPECT_EQ(lossy.steps, linear.steps);
}


// y'' = −ω²·y from y = 1 over two periods, restarted after the first (as the march does at a
// break time): every method lands on cos(ω·t) within its tolerance, and the work done before
// the restart is still counted after it (CVodeReInit zeroes the package's counters).
TEST(DynamicsIntegrator, EveryMethodFollowsAnOscillatorAcrossARestart) {
  const double omega = 2.0 * std::numbers::pi * 50.0, period = 0.02;
  for (const auto& m : dynamics::integrator_methods()) {
    dynamics::IntegratorOptions o;
    o.method = m.method;
    o.relative_tolerance = 1e-9;
    o.absolute_tolerance = 1e-12;
    const auto integrator = dynamics::make_integrator(2, [omega](double, const double* y, double* dy) {
      dy[0] = y[1];
      dy[1] = -omega * omega * y[0];
    }, o);
    integrator->reset(0.0, {1.0, 0.0});
    const auto half = integrator->advance(period, period);
    const long steps = integrator->steps();
    integrator->reset(period, half);
    const auto& y = integrator->advance(2.0 * period - 0.25 * period, 2.0 * period);
    EXPECT_NEAR(y[0], std::cos(omega * 1.75 * period), 1e-6) << m.key;  // 1e-9 per step, ~1e3 steps
    EXPECT_GT(integrator->steps(), steps) << m.key;
    EXPECT_GT(integrator->rhs_evaluations(), integrator->steps()) << m.key;
  }
}

// A falling body dropped at 1 m: rk8pd (whose roots are located by gsl_integrator.cpp, not
// by the package) stops at the root of g = y, at t = √(2/g₀), returns the state there, and a
// restart there does not find the same root again.
TEST(DynamicsIntegrator, Rk8pdStopsAtARootAndRestartsPastIt) {
  const double g0 = 9.81, t_root = std::sqrt(2.0 / g0);
  const auto falling = [g0](double, const double* y, double* dy) { dy[0] = y[1], dy[1] = -g0; };
  dynamics::IntegratorOptions o;  // the default: rk8pd
  o.relative_tolerance = 1e-10;
  const auto integrator = dynamics::make_integrator(2, falling, o);
  integrator->set_roots(1, [](double, const double* y, double* g) { g[0] = y[0]; });
  integrator->reset(0.0, {1.0, 0.0});
  const std::vector<double> at = integrator->advance(1.0, 1.0);
  ASSERT_TRUE(integrator->at_root());
  EXPECT_NEAR(integrator->time(), t_root, 1e-8);
  EXPECT_NEAR(at[0], 0.0, 1e-8);
  EXPECT_LE(at[0], 0.0);  // just past the root
  integrator->reset(integrator->time(), at);
  long events = 0;
  const auto& y = integrator->advance_across_roots(1.0, 1.0, 1e-12, events);
  EXPECT_EQ(events, 0);
  EXPECT_NEAR(y[0], 1.0 - 0.5 * g0, 1e-7);
}

// An exception of the right-hand side reaches the caller through GSL's C frames.
TEST(DynamicsIntegrator, Rk8pdPassesOnTheRightHandSidesException) {
  const auto integrator = dynamics::make_integrator(1, [](double t, const double*, double* dy) {
    if (t > 0.5) throw InputError("right-hand side refused");
    dy[0] = 1.0;
  }, dynamics::IntegratorOptions{});
  integrator->reset(0.0, {0.0});
  EXPECT_THROW((void)integrator->advance(1.0, 1.0), InputError);
}

TEST(DynamicsIntegrator, MethodKeysAreTheOfferedOnesAndABadKeyNamesTheAllowedOnes) {
  const auto read = [](const char* method) {
    const nlohmann::json section = {{"method", method}};
    model::ObjectReader r(section, "integrator");
    dynamics::IntegratorOptions o;
    dynamics::IntegratorOptions::table().read(r, o);
    return o.method;
  };
  EXPECT_EQ(read("dormand_prince"), dynamics::IntegratorMethod::dormand_prince);
  EXPECT_EQ(read("adams"), dynamics::IntegratorMethod::adams);
  EXPECT_EQ(read("rk8pd"), dynamics::IntegratorMethod::rk8pd);
  EXPECT_EQ(dynamics::IntegratorOptions{}.method, dynamics::IntegratorMethod::rk8pd);
  for (const char* refused : {"rk45", "verner", "fehlberg"}) {
    const auto message = testing_support::input_error_of([&] { (void)read(refused); });
    EXPECT_NE(message.find("integrator.method"), std::string::npos) << message;
    EXPECT_NE(message.find("dormand_prince"), std::string::npos) << message;
  }
  dynamics::IntegratorOptions o;
  o.relative_tolerance = 0.5;
  EXPECT_EQ(testing_support::input_error_of([&] { o.validate(); }),
            "integrator.rtol = 0.5: allowed range is [1e-14, 0.01]");
}

// The compiled kernels must be SUNDIALS' own operations, including a result that aliases
// the first input (the packages update vectors in place that way).
TEST(DynamicsIntegrator, SerialKernelsComputeWhatSundialsComputes) {
  SUNContext context = nullptr;
  ASSERT_EQ(SUNContext_Create(nullptr, &context), 0);
  constexpr sunindextype n = 15;
  N_Vector own = N_VNew_Serial(n, context), ours = N_VNew_Serial(n, context);
  N_VEnableFusedOps_Serial(own, SUNTRUE);
  N_VEnableFusedOps_Serial(ours, SUNTRUE);
  dynamics::install_serial_kernels(ours);
  auto run = [&](N_Vector base) {
    std::vector<N_Vector> v{N_VClone(base), N_VClone(base), N_VClone(base)};
    for (sunindextype i = 0; i < n; ++i)
      for (std::size_t j = 0; j < 3; ++j) NV_DATA_S(v[j])[i] = std::sin(1.0 + static_cast<double>(i) * (j + 1.5)) - 0.2;
    realtype c[3] = {0.5, -2.0, 3.25};
    N_VLinearCombination(3, c, v.data(), v[0]);  // in place
    N_VLinearSum(1.5, v[0], -0.25, v[1], v[2]);
    N_VAbs(v[2], v[1]);
    N_VAddConst(v[1], 0.1, v[1]);
    N_VInv(v[1], v[1]);
    std::vector<double> out(NV_DATA_S(v[0]), NV_DATA_S(v[0]) + n);
    out.insert(out.end(), NV_DATA_S(v[1]), NV_DATA_S(v[1]) + n);
    out.push_back(N_VWrmsNorm(v[0], v[1]));
    out.push_back(N_VMaxNorm(v[2]));
    for (N_Vector x : v) N_VDestroy(x);
    return out;
  };
  const auto a = run(own), b = run(ours);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-14 * std::max(1.0, std::abs(a[i]))) << i;
  N_VDestroy(own);
  N_VDestroy(ours);
  SUNContext_Free(&context);
}

}  // namespace
// The energy balance's relative residual is over the dissipation; with nothing dissipated it
// is over the largest other term, and 0 when every term is 0 (issue 20: once 0/0, exit 1).
TEST(DynamicsEnergyBalance, RelativeResidualIsFiniteWithoutDissipation) {
  dynamics::EnergyBalance e;
  EXPECT_EQ(e.relative_residual(), 0.0);
  e.input = 10.0;
  e.output = 8.0;
  e.damping = 1.5;
  e.friction = 0.5;
  e.energy_change = 0.1;
  EXPECT_DOUBLE_EQ(e.relative_residual(), 0.1 / 2.0);
  e.damping = e.friction = 0.0;
  e.energy_change = 2.0 + 0.5;
  EXPECT_DOUBLE_EQ(e.relative_residual(), 0.5 / 10.0);
}

}  // namespace gearbench
