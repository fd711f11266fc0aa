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
// Velocity profile and shear stress across the film from column_flow.h (seed 001's
// Newtonian profile with the effective viscosities of the generalized Reynolds equation, or
// the same with the Ree–Eyring equivalent viscosity); the shear heating is τ·∂u/∂z of that
// profile.
// Discretisation: first-order upwind in x (backward where u ≥ 0, forward in reverse flow),
// second-order differences across the film and into the solids (quadratically graded
// solid nodes), half-cell energy balances at the walls; each column is one tridiagonal
// solve (tridiagonal_system.h), the columns are swept Gauss–Seidel fashion from the inlet.
#include <array>
#include <limits>
#include <optional>
#include <vector>

#include "column_flow.h"
#include "tridiagonal_system.h"
#include "lubricant/rheology.h"
#include "lubricant/thermal_rheology.h"
#include "model/materials.h"

namespace gearbench::ehl {

struct FilmTemperatureOptions {
  int film_nodes = 10;        ///< nodes across the film (seed 001: 10)
  int solid_nodes = 14;       ///< nodes into each solid, surface and depth included (seed 001: 14)
  double depth = 0.0;         ///< d [m]: T = T0 below it; 0 picks the default (see .cpp)
  bool shear_heating = true;  ///< τ·∂u/∂z in the film
  /// Shear response of the film; Ree–Eyring takes τ0 from the lubricant's Eyring stress.
  lubricant::ShearRheology rheology = lubricant::ShearRheology::newtonian;
  bool compression = true;    ///< −(T/ρ)(∂ρ/∂T)·u·∂p/∂x in the film
};

/// Heat budget of the contact per unit length [W/m].
struct HeatBalance {
  double shear_heating = 0.0;    ///< ∫∫ τ·∂u/∂z dz dx
  double compression = 0.0;      ///< ∫∫ −(T/ρ)(∂ρ/∂T)u ∂p/∂x dz dx
  double film_outflow = 0.0;     ///< ∫ ρcu(T − T0) dz at the outlet
  std::array<double, 2> solid_outflow{};  ///< ρ_s c_s U_s ∫(T − T0) ds at the outlet
  std::array<double, 2> depth_loss{};     ///< ∫ k_s ∂T/∂s dx through the depth d
  [[nodiscard]] double generated() const { return shear_heating + compression; }
  [[nodiscard]] double removed() const {
    return film_outflow + solid_outflow[0] + solid_outflow[1] + depth_loss[0] + depth_loss[1];
  }
};

/// Linear prolongation along x to the grid twice as fine: coinciding nodes copied, each node
/// between two the mean of its neighbours (`mean(a, b)`; a value per node or a column of them).
template <class Value, class Mean>
[[nodiscard]] std::vector<Value> prolong_along_x(const std::vector<Value>& coarse, Mean mean) {
  std::vector<Value> fine;
  fine.reserve(2 * coarse.size() - 1);
  for (std::size_t I = 0; I < coarse.size(); ++I) {
    fine.push_back(coarse[I]);
    if (I + 1 < coarse.size()) fine.push_back(mean(coarse[I], coarse[I + 1]));
  }
  return fine;
}

/// The mean of two nodal values (prolong_along_x).
[[nodiscard]] inline double nodal_mean(double a, double b) { return 0.5 * (a + b); }

class FilmTemperature {
 public:
  /// x: uniform nodes [m]; Ua, Ub ≥ 0: surface speeds [m/s]; half_width: the Hertz b [m]
  /// (sets the default depth).
  FilmTemperature(std::vector<double> x, double Ua, double Ub, double half_width,
                  const lubricant::ThermalRheology& rheology, const model::ThermalSolids& solids,
                  FilmTemperatureOptions options);

  /// Sweeps for pressure p [Pa] and film h [m] (both on x) until the largest temperature change
  /// of a sweep is below `tolerance` [K] or `max_sweeps`; returns the last change. The columns'
  /// flow (velocity, shear rate, mass flux) is that of the temperatures the solve starts from
  /// (.cpp: why).
  /// `poiseuille` is the pressure solve's Poiseuille coefficient (ρ/η) per node [s/m²]: where an
  /// Eyring column's flow thins steeply with the gradient, the column flows at the gradient that
  /// carries that solve's Poiseuille flux (flux_carrying_gradient).
  double solve(const std::vector<double>& p, const std::vector<double>& h, const std::vector<double>& poiseuille,
               double tolerance, int max_sweeps);

  /// Takes the temperatures (film, solids) and Eyring wall stresses of the same contact on the grid
  /// half as fine (nodes (n − 1)/2 + 1, same film and solid nodes, same depth): coinciding
  /// nodes copied, the nodes between them linearly interpolated. The start of a nested solve.
  void interpolate_from(const FilmTemperature& coarse);

