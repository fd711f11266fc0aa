#include "pair_stiffness.h"

#include <cmath>

#include "hertz.h"

namespace gearbench::stiffness {

double PairCompliance::total() const {
  return hertz + tooth[0].sum() + tooth[1].sum() + foundation[0] + foundation[1];
}

PairStiffness::PairStiffness(const geometry::GearPairGeometry& geometry,
                             const std::array<model::Material, 2>& materials, ToothModel tooth_model,
                             const std::array<double, 2>& bore_radii,
                             const std::optional<GearCrack>& crack, bool with_foundation)
    : geometry_(geometry), with_foundation_(with_foundation), cracked_(crack && crack->crack.length > 0.0) {
  teeth_.reserve(2);
  for (int gear = 0; gear < 2; ++gear) {
    const auto i = static_cast<std::size_t>(gear);
    ToothProfile profile(geometry, gear, tooth_model);
    foundation_[i] = foundation_parameters(profile, bore_radii[i], materials[i].youngs_modulus, 1.0);
    if (with_foundation_)
      for (auto& w : foundation_validity_warnings(foundation_[i], gear)) warnings_.push_back(std::move(w));
    const bool cracked = crack && crack->gear == gear;
    teeth_.emplace_back(std::move(profile), materials[i], 1.0,
                        cracked ? std::optional<Crack>(crack->crack) : std::nullopt);
  }
  hertz_per_width_ = hertz_stiffness(materials[0], materials[1], 1.0);
}

// Roll angle of each flank at s: ψ1 = s/R_b1 on the pinion, ψ2 = (T1T2 − s)/R_b2 on the wheel.
double PairStiffness::roll_angle(int gear, double s) const {
  const double rb = geometry_.radii(gear).base;
  return gear == 0 ? s / rb : (geometry_.path().T2 - s) / rb;
}

PairCompliance PairStiffness::compliance(double s, bool healthy) const {
  return compliance(s, healthy ? ToothCompliance::CrackMode::healthy : ToothCompliance::CrackMode::automatic);
}

PairCompliance PairStiffness::compliance(double s, ToothCompliance::CrackMode mode) const {
  PairCompliance c;
  c.hertz = 1.0 / hertz_per_width_;
  for (int gear = 0; gear < 2; ++gear) {
    const auto i = static_cast<std::size_t>(gear);
    const double psi = roll_angle(gear, s);
    c.tooth[i] = teeth_[i].at(psi, mode);
    if (with_foundation_)
      c.foundation[i] = foundation_compliance(foundation_[i], teeth_[i].profile().involute_point(psi));
  }
  return c;
}

double PairStiffness::stiffness_per_width(double s, bool healthy) const {
  return stiffness_per_width(s, healthy ? ToothCompliance::CrackMode::healthy : ToothCompliance::CrackMode::automatic);
}

double PairStiffness::stiffness_per_width(double s, ToothCompliance::CrackMode mode) const {
  const auto& p = geometry_.path();
  if (s < p.A || s > p.E) return 0.0;
  return 1.0 / compliance(s, mode).total();
}

double StiffnessLoadSharing::share(const geometry::GearPairGeometry& g, double s) const {
  const auto& p = g.path();
  if (s < p.A || s > p.E) return 0.0;
  double total = 0.0;
  for (const double t : g.positions_in_contact(s)) total += pair_.stiffness_per_width(t, true);
  return pair_.stiffness_per_width(s, true) / total;
}

}  // namespace gearbench::stiffness
