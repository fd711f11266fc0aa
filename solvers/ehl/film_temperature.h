#pragma once
// Temperature field of a thermal line contact: the energy equation in the film and in both
// solids for a given pressure and film (seed 001 §1.4; Yang & Wen, J. Tribol. 112 (1990)
// 631). Across the film the coordinate is ζ = z/h ∈ [0, 1] (surface a = pinion at ζ = 0),
// and with Q(x, ζ) = h∫₀^ζ ρu dζ' the film equation
//   c·(ρu ∂T/∂x − q ∂T/∂z) − k ∂²T/∂z² = −(T/ρ)(∂ρ/∂T)·u ∂p/∂x + η(∂u/∂z)²,
//   q = ∂/∂x ∫₀^z ρu dz',
// becomes, exactly, c·(ρu ∂T/∂x|_ζ − (1/h)(∂Q/∂x|_ζ)·∂T/∂ζ) − (k/h²)∂²T/∂ζ² = source.
// The solids are moving half-spaces cut at depth d where T = T0:
//   ρ_s c_s U_s ∂T/∂x = k_s ∂²T/∂s²,
// with temperature and heat-flux continuity at both walls, T0 where the oil flows in.
// Newtonian velocity profile with the effective viscosities of the generalized Reynolds
// equation (seed 001 eqs for u and ∂u/∂z):
//   u = U_a + ∂p/∂x·h²·[f1(ζ) − (η_e/η′_e)·f0(ζ)] + η_e(U_b − U_a)·f0(ζ),
//   f0 = ∫₀^ζ dζ'/η,  f1 = ∫₀^ζ ζ' dζ'/η,  η_e = 1/f0(1),  η′_e = 1/f1(1).
// Discretisation: first-order upwind in x (backward where u ≥ 0, forward in reverse flow),
// second-order differences across the film and into the solids (quadratically graded
// solid nodes), half-cell energy balances at the walls; each column is one tridiagonal
// solve (GSL), the columns are swept Gauss–Seidel fashion from the inlet.
#include <array>
#include <vector>

#include "lubricant/thermal_rheology.h"
#include "model/materials.h"

namespace gearbench::ehl {

struct FilmTemperatureOptions {
  int film_nodes = 10;        ///< nodes across the film (seed 001: 10)
  int solid_nodes = 14;       ///< nodes into each solid, surface and depth included (seed 001: 14)
  double depth = 0.0;         ///< d [m]: T = T0 below it; 0 picks the default (see .cpp)
  bool shear_heating = true;  ///< η(∂u/∂z)² in the film
  bool compression = true;    ///< −(T/ρ)(∂ρ/∂T)·u·∂p/∂x in the film
};

/// The flow across the film at one column, for a given temperature profile.
struct ColumnFlow {
  std::vector<double> eta, rho, u, shear_rate;  ///< per film node
  std::vector<double> f0, f1;                   ///< ∫dζ/η, ∫ζdζ/η from the wall a
  double eta_e = 0.0, eta_e_prime = 0.0;        ///< η_e, η′_e [Pa·s]
  double rho_e = 0.0, rho_e1 = 0.0, rho_e2 = 0.0;  ///< ρ_e, ρ′_e·η-scaled, ρ″_e (ζ form)
  /// (ρ/η)_e = 12(η_e·ρ′_e/η′_e − ρ″_e) [kg·s/m⁴·…]: the Poiseuille coefficient.
  [[nodiscard]] double rho_over_eta_e() const { return 12.0 * (eta_e * rho_e1 / eta_e_prime - rho_e2); }
  /// ρ* = [ρ′_e·η_e·(U_b − U_a) + ρ_e·U_a]/U: the wedge density.
  [[nodiscard]] double rho_star(double Ua, double Ub) const {
    return (rho_e1 * eta_e * (Ub - Ua) + rho_e * Ua) / (0.5 * (Ua + Ub));
  }
};

/// Heat budget of the contact per unit length [W/m].
struct HeatBalance {
  double shear_heating = 0.0;    ///< ∫∫ η(∂u/∂z)² dz dx
  double compression = 0.0;      ///< ∫∫ −(T/ρ)(∂ρ/∂T)u ∂p/∂x dz dx
  double film_outflow = 0.0;     ///< ∫ ρcu(T − T0) dz at the outlet
  std::array<double, 2> solid_outflow{};  ///< ρ_s c_s U_s ∫(T − T0) ds at the outlet
  std::array<double, 2> depth_loss{};     ///< ∫ k_s ∂T/∂s dx through the depth d
  [[nodiscard]] double generated() const { return shear_heating + compression; }
  [[nodiscard]] double removed() const {
    return film_outflow + solid_outflow[0] + solid_outflow[1] + depth_loss[0] + depth_loss[1];
  }
};

class FilmTemperature {
 public:
  /// x: uniform nodes [m]; Ua, Ub ≥ 0: surface speeds [m/s]; half_width: the Hertz b [m]
  /// (sets the default depth).
  FilmTemperature(std::vector<double> x, double Ua, double Ub, double half_width,
                  const lubricant::ThermalRheology& rheology, const model::ThermalSolids& solids,
                  FilmTemperatureOptions options);

