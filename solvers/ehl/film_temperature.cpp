#include "film_temperature.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <limits>
#include <memory>
#include <stdexcept>

#include "model/errors.h"
#include "model/gsl_status.h"

namespace gearbench::ehl {

namespace {
/// ∫ y ds on graded nodes (trapezoid).
double integrate_graded(const std::vector<double>& y, const std::vector<double>& s) {
  double sum = 0.0;
  for (std::size_t k = 0; k + 1 < s.size(); ++k) sum += 0.5 * (y[k] + y[k + 1]) * (s[k + 1] - s[k]);
  return sum;
}

/// The exponential scheme's neighbour weights over the diffusion coefficient at cell Péclet
/// number P, exact for steady 1-D convection–diffusion (Patankar 1980, ch. 5, "the exponential
/// scheme"; Allen & Southwell 1955): {B(−P), B(P)} for the upstream (previous) and downstream
/// (next) neighbour, B(P) = P/(e^P − 1) → 1 − P/2 + P²/12 as P → 0. One exponential: B(|P|)
/// for the smaller weight, the larger from B(−P) = B(P) + P without cancellation.
struct ExponentialWeights {
  double prev, next;
};
ExponentialWeights exponential_weights(double P) {
  const double a = std::abs(P), small = a == 0.0 ? 1.0 : a / std::expm1(a), large = small + a;
  return P >= 0.0 ? ExponentialWeights{large, small} : ExponentialWeights{small, large};
}

}  // namespace

FilmTemperature::FilmTemperature(std::vector<double> x, double Ua, double Ub, double half_width,
                                 const lubricant::ThermalRheology& rheology, const model::ThermalSolids& solids,
                                 FilmTemperatureOptions options)
    : x_(std::move(x)), Ua_(Ua), Ub_(Ub), rheology_(rheology), solids_(solids), o_(options),
      T0_(rheology.inlet_temperature()) {
  if (o_.film_nodes < 4 || o_.film_nodes > 200)
    throw InputError(fmt::format("thermal.film_nodes = {} must lie in [4, 200]", o_.film_nodes));
  if (o_.solid_nodes < 3 || o_.solid_nodes > 200)
    throw InputError(fmt::format("thermal.solid_nodes = {} must lie in [3, 200]", o_.solid_nodes));
  if (Ua < 0.0 || Ub < 0.0)
    throw InputError(fmt::format("surface speeds [{}, {}] m/s: the thermal model needs both ≥ 0 (surfaces "
                                 "moving through the contact in the rolling direction)", Ua, Ub));
  for (int s = 0; s < 2; ++s) {
    const char* names[] = {"solids.thermal_conductivity_W_per_mK", "solids.specific_heat_J_per_kgK",
                           "solids.density_kg_m3"};
    const double values[] = {solids.conductivity[s], solids.specific_heat[s], solids.density[s]};
    for (int q = 0; q < 3; ++q)
      if (!(values[q] > 0.0) || !std::isfinite(values[q]))
        throw InputError(fmt::format("{}[{}] = {} must be a positive finite number", names[q], s, values[q]));
  }
  if (o_.rheology == lubricant::ShearRheology::eyring) {
    eyring_stress_ = rheology.data().eyring_stress;
    if (!eyring_stress_)
      throw InputError("rheology = \"eyring\": the lubricant needs its Eyring stress, lubricant.eyring_stress_MPa");
    if (!(*eyring_stress_ > 0.0) || !std::isfinite(*eyring_stress_))
      throw InputError(fmt::format("lubricant.eyring_stress_MPa = {} must be a positive finite number",
                                   *eyring_stress_ * 1e-6));
  }
  dx_ = x_[1] - x_[0];
  // Depth d: three thermal penetration lengths √(κ_s·L/U_s) of the slower solid over the
  // domain length L (the temperature rise of a moving half-space decays as erfc(s/(2√(κt)));
  // at s = 3√(κt) it is below 3 % of the surface rise), capped at L for slow surfaces.
  const double L = x_.back() - x_.front();
  if (o_.depth > 0.0) {
    depth_ = o_.depth;
  } else {
    depth_ = 0.0;
    for (int s = 0; s < 2; ++s) {
      const double kappa = solids.conductivity[s] / (solids.density[s] * solids.specific_heat[s]);
      const double U = s == 0 ? Ua : Ub;
      depth_ = std::max(depth_, U > 0.0 ? 3.0 * std::sqrt(kappa * L / U) : L);
    }
    depth_ = std::max(std::min(depth_, L), half_width);
  }
  zeta_.resize(static_cast<std::size_t>(o_.film_nodes));
  for (std::size_t j = 0; j < zeta_.size(); ++j) zeta_[j] = static_cast<double>(j) / static_cast<double>(zeta_.size() - 1);
  // Quadratically graded solid nodes, fine at the wall where the gradients are.
  s_.resize(static_cast<std::size_t>(o_.solid_nodes));
  for (std::size_t k = 0; k < s_.size(); ++k) {
    const double t = static_cast<double>(k) / static_cast<double>(s_.size() - 1);
    s_[k] = depth_ * t * t;
  }
  for (int body = 0; body < 2; ++body) solid_rows_[body] = conduction_rows(body);
  T_.assign(x_.size(), std::vector<double>(zeta_.size(), T0_));
  for (auto& body : Ts_) body.assign(x_.size(), std::vector<double>(s_.size(), T0_));
  flows_.resize(x_.size());
  Q_.assign(x_.size(), {});  // empty columns: the first solve takes its flow's Q whole
  wall_stress_.assign(x_.size(), std::numeric_limits<double>::quiet_NaN());
}

void FilmTemperature::interpolate_from(const FilmTemperature& coarse) {
  const std::size_t n = x_.size();
  if (coarse.x_.size() * 2 - 1 != n || coarse.zeta_.size() != zeta_.size() || coarse.s_.size() != s_.size() ||
      coarse.depth_ != depth_)
    throw std::logic_error("FilmTemperature::interpolate_from: not the same contact on the grid half as fine");
  const auto column_mean = [](const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> m(a.size());
    for (std::size_t j = 0; j < a.size(); ++j) m[j] = nodal_mean(a[j], b[j]);
    return m;
  };
  T_ = prolong_along_x(coarse.T_, column_mean);
  Ts_[0] = prolong_along_x(coarse.Ts_[0], column_mean);
  Ts_[1] = prolong_along_x(coarse.Ts_[1], column_mean);
  wall_stress_ = prolong_along_x(coarse.wall_stress_, nodal_mean);
  for (auto& Q : Q_) Q.clear();  // the first solve's mass flux is that of the interpolated field
}

double FilmTemperature::dpdx_at(const std::vector<double>& p, std::size_t i, double dx) {
  if (i == 0) return (p[1] - p[0]) / dx;
  if (i + 1 == p.size()) return (p[i] - p[i - 1]) / dx;
  return (p[i + 1] - p[i - 1]) / (2.0 * dx);
}

void FilmTemperature::column_flow(std::size_t i, double p, double dpdx, double h, ColumnFlow& flow) const {
  const auto at_p = rheology_.at_pressure(p);  // the column's nodes share p: one pressure factor
  flow.viscosity.resize(zeta_.size());
  for (std::size_t j = 0; j < zeta_.size(); ++j) flow.viscosity[j] = at_p.viscosity(T_[i][j]);
  complete_flow(i, at_p, dpdx, h, flow);
}

void FilmTemperature::complete_flow(std::size_t i, const lubricant::ThermalRheology::AtPressure& at_p, double dpdx,
                                    double h, ColumnFlow& flow) const {
  flow.rho.resize(zeta_.size());
  for (std::size_t j = 0; j < zeta_.size(); ++j) flow.rho[j] = at_p.density(T_[i][j]);
  std::optional<double> guess;
  if (std::isfinite(wall_stress_[i])) guess = wall_stress_[i];
  complete_column_flow(zeta_, Ua_, Ub_, dpdx, h, eyring_stress_, guess, flow);
}

const FilmTemperature::NodeViscosity& FilmTemperature::node_viscosity(std::size_t i, std::size_t j) {
  NodeViscosity& v = viscosity_[i][j];
  if (!(v.T == T_[i][j])) {
    v.T = T_[i][j];
    v.eta = at_pressure_[i].viscosity(v.T, &v.dln_dT);
  }
  return v;
}

double FilmTemperature::flux_carrying_gradient(std::size_t i, double p, double dpdx, double h,
                                               double poiseuille) const {
  // Why (twenty-fourth session): the coupling freezes the generalized-Reynolds factors between
  // pressure solves, and at the outlet spike of a near-rolling Eyring film the flow factor
  // rises steeply with the gradient it was computed at (s = ∂ln(ρ/η)_e/∂ln|∂p/∂x| 5–15). A
  // pressure solve on lagged factors then makes the spike's gradient steeper than the film can
  // carry (seed 004's contact at M 15.9, L 18.8 on 2561 nodes: |h·∂p/∂x| 37τ0 after the nested
  // start's first solve, against 19τ0 converged on 1281), and a column held at that gradient,
  // i.e. at that stress, shears at τ0/η·sinh(τ/τ0) and heats until non-finite (276 K, then
  // 1924 K, within five iterations). What the pressure solve does carry is the flux: the
  // Poiseuille flux (ρ/η)·h³·∂p/∂x/12 of its frozen coefficient. A column at the gradient that
  // carries that flux at its own temperatures shears less as it heats (a hotter, thinner oil
  // needs a smaller gradient), so its heating stays bounded. Where the flow barely thins with
  // the gradient (s ≤ 1: every Newtonian column, and the Hertzian zone and the inlet of an
  // Eyring film, s ~ 1e-4 … 3e-3) the two gradients coincide to first order and the pressure's
  // own is kept; holding the flux there makes the coupling stiff (tried in the fifteenth
  // session on every column: the Hertzian zone's Poiseuille flux is a tiny remainder that a
  // 1e-3 change of ρ* moves far).
  if (!eyring_stress_ || !(p > 0.0 && h > 0.0 && poiseuille > 0.0)) return dpdx;
  // Below a Poiseuille wall stress h·|∂p/∂x|/2 of τ0/2 no column flow is needed to know s ≪ 1:
  // with a = h·|∂p/∂x|/(2τ0) an Eyring film's Poiseuille flux is 3∫ζ·sinh(aζ)dζ/a = 1 + a²/10 +
  // O(a⁴) times the Newtonian one, so s ≈ a²/5, 0.05 at a = 1/2.
  if (h * std::abs(dpdx) <= *eyring_stress_ || dpdx == 0.0) return dpdx;
  // The column's thinning s = ∂ln(ρ/η)_e/∂ln|∂p/∂x| at the pressure's gradient.
  const double sign = dpdx < 0.0 ? -1.0 : 1.0, y0 = std::log(std::abs(dpdx));
  constexpr double step = 1e-3;  // in ln|∂p/∂x|
  const double log_coefficient = std::log(column_flow(i, p, dpdx, h).rho_over_eta_e());
  const double s = (std::log(column_flow(i, p, sign * std::exp(y0 + step), h).rho_over_eta_e()) - log_coefficient) / step;
  if (!(s > 1.0)) return dpdx;
  // φ(y) = ln[(ρ/η)_e(e^y)·e^y] − ln[(ρ/η)·|∂p/∂x|]: the column's Poiseuille flux against the
  // pressure solve's, in logarithms of y = ln|∂p/∂x|. The pressure solve's flux is set by its
  // frozen wedge term too, but matching the whole mass flux fails where the column's ρ* (at its
  // present temperatures) and the frozen one differ by more than the Poiseuille part: at the
  // spike of seed 004's contacts no gradient of either sign then carries it. (ρ/η)_e alone need
  // not rise with |∂p/∂x| across the whole bracket (with sliding, part of the film's stress
  // falls as the gradient grows), so the bracket grows from the pressure's gradient until φ
  // changes sign, and a column where it does not stops the solve with an error.
  struct CarriedFlux {
    const FilmTemperature* field;
    std::size_t i;
    double p, h, sign, target;
  } flux{this, i, p, h, sign, std::log(poiseuille * std::abs(dpdx))};
  gsl_function phi{[](double y, void* params) {
                     const auto& c = *static_cast<const CarriedFlux*>(params);
                     return std::log(c.field->column_flow(c.i, c.p, c.sign * std::exp(y), c.h).rho_over_eta_e()) + y -
                            c.target;
                   },
                   &flux};
  // Bracket the root by steps of e in |∂p/∂x| from the pressure's gradient, then Brent's method.
  const double phi0 = log_coefficient + y0 - flux.target;  // φ(y0), from the column flow above
  if (phi0 == 0.0) return dpdx;
  const double direction = phi0 > 0.0 ? -1.0 : 1.0;
  double near = y0, far = y0 + direction;
  constexpr int max_bracket_steps = 40;
  for (int k = 0; GSL_FN_EVAL(&phi, far) * phi0 > 0.0; ++k) {
    if (k == max_bracket_steps)
      throw ConvergenceError(fmt::format("film temperature: no gradient within e^{} of {:.4g} Pa/m carries the "
                                         "pressure solve's flux at x = {:.4g} m", max_bracket_steps, dpdx, x_[i]));
    near = far;
    far += direction;
  }
  model::gsl_use_status_codes();
  const std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  model::gsl_check(gsl_root_fsolver_set(solver.get(), &phi, std::min(near, far), std::max(near, far)),
                   "flux_carrying_gradient: gsl_root_fsolver_set");
  double y = y0;
  int status = GSL_CONTINUE;
  for (int k = 0; k < 100 && status == GSL_CONTINUE; ++k) {
    model::gsl_check(gsl_root_fsolver_iterate(solver.get()), "flux_carrying_gradient: gsl_root_fsolver_iterate");
    y = gsl_root_fsolver_root(solver.get());
    status = gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()), gsl_root_fsolver_x_upper(solver.get()),
                                    1e-12, 0.0);
  }
  return sign * std::exp(y);
}

