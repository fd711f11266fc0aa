#pragma once
// Closed-form references for the EHL line contact, written independently of solvers/ (no
// code shared; no solvers/model data needed). The multigrid solver is checked against them.
//
// Sources and conventions: docs/research/ehl.md (the verified facts) and
// /work/shared/REFERENCE-FACTS.md, section "EHL (line contact)". The two agree on every
// formula used here. Where REFERENCE-FACTS is silent, docs/research/ehl.md is followed:
// the Pan–Hamrock coefficients (§1), the sum speed in Moes' groups and the film at
// dp/dx = 0 as Moes' film (§3), and the Martin constants (§4).
//
// SI units throughout. Speeds: ū = (u1 + u2)/2 is the mean (entrainment) speed,
// u_Σ = u1 + u2 the sum speed. A capital H is a dimensionless film; a lower-case h is in
// metres.
//
// !! Pan–Hamrock (pan_hamrock_H_min, pan_hamrock_H_c): COEFFICIENTS NOT VERIFIED AT THE
// !! SOURCE. docs/research/ehl.md §1 tags them [NOT FOUND] (quoted from memory of the
// !! literature; the paper was not readable). Use them as a ±35 % sanity band only.

#include <numbers>

namespace gearbench::reference {

/// Inputs of a smooth, steady line contact.
struct LineContact {
  double reduced_radius = 0.0;      ///< R, 1/R = 1/R1 + 1/R2 [m]
  double load_per_length = 0.0;     ///< w [N/m]
  double u1 = 0.0;                  ///< surface speed of body 1 [m/s]
  double u2 = 0.0;                  ///< surface speed of body 2 [m/s]
  double reduced_modulus = 0.0;     ///< E', 2/E' = (1−ν1²)/E1 + (1−ν2²)/E2 [Pa]
  double viscosity = 0.0;           ///< η0 at ambient pressure [Pa·s]
  double pressure_viscosity = 0.0;  ///< α [1/Pa]
};

// ---- Dimensionless groups -------------------------------------------------------------
// Definitions (docs/research/ehl.md, Notation, §3 and §5; Venner & Lubrecht, Multilevel
// Methods in Lubrication, Elsevier 2000): exact by definition, no accuracy to state.

/// ū = (u1 + u2)/2 [m/s].
double mean_speed(const LineContact& c);
/// Dowson–Higginson speed parameter U = η0·ū/(E'R), ū the mean speed.
double speed_parameter(const LineContact& c);
/// Materials parameter G = α·E'.
double materials_parameter(const LineContact& c);
/// Line-contact load parameter W = w/(E'R) (not the point-contact F/(E'R²)).
double load_parameter(const LineContact& c);
/// Moes' speed parameter U_Σ = η0(u1 + u2)/(E'R) = 2U (sum speed).
double moes_speed_parameter(const LineContact& c);
/// Moes' load parameter M = W·U_Σ^(−1/2).
double moes_load_parameter(const LineContact& c);
/// Moes' materials parameter L = G·U_Σ^(1/4).
double moes_materials_parameter(const LineContact& c);
/// Venner's pressure–viscosity group ᾱ = α·p_h (= L·√(M/2π), ehl.md §5).
double venner_alpha_bar(const LineContact& c);
/// Venner's λ̄ = 12·η0·ū·R²/(b³·p_h), ū the mean speed (= 3π²/(8M²), ehl.md §5).
double venner_lambda_bar(const LineContact& c);

// ---- Hertz line contact ----------------------------------------------------------------
// Hertz (1882); Johnson, Contact Mechanics (CUP 1985), pp. 99–104. Exact for frictionless
// linear-elastic half-spaces (b ≪ R); no error figure stated.

/// Half-width b = R·√(8W/π) [m].
double hertz_half_width(const LineContact& c);
/// Maximum pressure p_h = E'·√(W/(2π)) [Pa].
double hertz_max_pressure(const LineContact& c);
/// Dry pressure p(x) = p_h·√(1 − x²/b²) for |x| < b, zero outside [Pa].
double hertz_pressure(const LineContact& c, double x);

// ---- Regression fits (film over reduced radius, H = h/R) -------------------------------
// Dowson & Higginson, Elasto-hydrodynamic Lubrication (1966/1977); Dowson & Toyoda, Proc.
// 5th Leeds–Lyon Symp. (1978/79); Pan & Hamrock, J. Tribol. 111 (1989) 246 (UNVERIFIED).
// U uses the mean speed (ehl.md §2 [CONSISTENCY]). Accuracy not stated for any of them.

/// Dowson–Higginson minimum film H_min = 2.65·U^0.70·G^0.54·W^−0.13.
double dowson_higginson_H_min(double U, double G, double W);
/// Dowson–Toyoda central film H_c = 3.06·U^0.69·G^0.56·W^−0.10.
double dowson_toyoda_H_c(double U, double G, double W);
/// Pan–Hamrock minimum film H_min = 1.714·W^−0.128·U^0.694·G^0.568 (NOT VERIFIED, see top).
double pan_hamrock_H_min(double U, double G, double W);
/// Pan–Hamrock central film H_c = 2.922·W^−0.166·U^0.692·G^0.470 (NOT VERIFIED, see top).
double pan_hamrock_H_c(double U, double G, double W);

/// The fits above in metres, with U, G, W from the contact: h = H·R.
double dowson_higginson_h_min(const LineContact& c);
double dowson_toyoda_h_c(const LineContact& c);
double pan_hamrock_h_min(const LineContact& c);
double pan_hamrock_h_c(const LineContact& c);

// ---- Moes line-contact film (H = (h/R)·U_Σ^(−1/2), the film where dp/dx = 0) ------------
// Moes (1992) as given by Venner & Lubrecht (2000); docs/research/ehl.md §3 (H_RI exact,
// coefficients [CONSISTENCY]: within 0–9 % of Dowson–Toyoda). Accuracy not stated.

/// Moes' four asymptotes: rigid-isoviscous, elastic-isoviscous, rigid-piezoviscous,
/// elastic-piezoviscous.
struct MoesAsymptotes {
  double H_RI = 0.0;  ///< 3/M (exact, = Martin's film at the pressure peak)
  double H_EI = 0.0;  ///< 2.621·M^(−1/5)
  double H_RP = 0.0;  ///< 1.287·L^(2/3)
  double H_EP = 0.0;  ///< 1.311·M^(−1/8)·L^(3/4)
};

MoesAsymptotes moes_asymptotes(double M, double L);
/// Moes' combined film H(M, L); L = 0 is the isoviscous case.
double moes_H(double M, double L);
/// Moes' film in metres for a contact.
double moes_h(const LineContact& c);
/// Converters between Moes' H and h in metres: h = H·R·√U_Σ.
double moes_H_to_metres(double H, const LineContact& c);
double metres_to_moes_H(double h, const LineContact& c);

// ---- Thermal reduction of the central film (Gupta et al.) -------------------------------
// Gupta, Cheng, Zhu & Wang, J. Tribol. 114 (1992) 676, curve fit to their Newtonian thermal
// line-contact solutions, in the form quoted by ../shared/REFERENCE-FACTS.md (NOT re-read at
// the source; the paper states no fit accuracy that we could check):
//   φ_T = h_c,thermal/h_c,isothermal
//       = [1 − 13.2·(p_h/E′)·L_t^0.42] / [1 + 0.213·(1 + 2.23·SRR^0.83)·L_t^0.64],
//   L_t = β·η0·ū²/k  (β the viscosity–temperature coefficient, k the oil's conductivity),
//   SRR = |u1 − u2|/ū.

/// The thermal loading parameter L_t = β·η0·ū²/k.
double thermal_loading_parameter(double beta, double eta0, double mean_speed, double conductivity);
/// Gupta's thermal reduction factor φ_T of the central film.
double gupta_thermal_reduction(double hertz_pressure, double reduced_modulus, double L_t, double slide_to_roll);

// ---- Rigid cylinder, isoviscous (Martin) -----------------------------------------------
// Reynolds' equation integrated once, p' = 6η0(u1 + u2)(h − h*)/h³ with h = h0 + x²/(2R),
// p(−∞) = 0. Lengths are scaled by √(2Rh0), films by h0, pressures by η0·ū·√(2Rh0)/h0².
// Martin, Engineering 102 (1916) 119 (not read); constants from docs/research/ehl.md §4
// [CONFIRMED-DERIVED]. Accuracy: exact for the model (rigid, isoviscous, flooded, h0 ≪ R),
// printed constants to the digits shown.

/// Printed constants (docs/research/ehl.md §4), for the Reynolds (cavitation) outlet.
inline constexpr double martin_load_constant = 4.8950;   ///< w·h0/(η0·ū·R), ū the mean speed
inline constexpr double martin_outlet_constant = 0.475130;  ///< x_out/√(2Rh0)
inline constexpr double martin_film_at_peak_constant = 1.225748;  ///< h*/h0

/// Minimum film h0 = 4.8950·η0·ū·R/w [m].
double martin_h0(const LineContact& c);
/// Outlet (cavitation) position x_out = 0.475130·√(2R·h0) [m], downstream of h0.
double martin_outlet(const LineContact& c);
/// Film where dp/dx = 0 (pressure peak and outlet), h* = 1.225748·h0 [m].
double martin_film_at_peak(const LineContact& c);

/// Dimensionless solution of the rigid-isoviscous problem, computed by GSL quadrature
/// (qagiu) and Brent root finding from the Reynolds equation itself.
struct RigidIsoviscousSolution {
  double load_constant = 0.0;   ///< w·h0/(η0·ū·R), ū the mean speed
  double outlet = 0.0;          ///< where the pressure ends, x/√(2Rh0)
  double film_at_peak = 0.0;    ///< h*/h0, the film where dp/dx = 0
  double peak_pressure = 0.0;   ///< p_max·h0²/(η0·ū·√(2Rh0))
};

/// Reynolds outlet: p = p' = 0 at the outlet. Throws std::runtime_error on a GSL failure.
RigidIsoviscousSolution rigid_isoviscous_reynolds();
/// Half-Sommerfeld: the full-Sommerfeld (antisymmetric) pressure with its negative part
/// discarded. Throws std::runtime_error on a GSL failure.
RigidIsoviscousSolution rigid_isoviscous_half_sommerfeld();

// ---- Rigid pure squeeze, cylinder on a plane, isoviscous, flooded ----------------------
// Derived here from d/dx(h³p'/(12η)) = ḣ0, h = h0 + x²/(2R), p(±∞) = 0 (derivation in the
// .cpp; no printed source checked). Exact for the model (no cavitation, h0 ≪ R).

/// w = squeeze_load_constant·η·R^(3/2)·(−ḣ0)/h0^(3/2), squeeze_load_constant = 3√2·π.
inline constexpr double squeeze_load_constant = 3.0 * std::numbers::sqrt2 * std::numbers::pi;
/// Pressure p(x) = 6·η·R·(−ḣ0)/h(x)², h = h0 + x²/(2R) [Pa]; ḣ0 < 0 when approaching.
double squeeze_pressure(double radius, double viscosity, double h0, double h0_rate, double x);
/// Load per unit length [N/m].
double squeeze_load_per_length(double radius, double viscosity, double h0, double h0_rate);

}  // namespace gearbench::reference
