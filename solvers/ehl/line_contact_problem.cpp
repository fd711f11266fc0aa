#include "line_contact_problem.h"

#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "lubricant/rheology.h"
#include "model/errors.h"

namespace gearbench::ehl {

namespace {
constexpr double pi = std::numbers::pi;
constexpr double martin_load_constant = 4.8950;  // w·h0/(η0·ū·R), Reynolds outlet (Martin 1916)
constexpr double moes_switch = 3.0;              // Hertzian scaling from M = 3 upward

/// The gap outside a Hertzian line contact, in units of b²/R at X = x/b ≥ 1 (Johnson 1985,
/// §5.6): ½(X√(X² − 1) − arcosh X), whose derivative is √(X² − 1).
double hertzian_gap(double X) { return 0.5 * (X * std::sqrt(X * X - 1.0) - std::acosh(X)); }

/// The X ≥ 1 at which the Hertzian gap is g, by Newton's method from the parabola's √(2g) + 1
/// (an upper bound: the gap lies below X²/2); the gap is convex there, so the iterates fall
/// monotonically to the root.
double where_gap_is(double g) {
  double X = std::sqrt(2.0 * g) + 1.0;
  for (int k = 0; k < 50; ++k) {
    const double step = (hertzian_gap(X) - g) / std::sqrt(X * X - 1.0);
    X -= step;
    if (std::abs(step) <= 1e-12 * X) break;
  }
  return X;
}

/// The inlet's film deficit, measured (seventeenth session) as the central film on an inlet at
/// X_in against one at 3–4 times that distance, 8193 nodes: d ≈ c·(H̄_c/g(X_in))^1.5 with c
/// 1.19–1.51 at (M, L) = (10, 0), (20, 10), (10, 17.5), (5, 25), (3, 20), H̄_c = h_c·R/b² the
/// central film and g the Hertzian gap at the inlet. The domain is chosen for a deficit of at
/// most 1e-3, a fifth of the default 0.5 % discretisation-error target.
constexpr double inlet_deficit_coefficient = 1.5;  // c, the largest measured rounded up
constexpr double inlet_deficit_exponent = 1.5;
constexpr double inlet_deficit = 1e-3;
}  // namespace

double moes_central_film(double M, double L) {
  const double rigid_iso = 3.0 / M, elastic_iso = 2.621 * std::pow(M, -0.2);
  const double isoviscous_sum = std::pow(rigid_iso, 7.0 / 3.0) + std::pow(elastic_iso, 7.0 / 3.0);
  if (L <= 0.0) return std::pow(isoviscous_sum, 3.0 / 7.0);  // both piezoviscous asymptotes vanish
  const double s = (7.0 + 8.0 * std::exp(-2.0 * elastic_iso / rigid_iso)) / 5.0;
  const double isoviscous = std::pow(isoviscous_sum, 3.0 * s / 7.0);
  const double rigid_piezo = 1.287 * std::pow(L, 2.0 / 3.0);
  const double elastic_piezo = 1.311 * std::pow(M, -0.125) * std::pow(L, 0.75);
  const double piezoviscous = std::pow(std::pow(rigid_piezo, -3.5) + std::pow(elastic_piezo, -3.5), -2.0 * s / 7.0);
  return std::pow(isoviscous + piezoviscous, 1.0 / s);
}

double LineContactData::moes_speed_sum() const { return viscosity * (u1 + u2) / (reduced_modulus * reduced_radius); }

double LineContactData::moes_film_scale() const { return reduced_radius * std::sqrt(moes_speed_sum()); }

double LineContactData::moes_M() const {
  return load_per_length / (reduced_modulus * reduced_radius) / std::sqrt(moes_speed_sum());
}

double LineContactData::moes_L() const { return pressure_viscosity * reduced_modulus * std::pow(moes_speed_sum(), 0.25); }

LineContactData LineContactData::from_moes(double M, double L) {
  LineContactData d;
  d.reduced_radius = 0.01;
  d.reduced_modulus = 2.2e11;
  d.viscosity = 0.04;
  d.u1 = d.u2 = 1.0;
  const double U_sum = d.moes_speed_sum();
  d.load_per_length = M * std::sqrt(U_sum) * d.reduced_modulus * d.reduced_radius;
  d.pressure_viscosity = L / std::pow(U_sum, 0.25) / d.reduced_modulus;
  d.viscosity_model = ViscosityModel::barus;
  d.density_model = DensityModel::incompressible;
  d.pressure_viscosity_key = "moes.L";
  return d;
}

LineContactData LineContactData::from_gear_media(const std::array<model::Material, 2>& materials,
                                                 const model::Lubricant& lubricant) {
  LineContactData d;
  d.reduced_modulus = model::reduced_modulus(materials);
  d.viscosity = lubricant.viscosity;
  d.pressure_viscosity = lubricant.pressure_viscosity;
  d.roelands_z = lubricant.roelands_z.value_or(0.0);
  return d;
}

LineContactProblem::LineContactProblem(const LineContactData& data) : data_(data) {
  const double R = data.reduced_radius;
  const double w = data.load_per_length;
  const double E = data.reduced_modulus;
  const double u = data.mean_speed();
  // Hertz line contact: b = √(8wR/(πE′)), p_h = 2w/(πb).
  b_ = std::sqrt(8.0 * w * R / (pi * E));
  p_h_ = 2.0 * w / (pi * b_);
  hertzian_ = data.moes_M() >= moes_switch;
  if (hertzian_) {
    ell_ = b_;
    p_r_ = p_h_;
  } else {
    const double h_martin = martin_load_constant * data.viscosity * u * R / w;
    ell_ = std::sqrt(2.0 * R * h_martin);
    p_r_ = w / ell_;
  }
  lambda_ = 12.0 * data.viscosity * u * R * R / (ell_ * ell_ * ell_ * p_r_);
  D_ = 4.0 * p_r_ * R / (E * ell_);
  F_ = w / (p_r_ * ell_);
  // Roelands' asymptote η∞ = 6.31e-5 Pa·s: at or below it the law no longer rises with p.
  const double eta_inf = std::exp(-lubricant::roelands_ln_eta_inf);
  if (data.viscosity_model == ViscosityModel::roelands && data.viscosity <= eta_inf)
    throw InputError(fmt::format("lubricant.viscosity_Pa_s = {:.6g}: allowed is > {:.3g} Pa*s (Roelands' "
                                 "asymptotic viscosity) with viscosity_model \"roelands\"", data.viscosity, eta_inf));
  roelands_z_ = data.roelands_z > 0.0 ? data.roelands_z
                                      : lubricant::roelands_z_from_alpha(data.viscosity, data.pressure_viscosity);
  // Barus at ᾱ = α·p_h beyond ~40 means η/η0 ~ e^40 and more: no meaningful lubricant.
  const double alpha_bar = data.pressure_viscosity * p_h_;
  if (data.viscosity_model == ViscosityModel::barus && alpha_bar > 40.0) {
    const std::string value = data.pressure_viscosity_key == "moes.L"
                                  ? fmt::format("{:.6g}", data.moes_L())
                                  : fmt::format("{:.6g}", data.pressure_viscosity * 1e9);
    const std::string allowed = data.pressure_viscosity_key == "moes.L"
                                    ? fmt::format("L <= {:.4g} at this M", data.moes_L() * 40.0 / alpha_bar)
                                    : fmt::format("<= {:.4g} 1/GPa at this load", 40.0 / p_h_ * 1e-9);
    throw InputError(fmt::format("{} = {}: ᾱ = α·p_h = {:.1f} exceeds 40 (viscosity ratio e^{:.0f} at the "
                                 "Hertz pressure with Barus); allowed is {}",
                                 data.pressure_viscosity_key, value, alpha_bar, alpha_bar, allowed));
  }
}

double LineContactProblem::x_in() const {
  if (!hertzian_) return -40.0;
  const double M = data_.moes_M();
  // Moes' film in Hertzian units: H̄ = h·R/b² = (π/8M)·H_Moes.
  const double film = pi / (8.0 * M) * moes_central_film(M, data_.moes_L());
  // d = c·(H̄/g)^1.5 ≤ inlet_deficit where g ≥ (c/d)^(1/1.5)·H̄ = 131·H̄.
  const double flooded_gap = std::pow(inlet_deficit_coefficient / inlet_deficit, 1.0 / inlet_deficit_exponent) * film;
  return -std::max(4.5 + 6.0 * 1.535 / M, where_gap_is(flooded_gap));
}

double LineContactProblem::x_out() const {
  if (!hertzian_) return 3.0;
  return 1.5 + 1.535 / data_.moes_M();
}

double LineContactProblem::isoviscous_film() const {
  return moes_central_film(data_.moes_M(), 0.0) * data_.moes_film_scale() / film_scale();
}

double LineContactProblem::viscosity(double P) const {
  const double p = std::max(P, 0.0) * p_r_;
  if (data_.viscosity_model == ViscosityModel::barus)
    return lubricant::barus_viscosity(1.0, data_.pressure_viscosity, p);
  return lubricant::roelands_viscosity(data_.viscosity, roelands_z_, p) / data_.viscosity;
}

double LineContactProblem::log_viscosity(double P) const {
  const double p = std::max(P, 0.0) * p_r_;
  if (data_.viscosity_model == ViscosityModel::barus) return lubricant::barus_log_ratio(data_.pressure_viscosity, p);
  return lubricant::roelands_log_ratio(data_.viscosity, roelands_z_, p);
}

double LineContactProblem::density(double P) const {
  if (data_.density_model == DensityModel::incompressible) return 1.0;
  return lubricant::dowson_higginson_density_ratio(std::max(P, 0.0) * p_r_);
}

double LineContactProblem::log_viscosity_slope(double P) const {
  if (P < 0.0) return 0.0;
  if (data_.viscosity_model == ViscosityModel::barus) return data_.pressure_viscosity * p_r_;
  return lubricant::roelands_log_ratio_slope(data_.viscosity, roelands_z_, P * p_r_) * p_r_;
}

double LineContactProblem::density_slope(double P) const {
  if (P < 0.0 || data_.density_model == DensityModel::incompressible) return 0.0;
  return lubricant::dowson_higginson_density_slope(P * p_r_) * p_r_;
}

}  // namespace gearbench::ehl
