#pragma once
// The flow across one column of a thermal EHL film: velocity, shear rate, shear stress and the
// film integrals of the generalized Reynolds equation (Yang & Wen, J. Tribol. 112 (1990) 631),
// for given viscosity and density profiles across the film, ζ = z/h ∈ [0, 1] from surface a.
//
// Momentum across the film, ∂τ/∂z = ∂p/∂x, makes the shear stress linear in z whatever the
// rheology: τ(ζ) = τ_a + (∂p/∂x)·h·ζ. With the equivalent viscosity η* = τ/γ̇ the velocity
// integrates as for a Newtonian film whose viscosity is η* (Yang & Wen's generalized
// Reynolds equation for non-Newtonian flow, Acta Mech. Sinica 6 (1990) 289; the same
// "effective viscosity" route in J. Tribol. 127 (2005) 70):
//   f0 = ∫₀^ζ dζ′/η*,  f1 = ∫₀^ζ ζ′dζ′/η*,  η_e = 1/f0(1),  η′_e = 1/f1(1),
//   u = U_a + ∂p/∂x·h²·[f1 − (η_e/η′_e)·f0] + η_e(U_b − U_a)·f0,
//   τ_a = η_e(U_b − U_a)/h − ∂p/∂x·h·η_e/η′_e,
//   ρ_e = ∫ρ dζ, ρ′_e = ∫ρ f0 dζ, ρ″_e = ∫ρ f1 dζ,
//   (ρ/η)_e = 12(η_e ρ′_e/η′_e − ρ″_e),  ρ* = [ρ′_e η_e (U_b − U_a) + ρ_e U_a]/U.
// Newtonian: η* = η. Ree–Eyring (lubricant/rheology.h): η* depends on τ, so the wall stress
// τ_a is the root of the no-slip condition ∫₀¹ γ̇(τ_a + ∂p/∂x·h·ζ) dζ = (U_b − U_a)/h, solved
// by safeguarded Newton (the integral increases strictly with τ_a). f0 and f1 by the
// trapezoidal rule, with the same rule in the no-slip condition, so that the root makes the
// discrete velocity meet U_b exactly and the stress from the η* formulas equal τ_a + p_x h ζ.
#include <optional>
#include <vector>

namespace gearbench::ehl {

/// The flow across the film at one column.
struct ColumnFlow {
  std::vector<double> viscosity;  ///< η(p, T): the low-shear viscosity per film node [Pa·s]
  std::vector<double> eta_star;   ///< equivalent viscosity τ/γ̇ (η for a Newtonian film) [Pa·s]
  std::vector<double> rho, u, shear_rate, stress;  ///< per film node (SI)
  std::vector<double> f0, f1;                      ///< ∫dζ/η*, ∫ζdζ/η* from the wall a
  double eta_e = 0.0, eta_e_prime = 0.0;           ///< η_e, η′_e [Pa·s]
  double rho_e = 0.0, rho_e1 = 0.0, rho_e2 = 0.0;  ///< ρ_e, ρ′_e·η-scaled, ρ″_e (ζ form)
  double eyring_wall_stress = 0.0;                 ///< τ_a, the Eyring root (0 for a Newtonian film) [Pa]
  /// (ρ/η)_e = 12(η_e·ρ′_e/η′_e − ρ″_e): the Poiseuille coefficient.
  [[nodiscard]] double rho_over_eta_e() const { return 12.0 * (eta_e * rho_e1 / eta_e_prime - rho_e2); }
  /// ρ* = [ρ′_e·η_e·(U_b − U_a) + ρ_e·U_a]/U: the wedge density.
  [[nodiscard]] double rho_star(double Ua, double Ub) const {
    return (rho_e1 * eta_e * (Ub - Ua) + rho_e * Ua) / (0.5 * (Ua + Ub));
  }
};

/// The column's flow on the uniform nodes `zeta` (0 … 1) for the viscosity η(p, T) and
/// density per node, surface speeds U_a, U_b, pressure gradient ∂p/∂x and film h; with
/// `eyring_stress` τ0 [Pa] the film is Ree–Eyring, without it Newtonian.
ColumnFlow column_flow(const std::vector<double>& zeta, std::vector<double> viscosity, std::vector<double> density,
                       double Ua, double Ub, double dpdx, double h, std::optional<double> eyring_stress,
                       std::optional<double> wall_stress_guess = std::nullopt);

/// The same in place: the rest of `c` from its viscosity and rho (set by the caller), reusing
/// c's storage (the temperature solve evaluates every column's flow twice per iteration, and
/// nine allocations per flow cost a tenth of those evaluations).
void complete_column_flow(const std::vector<double>& zeta, double Ua, double Ub, double dpdx, double h,
                          std::optional<double> eyring_stress, std::optional<double> wall_stress_guess, ColumnFlow& c);

/// The Ree–Eyring wall stress τ_a of a column: the root of the trapezoidal no-slip condition
/// Σ w_j·γ̇_j(τ_a + ∂p/∂x·h·ζ_j) = (U_b − U_a)/h. Exposed for its tests. `guess` (a root
/// nearby, e.g. the column's of the last sweep) only shortens the Newton steps.
double eyring_wall_stress(const std::vector<double>& zeta, const std::vector<double>& viscosity, double sliding,
                          double dpdx, double h, double eyring_stress, std::optional<double> guess = std::nullopt);

/// ∫₀¹ y dζ on `nodes` uniform nodes, y(j) the value at node j: composite Simpson, with
/// Simpson's 3/8 rule on the last three intervals when their number is odd; both are exact for
/// cubics, so the isothermal Newtonian integrals (quadratic in ζ) come out exact.
template <class Values>
double film_integral(std::size_t nodes, Values y) {
  const std::size_t n = nodes - 1;  // intervals
  const double d = 1.0 / static_cast<double>(n);
  if (n == 1) return 0.5 * d * (y(0) + y(1));
  const std::size_t simpson_end = n % 2 == 0 ? n : n - 3;
  double sum = 0.0;
  for (std::size_t j = 0; j + 2 <= simpson_end; j += 2) sum += d / 3.0 * (y(j) + 4.0 * y(j + 1) + y(j + 2));
  if (simpson_end != n) {
    const std::size_t j = simpson_end;
    sum += 3.0 * d / 8.0 * (y(j) + 3.0 * y(j + 1) + 3.0 * y(j + 2) + y(j + 3));
  }
  return sum;
}

/// ∫₀¹ y dζ of nodal values y (film_integral above).
inline double film_integral(const std::vector<double>& y) {
  return film_integral(y.size(), [&y](std::size_t j) { return y[j]; });
}

}  // namespace gearbench::ehl
