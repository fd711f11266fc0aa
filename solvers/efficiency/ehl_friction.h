#pragma once
// The friction laws computed by an EHL solver at every contact point of a gear mesh, in place
// of a regression:
//  - "ehl": the isothermal line-contact EHL solver with Eyring traction post-processed on the
//    Newtonian film (ehl/traction.h);
//  - "ehl_thermal": the thermal line-contact EHL solver with a Ree–Eyring film
//    (ehl/thermal_line_contact.h, rheology eyring): the traction is the film's wall stress, with
//    its shear heating and the solids' temperatures (seed 004: friction "from the mean of a
//    thermal EHL").
// One class for both: the law only chooses how one contact is solved. Each distinct contact
// (load, radius, speeds) is solved once and remembered, so a mesh period costs one solve per
// contact point of the series.
#include <array>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>

#include "ehl/line_contact_solver.h"
#include "ehl/thermal_line_contact.h"
#include "lubricant/friction_laws.h"
#include "model/json_reader.h"
#include "model/materials.h"

namespace gearbench::efficiency {

/// What the thermal law needs beyond the isothermal one, in the form of the thermal EHL kinds.
struct ThermalFrictionMedia {
  model::ThermalLubricant lubricant;  ///< with its Eyring stress τ0
  model::ThermalSolids solids;
  double inlet_temperature = 0.0;     ///< T0 [K]: the oil temperature of the operating point
};

/// The thermal data of a gear case: "lubricant" (density_kg_m3 at the oil temperature,
/// thermal_conductivity_W_per_mK, specific_heat_J_per_kgK, eyring_stress_MPa, and
/// temperature_viscosity_1_per_K or nu40_mm2_s with nu100_mm2_s) and "materials"
/// (thermal_conductivity_W_per_mK, specific_heat_J_per_kgK, density_kg_m3 per gear).
/// InputError naming the missing key and the law that needs it; also for a roelands_z other
/// than the one the thermal solver derives from η0 and α (it has no other).
ThermalFrictionMedia thermal_friction_media(const std::array<model::Material, 2>& materials,
                                            const model::Lubricant& lubricant, double oil_temperature);

class EhlFriction {
 public:
  /// τ0 of the "ehl" law [MPa], as its case key friction.eyring_stress_MPa reads it.
  static model::Range eyring_stress_range() { return {0.0, 1e3, true, false}; }

  /// "ehl". `fluid`: E′, η0, α (or z), rheology models; `eyring_stress`: τ0 [Pa] in
  /// eyring_stress_range(); `grid`: the EHL grid (161 nodes by default: the traction changes
  /// by < 1 % to 641 nodes, see the tests).
  EhlFriction(const ehl::LineContactData& fluid, double eyring_stress, ehl::EhlOptions grid = default_grid());
  /// "ehl_thermal". `fluid`: E′ (its lubricant fields come from `media`); `options`: the
  /// thermal solver's (its Ree–Eyring rheology is set here).
  EhlFriction(const ehl::LineContactData& fluid, ThermalFrictionMedia media,
              ehl::ThermalEhlOptions options = default_thermal_options());

  /// |μ| at the contact; throws ConvergenceError naming the law and the contact when the solve
  /// fails or gives no finite μ.
  [[nodiscard]] double coefficient(const lubricant::ContactState& c) const;
  [[nodiscard]] int solves() const;
  [[nodiscard]] lubricant::FrictionModel law() const { return law_; }

  static ehl::EhlOptions default_grid();
  /// 81 nodes, factor relaxation 0.15, h_min settled to 1e-3, at most 300 iterations: what
  /// settles every contact of seed 004's path (the reasons and figures in the .cpp).
  static ehl::ThermalEhlOptions default_thermal_options();

  /// μ (signed, on surface 1) of one contact by each law, without cache or range checks: the
  /// limits of the verification matrix take τ0 → ∞ here.
  static double isothermal_coefficient(const ehl::LineContactData& contact, double eyring_stress,
                                       const ehl::EhlOptions& grid);
  static double thermal_coefficient(const ehl::LineContactData& contact, const lubricant::ThermalRheology& rheology,
                                    const model::ThermalSolids& solids, const ehl::ThermalEhlOptions& options);

 private:
  using Solve = std::function<double(const ehl::LineContactData&)>;

  lubricant::FrictionModel law_;
  ehl::LineContactData fluid_;
  Solve solve_;
  mutable std::map<std::tuple<double, double, double, double>, double> cache_;
  mutable std::mutex mutex_;
};

}  // namespace gearbench::efficiency