std::vector<double> FilmTemperature::mass_flux_profile(const ColumnFlow& flow, double h) const {
  const double dz = 1.0 / static_cast<double>(zeta_.size() - 1);
  std::vector<double> Q(zeta_.size(), 0.0);
  for (std::size_t j = 1; j < Q.size(); ++j)
    Q[j] = Q[j - 1] + 0.5 * dz * h * (flow.rho[j - 1] * flow.u[j - 1] + flow.rho[j] * flow.u[j]);
  return Q;
}

FilmTemperature::SolidRows FilmTemperature::conduction_rows(int body) const {
  const double ks = solids_.conductivity[body];
  SolidRows rows;
  rows.convection = solids_.density[body] * solids_.specific_heat[body] * (body == 0 ? Ua_ : Ub_) / dx_;
  rows.deeper.assign(s_.size(), 0.0);
  rows.shallower.assign(s_.size(), 0.0);
  for (std::size_t kk = 1; kk + 1 < s_.size(); ++kk) {
    const double span = s_[kk + 1] - s_[kk - 1];
    rows.deeper[kk] = 2.0 * ks / (span * (s_[kk + 1] - s_[kk]));
    rows.shallower[kk] = 2.0 * ks / (span * (s_[kk] - s_[kk - 1]));
  }
  return rows;
}

