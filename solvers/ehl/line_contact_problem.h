#pragma once
// A steady isothermal line contact in dimensionless form, with the scaling chosen for the
// regime. With x = ℓX, p = p_r·P, h = (ℓ²/R)·H (Venner & Lubrecht 2000, ch. 6, generalised):
//   d/dX(ε dP/dX) − d(ρ̄H)/dX = 0,   ε = ρ̄H³/(η̄λ),  λ = 12η0·ū·R²/(ℓ³p_r),  ū = (u1+u2)/2,
//   H = H0 + X²/2 − (D/π)∫ln|X − X'|P dX',  D = 4p_r·R/(E'ℓ),
//   ∫P dX = F = w/(p_r·ℓ),  P ≥ 0 (Reynolds outlet by complementarity).
// Hertzian scaling (ℓ = b, p_r = p_h) gives D = 1, F = π/2 and Venner's λ̄; it is used when
// the contact is elastic (Moes M ≥ 3). Below that the Hertz width no longer measures the
// pressure zone, and the rigid-isoviscous length ℓ = √(2R·h_M) with Martin's film
// h_M = 4.8950·η0ūR/w and p_r = w/ℓ is used (F = 1, λ = 6/4.8950, D → 0 for rigid solids).
#include <array>
#include <string>

#include "model/materials.h"

namespace gearbench::ehl {

enum class ViscosityModel { barus, roelands };
enum class DensityModel { incompressible, dowson_higginson };

/// Dimensional line-contact data (SI).
struct LineContactData {
  double reduced_radius = 0.0;     ///< R [m]
  double load_per_length = 0.0;    ///< w [N/m]
  double u1 = 0.0, u2 = 0.0;       ///< surface speeds [m/s]
  double reduced_modulus = 0.0;    ///< E′ = 2/((1−ν1²)/E1 + (1−ν2²)/E2) [Pa]
  double viscosity = 0.0;          ///< η0 [Pa·s]
  double pressure_viscosity = 0.0; ///< α [1/Pa]
  double roelands_z = 0.0;         ///< z (0: derived from α)
  ViscosityModel viscosity_model = ViscosityModel::roelands;
  /// The case key that sets α, for error messages ("moes.L" for Moes input).
  std::string pressure_viscosity_key = "lubricant.pressure_viscosity_1_per_GPa";
  DensityModel density_model = DensityModel::dowson_higginson;

  [[nodiscard]] double mean_speed() const { return 0.5 * (u1 + u2); }
  /// Moes' M = W·U_Σ^(−1/2) and L = G·U_Σ^(1/4), U_Σ = η0(u1+u2)/(E′R), W = w/(E′R), G = αE′.
  [[nodiscard]] double moes_M() const;
  [[nodiscard]] double moes_L() const;
  /// Moes' speed parameter U_Σ = η0(u1 + u2)/(E′R).
  [[nodiscard]] double moes_speed_sum() const;
  /// Metres per Moes film unit, R·√U_Σ: Moes' film H = (h/R)·U_Σ^(−1/2) is h over it.
  [[nodiscard]] double moes_film_scale() const;
  /// Dimensional data with the given Moes M and L (Barus, incompressible): R = 0.01 m,
  /// E′ = 2.2e11 Pa, η0 = 0.04 Pa·s, u1 = u2 fixed; w and α chosen to meet M and L.
  static LineContactData from_moes(double M, double L);
  /// The lubricant and solids of a gear pair (E′ from the materials; η0, α, z from the
  /// lubricant; Roelands, Dowson–Higginson); radius, load and speeds are left for the mesh.
  static LineContactData from_gear_media(const std::array<model::Material, 2>& materials,
                                         const model::Lubricant& lubricant);
};

/// Moes' central film of a line contact (Moes 1992, as given by Venner & Lubrecht 2000;
/// ../shared/REFERENCE-FACTS.md), in Moes' units H = (h/R)·U_Σ^(−1/2): the four asymptotes
/// blended with s = (7 + 8e^(−2H_EI/H_RI))/5; at L = 0 the isoviscous blend
/// (H_RI^(7/3) + H_EI^(7/3))^(3/7). Within 6 % of the solver's own film at (10, 17.5). Sizes
/// the default inlet, the start's film and the coarsest grid (fas_multigrid.cpp).
[[nodiscard]] double moes_central_film(double M, double L);

/// The dimensionless problem derived from the data.
class LineContactProblem {
 public:
  explicit LineContactProblem(const LineContactData& data);

  [[nodiscard]] const LineContactData& data() const { return data_; }
  [[nodiscard]] bool hertzian_scaling() const { return hertzian_; }
  [[nodiscard]] double length_scale() const { return ell_; }     ///< ℓ [m]
  [[nodiscard]] double pressure_scale() const { return p_r_; }   ///< p_r [Pa]
  [[nodiscard]] double film_scale() const { return ell_ * ell_ / data_.reduced_radius; }  ///< [m]
  [[nodiscard]] double lambda() const { return lambda_; }
  [[nodiscard]] double deformation_factor() const { return D_; }
  [[nodiscard]] double load() const { return F_; }  ///< required ∫P dX
  [[nodiscard]] double hertz_half_width() const { return b_; }
  [[nodiscard]] double hertz_pressure() const { return p_h_; }
  /// Default computational domain [X_in, X_out]: Venner's [−4.5, 1.5] in Hertzian scaling,
  /// widened by six rigid-isoviscous lengths √(2H_RI) ≈ 1.535/M (H_RI = 3π/(8M²) in these
  /// units) at the inlet where the pressure builds up over that length, and further where the
  /// film is thick against the gap there: the inlet's gap is at least 131 times Moes' central
  /// film (a film deficit of at most 1e-3, line_contact_problem.cpp; the fixed inlet left the
  /// film 0.5 % thin at (10, 17.5) and 1.2 % at (5, 25)). [−40, 3] in rigid scaling, where the
  /// pressure decays as |X|⁻³ and the load lost beyond X_in is 4/(4.895·X_in²) ≈ 5e-4 relative.
  [[nodiscard]] double x_in() const;
  [[nodiscard]] double x_out() const;
  /// Moes' isoviscous central film (L = 0) in the problem's film units: the film scale the
  /// start, the coarsest grid and the finest grid are sized by (at L > 0 the film is thicker).
  [[nodiscard]] double isoviscous_film() const;

  /// η̄(P) = η/η0 and ρ̄(P) = ρ/ρ0.
  [[nodiscard]] double viscosity(double P) const;
  /// ln η̄(P): the exponent of viscosity(), finite at pressures where η̄ overflows a double
  /// (a Barus spike on a fine grid reaches ᾱP > 709), so that ε = ρ̄H³e^{−ln η̄}/λ underflows
  /// to 0 instead of turning its derivative into NaN.
  [[nodiscard]] double log_viscosity(double P) const;
  [[nodiscard]] double density(double P) const;
  /// d ln η̄/dP and dρ̄/dP, the laws' own derivatives (0 below P = 0, where both laws are held
  /// at their P = 0 values; the right-hand derivative at P = 0).
  [[nodiscard]] double log_viscosity_slope(double P) const;
  [[nodiscard]] double density_slope(double P) const;

 private:
  LineContactData data_;
  bool hertzian_ = true;
  double ell_ = 0.0, p_r_ = 0.0, lambda_ = 0.0, D_ = 0.0, F_ = 0.0, b_ = 0.0, p_h_ = 0.0;
  double roelands_z_ = 0.0;
};

}  // namespace gearbench::ehl
