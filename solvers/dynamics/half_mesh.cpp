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

void FourierSeries::evaluate(double t, std::span<const FourierSeries* const> series, std::span<double> values,
                             double& first_derivative) {
  const FourierSeries& first = *series.front();
  for (const FourierSeries* f : series)
    if (f->a_.size() != first.a_.size() || f->omega_ != first.omega_)
      throw std::logic_error("FourierSeries::evaluate: series of different periods or lengths");
  std::fill(values.begin(), values.end(), 0.0);
  first_derivative = 0.0;
  // As value() does, term by term, on the same rotations.
  const std::complex<double> step = std::polar(1.0, first.omega_ * t);
  std::complex<double> e = 1.0;
  for (std::size_t k = 0; k < first.a_.size(); ++k, e *= step) {
    for (std::size_t j = 0; j < series.size(); ++j) values[j] += series[j]->a_[k] * e.real() + series[j]->b_[k] * e.imag();
    if (k > 0) first_derivative += first.omega_ * static_cast<double>(k) * (first.b_[k] * e.real() - first.a_[k] * e.imag());
  }
}

// ---- HalfMesh ---------------------------------------------------------------------------

void HalfMeshOptions::validate() const {
  table().validate(*this, "mesh.");
  friction.validate();
}

namespace {
constexpr int load_levels = 12;  // F_l = (l/4)·F_nom, l = 0..12
}  // namespace

HalfMesh::HalfMesh(const geometry::GearPairGeometry& geometry, const std::array<model::Material, 2>& materials,
                   const model::OperatingPoint& operating, HalfMeshOptions options)
    : geometry_(geometry),
      options_((options.validate(), options)),
      spur_(geometry, materials, operating.pinion_speed, options_.fillet),
      friction_(geometry, materials, operating, options_.friction) {
  period_ = spur_.period();
  const double halves = geometry_.pair().herringbone ? 2.0 : 1.0;
  nominal_force_ = operating.pinion_torque / halves / (geometry_.radii(0).base * std::cos(geometry_.base_helix_angle()));
  if (load_dependent_friction() && !(nominal_force_ > 0.0))
    throw InputError(fmt::format("operating.pinion_torque_Nm = {}: friction.model = {} needs a load > 0",
                                 operating.pinion_torque, lubricant::friction_model_name(options_.friction.friction_model)));
  if (geometry_.base_helix_angle() > 0.0) {
    build_tables(materials);
  } else {
    mean_.stiffness = spur_.mean_stiffness();
    const auto arms = spur_.mean_arms(friction_, nominal_force_);
    mean_.chi_pinion = arms[0];
    mean_.chi_wheel = arms[1];
  }
}

// Helical half: every pair of every slice (helical_contacts, as stiffness::MeshStiffness::
// mesh_cycle slices the face) adds w·k'(s) to k_m and its share to the arms.
void HalfMesh::build_tables(const std::array<model::Material, 2>& materials) {
  stiffness::MeshStiffnessOptions mo;
  mo.positions = options_.positions;
  mo.slices = options_.slices;
  mo.fillet = options_.fillet;
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
    const auto contacts = helical_contacts(s0);
    const auto arms = friction_arms(contacts, friction_, path.T2, nominal_force_, line);
    double k_sum = 0.0;
    for (const MeshContact& c : contacts) k_sum += c.k;
    k[i] = sliced.mesh_stiffness[i] / halves;
    chi_p[i] = arms[0];
    chi_g[i] = arms[1];
    consistency_ = std::max(consistency_, std::abs(k_sum / k[i] - 1.0));
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
std::vector<MeshContact> HalfMesh::helical_contacts(double s0) const {
  const auto& path = geometry_.path();
  const double b = geometry_.pair().face_width, w = b / options_.slices;
  const double tan_bb = std::tan(geometry_.base_helix_angle());
  std::vector<MeshContact> contacts;
  for (int j = 0; j < options_.slices; ++j)
    for (const double s : geometry_.positions_in_contact(s0 - (j + 0.5) * w * tan_bb))
      contacts.push_back({s, w / b * spur_.pair_stiffness(s), sliding_sign(s, path.C)});
  return contacts;
}

// The arms' tables at F_l = (l/4)·F_nom, l = 0..12, each by its leading harmonics.
void HalfMesh::build_load_levels() {
  const auto& path = geometry_.path();
  const double pb = geometry_.base_pitch_transverse();
  const double line = geometry_.pair().face_width / options_.slices / std::cos(geometry_.base_helix_angle());
  const auto n = static_cast<std::size_t>(options_.positions);
  std::vector<std::vector<MeshContact>> contacts;
  for (std::size_t i = 0; i < n; ++i)
    contacts.push_back(helical_contacts(path.A + pb * static_cast<double>(i) / static_cast<double>(n)));
  for (int l = 0; l <= load_levels; ++l) {
    std::vector<double> chi_p(n), chi_g(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto arms = friction_arms(contacts[i], friction_, path.T2, nominal_force_ * l / 4.0, line);
      chi_p[i] = arms[0];
      chi_g[i] = arms[1];
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
  const std::array<const FourierSeries*, 4> series{&chi_p_levels_[l], &chi_p_levels_[l + 1], &chi_g_levels_[l],
                                                    &chi_g_levels_[l + 1]};
  std::array<double, 4> v{};
  double unused = 0.0;
  FourierSeries::evaluate(t, series, v, unused);
  return {(1.0 - f) * v[0] + f * v[1], (1.0 - f) * v[2] + f * v[3]};
}

// Spur half: the pairs of the interval holding t_mid, those of the 6-DOF model (SpurMesh),
// the arms at their shares of `force`.
MeshPoint HalfMesh::spur_point(double t, double t_mid, double force) const {
  std::array<MeshContact, 3> contacts{};
  std::size_t count = 0;
  MeshPoint m;
  for (const SpurPair& p : spur_.pairs(t, t_mid)) {
    contacts[count++] = {p.s, p.stiffness, p.lambda};
    m.stiffness += p.stiffness;
    m.rate += p.rate;
  }
  const auto arms =
      friction_arms(std::span(contacts.data(), count), friction_, geometry_.path().T2, force, geometry_.pair().face_width);
  m.chi_pinion = arms[0];
  m.chi_wheel = arms[1];
  return m;
}

MeshPoint HalfMesh::at(double t, double t_mid) const {
  if (!k_) return spur_point(t, t_mid, nominal_force_);
  const std::array<const FourierSeries*, 3> series{&*k_, &*chi_p_, &*chi_g_};
  std::array<double, 3> v{};
  double rate = 0.0;
  FourierSeries::evaluate(t, series, v, rate);
  return {v[0], rate, v[1], v[2]};
}

std::vector<double> HalfMesh::switch_times(double t0, double t1) const {
  if (k_) return {};
  return spur_.break_times(t0, t1);
}

}  // namespace gearbench::dynamics
