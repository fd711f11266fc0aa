#include "friction_laws.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "model/errors.h"

namespace gearbench::lubricant {
namespace {

/// Bounds that separate the unit system of a law from its neighbours (not the regression's
/// range of validity): a value outside names its key, its unit and the range.
void require(double value, double lo, double hi, const char* key, const char* unit, const char* hint) {
  if (!(value >= lo && value <= hi))
    throw InputError(fmt::format("{} = {:.6g} {}: allowed range is [{:g}, {:g}] {} ({})", key, value, unit, lo,
                                 hi, unit, hint));
}

/// Roughness given in metres reads as a few nanometres in µm: reject 0 < S < 1 nm.
void require_roughness_um(double value, double hi, const char* key) {
  require(value, 0.0, hi, key, "um", "roughness in micrometres");
  if (value > 0.0 && value < 1e-3)
    throw InputError(fmt::format("{} = {:.6g} um: below 1 nm, a value in metres? give micrometres", key, value));
}

// Xu et al. (2007) coefficients for 75W90 at 100 °C, as printed by seed 000 (table after eq. 10).
constexpr double b1 = -8.916465, b2 = 1.03303, b3 = 1.036077, b4 = -0.354068, b5 = 2.812084,
                 b6 = -0.100601, b7 = 0.752755, b8 = -0.390958, b9 = 0.620305;

constexpr double um = 1e-6;

}  // namespace

void XuKahramanInputs::validate() const {
  require(hertz_pressure_GPa, 1e-3, 10.0, "xu_kahraman.hertz_pressure", "GPa", "P_h in GPa, not Pa or MPa");
  require(slide_to_roll, -2.0, 2.0, "xu_kahraman.slide_to_roll", "-", "|u1 − u2|/ū ≤ 2");
  require(entrainment_m_s, 1e-6, 200.0, "xu_kahraman.entrainment", "m/s", "V_e in m/s");
  require(viscosity_cP, 0.5, 1e5, "xu_kahraman.viscosity", "cP", "absolute viscosity in cP = mPa·s, not Pa·s");
  require(radius_m, 1e-6, 1.0, "xu_kahraman.radius", "m", "R in metres, not millimetres");
  require_roughness_um(roughness_um, 10.0, "xu_kahraman.roughness");
}

// S is an rms roughness (REFERENCE-FACTS, after the public port): the mean of the flanks' Rq,
// from their mean Ra by the Gaussian ratio Rq/Ra = √(π/2).
XuKahramanInputs XuKahramanInputs::from_si(const ContactState& c) {
  return {c.hertz_pressure * 1e-9, c.slide_to_roll(), c.entrainment(), c.viscosity * 1e3, c.reduced_radius,
          std::sqrt(M_PI / 2.0) * c.roughness_Ra / um};
}

double xu_kahraman(const XuKahramanInputs& in) {
  in.validate();
  const double sr = std::abs(in.slide_to_roll);
  const double x = sr * in.hertz_pressure_GPa * std::log10(in.viscosity_cP);
  const double f = b1 + b4 * x + b5 * std::exp(-x) + b9 * std::exp(in.roughness_um);
  return std::exp(f) * std::pow(in.hertz_pressure_GPa, b2) * std::pow(sr, b3) * std::pow(in.entrainment_m_s, b6) *
         std::pow(in.viscosity_cP, b7) * std::pow(in.radius_m, b8);
}

void BenedictKelleyInputs::validate() const {
  require(load_per_length_N_m, 1.0, 1e9, "benedict_kelley.load_per_length", "N/m", "load per unit length in N/m");
  require(viscosity_cP, 0.5, 1e5, "benedict_kelley.viscosity", "cP", "viscosity in cP = mPa·s, not Pa·s");
  require(sliding_m_s, 0.0, 200.0, "benedict_kelley.sliding", "m/s", "|V_s| in m/s");
  require(rolling_sum_m_s, 1e-6, 400.0, "benedict_kelley.rolling_sum", "m/s", "u1 + u2 in m/s");
  // C_R = 50/(50 − S_avg[µin]) needs S_avg < 50 µin = 1.27 µm.
  require_roughness_um(roughness_um, 1.2, "benedict_kelley.roughness");
}

BenedictKelleyInputs BenedictKelleyInputs::from_si(const ContactState& c) {
  return {c.load_per_length, c.viscosity * 1e3, std::abs(c.sliding()), c.u1 + c.u2, c.roughness_Ra / um};
}

double benedict_kelley(const BenedictKelleyInputs& in) {
  in.validate();
  if (in.sliding_m_s == 0.0) return benedict_kelley_cap;
  const double s_avg_microinch = in.roughness_um / 0.0254;
  const double c_r = 50.0 / (50.0 - s_avg_microinch);
  const double argument =
      29.66 * in.load_per_length_N_m / (in.viscosity_cP * in.sliding_m_s * in.rolling_sum_m_s * in.rolling_sum_m_s);
  return std::clamp(0.0127 * c_r * std::log10(argument), 0.0, benedict_kelley_cap);
}

void Iso14179Inputs::validate() const {
  require(load_per_width_N_mm, 1e-3, 1e5, "iso14179.load_per_width", "N/mm", "F_bt/b in N/mm, not N/m");
  require(sum_velocity_m_s, 1e-6, 400.0, "iso14179.sum_velocity", "m/s", "v_ΣC in m/s");
  require(reduced_radius_mm, 0.05, 1e4, "iso14179.reduced_radius", "mm", "ρ_redC in mm, not m");
  require(viscosity_mPa_s, 0.5, 1e5, "iso14179.viscosity", "mPa*s", "η_oil in mPa·s, not Pa·s");
  require_roughness_um(roughness_um, 10.0, "operating.roughness_Ra_um (iso14179)");
  if (roughness_um <= 0.0)
    throw InputError("operating.roughness_Ra_um = 0: the ISO/TR 14179-2 coefficient grows as Ra^0.25 and needs Ra > 0");
  require(lubricant_factor, 0.1, 2.0, "friction.lubricant_factor", "-", "X_L, 1 for mineral oil");
}

double iso14179_mean(const Iso14179Inputs& in) {
  in.validate();
  return 0.048 * std::pow(in.load_per_width_N_mm / (in.sum_velocity_m_s * in.reduced_radius_mm), 0.2) *
         std::pow(in.viscosity_mPa_s, -0.05) * std::pow(in.roughness_um, 0.25) * in.lubricant_factor;
}

double fluid_load_share(double lambda) {
  if (!(lambda >= 0.0)) throw InputError(fmt::format("specific film thickness λ = {}: must be ≥ 0", lambda));
  if (lambda >= 2.0) return 1.0;  // the fit reaches 0.9995 at λ = 2 and exceeds 1 beyond
  return std::clamp(1.21 * std::pow(lambda, 0.64) / (1.0 + 0.37 * std::pow(lambda, 1.26)), 0.0, 1.0);
}

double composite_rms_roughness(double ra1, double ra2) {
  const double k = std::sqrt(M_PI / 2.0);  // Rq/Ra of a Gaussian height distribution
  return std::hypot(k * ra1, k * ra2);
}

double mixed_friction(double fluid_share, double mu_full_film, double mu_boundary) {
  return fluid_share * mu_full_film + (1.0 - fluid_share) * mu_boundary;
}

double friction_coefficient(const FrictionLaw& law, const ContactState& c) {
  switch (law.model) {
    case FrictionModel::constant: return law.constant_mu;
    case FrictionModel::iso14179: return law.iso14179_mu;
    case FrictionModel::benedict_kelley: return benedict_kelley(BenedictKelleyInputs::from_si(c));
    case FrictionModel::xu_kahraman: return xu_kahraman(XuKahramanInputs::from_si(c));
    case FrictionModel::mixed: {
      const double share = law.composite_roughness > 0.0 ? fluid_load_share(c.film_thickness / law.composite_roughness) : 1.0;
      return mixed_friction(share, xu_kahraman(XuKahramanInputs::from_si(c)), law.boundary_mu);
    }
    case FrictionModel::ehl:
    case FrictionModel::ehl_thermal: break;
  }
  throw InputError(fmt::format("friction.model = \"{}\": no closed-form coefficient; allowed are \"constant\", "
                               "\"xu_kahraman\", \"benedict_kelley\", \"iso14179\", \"mixed\"",
                               friction_model_name(law.model)));
}

FrictionModel parse_friction_model(const std::string& name, const std::string& key) {
  for (const auto m : {FrictionModel::constant, FrictionModel::xu_kahraman, FrictionModel::benedict_kelley,
                       FrictionModel::iso14179, FrictionModel::mixed, FrictionModel::ehl, FrictionModel::ehl_thermal})
    if (friction_model_name(m) == name) return m;
  throw InputError(fmt::format("{} = \"{}\": allowed are \"constant\", \"xu_kahraman\", \"benedict_kelley\", "
                               "\"iso14179\", \"mixed\", \"ehl\", \"ehl_thermal\"", key, name));
}

std::string friction_model_name(FrictionModel model) {
  switch (model) {
    case FrictionModel::constant: return "constant";
    case FrictionModel::xu_kahraman: return "xu_kahraman";
    case FrictionModel::benedict_kelley: return "benedict_kelley";
    case FrictionModel::iso14179: return "iso14179";
    case FrictionModel::mixed: return "mixed";
    case FrictionModel::ehl: return "ehl";
    case FrictionModel::ehl_thermal: return "ehl_thermal";
  }
  return "constant";
}

}  // namespace gearbench::lubricant
