// Unit tests of the mesh-loss integration (solvers/efficiency/mesh_loss) and of the dynamic
// efficiency (solvers/efficiency/dynamic_efficiency): the sign of the loss for every law and
// operating point with either gear driving, identities of the integration, and the
// interpolation of loss-versus-load curves.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "dynamics/spur6_dynamics.h"
#include "efficiency/dynamic_efficiency.h"
#include "efficiency/efficiency_sweep.h"
#include "efficiency/ehl_friction.h"
#include "efficiency/mesh_loss.h"
#include "support/test_support.h"

namespace gearbench {
namespace {

using efficiency::MeshLoss;
using efficiency::MeshLossMedia;
using efficiency::MeshLossOptions;
using lubricant::FrictionModel;

constexpr double rpm = std::numbers::pi / 30.0;

/// Seed 004's steel and oil (E 206 GPa, η0 0.08 Pa·s, α 24.8/GPa); ν 0.3 assumed.
MeshLossMedia seed004_media() {
  model::Lubricant oil;
  oil.viscosity = 0.08;
  oil.pressure_viscosity = 24.8e-9;
  const model::Material steel{206e9, 0.3, 7850};
  return {std::array<model::Material, 2>{steel, steel}, oil};
}

model::OperatingPoint operating(double speed_rpm, double torque, double ra_um = 0.4) {
  return {speed_rpm * rpm, torque, 313.15, {ra_um * 1e-6, ra_um * 1e-6}};
}

struct Drive {
  model::GearPair pair;
  model::OperatingPoint op;
};

/// The seed 004 drive with the pinion (22 teeth) or the wheel (32 teeth) driving: the
/// driving gear is gear 1, torque and speed follow from the same transmitted power.
Drive seed004_drive(bool wheel_drives, double speed_rpm, double torque) {
  if (!wheel_drives) return {testing_support::seed004_pair(), operating(speed_rpm, torque)};
  return {testing_support::spur_pair(32, 22, 2.0, 25.0, 20.0),
          operating(speed_rpm * 22.0 / 32.0, torque * 32.0 / 22.0)};
}

// Table: every friction law × torque 50/100/200 N·m × speed 300/1000/3000 rpm × driver. A
// dissipative law never gives a loss ≤ 0 or an efficiency ≥ 1 at any mesh position.
TEST(MeshLoss, LossesPositiveForEveryLawAndOperatingPoint) {
  int cases = 0;
  for (const auto law : {FrictionModel::constant, FrictionModel::xu_kahraman, FrictionModel::benedict_kelley,
                         FrictionModel::iso14179, FrictionModel::mixed})
    for (const double torque : {50.0, 100.0, 200.0})
      for (const double speed : {300.0, 1000.0, 3000.0})
        for (const bool wheel_drives : {false, true}) {
          const auto d = seed004_drive(wheel_drives, speed, torque);
          const geometry::GearPairGeometry g(d.pair);
          MeshLossOptions o;
          o.friction_model = law;
          o.positions = 40;
          const auto r = MeshLoss(g, d.op, o, seed004_media()).solve();
          for (std::size_t i = 0; i < r.efficiency.size(); ++i) {
            ASSERT_GT(r.sliding_loss[i] + r.rolling_loss[i], 0.0) << lubricant::friction_model_name(law);
            ASSERT_LT(r.efficiency[i], 1.0);
            ASSERT_GT(r.rolling_loss[i], 0.0);
          }
          EXPECT_GT(r.power_loss_mean, 0.0);
          EXPECT_LT(r.efficiency_mean, 1.0);
          ++cases;
        }
  EXPECT_EQ(cases, 90);
}

// With a constant μ Ohlendorf's H_V is symmetric in the two gears (π(u+1)/(z1·u) = π(1+1/u)/z2):
// the wheel-driven drive has the same numeric loss factor and sliding efficiency. The
// integration is exact on each smooth piece, so only rounding separates the two (1e-12).
TEST(MeshLoss, EitherGearDrivingGivesTheSameConstantMuLoss) {
  MeshLossOptions o;
  const auto p = seed004_drive(false, 1000, 100), w = seed004_drive(true, 1000, 100);
  const geometry::GearPairGeometry gp(p.pair), gw(w.pair);
  const auto rp = MeshLoss(gp, p.op, o).solve(), rw = MeshLoss(gw, w.op, o).solve();
  EXPECT_NEAR(rp.loss_factor_numeric, rw.loss_factor_numeric, 1e-12);
  EXPECT_NEAR(rp.efficiency_mean, rw.efficiency_mean, 1e-12);
}

// Stiffness sharing puts less than half the load on a pair entering at A (its tip meets the
// other gear's root where the pair is softest) and the whole load in single contact: the
// mean loss with constant μ differs from Ohlendorf's by the few per cent of the literature
// (Pleguezuelos et al. 2013 report a few per cent), and stays positive.
TEST(MeshLoss, StiffnessSharingIsCloseToEqualSharing) {
  const auto d = seed004_drive(false, 1000, 100);
  const geometry::GearPairGeometry g(d.pair);
  MeshLossOptions equal, stiff;
  stiff.load_sharing = "stiffness";
  stiff.positions = 40;
  const auto re = MeshLoss(g, d.op, equal, seed004_media()).solve();
  const auto rs = MeshLoss(g, d.op, stiff, seed004_media()).solve();
  EXPECT_GT(rs.loss_factor_numeric, 0.0);
  EXPECT_NEAR(rs.loss_factor_numeric / re.loss_factor_numeric, 1.0, 0.15);
  EXPECT_NE(rs.loss_factor_numeric, re.loss_factor_numeric);
}

// The spur mean is Gauss–Legendre on the smooth pieces; for a law that is not polynomial
// along the path (Xu–Kahraman, and the rolling loss) it must still agree with the midpoint
// mean of the series. The midpoint rule errs by up to |jump|·h/2 at each of the two zone
// changes in a period (jumps ≲ the mean, h = p_b/40000): ≤ 4e-5 relative; measured 5e-6.
TEST(MeshLoss, GaussMeanAgreesWithFineMidpointMean) {
  const auto d = seed004_drive(false, 1000, 100);
  const geometry::GearPairGeometry g(d.pair);
  MeshLossOptions o;
  o.friction_model = FrictionModel::xu_kahraman;
  o.positions = 40000;
  const auto r = MeshLoss(g, d.op, o, seed004_media()).solve();
  double sliding = 0.0, rolling = 0.0;
  for (std::size_t i = 0; i < r.sliding_loss.size(); ++i) sliding += r.sliding_loss[i], rolling += r.rolling_loss[i];
  const double n = static_cast<double>(r.sliding_loss.size());
  EXPECT_NEAR(sliding / n, r.sliding_loss_mean, 4e-5 * r.sliding_loss_mean);
  EXPECT_NEAR(rolling / n, r.rolling_loss_mean, 4e-5 * r.rolling_loss_mean);
}

TEST(MeshLoss, LawsNeedTheirData) {
  const auto d = seed004_drive(false, 1000, 100);
  const geometry::GearPairGeometry g(d.pair);
  MeshLossOptions o;
  o.friction_model = FrictionModel::xu_kahraman;
  EXPECT_NE(testing_support::input_error_of([&] { MeshLoss(g, d.op, o); }).find("lubricant: missing"),
            std::string::npos);
  o.friction_model = FrictionModel::iso14179;
  auto smooth = d.op;
  smooth.roughness_Ra = {0.0, 0.0};
  EXPECT_NE(testing_support::input_error_of([&] { MeshLoss(g, smooth, o, seed004_media()); }).find("Ra > 0"),
            std::string::npos);
  o.friction_model = FrictionModel::ehl;
  EXPECT_NE(testing_support::input_error_of([&] { MeshLoss(g, d.op, o, seed004_media()); }).find("eyring_stress_MPa"),
            std::string::npos);
  o.friction_model = FrictionModel::xu_kahraman;
  o.eyring_stress = 5e6;
  EXPECT_NE(testing_support::input_error_of([&] { MeshLoss(g, d.op, o, seed004_media()); }).find("\"ehl\" only"),
            std::string::npos);
}

// The "ehl" law (isothermal EHL film, Eyring traction, τ0 = 5 MPa) with either gear driving:
// losses positive and efficiency below 1 at every position; the friction falls towards the
// pitch point, where the sliding (and so the Couette shear) vanishes, and each distinct
// contact is solved once.
TEST(MeshLoss, EhlLawIsDissipativeAndFallsAtThePitchPoint) {
  for (const bool wheel_drives : {false, true}) {
    const auto d = seed004_drive(wheel_drives, 1000, 100);
    const geometry::GearPairGeometry g(d.pair);
    MeshLossOptions o;
    o.friction_model = FrictionModel::ehl;
    o.eyring_stress = 5e6;
    o.positions = 8;
    const MeshLoss loss(g, d.op, o, seed004_media());
    const auto r = loss.solve();
    for (std::size_t i = 0; i < r.efficiency.size(); ++i) {
      ASSERT_GT(r.sliding_loss[i], 0.0);
      ASSERT_LT(r.efficiency[i], 1.0);
    }
    const double at_A = loss.loss_at(g.path().A + 1e-9).mu, at_C = loss.loss_at(g.path().C).mu;
    EXPECT_LT(at_C, 0.5 * at_A) << "wheel drives: " << wheel_drives;
    const int solves = loss.ehl_solves();
    (void)loss.loss_at(g.path().C);
    EXPECT_EQ(loss.ehl_solves(), solves);  // remembered
  }
}

// The "ehl" law's default grid (161 nodes) against 641 nodes at seed 004 contacts from A to
// near C (half load, the double-contact zone): the traction is an integral of the film and
// pressure and settles early; measured 0.3–0.4 %, held to the 1 % the law's doc promises.
TEST(EhlFriction, DefaultGridWithinOnePercentOfFourTimesFiner) {
  const auto d = seed004_drive(false, 1000, 100);
  const geometry::GearPairGeometry g(d.pair);
  const auto fluid = ehl::LineContactData::from_gear_media(*seed004_media().materials, *seed004_media().lubricant);
  auto fine = efficiency::EhlFriction::default_grid();
  fine.nodes = 641;
  for (double f : {0.0, 0.5, 0.9}) {
    const auto k = g.kinematics(g.path().A + f * (g.path().C - g.path().A), d.op.pinion_speed);
    lubricant::ContactState c;
    c.load_per_length = 0.5 * d.op.pinion_torque / g.radii(0).base / d.pair.face_width;
    c.reduced_radius = k.reduced_radius;
    c.u1 = k.u1;
    c.u2 = k.u2;
    const double coarse_mu = efficiency::EhlFriction(fluid, 5e6).coefficient(c);
    const double fine_mu = efficiency::EhlFriction(fluid, 5e6, fine).coefficient(c);
    EXPECT_NEAR(coarse_mu / fine_mu, 1.0, 0.01) << f;
  }
}

/// Seed 004's media with the thermal data of cases/efficiency_seed004_ehl_thermal.json (mineral
/// oil ρ 870 kg/m³, k 0.14, c 2000, β 0.03 1/K, τ0 5 MPa; steel 46 W/(m·K), 470 J/(kg·K)).
MeshLossMedia seed004_thermal_media() {
  auto m = seed004_media();
  m.lubricant->density = 870.0;
  m.lubricant->thermal_conductivity = 0.14;
  m.lubricant->specific_heat = 2000.0;
  m.lubricant->temperature_viscosity = 0.03;
  m.lubricant->eyring_stress = 5e6;
  for (auto& steel : *m.materials) {
    steel.thermal_conductivity = 46.0;
    steel.specific_heat = 470.0;
  }
  return m;
}

// "ehl_thermal" names each piece of thermal data it lacks, and refuses the "ehl" law's τ0 key
// (its film's τ0 is the lubricant's).
TEST(MeshLoss, ThermalEhlLawNeedsItsData) {
  const auto d = seed004_drive(false, 1000, 100);
  const geometry::GearPairGeometry g(d.pair);
  MeshLossOptions o;
  o.friction_model = FrictionModel::ehl_thermal;
  const auto error_without = [&](const std::function<void(MeshLossMedia&)>& edit) {
    auto m = seed004_thermal_media();
    edit(m);
    return testing_support::input_error_of([&] { MeshLoss(g, d.op, o, m); });
  };
  EXPECT_NE(error_without([](auto& m) { m.lubricant->eyring_stress.reset(); }).find("lubricant.eyring_stress_MPa: missing"),
            std::string::npos);
  EXPECT_NE(error_without([](auto& m) { m.lubricant->density.reset(); }).find("lubricant.density_kg_m3: missing"),
            std::string::npos);
  EXPECT_NE(error_without([](auto& m) { m.lubricant->temperature_viscosity.reset(); })
                .find("temperature_viscosity_1_per_K: missing"),
            std::string::npos);
  EXPECT_NE(error_without([](auto& m) { (*m.materials)[1].specific_heat.reset(); })
                .find("materials.specific_heat_J_per_kgK (gear 2): missing"),
            std::string::npos);
  EXPECT_NE(error_without([](auto& m) { m.lubricant->roelands_z = 0.5; }).find("lubricant.roelands_z = 0.5"),
            std::string::npos);
  EXPECT_NE(error_without([](auto& m) { m.materials.reset(); }).find("materials: missing"), std::string::npos);
  o.eyring_stress = 5e6;
  EXPECT_NE(testing_support::input_error_of([&] { MeshLoss(g, d.op, o, seed004_thermal_media()); })
                .find("lubricant.eyring_stress_MPa"),
            std::string::npos);
  // The "ehl" law's τ0 range, from the one model::Range of its key.
  const auto fluid = ehl::LineContactData::from_gear_media(*seed004_media().materials, *seed004_media().lubricant);
  EXPECT_NE(testing_support::input_error_of([&] { efficiency::EhlFriction(fluid, 2e9); })
                .find("friction.eyring_stress_MPa = 2000: allowed range is (0, 1000] MPa"),
            std::string::npos);
}

// A thermal contact that does not settle is a ConvergenceError naming the law and the contact
// (exit 3 from the CLI), never a NaN in the loss; a settled one is remembered.
TEST(EhlFriction, ThermalContactThatDoesNotSettleIsAnError) {
  const auto d = seed004_drive(false, 1000, 100);
  const geometry::GearPairGeometry g(d.pair);
  const auto m = seed004_thermal_media();
  const auto fluid = ehl::LineContactData::from_gear_media(*m.materials, *m.lubricant);
  const auto media = efficiency::thermal_friction_media(*m.materials, *m.lubricant, d.op.oil_temperature);
  const auto k = g.kinematics(g.path().A + 0.1 * (g.path().E - g.path().A), d.op.pinion_speed);
  lubricant::ContactState c;
  c.load_per_length = 0.5 * d.op.pinion_torque / g.radii(0).base / d.pair.face_width;
  c.reduced_radius = k.reduced_radius;
  c.u1 = k.u1;
  c.u2 = k.u2;
  auto once = efficiency::EhlFriction::default_thermal_options();
  once.max_iterations = 1;
  try {
    (void)efficiency::EhlFriction(fluid, media, once).coefficient(c);
    ADD_FAILURE() << "one thermal iteration reported as converged";
  } catch (const ConvergenceError& e) {
    EXPECT_NE(std::string(e.what()).find("friction.model = \"ehl_thermal\": the thermal EHL solve at w"),
              std::string::npos)
        << e.what();
  }
  const efficiency::EhlFriction law(fluid, media);
  const double mu = law.coefficient(c);
  EXPECT_TRUE(std::isfinite(mu) && mu > 0.0 && mu < 0.2) << mu;
  EXPECT_EQ(law.coefficient(c), mu);
  EXPECT_EQ(law.solves(), 1);
}

// A sweep reports one progress line per point, changes only its own parameter (the base
// point appears in every block with the same figures), and rejects an empty or odd spec.
TEST(EfficiencySweep, OneParameterAtATime) {
  const auto d = seed004_drive(false, 1000, 100);
  MeshLossOptions o;
  o.friction_model = FrictionModel::xu_kahraman;
  o.positions = 20;
  std::vector<std::string> lines;
  const efficiency::SweepSpec spec{{50, 100}, {1000, 2000}, {20, 25}};
  const auto rows = efficiency::efficiency_sweep(d.pair, d.op, o, seed004_media(), spec,
                                                 [&](const std::string& l) { lines.push_back(l); });
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines.front(), "efficiency sweep 1/6: torque_Nm = 50");
  EXPECT_DOUBLE_EQ(rows[1].efficiency_mean, rows[2].efficiency_mean);  // 100 N·m, 1000 rpm, 25° twice
  EXPECT_DOUBLE_EQ(rows[1].efficiency_mean, rows[5].efficiency_mean);
  EXPECT_NE(rows[0].efficiency_mean, rows[1].efficiency_mean);
  EXPECT_NE(testing_support::input_error_of([&] {
              (void)efficiency::efficiency_sweep(d.pair, d.op, o, seed004_media(), {{}, {}, {5.0}});
            }).find("sweep.pressure_angle_deg[0] = 5: allowed range is (10, 40] deg"),
            std::string::npos);
}

// --- Dynamic efficiency ---------------------------------------------------------------------------

/// Times at the midpoints of the phase grid over `cycles` mesh periods, so that the
/// interpolation in phase returns the curve values exactly.
std::vector<double> midpoint_times(double mesh_frequency, int phases, int cycles) {
  std::vector<double> t;
  for (int c = 0; c < cycles; ++c)
    for (int i = 0; i < phases; ++i) t.push_back((c + (i + 0.5) / phases) / mesh_frequency);
  return t;
}

// A constant force equal to the static one reproduces the static efficiency; twice that
// force doubles the loss (constant μ, no rolling loss: the loss is linear in the load, and
// linear interpolation between load levels is exact). Rounding only: 1e-12.
TEST(DynamicEfficiency, ConstantForceReproducesStatic) {
  const auto d = seed004_drive(false, 1000, 100);
  const geometry::GearPairGeometry g(d.pair);
  const double f0 = d.op.pinion_torque / g.radii(0).base;
  const double fm = d.op.pinion_speed * g.pair().teeth[0] / (2.0 * std::numbers::pi);
  efficiency::DynamicEfficiencyOptions o;
  o.phases = 50;
  const auto t = midpoint_times(fm, o.phases, 2);
  const auto same = efficiency::dynamic_efficiency(g, d.op, {}, {}, t, {std::vector<double>(t.size(), f0)}, fm, o);
  EXPECT_NEAR(same.mean, same.static_mean, 1e-12);
  std::vector<double> ramp(t.size());
  // 0.5 F0 over the first mesh period, 2 F0 over the second: every phase sees both forces.
  for (std::size_t i = 0; i < t.size(); ++i) ramp[i] = i < t.size() / 2 ? 0.5 * f0 : 2.0 * f0;
  const auto alt = efficiency::dynamic_efficiency(g, d.op, {}, {}, t, {ramp}, fm, o);
  EXPECT_EQ(alt.load_levels.size(), 5u);
  EXPECT_NEAR(alt.load_levels.front(), 0.5 * f0, 1e-9 * f0);
  EXPECT_NEAR(alt.load_levels.back(), 2.0 * f0, 1e-9 * f0);
  // Mean of 0.5 and 2 times the static loss, phase by phase: 1.25 × the static loss.
  EXPECT_NEAR(1.0 - alt.mean, 1.25 * (1.0 - same.static_mean), 1e-12);
}

// The static loss at the nominal force is computed on construction, before any force series
// exists, so that a caller can construct first and integrate after: a contact beyond the
// friction law's range is refused there (issue 20: a dynamics run met Xu–Kahraman's refusal
// of an 87 GPa Hertz pressure only after its integration, 33 s in).
TEST(DynamicEfficiency, ConstructionRefusesAContactBeyondTheFrictionLaw) {
  const geometry::GearPairGeometry g(testing_support::spur_pair(22, 32, 0.04, 25.0, 20.0));
  MeshLossOptions o;
  o.friction_model = FrictionModel::xu_kahraman;
  const auto msg = testing_support::input_error_of(
      [&] { efficiency::DynamicEfficiency(g, operating(1000, 100), o, seed004_media(), 1); });
  EXPECT_EQ(msg.rfind("xu_kahraman.hertz_pressure = ", 0), 0u) << msg;
  EXPECT_NE(msg.find("allowed range is [0.001, 10] GPa"), std::string::npos) << msg;
}

// The force series of the 6-DOF spur dynamics (seed 003 pair) fed to the dynamic efficiency:
// every instant dissipates, and the dynamic mean lies within 1 % (absolute) of the static one
// (seed 000 finds 0.3 % lower with its herringbone model).
TEST(DynamicEfficiency, FromSpur6Dynamics) {
  const geometry::GearPairGeometry g(testing_support::seed003_pair());
  const std::array<model::Material, 2> steel{model::Material{212e9, 0.289, 7850}, model::Material{212e9, 0.289, 7850}};
  const model::OperatingPoint op{996.0 * rpm, 50.0, 313.15, {0.4e-6, 0.4e-6}};
  dynamics::Spur6Options so;
  so.runup_cycles = 30;
  so.record_cycles = 8;
  const auto dyn = dynamics::Spur6Dynamics(g, steel, op, so).solve();
  const auto r = efficiency::dynamic_efficiency(g, op, {}, {}, dyn.time, {dyn.mesh_force}, dyn.mesh_frequency);
  ASSERT_EQ(r.efficiency.size(), dyn.time.size());
  for (const double e : r.efficiency) ASSERT_LT(e, 1.0);
  EXPECT_NEAR(r.mean, r.static_mean, 0.01);
}

}  // namespace
}  // namespace gearbench
