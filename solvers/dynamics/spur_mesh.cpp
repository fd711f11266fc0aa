#include "spur_mesh.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "model/errors.h"
#include "stiffness/mesh_stiffness.h"

namespace gearbench::dynamics {

std::array<double, 2> friction_arms(std::span<const MeshContact> contacts, const PairFriction& friction, double T1T2,
                                    double force, double length) {
  double k = 0.0, k_rho1 = 0.0, k_rho2 = 0.0;
  for (const MeshContact& c : contacts) k += c.k;
  if (!(k > 0.0)) return {0.0, 0.0};
  for (const MeshContact& c : contacts) {
    const double f = friction.factor(c.s, std::abs(force) * c.k / k / length);
    k_rho1 += c.k * c.lambda * c.s * f;
    k_rho2 += c.k * c.lambda * (T1T2 - c.s) * f;
  }
  return {friction.scale() * k_rho1 / k, friction.scale() * k_rho2 / k};
}

SpurMesh::SpurMesh(const geometry::GearPairGeometry& geometry, const std::array<model::Material, 2>& materials,
                   double pinion_speed, stiffness::Fillet fillet, const std::optional<stiffness::GearCrack>& crack)
    : geometry_(geometry),
      crack_(crack && crack->crack.length > 0.0 ? crack : std::nullopt),
      pair_(geometry, materials, stiffness::ToothModel{stiffness::BeamStart::improved, fillet},
            {0.5 * geometry.radii(0).root, 0.5 * geometry.radii(1).root}, crack, true) {
  if (!(pinion_speed > 0.0))
    throw InputError(fmt::format("operating.pinion_speed_rpm = {}: must be > 0", pinion_speed * 30.0 / M_PI));
  const auto& path = geometry_.path();
  // The healthy pair's spline on A..E, on as many nodes as stiffness::MeshStiffness's (one
  // single-pair curve for the sliced and the transverse mesh alike).
  const auto nodes = static_cast<std::size_t>(stiffness::MeshStiffnessOptions{}.spline_nodes);
  std::vector<double> s(nodes), k(nodes);
  for (std::size_t i = 0; i < nodes; ++i) {
    s[i] = path.A + (path.E - path.A) * static_cast<double>(i) / static_cast<double>(nodes - 1);
    k[i] = geometry_.pair().face_width * pair_.stiffness_per_width(s[i], true);
  }
  healthy_.emplace(std::move(s), std::move(k));
  speed_ = pinion_speed * geometry_.radii(0).base;
  period_ = geometry_.base_pitch_transverse() / speed_;
  crack_mouth_ = geometry_.radii(0).base * std::tan(geometry_.transverse_pressure_angle());
  const double pb = geometry_.base_pitch_transverse();
  for (int i = 0; i < mean_positions; ++i)
    for (const double s0 : geometry_.positions_in_contact(path.A + pb * i / mean_positions))
      mean_stiffness_ += pair_stiffness(s0) / mean_positions;
}

double SpurMesh::pair_stiffness(double s, bool cracked_tooth, bool crack_acting) const {
  using Mode = stiffness::ToothCompliance::CrackMode;
  // A pair's interval starts or ends at A or E: its position there is A or E up to rounding.
  const auto& path = geometry_.path();
  const double on_path = std::clamp(s, path.A, path.E);
  if (cracked_tooth)
    return geometry_.pair().face_width * pair_.stiffness_per_width(on_path, crack_acting ? Mode::active : Mode::inactive);
  return (*healthy_)(on_path);
}

SpurPairs SpurMesh::pairs(double t, double t_mid) const {
  const auto& path = geometry_.path();
  const double pb = geometry_.base_pitch_transverse();
  const double n = std::floor(speed_ * t_mid / pb);
  const int z1 = geometry_.pair().teeth[0];
  SpurPairs out;
  for (int j = 0; j < 3; ++j) {
    const double s_mid = path.A + speed_ * t_mid - n * pb + j * pb;
    if (s_mid < path.A || s_mid > path.E) continue;
    const double s = std::clamp(path.A + speed_ * t - n * pb + j * pb, path.A, path.E);
    const long tooth = static_cast<long>(n) - j;
    const bool cracked = crack_ && ((tooth % z1) + z1) % z1 == 0;
    // A pitch crack acts once the contact is above its mouth; a root crack always.
    const bool acting = cracked && (crack_->crack.type == stiffness::Crack::Type::root || s_mid > crack_mouth_);
    SpurPair& p = out.pair[out.count++];
    p.s = s;
    p.s_mid = s_mid;
    p.stiffness = cracked ? pair_stiffness(s, cracked, acting) : (*healthy_)(s, cursors_[static_cast<std::size_t>(j)]);
    if (cracked) {
      // dk/dt = u·dk/ds by a central difference (the cracked pair is integrated directly),
      // one-sided at the path's ends.
      const double h = 1e-6 * (path.E - path.A);
      const double lo = std::max(path.A, s - h), hi = std::min(path.E, s + h);
      p.rate = speed_ * (pair_stiffness(hi, cracked, acting) - pair_stiffness(lo, cracked, acting)) / (hi - lo);
    } else {
      p.rate = speed_ * healthy_->derivative(s, cursors_[static_cast<std::size_t>(j)]);  // u·dk/ds of the spline itself
    }
    // The sliding direction of the whole interval (intervals end where a pair passes C).
    p.lambda = sliding_sign(s_mid, path.C);
  }
  return out;
}

// Once per mesh period each: a pair enters (u·t ≡ 0), the leading pair leaves
// (u·t ≡ E − A − p_bt), a pair passes the pitch point, reversing its friction
// (u·t ≡ C − A, mod p_bt), and, with a pitch crack, passes the crack's mouth.
std::vector<double> SpurMesh::break_times(double t0, double t1) const {
  const auto& path = geometry_.path();
  const double pb = geometry_.base_pitch_transverse();
  const double exit_offset = (path.E - path.A - pb) / speed_;
  const double pitch_offset = std::fmod(path.C - path.A, pb) / speed_;
  const double mouth_offset = std::fmod(crack_mouth_ - path.A, pb) / speed_;
  const bool mouth = crack_ && crack_->crack.type == stiffness::Crack::Type::pitch;
  std::vector<double> times;
  for (double base = std::floor(t0 / period_) * period_; base < t1 + period_; base += period_)
    for (const double t : {base, base + exit_offset, base + pitch_offset, base + (mouth ? mouth_offset : 0.0)})
      if (t > t0 && t < t1) times.push_back(t);
  std::sort(times.begin(), times.end());
  // Coinciding events (the mouth is the pitch point of an unshifted pinion) give one restart.
  times.erase(std::unique(times.begin(), times.end(),
                          [this](double a, double b) { return std::abs(a - b) < 1e-12 * period_; }),
              times.end());
  return times;
}

std::array<double, 2> SpurMesh::mean_arms(const PairFriction& friction, double force) const {
  const auto& path = geometry_.path();
  const double pb = geometry_.base_pitch_transverse();
  std::array<double, 2> mean{};
  for (int i = 0; i < mean_positions; ++i) {
    std::vector<MeshContact> contacts;
    for (const double s0 : geometry_.positions_in_contact(path.A + pb * (i + 0.5) / mean_positions))
      contacts.push_back({s0, pair_stiffness(s0), sliding_sign(s0, path.C)});
    const auto arms = friction_arms(contacts, friction, path.T2, force, geometry_.pair().face_width);
    mean[0] += arms[0] / mean_positions;
    mean[1] += arms[1] / mean_positions;
  }
  return mean;
}

}  // namespace gearbench::dynamics
