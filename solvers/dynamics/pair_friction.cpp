#include "pair_friction.h"

#include <algorithm>
#include <fmt/format.h>

#include "efficiency/film_thickness.h"
#include "efficiency/mesh_loss.h"
#include "model/errors.h"

namespace gearbench::dynamics {

using lubricant::FrictionModel;

void FrictionLawOptions::validate() const {
  const auto name = lubricant::friction_model_name(model);
  if (model == FrictionModel::ehl)
    throw InputError("friction.model = \"ehl\": no closed-form coefficient for the dynamics models; allowed are "
                     "\"constant\", \"xu_kahraman\", \"benedict_kelley\", \"iso14179\", \"mixed\"");
  if (model != FrictionModel::constant && !lubricant)
    throw InputError(fmt::format("lubricant: missing, needed for friction.model = {}", name));
  if (!(boundary_mu >= 0.07 && boundary_mu <= 0.15))
    throw InputError(fmt::format("friction.mu_boundary = {}: allowed range is [0.07, 0.15]", boundary_mu));
  if (!(lubricant_factor > 0.0 && lubricant_factor <= 2.0))
    throw InputError(fmt::format("friction.lubricant_factor = {}: allowed range is (0, 2]", lubricant_factor));
}

PairFriction::PairFriction(const geometry::GearPairGeometry& geometry, const std::array<model::Material, 2>& materials,
                           const model::OperatingPoint& operating, double constant_mu, FrictionLawOptions law)
    : geometry_(geometry),
      pinion_speed_(operating.pinion_speed),
      reduced_modulus_(model::reduced_modulus(materials)),
      mean_roughness_(0.5 * (operating.roughness_Ra[0] + operating.roughness_Ra[1])),
      lubricant_(law.lubricant) {
  law.validate();
  law_.model = law.model;
  law_.constant_mu = constant_mu;
  law_.boundary_mu = law.boundary_mu;
  law_.composite_roughness = lubricant::composite_rms_roughness(operating.roughness_Ra[0], operating.roughness_Ra[1]);
  if (law.model == FrictionModel::iso14179) {
    // The pair's ISO/TR 14179-2 mean coefficient, as the efficiency solver computes it.
    efficiency::MeshLossOptions o;
    o.friction_model = FrictionModel::iso14179;
    o.lubricant_factor = law.lubricant_factor;
    law_.iso14179_mu = efficiency::MeshLoss(geometry, operating, o, {materials, law.lubricant}).iso14179_coefficient();
  }
}

// The contact state of the efficiency solver's point_loss at s: nominal surface speeds
// and the normal-section reduced radius from the geometry, Hertz pressure and (mixed law)
// the Dowson–Higginson film under w.
double PairFriction::factor(double s, double load_per_length) const {
  if (constant()) return 1.0;
  const double w = std::max(load_per_length, load_floor);
  const auto k = geometry_.kinematics(s, pinion_speed_);
  lubricant::ContactState c;
  c.load_per_length = w;
  c.reduced_radius = k.reduced_radius_normal;
  c.u1 = k.u1;
  c.u2 = k.u2;
  c.roughness_Ra = mean_roughness_;
  c.viscosity = lubricant_->viscosity;
  c.hertz_pressure = efficiency::hertz_line_pressure(w, c.reduced_radius, reduced_modulus_);
  if (law_.model == FrictionModel::mixed)
    c.film_thickness = efficiency::dowson_higginson_min_film(w, c.reduced_radius, c.entrainment(), lubricant_->viscosity,
                                                             lubricant_->pressure_viscosity, reduced_modulus_);
  return lubricant::friction_coefficient(law_, c);
}

}  // namespace gearbench::dynamics
