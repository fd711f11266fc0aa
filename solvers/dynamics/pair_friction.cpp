#include "pair_friction.h"

#include <algorithm>
#include <fmt/format.h>

#include "efficiency/film_thickness.h"
#include "efficiency/friction_keys.h"
#include "efficiency/mesh_loss.h"
#include "model/errors.h"

namespace gearbench::dynamics {

using lubricant::FrictionModel;

namespace {

model::OptionTable<FrictionLawOptions> make_table() {
  model::OptionTable<FrictionLawOptions> t;
  // The "ehl" law has no closed-form coefficient to evaluate at every step.
  efficiency::add_friction_keys(t, {FrictionModel::constant, FrictionModel::xu_kahraman, FrictionModel::benedict_kelley,
                                    FrictionModel::iso14179, FrictionModel::mixed});
  t.rule([](const FrictionLawOptions& o, const std::string&) {
    if (o.friction_model != FrictionModel::constant && !o.lubricant)
      throw InputError(fmt::format("lubricant: missing, needed for friction.model = {}",
                                   lubricant::friction_model_name(o.friction_model)));
  });
  return t;
}

}  // namespace

const model::OptionTable<FrictionLawOptions>& FrictionLawOptions::table() {
  static const auto t = make_table();
  return t;
}

PairFriction::PairFriction(const geometry::GearPairGeometry& geometry, const std::array<model::Material, 2>& materials,
                           const model::OperatingPoint& operating, FrictionLawOptions law)
    : geometry_(geometry),
      pinion_speed_(operating.pinion_speed),
      reduced_modulus_(model::reduced_modulus(materials)),
      mean_roughness_(0.5 * (operating.roughness_Ra[0] + operating.roughness_Ra[1])),
      lubricant_(law.lubricant) {
  law.validate();
  law_.model = law.friction_model;
  law_.constant_mu = law.friction_coefficient;
  law_.boundary_mu = law.boundary_friction;
  law_.composite_roughness = lubricant::composite_rms_roughness(operating.roughness_Ra[0], operating.roughness_Ra[1]);
  if (law.friction_model == FrictionModel::iso14179) {
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
