#include "half_mesh.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <fmt/format.h>
#include <stdexcept>
#include <string>

#include "model/errors.h"
#include "stiffness/mesh_stiffness.h"

namespace gearbench::dynamics {

namespace {
constexpr int curve_nodes = 1025;  // nodes of the pair-stiffness spline on A..E (as MeshStiffness)
}  // namespace

// ---- FourierSeries ----------------------------------------------------------------------

FourierSeries::FourierSeries(double period, const std::vector<double>& y, int harmonics)
    : omega_(2.0 * M_PI / period) {
  const int n = static_cast<int>(y.size());
  std::vector<double> in(y);
  std::vector<std::complex<double>> out(static_cast<std::size_t>(n / 2 + 1));
  fftw_plan plan = fftw_plan_dft_r2c_1d(n, in.data(), reinterpret_cast<fftw_complex*>(out.data()), FFTW_ESTIMATE);
  fftw_execute(plan);
  fftw_destroy_plan(plan);
  for (std::size_t k = 0; k <= static_cast<std::size_t>(harmonics); ++k) {
    const double scale = (k == 0 ? 1.0 : 2.0) / n;
    a_.push_back(scale * out[k].real());
    b_.push_back(-scale * out[k].imag());
  }
  for (int i = 0; i < n; ++i)
    deviation_ = std::max(deviation_, std::abs(value(period * i / n) - y[static_cast<std::size_t>(i)]));
}

// Σ a_k cos kωt + b_k sin kωt, the harmonics by complex rotation from e^{iωt}.
double FourierSeries::value(double t) const {
  const std::complex<double> step = std::polar(1.0, omega_ * t);
  std::complex<double> e = 1.0;
  double v = 0.0;
  for (std::size_t k = 0; k < a_.size(); ++k, e *= step) v += a_[k] * e.real() + b_[k] * e.imag();
  return v;
}

double FourierSeries::derivative(double t) const {
  const std::complex<double> step = std::polar(1.0, omega_ * t);
  std::complex<double> e = step;
  double v = 0.0;
  for (std::size_t k = 1; k < a_.size(); ++k, e *= step)
    v += omega_ * static_cast<double>(k) * (b_[k] * e.real() - a_[k] * e.imag());
  return v;
}

// ---- HalfMesh ---------------------------------------------------------------------------

void HalfMeshOptions::validate() const {
  if (slices < 1 || slices > 10000)
    throw InputError(fmt::format("mesh.slices = {}: allowed range is [1, 10000]", slices));
  if (positions < 16 || positions > 100000)
    throw InputError(fmt::format("mesh.positions = {}: allowed range is [16, 100000]", positions));
  if (harmonics < 1 || 2 * harmonics >= positions)
    throw InputError(fmt::format("mesh.harmonics = {}: allowed range is [1, mesh.positions/2) = [1, {})", harmonics,
                                 (positions + 1) / 2));
  if (!(friction_coefficient >= 0.0 && friction_coefficient <= 0.5))
    throw InputError(fmt::format("friction.mu = {}: allowed range is [0, 0.5]", friction_coefficient));
}

namespace {
// Sliding reverses at the pitch point: λ = +1 beyond C (the pinion flank slides ahead),
// −1 before it (docs/dynamics-model.md, "Friction").
double sliding_sign(double s, const geometry::PathOfContact& path) { return s > path.C ? 1.0 : (s < path.C ? -1.0 : 0.0); }

constexpr int load_levels = 12;  // F_l = (l/4)·F_nom, l = 0..12
}  // namespace

// Arms ρ1 = s, ρ2 = T1T2 − s; `factor` is μ_c/scale of the friction law (1 for a constant μ).
void HalfMesh::Sums::add(double k_pair, double s, double lambda, const geometry::PathOfContact& path, double factor) {
  k += k_pair;
  k_rho1 += k_pair * lambda * s * factor;
  k_rho2 += k_pair * lambda * (path.T2 - s) * factor;
}

HalfMesh::Sums HalfMesh::loaded_sums(std::span<const Contact> contacts, double force, double length) const {
  double total = 0.0;
  for (const Contact& c : contacts) total += c.k;
  Sums sums;
  for (const Contact& c : contacts)
    sums.add(c.k, c.s, c.lambda, geometry_.path(), friction_.factor(c.s, std::abs(force) * c.k / total / length));
  return sums;
}

HalfMesh::HalfMesh(const geometry::GearPairGeometry& geometry, const std::array<model::Material, 2>& materials,
                   const model::OperatingPoint& operating, HalfMeshOptions options)
    : geometry_(geometry),
      options_((options.validate(), options)),
      pair_(geometry, materials, stiffness::ToothModel{stiffness::BeamStart::improved, options_.fillet},
            {0.5 * geometry.radii(0).root, 0.5 * geometry.radii(1).root}, std::nullopt, true),
      friction_(geometry, materials, operating, options_.friction_coefficient, options_.friction_law) {
  const double pinion_speed = operating.pinion_speed;
  if (!(pinion_speed > 0.0))
    throw InputError(fmt::format("operating.pinion_speed_rpm = {}: must be > 0", pinion_speed * 30.0 / M_PI));
  const auto& path = geometry_.path();
  std::vector<double> s(curve_nodes), k(curve_nodes);
  for (std::size_t i = 0; i < s.size(); ++i) {
    s[i] = path.A + (path.E - path.A) * static_cast<double>(i) / (curve_nodes - 1);
    k[i] = geometry_.pair().face_width * pair_.stiffness_per_width(s[i], true);
  }
  pair_curve_.emplace(std::move(s), std::move(k));
  speed_ = pinion_speed * geometry_.radii(0).base;
  period_ = geometry_.base_pitch_transverse() / speed_;
  const double halves = geometry_.pair().herringbone ? 2.0 : 1.0;
  nominal_force_ = operating.pinion_torque / halves / (geometry_.radii(0).base * std::cos(geometry_.base_helix_angle()));
  if (load_dependent_friction() && !(nominal_force_ > 0.0))
    throw InputError(fmt::format("operating.pinion_torque_Nm = {}: friction.model = {} needs a load > 0",
                                 operating.pinion_torque, lubricant::friction_model_name(options_.friction_law.model)));
  if (geometry_.base_helix_angle() > 0.0) {
    build_tables(materials);
  } else {
    // As the 6-DOF model: k̄ over the positions A + i·p_bt/N, the arms over the midpoints.
    constexpr int samples = 720;
    const double pb = geometry_.base_pitch_transverse();
    for (int i = 0; i < samples; ++i) {
      for (const double s0 : geometry_.positions_in_contact(path.A + pb * i / samples))
        mean_.stiffness += (*pair_curve_)(s0) / samples;
      std::vector<Contact> contacts;
      for (const double s0 : geometry_.positions_in_contact(path.A + pb * (i + 0.5) / samples))
        contacts.push_back({s0, (*pair_curve_)(s0), sliding_sign(s0, path)});
      const Sums sums = loaded_sums(contacts, nominal_force_, geometry_.pair().face_width);
      mean_.chi_pinion += friction_.scale() * sums.k_rho1 / sums.k / samples;
      mean_.chi_wheel += friction_.scale() * sums.k_rho2 / sums.k / samples;
    }
  }
}

// Helical half: every pair of every slice (helical_contacts, as stiffness::MeshStiffness::
// mesh_cycle slices the face) adds w·k'(s) to k_m and its share to the arms.
void HalfMesh::build_tables(const std::array<model::Material, 2>& materials) {
  stiffness::MeshStiffnessOptions mo;
  mo.positions = options_.positions;
  mo.slices = options_.slices;
  const auto sliced = stiffness::MeshStiffness(geometry_, materials, mo).solve();
  const double halves = geometry_.pair().herringbone ? 2.0 : 1.0;
  const auto& path = geometry_.path();
  const double pb = geometry_.base_pitch_transverse();
  const double b = geometry_.pair().face_width;
  const double w = b / options_.slices;
  const double line = w / std::cos(geometry_.base_helix_angle());  // contact-line length of a slice
  std::vector<double> k(static_cast<std::size_t>(options_.positions)), chi_p(k.size()), chi_g(k.size());
  for (std::size_t i = 0; i < k.size(); ++i) {
    const double s0 = path.A + pb * static_cast<double>(i) / static_cast<double>(k.size());
    const Sums sums = loaded_sums(helical_contacts(s0), nominal_force_, line);
    k[i] = sliced.mesh_stiffness[i] / halves;
    chi_p[i] = friction_.scale() * sums.k_rho1 / sums.k;
    chi_g[i] = friction_.scale() * sums.k_rho2 / sums.k;
    consistency_ = std::max(consistency_, std::abs(sums.k / k[i] - 1.0));
    mean_.stiffness += k[i] / static_cast<double>(k.size());
    mean_.chi_pinion += chi_p[i] / static_cast<double>(k.size());
    mean_.chi_wheel += chi_g[i] / static_cast<double>(k.size());
  }
  k_.emplace(period_, k, options_.harmonics);
  chi_p_.emplace(period_, chi_p, options_.harmonics);
  chi_g_.emplace(period_, chi_g, options_.harmonics);
  truncation_ = k_->max_table_deviation() / mean_.stiffness;
  if (load_dependent_friction()) build_load_levels();
}

// Slice j of width w at y_j = (j + ½)w meets the contact that is at s0 on the front face at
// s0 − y_j·tan β_b; each of its pairs has the stiffness w/b·k_pair(s).
std::vector<HalfMesh::Contact> HalfMesh::helical_contacts(double s0) const {
  const auto& path = geometry_.path();
  const double b = geometry_.pair().face_width, w = b / options_.slices;
  const double tan_bb = std::tan(geometry_.base_helix_angle());
  std::vector<Contact> contacts;
  for (int j = 0; j < options_.slices; ++j)
    for (const double s : geometry_.positions_in_contact(s0 - (j + 0.5) * w * tan_bb))
      contacts.push_back({s, w / b * (*pair_curve_)(s), sliding_sign(s, path)});
  return contacts;
}

// The arms' tables at F_l = (l/4)·F_nom, l = 0..12, each by its leading harmonics.
void HalfMesh::build_load_levels() {
  const auto& path = geometry_.path();
  const double pb = geometry_.base_pitch_transverse();
  const double line = geometry_.pair().face_width / options_.slices / std::cos(geometry_.base_helix_angle());
  const auto n = static_cast<std::size_t>(options_.positions);
  std::vector<std::vector<Contact>> contacts;
  for (std::size_t i = 0; i < n; ++i)
    contacts.push_back(helical_contacts(path.A + pb * static_cast<double>(i) / static_cast<double>(n)));
  for (int l = 0; l <= load_levels; ++l) {
    std::vector<double> chi_p(n), chi_g(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Sums sums = loaded_sums(contacts[i], nominal_force_ * l / 4.0, line);
      chi_p[i] = sums.k_rho1 / sums.k;
      chi_g[i] = sums.k_rho2 / sums.k;
    }
    chi_p_levels_.emplace_back(period_, chi_p, options_.harmonics);
    chi_g_levels_.emplace_back(period_, chi_g, options_.harmonics);
  }
}

std::array<double, 2> HalfMesh::arms(double t, double t_mid, double force) const {
  if (!k_) {
    const MeshPoint m = spur_point(t, t_mid, force);
    return {m.chi_pinion, m.chi_wheel};
  }
  // Linear in F between the levels, held at the top one.
  const double x = std::min(std::abs(force) / (nominal_force_ / 4.0), static_cast<double>(load_levels));
  const auto l = std::min(static_cast<std::size_t>(x), static_cast<std::size_t>(load_levels - 1));
  const double f = x - static_cast<double>(l);
  auto blend = [&](const std::vector<FourierSeries>& levels) {
    return (1.0 - f) * levels[l].value(t) + f * levels[l + 1].value(t);
  };
  return {blend(chi_p_levels_), blend(chi_g_levels_)};
}

// Spur half: the pairs of the interval holding t_mid, as in the 6-DOF model (pair j, j base
// pitches ahead of the newest, at s_j = A + u·t − n·p_bt + j·p_bt).
MeshPoint HalfMesh::spur_point(double t, double t_mid, double force) const {
  const auto& path = geometry_.path();
  const double pb = geometry_.base_pitch_transverse();
  const double n = std::floor(speed_ * t_mid / pb);
  auto k_at = [&](double s) { return (*pair_curve_)(std::clamp(s, path.A, path.E)); };
  std::array<Contact, 3> contacts{};
  std::size_t count = 0;
  double rate = 0.0;
  for (int j = 0; j < 3; ++j) {
    const double s_mid = path.A + speed_ * t_mid - n * pb + j * pb;
    if (s_mid < path.A || s_mid > path.E) continue;
    const double s = std::clamp(path.A + speed_ * t - n * pb + j * pb, path.A, path.E);
    // λ of the whole interval: intervals end where a pair passes C.
    contacts[count++] = {s, k_at(s), sliding_sign(s_mid, path)};
    // dk/dt = u·dk/ds by a central difference on the spline, one-sided at the path's ends.
    const double h = 1e-6 * (path.E - path.A);
    const double lo = std::max(path.A, s - h), hi = std::min(path.E, s + h);
    rate += speed_ * (k_at(hi) - k_at(lo)) / (hi - lo);
  }
  const Sums sums = loaded_sums(std::span(contacts.data(), count), force, geometry_.pair().face_width);
  const double mu = friction_.scale();
  return {sums.k, rate, sums.k > 0.0 ? mu * sums.k_rho1 / sums.k : 0.0, sums.k > 0.0 ? mu * sums.k_rho2 / sums.k : 0.0};
}

MeshPoint HalfMesh::at(double t, double t_mid) const {
  if (!k_) return spur_point(t, t_mid, nominal_force_);
  return {k_->value(t), k_->derivative(t), chi_p_->value(t), chi_g_->value(t)};
}

// Spur: once per mesh period each, a pair enters (u·t ≡ 0), the leading pair leaves
// (u·t ≡ E − A − p_bt) and a pair passes the pitch point (u·t ≡ C − A mod p_bt).
std::vector<double> HalfMesh::switch_times(double t0, double t1) const {
  std::vector<double> times;
  if (k_) return times;
  const auto& path = geometry_.path();
  const double pb = geometry_.base_pitch_transverse();
  const double exit_offset = std::fmod(path.E - path.A, pb) / speed_;
  const double pitch_offset = std::fmod(path.C - path.A, pb) / speed_;
  for (double base = std::floor(t0 / period_) * period_; base < t1 + period_; base += period_)
    for (const double t : {base, base + exit_offset, base + pitch_offset})
      if (t > t0 && t < t1) times.push_back(t);
  std::sort(times.begin(), times.end());
  return times;
}

}  // namespace gearbench::dynamics