void FilmTemperature::solve_column(std::size_t i, const std::vector<double>& p, const std::vector<double>& h) {
  const std::size_t nz = zeta_.size(), ns = s_.size(), n = x_.size();
  const double dz = 1.0 / static_cast<double>(nz - 1);
  const double dpdx = dpdx_[i];
  const ColumnFlow& flow = flows_[i];
  // The shear stress at the column's shear rate and this sweep's temperature, and ∂ln η/∂T
  // per film node for the source slope.
  std::vector<double>& stress = column_.stress;
  std::vector<double>& dln_eta = column_.dln_eta;
  stress.resize(nz);
  dln_eta.resize(nz);
  for (std::size_t j = 0; j < nz; ++j) {
    const NodeViscosity& v = node_viscosity(i, j);
    const double eta = v.eta, rate = flow.shear_rate[j];
    dln_eta[j] = v.dln_dT;
    stress[j] = eyring_stress_ ? lubricant::eyring_stress(rate, eta, *eyring_stress_) : eta * rate;
  }
  const double k = rheology_.data().thermal_conductivity, c = rheology_.data().specific_heat;
  const double hi = h[i];
  // ∂Q/∂x at fixed ζ from the neighbouring columns.
  std::vector<double>& Qx = column_.Qx;
  Qx.resize(nz);
  for (std::size_t j = 0; j < nz; ++j)
    Qx[j] = i + 1 < n ? (Q_[i + 1][j] - Q_[i - 1][j]) / (2.0 * dx_) : (Q_[i][j] - Q_[i - 1][j]) / dx_;

  // Unknowns: solid a from the deepest free node up to k = 1, the film j = 0..nz−1 (the
  // walls are j = 0 and nz−1), solid b from k = 1 down to the deepest free node.
  const std::size_t na = ns - 2, N = 2 * na + nz;
  auto row_a = [&](std::size_t kk) { return na - kk; };
  auto row_film = [&](std::size_t j) { return na + j; };
  auto row_b = [&](std::size_t kk) { return na + nz - 1 + kk; };
  TridiagonalSystem& system = column_.system;
  system.resize(N);  // each row below is set once

  // Heat source S = S* + S'·(T − T*) about the last temperature T* (Patankar 1980, §4.2.5):
  // shear heating τ·∂u/∂z at the frozen shear rate falls with temperature as the stress does,
  // S' = S·∂ln τ/∂T < 0, which goes on the diagonal; without it the first sweep of a
  // sliding contact overshoots (cold, viscous film → huge heating → hot, thin oil → ...).
  // Newtonian: ∂ln τ/∂T = ∂ln η/∂T. Ree–Eyring, τ = τ0·asinh(ηγ̇/τ0) at fixed γ̇:
  // ∂ln τ/∂T = [tanh(s)/s]·∂ln η/∂T with s = τ/τ0 (1 at s = 0). The fixed point does not
  // depend on S′; it only keeps the sweeps stable. Compression work stays explicit.
  struct Source {
    double value = 0.0, slope = 0.0;  // S*, S' ≤ 0
  };
  auto stress_response = [&](double tau) {  // ∂ln τ/∂ln η at fixed shear rate
    if (!eyring_stress_ || tau == 0.0) return 1.0;
    const double s = tau / *eyring_stress_;
    return std::tanh(s) / s;
  };
  auto source = [&](std::size_t j) {
    Source S;
    const double T = T_[i][j];
    if (o_.shear_heating) {
      const double heating = stress[j] * flow.shear_rate[j];
      S.value += heating;
      S.slope += std::min(0.0, heating * stress_response(stress[j]) * dln_eta[j]);
    }
    if (o_.compression) S.value -= T * rheology_.thermal_expansion(p[i], T) * flow.u[j] * dpdx;
    return S;
  };

  // Solids: ρ_s c_s U_s (T − T_upstream)/Δx = k_s ∂²T/∂s² on the graded nodes.
  for (int body = 0; body < 2; ++body) {
    const SolidRows& rows = solid_rows_[body];
    const double C = rows.convection;
    for (std::size_t kk = 1; kk + 1 < ns; ++kk) {
      const double deeper = rows.deeper[kk], shallower = rows.shallower[kk];
      double b = C * Ts_[body][i - 1][kk];
      const bool deepest = kk + 2 == ns;
      if (deepest) b += deeper * T0_;
      if (body == 0)  // ordering deep → shallow: the deeper node is the previous row
        system.set_row(row_a(kk), deepest ? 0.0 : -deeper, C + deeper + shallower, -shallower, b);
      else            // ordering shallow → deep
        system.set_row(row_b(kk), -shallower, C + deeper + shallower, deepest ? 0.0 : -deeper, b);
    }
  }

  // Film interior: upwind convection in x; across the film the exponential scheme, whose
  // neighbour weights D·B(∓P) are smooth in the cell Péclet number P = v·Δζ/(k/h²): central
  // differences as P → 0 (second order), upwind as |P| → ∞. The hybrid switch it replaces
  // (central up to |P| = 2, upwind with the diffusion above) jumped its weights by D there, and
  // a node at the switch toggled between the two: the sliding contact at SRR 0.5 on 321 nodes
  // (cases/tehl_point_sliding.json) cycled with period 3 at an inlet backflow node (x_27, ζ 0.44,
  // P = 2 to 1e-5) by 5e-4 K, so the coupling could not settle below 7e-6 of the rise.
  const double D = k / (hi * hi * dz * dz);
  for (std::size_t j = 1; j + 1 < nz; ++j) {
    const double a = c * flow.rho[j] * flow.u[j] / dx_;
    const Source S = source(j);
    const double v = -c * Qx[j] / hi;  // coefficient of ∂T/∂ζ
    const auto [b_prev, b_next] = exponential_weights(v / (dz * D));
    const double w_prev = D * b_prev, w_next = D * b_next;
    double d = w_prev + w_next - S.slope, b = S.value - S.slope * T_[i][j];
    if (a >= 0.0) {
      d += a;
      b += a * T_[i - 1][j];
    } else if (i + 1 < n) {
      d -= a;
      b -= a * T_[i + 1][j];
    }
    system.set_row(row_film(j), -w_prev, d, -w_next, b);
  }

  // Walls: half-cell energy balances with conduction from the film and the solid, the
  // half cells' convection with the surface speed, and the film half cell's heat source.
  for (int body = 0; body < 2; ++body) {
    const std::size_t j = body == 0 ? 0 : nz - 1;
    const double U = body == 0 ? Ua_ : Ub_;
    const double film_g = k / (hi * dz), solid_g = solids_.conductivity[body] / s_[1];
    const double storage = (0.5 * s_[1] * solids_.density[body] * solids_.specific_heat[body] +
                            0.5 * hi * dz * c * flow.rho[j]) * U / dx_;
    const Source S = source(j);
    const double half = 0.5 * hi * dz;
    const double b = storage * T_[i - 1][j] + half * (S.value - S.slope * T_[i][j]);
    const double d = film_g + solid_g + storage - half * S.slope;
    if (body == 0)  // neighbours: solid a's first node (previous row), the film (next)
      system.set_row(row_film(j), -solid_g, d, -film_g, b);
    else
      system.set_row(row_film(j), -film_g, d, -solid_g, b);
  }

  const std::vector<double>& T = system.solve("tridiagonal solve of a film-temperature column");
  for (std::size_t j = 0; j < nz; ++j) T_[i][j] = T[row_film(j)];
  for (std::size_t kk = 1; kk + 1 < ns; ++kk) {
    Ts_[0][i][kk] = T[row_a(kk)];
    Ts_[1][i][kk] = T[row_b(kk)];
  }
  Ts_[0][i][0] = T_[i][0];
  Ts_[1][i][0] = T_[i][nz - 1];
}

