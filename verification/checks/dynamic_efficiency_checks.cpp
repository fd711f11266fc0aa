// Dynamic efficiency of seed 000 (eq. 12): the 12-DOF herringbone mesh forces of the seed
// case fed into the mesh-loss solver, against the paper's dynamic mean (98.8 %, below its
// static 99.1 %).
#include <fmt/format.h>
#include <map>

#include "check_registry.h"
#include "dynamics/herringbone12_dynamics.h"
#include "efficiency/dynamic_efficiency.h"
#include "geometry/gear_pair_geometry.h"

namespace gearbench::verification {
namespace {

const std::string section = "Seed 000: dynamic efficiency";

/// The seed case as cases/seed000_herringbone_dynamics.json runs it: the dynamics defaults
/// with μ = 0.05 (no mesh-in impact), the loss with its "dynamic_efficiency" section.
efficiency::DynamicEfficiencyResult seed000_dynamic_efficiency(const CheckContext& ctx) {
  static std::map<std::string, efficiency::DynamicEfficiencyResult> cache;
  if (auto it = cache.find(ctx.cases_dir); it != cache.end()) return it->second;
  const auto c = ctx.gear_case("seed000_herringbone_dynamics.json");
  const geometry::GearPairGeometry geometry(c.gear_pair);
  dynamics::Herringbone12Options o;
  o.mesh.friction_coefficient = 0.05;
  const auto r = dynamics::Herringbone12Dynamics(geometry, *c.materials, *c.operating, o).solve();
  efficiency::MeshLossOptions loss;
  loss.friction_model = lubricant::FrictionModel::mixed;
  loss.boundary_friction = 0.1;
  loss.rolling_loss_constant = 0.0;
  loss.positions = 100;
  const geometry::GearPairGeometry half_geometry(c.gear_pair.one_mesh());
  auto e = efficiency::dynamic_efficiency(half_geometry, *c.operating, loss, {c.materials, c.lubricant}, r.time,
                                          {r.mesh_force[0], r.mesh_force[1]}, r.mesh_frequency);
  return cache.emplace(ctx.cases_dir, std::move(e)).first->second;
}

const RegisterCheck dynamic_mean(CheckSpec{
    .id = "seed000.dynamic_efficiency_mean", .section = section, .solver = "efficiency.dynamic",
    .reference = "seed 000 (dynamic mean 98.8 %)", .quantity = "mean dynamic efficiency", .unit = "%",
    .tolerance = {0.1, 0}, .justification = "the paper prints one decimal",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) {
      const auto& e = seed000_dynamic_efficiency(ctx);
      return CheckValue{100.0 * e.mean, 98.8, {{"static_mean_percent", 100.0 * e.static_mean}}};
    },
    .recorded = 99.1220, .recorded_tolerance = 0.0005});

void add_note(const CheckContext& ctx, reports::Report& report) {
  const auto& e = seed000_dynamic_efficiency(ctx);
  report.notes.push_back({section, fmt::format(
      "The 12-DOF mesh forces of the seed case (20 recorded mesh cycles, dynamic factor 1.01; the mesh-in "
      "impact is off, its eq. 6 pulse being outside its premise at 2000 rpm: section \"Gear dynamics (12-DOF "
      "herringbone)\") give a dynamic mean efficiency of {:.3f} % against the static {:.3f} % on the same "
      "phase grid, both from loss-versus-load curves at 5 load levels interpolated at the instant's force; "
      "the paper has 98.8 % below 99.1 %. Here the two agree to 0.01 points: the helical overlap keeps the "
      "mesh force within about 1 % of its mean, and with the mixed law the loss grows almost in proportion to "
      "the load, so such fluctuations barely change the mean loss. With the pulse on (dynamic factor 2.9) the "
      "dynamic mean was 99.147 %, still not below the static one: the instants where the pulse drives the mesh "
      "force below zero dissipate nothing. The paper's drop needs a loss that grows faster than the load, or "
      "larger dynamic loads than this model's; its friction inputs (roughness, pressure-viscosity coefficient) "
      "are not printed.",
      100.0 * e.mean, 100.0 * e.static_mean)});
  report.figures.push_back({"seed000_dynamic_efficiency", section, "Dynamic efficiency over the recorded window",
                            "time [ms]", "efficiency [%]",
                            {{"η_D(t)", scaled(std::vector<double>(e.time), 1e3), scaled(e.efficiency, 100.0)}}});
}

const RegisterSection dynamic_efficiency_section(SectionSpec{
    .id = "seed000_dynamic_efficiency", .tier = Tier::fast, .add = add_note});

}  // namespace
}  // namespace gearbench::verification