  /// The flow at column i at pressure p, gradient ∂p/∂x and film h, at the current temperatures.
  [[nodiscard]] ColumnFlow column_flow(std::size_t i, double p, double dpdx, double h) const {
    ColumnFlow flow;
    column_flow(i, p, dpdx, h, flow);
    return flow;
  }
  /// The same into `flow`, reusing its storage.
  void column_flow(std::size_t i, double p, double dpdx, double h, ColumnFlow& flow) const;
  /// The flow at column i for the pressure and film fields (∂p/∂x by central differences).
  [[nodiscard]] ColumnFlow column_flow(std::size_t i, const std::vector<double>& p, const std::vector<double>& h) const {
    return column_flow(i, p[i], dpdx_at(p, i, dx_), h[i]);
  }
  /// The same into `flow`, reusing its storage.
  void column_flow(std::size_t i, const std::vector<double>& p, const std::vector<double>& h, ColumnFlow& flow) const {
    column_flow(i, p[i], dpdx_at(p, i, dx_), h[i], flow);
  }
  [[nodiscard]] static double dpdx_at(const std::vector<double>& p, std::size_t i, double dx);
  /// The ∂p/∂x at which column i flows in a temperature solve: dpdx, the pressure's own, except
  /// in an Eyring column whose Poiseuille coefficient thins steeply with the gradient
  /// (∂ln(ρ/η)_e/∂ln|∂p/∂x| > 1), where it is the gradient at which the column, at its current
  /// temperatures, carries the Poiseuille flux (ρ/η)·h³·dpdx/12 of the pressure solve whose
  /// coefficient is `poiseuille` (.cpp: why). Both agree where the coupling has converged.
  [[nodiscard]] double flux_carrying_gradient(std::size_t i, double p, double dpdx, double h,
                                              double poiseuille) const;
  [[nodiscard]] HeatBalance heat_balance(const std::vector<double>& p, const std::vector<double>& h) const;

  [[nodiscard]] double depth() const { return depth_; }
  [[nodiscard]] const std::vector<double>& film_coordinates() const { return zeta_; }  ///< ζ_j
  [[nodiscard]] const std::vector<double>& solid_coordinates() const { return s_; }   ///< s_k [m]
  /// T[i][j]: film temperature at x_i, ζ_j [K]; solid(0/1)[i][k] at depth s_k.
  [[nodiscard]] const std::vector<std::vector<double>>& film() const { return T_; }
  [[nodiscard]] const std::vector<std::vector<double>>& solid(int body) const { return Ts_[body]; }
  [[nodiscard]] double inlet_temperature() const { return T0_; }

 private:
  /// One Gauss–Seidel sweep over the columns, downstream then upstream; the largest change [K].
  double sweep(const std::vector<double>& p, const std::vector<double>& h);
  void solve_column(std::size_t i, const std::vector<double>& p, const std::vector<double>& h);
  /// η(p, T) and ∂ln η/∂T of a film node at this solve()'s pressure, and the temperature T
  /// they are of (NaN: none yet).
  struct NodeViscosity {
    double T = std::numeric_limits<double>::quiet_NaN(), eta = 0.0, dln_dT = 0.0;
  };
  /// Film node (i, j)'s at its present temperature, evaluated only when that temperature moved
  /// since the last evaluation in this solve(): a column's first solve of a sweep meets the
  /// temperatures its flow was evaluated at, which saves a quarter of the viscosities' pow.
  const NodeViscosity& node_viscosity(std::size_t i, std::size_t j);
  /// The rest of column i's flow from flow.viscosity (set by the caller) at the present
  /// temperatures, with `at_p` the rheology at the column's pressure.
  void complete_flow(std::size_t i, const lubricant::ThermalRheology::AtPressure& at_p, double dpdx, double h,
                     ColumnFlow& flow) const;
  /// The conduction coefficients of a solid's rows on the graded nodes and its convection per
  /// Δx: the same for every column, so set once (constructor).
  struct SolidRows {
    double convection = 0.0;                ///< ρ_s c_s U_s/Δx
    std::vector<double> deeper, shallower;  ///< per node k: the coefficients of T_{k+1}, T_{k−1}
  };
  [[nodiscard]] SolidRows conduction_rows(int body) const;
  [[nodiscard]] std::vector<double> mass_flux_profile(const ColumnFlow& flow, double h) const;

  std::vector<double> x_;
  double dx_ = 0.0, Ua_ = 0.0, Ub_ = 0.0;
  const lubricant::ThermalRheology& rheology_;
  model::ThermalSolids solids_;
  FilmTemperatureOptions o_;
  double T0_ = 0.0, depth_ = 0.0;
  std::optional<double> eyring_stress_;                ///< τ0 [Pa] of a Ree–Eyring film (none: Newtonian)
  std::vector<double> zeta_, s_;
  std::vector<std::vector<double>> T_;                 ///< film [i][j]
  std::array<std::vector<std::vector<double>>, 2> Ts_; ///< solids [body][i][k]
  std::vector<double> dpdx_;                           ///< each column's ∂p/∂x in this solve() [Pa/m]
  std::vector<ColumnFlow> flows_;                      ///< each column's flow of this solve()
  std::vector<lubricant::ThermalRheology::AtPressure> at_pressure_;  ///< each column's at this solve()'s p
  std::vector<std::vector<NodeViscosity>> viscosity_;  ///< [i][j] at this solve()'s p (node_viscosity)
  std::vector<std::vector<double>> Q_;                 ///< Q(x_i, ζ_j) [kg/(m·s)], relaxed towards flows_' (solve)
  std::vector<double> wall_stress_;  ///< each column's Eyring root τ_a of the last solve() (NaN: none yet), a Newton start
  std::array<SolidRows, 2> solid_rows_;                ///< per body (conduction_rows)
  std::vector<std::vector<double>> sweep_start_;       ///< T_ where the last sweep started (its change)
  /// A column solve's work space, kept between columns (a sweep solves 2(n − 1) columns of
  /// the same size: allocating per column cost a tenth of the sweeps' instructions).
  struct ColumnWorkspace {
    std::vector<double> stress, dln_eta, Qx;
    TridiagonalSystem system;
  } column_;
};

}  // namespace gearbench::ehl