double FilmTemperature::sweep(const std::vector<double>& p, const std::vector<double>& h) {
  double change = 0.0;
  sweep_start_ = T_;  // copied into kept storage
  // Symmetric sweep: downstream, where the oil and the solids carry the heat, then upstream,
  // which carries the reverse flow of the inlet back in one pass instead of one column per sweep.
  for (std::size_t i = 1; i < x_.size(); ++i) solve_column(i, p, h);
  for (std::size_t i = x_.size() - 1; i >= 1; --i) solve_column(i, p, h);
  for (std::size_t i = 0; i < x_.size(); ++i)
    for (std::size_t j = 0; j < zeta_.size(); ++j) {
      if (!std::isfinite(T_[i][j]))
        throw ConvergenceError(fmt::format("film temperature: non-finite temperature at x = {:.4g} m", x_[i]));
      change = std::max(change, std::abs(T_[i][j] - sweep_start_[i][j]));
    }
  return change;
}

double FilmTemperature::solve(const std::vector<double>& p, const std::vector<double>& h,
                              const std::vector<double>& poiseuille, double tolerance, int max_sweeps) {
  dpdx_.resize(x_.size());
  at_pressure_.resize(x_.size());
  viscosity_.resize(x_.size());
  for (std::size_t i = 0; i < x_.size(); ++i) {  // a new pressure: every viscosity anew
    at_pressure_[i] = rheology_.at_pressure(p[i]);
    viscosity_[i].assign(zeta_.size(), NodeViscosity{});
  }
  for (std::size_t i = 0; i < x_.size(); ++i)
    dpdx_[i] = flux_carrying_gradient(i, p[i], dpdx_at(p, i, dx_), h[i], poiseuille[i]);
  // Each column's flow (velocity, shear rate, mass flux Q) is that of the temperatures this
  // solve starts from, and the sweeps update the heating τ(T, γ̇)·γ̇ at that shear rate: it
  // falls as the oil heats, which is what the source slope above assumes. Why, measured
  // (fourteenth session):
  // - Recomputed in every column solve, the flow is that of a frozen pressure gradient, i.e. a
  //   frozen stress, at which an Eyring column shears faster as it heats (γ̇ = τ0/η·sinh(τ/τ0)):
  //   on 641 nodes a near-pure-rolling contact of seed 004 (M 15.9, L 18.8; |h·∂p/∂x| = 21τ0
  //   at 0.88b after the first pressure solve) ran away to a non-finite temperature in its first
  //   sweeps; with the shear rate held it converges (38 + 16 iterations).
  // - Updated in place, the central ∂Q/∂x mixed this sweep's upstream column with the last
  //   sweep's downstream one: on 2561 nodes the Eyring roller's inlet backflow layer (ζ ≈ 0.78,
  //   x = −4.7 … −3.4b) changed 0.28 K a sweep after 100 sweeps at a fixed pressure and film, and
  //   the coupling stopped at its cap of 60 iterations (117 needed); now 19.
  // - The mass flux Q, whose ∂Q/∂x carries heat across the film, follows the temperatures' by
  //   half its change from one solve to the next (mass_flux_relaxation). Taken whole, a
  //   near-rolling inlet's backflow layer did not converge: at 1.2 GPa, SRR 0.02, 47 °C
  //   (cases/tehl_point_lohner2016.json at 0.08 m/s; twenty-second session) the layer at
  //   x ≈ −3.6b, ζ ≈ 0.2 and 0.78 changed by 0.07–0.19 K every sweep for 400 sweeps at a fixed
  //   pressure and film, and the coupling cycled for its 60 iterations. With Q held the sweeps
  //   reach 1e-12 K; with Q halfway the coupling converges in 12 + 18 iterations. Halfway for
  //   every part of the flow (velocity and shear rate too) lost the Newtonian 1 MN/m roller
  //   (24 + 36 iterations → none in 60); Q alone costs it 32 + 41 and moves the other cases by
  //   ≤ 1 iteration.
  // At the coupling's fixed point the flow is that of the converged temperatures either way.
  constexpr double mass_flux_relaxation = 0.5;
  for (std::size_t i = 0; i < x_.size(); ++i) {
    ColumnFlow& flow = flows_[i];
    flow.viscosity.resize(zeta_.size());
    for (std::size_t j = 0; j < zeta_.size(); ++j) flow.viscosity[j] = node_viscosity(i, j).eta;
    complete_flow(i, at_pressure_[i], dpdx_[i], h[i], flow);
    if (eyring_stress_) wall_stress_[i] = flows_[i].eyring_wall_stress;
    const std::vector<double> Q = mass_flux_profile(flows_[i], h[i]);
    if (Q_[i].size() != Q.size()) {  // the first solve, or the first after interpolate_from
      Q_[i] = Q;
      continue;
    }
    for (std::size_t j = 0; j < Q.size(); ++j) Q_[i][j] += mass_flux_relaxation * (Q[j] - Q_[i][j]);
  }
  double change = 0.0;
  for (int s = 0; s < max_sweeps; ++s) {
    change = sweep(p, h);
    if (change <= tolerance) break;
  }
  return change;
}

