#pragma once
// Pressure dependence of a lubricant's viscosity and density (isothermal), each a small
// function citing its source. Pressures in Pa, viscosities in Pa·s.

namespace gearbench::lubricant {

/// Roelands' reference pressure p0 = 1.96e8 Pa (Roelands, 1966).
inline constexpr double roelands_p0 = 1.96e8;
/// −ln η∞ with η∞ = 6.31e-5 Pa·s, the Roelands asymptotic viscosity (Roelands, 1966).
inline constexpr double roelands_ln_eta_inf = 9.67;

/// Barus (1893): η = η0·exp(α·p).
double barus_viscosity(double eta0, double alpha, double p);
/// ln(η/η0) of Barus' law, α·p: finite where η itself overflows (α·p > 709).
double barus_log_ratio(double alpha, double p);

/// Roelands (1966), as written by Venner & Lubrecht (2000):
///   η = η0·exp{(ln η0 + 9.67)·[−1 + (1 + p/p0)^z]},  p0 = 1.96e8 Pa.
double roelands_viscosity(double eta0, double z, double p);
/// ln(η/η0) of Roelands' law: finite where η itself overflows.
double roelands_log_ratio(double eta0, double z, double p);
/// d ln(η/η0)/dp of Roelands' law: (ln η0 + 9.67)·z·(1 + p/p0)^(z−1)/p0 [1/Pa].
double roelands_log_ratio_slope(double eta0, double z, double p);

/// The Roelands index that matches the Barus pressure–viscosity coefficient at p = 0:
///   z = α·p0/(ln η0 + 9.67)  (d ln η/dp at p = 0 equals α).
double roelands_z_from_alpha(double eta0, double alpha);

/// Dowson & Higginson (1966) compressibility: ρ/ρ0 = (5.9e8 + 1.34·p)/(5.9e8 + p), p in Pa.
double dowson_higginson_density_ratio(double p);
/// d(ρ/ρ0)/dp of Dowson & Higginson: 0.34·5.9e8/(5.9e8 + p)² [1/Pa].
double dowson_higginson_density_slope(double p);

/// The shear response of the film: Newtonian (τ = η·γ̇) or Ree–Eyring.
enum class ShearRheology { newtonian, eyring };

/// Ree–Eyring shear rate at the shear stress τ (Eyring 1936; the sinh law as used for EHL
/// films by Johnson & Tevaarwerk, Proc. R. Soc. A 356 (1977) 215, and in thermal EHL by Yang
/// & Wen, J. Tribol. 112 (1990) 631): γ̇ = (τ0/η)·sinh(τ/τ0), the inverse of
/// τ = τ0·asinh(η·γ̇/τ0). η is the low-shear viscosity η(p, T), τ0 the Eyring stress [Pa].
double eyring_shear_rate(double tau, double eta, double eyring_stress);
/// The Ree–Eyring shear stress at the shear rate γ̇ (of either sign), τ = τ0·asinh(η·γ̇/τ0)
/// (the same law).
double eyring_stress(double shear_rate, double eta, double eyring_stress);
/// The Ree–Eyring equivalent viscosity η* = τ/γ̇ = η·(τ/τ0)/sinh(τ/τ0) (η at τ = 0): the
/// viscosity that makes a Newtonian film law carry the Eyring stress (Yang & Wen's
/// "equivalent viscosity", Acta Mech. Sinica 6 (1990) 289).
double eyring_equivalent_viscosity(double tau, double eta, double eyring_stress);

}  // namespace gearbench::lubricant
