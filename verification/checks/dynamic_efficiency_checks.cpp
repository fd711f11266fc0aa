// Dynamic efficiency of seed 000 (eq. 12): the 12-DOF herringbone mesh forces of the seed
// case fed into the mesh-loss solver, against the paper's dynamic mean (98.8 %, below its
// static 99.1 %).
#include <cmath>
#include <fmt/format.h>
#include <map>

#include "check_registry.h"
#include "dynamics/herringbone12_dynamics.h"
#include "efficiency/dynamic_efficiency.h"
#include "geometry/gear_pair_geometry.h"

namespace gearbench::verification {
namespace {

const std::string section = "Seed 000: dynamic efficiency";

struct SeedRun {
  efficiency::DynamicEfficiencyResult e;
  double mean_force = 0.0;     ///< mean recorded mesh force of the halves [N]
  double nominal_force = 0.0;  ///< T_p/(r_b1·cos β_b) per half, where the static curve is taken [N]
};

/// The seed case as cases/seed000_herringbone_dynamics.json runs it: the dynamics defaults
/// with μ = 0.05 (no mesh-in impact), the loss with its "dynamic_efficiency" section.
const SeedRun& seed000_run(const CheckContext& ctx) {
  static std::map<std::string, SeedRun> cache;
  if (auto it = cache.find(ctx.cases_dir); it != cache.end()) return it->second;
  const auto c = ctx.gear_case("seed000_herringbone_dynamics.json");
  const geometry::GearPairGeometry geometry(c.gear_pair);
  dynamics::Herringbone12Options o;
  o.mesh.friction.friction_coefficient = 0.05;
  const auto r = dynamics::Herringbone12Dynamics(geometry, *c.materials, *c.operating, o).solve();
  efficiency::MeshLossOptions loss;
  loss.friction_model = lubricant::FrictionModel::mixed;
  loss.boundary_friction = 0.1;
  loss.rolling_loss_constant = 0.0;
  loss.positions = 100;
  const geometry::GearPairGeometry half_geometry(c.gear_pair.one_mesh());
  SeedRun run{efficiency::dynamic_efficiency(half_geometry, *c.operating, loss, {c.materials, c.lubricant}, r.time,
                                             {r.mesh_force[0], r.mesh_force[1]}, r.mesh_frequency)};
  for (const auto& series : r.mesh_force)
    for (const double f : series) run.mean_force += f / static_cast<double>(2 * series.size());
  run.nominal_force = 0.5 * c.operating->pinion_torque /
                      (half_geometry.radii(0).base * std::cos(half_geometry.base_helix_angle()));
  return cache.emplace(ctx.cases_dir, std::move(run)).first->second;
}

const RegisterCheck dynamic_mean(CheckSpec{
    .id = "seed000.dynamic_efficiency_mean", .section = section, .solver = "efficiency.dynamic",
    .reference = "seed 000 (dynamic mean 98.8 %)", .quantity = "mean dynamic efficiency", .unit = "%",
    .tolerance = {0.1, 0}, .justification = "the paper prints one decimal",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) {
      const auto& e = seed000_run(ctx).e;
      return CheckValue{100.0 * e.mean, 98.8, {{"static_mean_percent", 100.0 * e.static_mean}}};
    },
    .recorded = 99.1220, .recorded_tolerance = 0.0005});

void add_note(const CheckContext& ctx, reports::Report& report) {
  const auto& run = seed000_run(ctx);
  const auto& e = run.e;
  // The static curve at the mean force the dynamics carries: its loss scales with the force
  // (the mixed law's loss is nearly proportional to it over this 0.6 % step).
  const double equal_force = 1.0 - (1.0 - e.static_mean) * run.mean_force / run.nominal_force;
  report.notes.push_back({section, fmt::format(
      "Why 98.8 % is missed. The method is the seed's: the 12-DOF mesh forces of the seed case (20 recorded mesh "
      "cycles; mesh-in impact off, section \"Gear dynamics (12-DOF herringbone)\") split into 5 equally spaced "
      "load levels from their smallest to their largest ({:.0f}–{:.0f} N per half), a loss curve over the mesh "
      "period at each, the loss of each instant interpolated at its phase and force, η_D = 1 − (P[F_n1] + "
      "P[F_n2])/P_in. It gives {:.3f} % against the static {:.3f} % (the paper: 98.8 % below 99.1 %). The small "
      "excess is not dynamics: the dynamics' mean force per half, {:.1f} N, carries the friction arms of its "
      "μ = 0.05 and is {:.2f} % below the frictionless nominal {:.1f} N at which the static curve is taken; the "
      "static efficiency at the dynamics' mean force is {:.4f} %, {:.1e} points from the dynamic mean. So at "
      "equal mean load this model's dynamics leave the efficiency unchanged: the helical overlap keeps the force "
      "within 1.4 % of its mean (dynamic factor 1.01) and the mixed law's loss is nearly linear in the load over "
      "that range, so the mean loss is the loss at the mean force. The paper's 0.3-point drop needs a mean loss "
      "35 % above the static one, i.e. far larger dynamic loads (its model folds grade-6 pitch errors into the "
      "stiffness and adds the eq. 6 impact) or a loss much more convex in the load. The mesh-in pulse does not "
      "supply it: on (under the approach, dynamic factor 1.48) the dynamic mean is 99.161 %, with eq. 6 as "
      "printed (2.9) 99.145 % — higher, since the pulse carries part of the load outside F_n, whose friction "
      "eq. 12 as the seed writes it does not count. No constant is tuned toward 98.8 %; the paper's friction "
      "inputs (roughness, pressure-viscosity coefficient) are not printed.",
      e.load_levels.front(), e.load_levels.back(), 100.0 * e.mean, 100.0 * e.static_mean, run.mean_force,
      100.0 * (1.0 - run.mean_force / run.nominal_force), run.nominal_force, 100.0 * equal_force,
      100.0 * std::abs(e.mean - equal_force))});
  report.figures.push_back({"seed000_dynamic_efficiency", section, "Dynamic efficiency over the recorded window",
                            "time [ms]", "efficiency [%]",
                            {{"η_D(t)", scaled(std::vector<double>(e.time), 1e3), scaled(e.efficiency, 100.0)}}});
}

const RegisterSection dynamic_efficiency_section(SectionSpec{
    .id = "seed000_dynamic_efficiency", .tier = Tier::fast, .add = add_note});

}  // namespace
}  // namespace gearbench::verification
