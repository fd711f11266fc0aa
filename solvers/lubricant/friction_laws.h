#pragma once
// Friction laws of a lubricated gear contact, each a small function citing its source and
// the units it was fitted in. Every regression takes its inputs in the units of its source
// (the field names say which) and rejects values that can only come from another unit
// system; `ContactState` carries the same data in SI and the adapters convert.
#include <string>

namespace gearbench::lubricant {

/// One contact point of a gear mesh in SI units.
struct ContactState {
  double load_per_length = 0.0;   ///< w = F/l [N/m]
  double reduced_radius = 0.0;    ///< R (normal section) [m]
  double u1 = 0.0, u2 = 0.0;      ///< surface speeds along the profile [m/s]
  double hertz_pressure = 0.0;    ///< p_h = √(w·E′/(2πR)) [Pa]
  double film_thickness = 0.0;    ///< h_min [m]
  double viscosity = 0.0;         ///< η0 at the oil temperature [Pa·s]
  double roughness_Ra = 0.0;      ///< mean arithmetic roughness (Ra1 + Ra2)/2 [m]

  [[nodiscard]] double sliding() const { return u1 - u2; }
  [[nodiscard]] double entrainment() const { return 0.5 * (u1 + u2); }
  [[nodiscard]] double slide_to_roll() const { return sliding() / entrainment(); }
};

// --- Xu & Kahraman ---------------------------------------------------------------------------

/// Inputs of the Xu–Kahraman regression in the units it was fitted in.
struct XuKahramanInputs {
  double hertz_pressure_GPa = 0.0;   ///< P_h [GPa]
  double slide_to_roll = 0.0;        ///< SR = u_s/ū [-]
  double entrainment_m_s = 0.0;      ///< V_e = (u1 + u2)/2 [m/s]
  double viscosity_cP = 0.0;         ///< ν0, absolute (dynamic) viscosity [cP = mPa·s]
  double radius_m = 0.0;             ///< R, effective radius of curvature [m]
  double roughness_um = 0.0;         ///< S, rms surface roughness [µm] (from_si: mean Rq of the flanks)

  /// InputError when a value lies outside what the unit system allows (e.g. P_h given in
  /// Pa or MPa, ν0 in Pa·s, R in mm, S in m).
  void validate() const;
  static XuKahramanInputs from_si(const ContactState& c);
};

/// Xu, Kahraman, Anderson & Maddock, J. Mech. Des. 129 (2007) 58, eqs. (4)–(5), as used by
/// seed 000 (eqs. 9–10, 75W90 coefficients b1..b9 of its table):
///   μ = e^f·P_h^b2·|SR|^b3·V_e^b6·ν0^b7·R^b8,
///   f = b1 + b4·|SR|·P_h·log10 ν0 + b5·e^(−|SR|·P_h·log10 ν0) + b9·e^S.
/// Seed 000 prints b4 in front of the exponential term; the original has b5 there (b5 is
/// otherwise unused), and that is what is coded.
double xu_kahraman(const XuKahramanInputs& in);

// --- Benedict & Kelley -----------------------------------------------------------------------

/// Inputs of Benedict & Kelley in the SI form of the law.
struct BenedictKelleyInputs {
  double load_per_length_N_m = 0.0;  ///< w [N/m]
  double viscosity_cP = 0.0;         ///< η [cP]
  double sliding_m_s = 0.0;          ///< |V_s| [m/s]
  double rolling_sum_m_s = 0.0;      ///< V_r = u1 + u2 [m/s]
  double roughness_um = 0.0;         ///< S_avg, mean roughness of the flanks [µm]