HeatBalance FilmTemperature::heat_balance(const std::vector<double>& p, const std::vector<double>& h) const {
  HeatBalance hb;
  const std::size_t n = x_.size(), nz = zeta_.size(), ns = s_.size();
  const double c = rheology_.data().specific_heat;
  std::vector<double> y(nz);
  for (std::size_t i = 0; i < n; ++i) {
    const double w = (i == 0 || i + 1 == n) ? 0.5 * dx_ : dx_;
    const double dpdx = dpdx_at(p, i, dx_);
    const ColumnFlow flow = column_flow(i, p[i], dpdx, h[i]);
    for (std::size_t j = 0; j < nz; ++j) y[j] = flow.stress[j] * flow.shear_rate[j];
    if (o_.shear_heating) hb.shear_heating += w * h[i] * film_integral(y);
    for (std::size_t j = 0; j < nz; ++j)
      y[j] = -T_[i][j] * rheology_.thermal_expansion(p[i], T_[i][j]) * flow.u[j] * dpdx;
    if (o_.compression) hb.compression += w * h[i] * film_integral(y);
    for (int body = 0; body < 2; ++body)
      hb.depth_loss[body] += w * solids_.conductivity[body] * (Ts_[body][i][ns - 2] - T0_) / (s_[ns - 1] - s_[ns - 2]);
    if (i + 1 == n) {
      for (std::size_t j = 0; j < nz; ++j) y[j] = flow.rho[j] * c * flow.u[j] * (T_[i][j] - T0_);
      hb.film_outflow = h[i] * film_integral(y);
    }
  }
  for (int body = 0; body < 2; ++body) {
    std::vector<double> rise(ns);
    for (std::size_t k = 0; k < ns; ++k) rise[k] = Ts_[body][n - 1][k] - T0_;
    hb.solid_outflow[body] = solids_.density[body] * solids_.specific_heat[body] * (body == 0 ? Ua_ : Ub_) *
                             integrate_graded(rise, s_);
  }
  return hb;
}

}  // namespace gearbench::ehl