  /// One Gauss–Seidel sweep over the columns for pressure p [Pa] and film h [m] (both on x);
  /// returns the largest temperature change [K].
  double sweep(const std::vector<double>& p, const std::vector<double>& h);
  /// Sweeps until the change is below `tolerance` [K] or `max_sweeps`; returns the last change.
  double solve(const std::vector<double>& p, const std::vector<double>& h, double tolerance, int max_sweeps);

  [[nodiscard]] ColumnFlow column_flow(std::size_t i, double p, double dpdx, double h) const;
  /// The flow at column i for the pressure and film fields (∂p/∂x by central differences).
  [[nodiscard]] ColumnFlow column_flow(std::size_t i, const std::vector<double>& p, const std::vector<double>& h) const {
    return column_flow(i, p[i], dpdx_at(p, i, dx_), h[i]);
  }
  [[nodiscard]] static double dpdx_at(const std::vector<double>& p, std::size_t i, double dx);
  [[nodiscard]] HeatBalance heat_balance(const std::vector<double>& p, const std::vector<double>& h) const;

  [[nodiscard]] double depth() const { return depth_; }
  [[nodiscard]] const std::vector<double>& film_coordinates() const { return zeta_; }  ///< ζ_j
  [[nodiscard]] const std::vector<double>& solid_coordinates() const { return s_; }   ///< s_k [m]
  /// T[i][j]: film temperature at x_i, ζ_j [K]; solid(0/1)[i][k] at depth s_k.
  [[nodiscard]] const std::vector<std::vector<double>>& film() const { return T_; }
  [[nodiscard]] const std::vector<std::vector<double>>& solid(int body) const { return Ts_[body]; }
  [[nodiscard]] double inlet_temperature() const { return T0_; }

 private:
  void solve_column(std::size_t i, const std::vector<double>& p, const std::vector<double>& h);
  [[nodiscard]] std::vector<double> mass_flux_profile(const ColumnFlow& flow, double h) const;

  std::vector<double> x_;
  double dx_ = 0.0, Ua_ = 0.0, Ub_ = 0.0;
  const lubricant::ThermalRheology& rheology_;
  model::ThermalSolids solids_;
  FilmTemperatureOptions o_;
  double T0_ = 0.0, depth_ = 0.0;
  std::vector<double> zeta_, s_;
  std::vector<std::vector<double>> T_;                 ///< film [i][j]
  std::array<std::vector<std::vector<double>>, 2> Ts_; ///< solids [body][i][k]
  std::vector<std::vector<double>> Q_;                 ///< Q(x_i, ζ_j) of the last sweep [kg/(m·s)]
};

}  // namespace gearbench::ehl