  void validate() const;
  static BenedictKelleyInputs from_si(const ContactState& c);
};

/// Benedict & Kelley, ASLE Trans. 4 (1961) 59, in the form quoted by Xu et al. (2007):
///   μ = 0.0127·C_R·log10[3.17e8·W/(ν0·V_s·V_r²)],  C_R = 50/(50 − S_avg),
/// W in lb/in, ν0 in cP, V in in/s, S_avg in µin. In SI (W in N/m, V in m/s):
/// 3.17e8·0.0254³/175.127 = 29.66 (REFERENCE-FACTS), and S_avg[µin] = S[µm]/0.0254.
/// The law diverges where V_s → 0 (the pitch point); the coefficient is capped at
/// `benedict_kelley_cap` and floored at 0 where the logarithm turns negative.
double benedict_kelley(const BenedictKelleyInputs& in);
/// Cap of μ for Benedict & Kelley near the pitch point: the top of the measured boundary
/// range 0.07–0.15 of seed 000 (a full film cannot exceed boundary friction).
inline constexpr double benedict_kelley_cap = 0.15;

// --- ISO/TR 14179-2 (Schlenk) ----------------------------------------------------------------

/// Inputs of the ISO/TR 14179-2 mean coefficient at the pitch point.
struct Iso14179Inputs {
  double load_per_width_N_mm = 0.0;    ///< F_bt/b, transverse force on the base circle per face width [N/mm]
  double sum_velocity_m_s = 0.0;       ///< v_ΣC = u1 + u2 at the pitch point [m/s]
  double reduced_radius_mm = 0.0;      ///< ρ_redC at the pitch point (normal section) [mm]
  double viscosity_mPa_s = 0.0;        ///< η_oil at the oil temperature [mPa·s]
  double roughness_um = 0.0;           ///< Ra = (Ra1 + Ra2)/2 [µm]
  double lubricant_factor = 1.0;       ///< X_L: 1 for mineral oil

  void validate() const;
};

/// ISO/TR 14179-2:2001 (after Schlenk, 1994), mean coefficient over the mesh:
///   μ_mZ = 0.048·[(F_bt/b)/(v_ΣC·ρ_redC)]^0.2·η_oil^−0.05·Ra^0.25·X_L.
double iso14179_mean(const Iso14179Inputs& in);

// --- Mixed lubrication -----------------------------------------------------------------------

/// Fluid share of the load f(λ) at specific film thickness λ = h_min/σ: the fit of
/// Zhou & Hoeprich, J. Tribol. 113 (1991) 590, f = 1.21·λ^0.64/(1 + 0.37·λ^1.26), as used
/// for the mixed friction of gear teeth (e.g. Wang & Chen 2014, seed 004 ref. [5]).
/// The fit reaches 0.9995 at λ = 2, exceeds 1 up to λ ≈ 2.7 and turns down beyond;
/// gearbench takes f = 1 (full film) for λ ≥ 2. The coefficients were not re-read from the
/// primary text (verify).
double fluid_load_share(double lambda);

/// Composite roughness σ = √(Rq1² + Rq2²) from the flanks' Ra with Rq = 1.25·Ra (Gaussian
/// heights: Rq/Ra = √(π/2)).
double composite_rms_roughness(double ra1, double ra2);

/// μ = f·μ_EL + (1 − f)·μ_BL (seed 000 eq. 8).
double mixed_friction(double fluid_share, double mu_full_film, double mu_boundary);

// --- Selection ---------------------------------------------------------------------------

enum class FrictionModel { constant, xu_kahraman, benedict_kelley, iso14179, mixed, ehl, ehl_thermal };

/// The laws computed by an EHL solver at every contact (efficiency/ehl_friction.h), not by a closed form.
inline bool solved_by_ehl(FrictionModel m) { return m == FrictionModel::ehl || m == FrictionModel::ehl_thermal; }

/// "constant" | "xu_kahraman" | "benedict_kelley" | "iso14179" | "mixed" | "ehl" | "ehl_thermal"; InputError
/// naming `key` otherwise.
FrictionModel parse_friction_model(const std::string& name, const std::string& key);
std::string friction_model_name(FrictionModel model);

/// A chosen law with what it needs beyond the contact state.
struct FrictionLaw {
  FrictionModel model = FrictionModel::constant;
  double constant_mu = 0.05;          ///< μ of the constant law
  double boundary_mu = 0.1;           ///< μ_BL of the mixed law
  double composite_roughness = 0.0;   ///< σ = composite_rms_roughness(Ra1, Ra2) of the mixed law [m]
  double iso14179_mu = 0.0;           ///< μ_mZ of the pair (iso14179_mean at its pitch point)
};

/// μ of `law` at the contact `c` (the film thickness is read by the mixed law only; with
/// σ = 0 the mixed law is the full-film Xu–Kahraman coefficient). InputError for the "ehl"
/// and "ehl_thermal" models, which have no closed form.
double friction_coefficient(const FrictionLaw& law, const ContactState& c);

}  // namespace gearbench::lubricant
