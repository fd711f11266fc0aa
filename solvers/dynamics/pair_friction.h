#pragma once
// The friction coefficient of one contact of the dynamics models, from a friction law of
// solvers/lubricant (the laws of the efficiency solver) evaluated at the contact point s
// on the path of contact with the load per unit length that the contact carries at that
// instant (docs/dynamics-model.md, "Friction laws").
//
// μ_j = scale()·factor(s, w): for the constant law scale() = μ and factor() = 1, so that a
// sum Σ μ_j·x_j = μ·Σ x_j keeps the arithmetic (and the bits) of a constant coefficient.
#include <array>
#include <optional>

#include "geometry/gear_pair_geometry.h"
#include "lubricant/friction_laws.h"
#include "model/materials.h"
#include "model/option_table.h"

namespace gearbench::dynamics {

/// The friction of a dynamics model: the case's "friction" section (the keys of the
/// efficiency kind's, efficiency/friction_keys.h, every law but "ehl") and the oil the laws
/// other than the constant one need. The holder sets its own default μ.
struct FrictionLawOptions {
  lubricant::FrictionModel friction_model = lubricant::FrictionModel::constant;
  double friction_coefficient = 0.0;  ///< μ of the constant law ("friction.mu")
  double boundary_friction = 0.1;     ///< μ_BL of the mixed law ("friction.mu_boundary")
  double lubricant_factor = 1.0;      ///< X_L of ISO/TR 14179-2 ("friction.lubricant_factor")
  std::optional<model::Lubricant> lubricant;  ///< the case's "lubricant", needed by every law but the constant one

  /// The "friction" section's keys, with the rule that a law other than the constant one needs the oil.
  static const model::OptionTable<FrictionLawOptions>& table();
  void validate() const { table().validate(*this, "friction."); }  ///< InputError naming the key
};

class PairFriction {
 public:
  /// `geometry` must outlive this object.
  PairFriction(const geometry::GearPairGeometry& geometry, const std::array<model::Material, 2>& materials,
               const model::OperatingPoint& operating, FrictionLawOptions law);

  [[nodiscard]] bool constant() const { return law_.model == lubricant::FrictionModel::constant; }
  /// μ for the constant law, 1 otherwise.
  [[nodiscard]] double scale() const { return constant() ? law_.constant_mu : 1.0; }
  /// 1 for the constant law; otherwise μ of the law at the contact point s [m from T1]
  /// under w [N/m] (w below `load_floor` is taken as the floor: the friction force μ·w·l
  /// vanishes with w whatever μ is there, and the regressions are not defined at w = 0).
  [[nodiscard]] double factor(double s, double load_per_length) const;
  /// μ = scale()·factor(s, w).
  [[nodiscard]] double coefficient(double s, double load_per_length) const { return scale() * factor(s, load_per_length); }

  /// 10 N/m: three to five orders below a working load, above the smallest load the laws
  /// accept (Benedict–Kelley 1 N/m; Xu–Kahraman p_h ≥ 1 MPa, w ≳ 0.2 N/m on R ≥ 1 mm).
  static constexpr double load_floor = 10.0;

 private:
  const geometry::GearPairGeometry& geometry_;
  double pinion_speed_ = 0.0;
  double reduced_modulus_ = 0.0;
  double mean_roughness_ = 0.0;  ///< (Ra1 + Ra2)/2 [m]
  std::optional<model::Lubricant> lubricant_;
  lubricant::FrictionLaw law_;
};

}  // namespace gearbench::dynamics
