#include "fas_multigrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <memory>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "coarsest_solve.h"
#include "deformation.h"
#include "model/errors.h"

namespace gearbench::ehl {

namespace {
constexpr double pi = std::numbers::pi;
/// Order of the discretisation (second-order wedge, central Poiseuille): the error estimate
/// from two grids is their difference over 2^p − 1.
constexpr double order = 2.0;
/// Newton steps of the coarsest grid per visit within a cycle (its problem, with ε and ρ̄
/// from the fine grid, is nearly linear: two steps meet it to rounding where it is smooth).
constexpr int coarsest_steps_per_visit = 3;
/// Newton steps per stage of the start on the coarsest grid.
constexpr int coarsest_steps_per_stage = 30;
/// Relative change of P and H0 at which a coarsest-grid Newton solve stops; the stages of
/// the start before the last need only be close enough to start the next.
constexpr double coarsest_tolerance = 1e-8;
constexpr double homotopy_tolerance = 1e-3;
/// The largest coarsest grid: its dense (P, H0) solve costs ~n³/3 multiply–adds.
constexpr std::size_t max_coarsest_nodes = 1025;
/// Halvings of a coarsest-grid Newton step before it is taken as it is.
constexpr int max_halvings = 6;
/// Rise of ln η̄ at the Hertz pressure per stage of the start.
constexpr double homotopy_step = 8.0;
/// A dense Newton step on n nodes is counted as n³/150 node-sweeps: its LU takes ~n³/3
/// multiply–adds, a banded line sweep with the FFT film ~50 per node.
constexpr double dense_step_cost = 1.0 / 150.0;

/// One grid of the hierarchy with its unknowns, coefficients and FAS right-hand sides.
struct Level {
  Level(std::size_t nodes, double x_in, double x_out)
      : n(nodes), h((x_out - x_in) / static_cast<double>(nodes - 1)), deformation(nodes, h),
        X(nodes), P(nodes, 0.0), H(nodes, 0.0), W(nodes, 0.0), rho(nodes, 1.0), eps_face(nodes - 1, 0.0),
        f(nodes, 0.0), flow_factor(nodes, 1.0), wedge_factor(nodes, 1.0) {
    for (std::size_t i = 0; i < n; ++i) X[i] = x_in + static_cast<double>(i) * h;
  }
  std::size_t n;
  double h;
  Deformation deformation;
  std::vector<double> X, P, H, W, rho;
  std::vector<double> eps_face;  ///< ε_{i+½}
  std::vector<double> f;         ///< FAS right-hand side of the Reynolds equation
  std::vector<double> flow_factor, wedge_factor;  ///< thermal film factors (1: isothermal)
  std::vector<double> rho_h_old;  ///< ρ̄H of the previous time step (transient only)
  /// Every grid's ε and ρ̄ are recomputed from its own P and H ("live" coarse grids, as
  /// Venner & Lubrecht): coefficients frozen from the fine grid lack the piezoviscous
  /// response e^{ᾱP} and halve the two-grid factor's quality (docs/research/
  /// ehl-multigrid-rebuild.md, eighth session: 0.53 frozen against 0.36 live at (20, 10)).
  std::vector<double> rho_slope;      ///< dρ̄/dP at the nodes
  std::vector<double> eps_log_slope;  ///< d ln ε/dP at the nodes (the piezoviscous and density response)
  std::vector<double> eps;            ///< ε at the nodes
  std::vector<double> eps_face_dP_left, eps_face_dP_right;  ///< ∂ε_{i+½}/∂P_i, ∂ε_{i+½}/∂P_{i+1}
  /// FAS right-hand side of the film equation on a coarse grid: the injected fine film minus
  /// the coarse film of the injected pressure (Venner & Lubrecht 2000, §6.4).
  std::vector<double> film_correction;
  double g = 0.0;  ///< FAS right-hand side of the force balance
  double seconds = 0.0;
};

/// The last pressurised node (the outlet's free boundary); 0 if none.
std::size_t last_pressurised(const std::vector<double>& P) {
  std::size_t last = 0;
  for (std::size_t i = 0; i < P.size(); ++i) if (P[i] > 0.0) last = i;
  return last;
}

/// The pressure spike: the last local maximum of P before the outlet's cavitation.
std::size_t spike_index(const std::vector<double>& P) {
  std::size_t last = 0;
  for (std::size_t i = 0; i < P.size(); ++i) if (P[i] > 0.0) last = i;
  for (std::size_t i = last; i > 1; --i)
    if (P[i] >= P[i - 1] && P[i] >= P[i + 1]) return i;
  return last;
}

/// Relative change |a − b|/|b|, 0 for b = 0 = a.
double relative(double a, double b) {
  if (a == b) return 0.0;
  return std::abs(a - b) / std::max(std::abs(b), 1e-300);
}

/// The figures the stop rule watches, dimensionless.
struct Watched {
  double H_c = 0.0, H_min = 0.0, H0 = 0.0;
};

}  // namespace

class FasMultigrid::Impl {
 public:
  Impl(const LineContactProblem& problem, const EhlOptions& o, ContactState state)
      : problem_(problem), o_(o), state_(std::move(state)) {
    o_.validate();
    if (state_.load <= 0.0) state_.load = problem_.load();
    x_in_ = o_.x_in != 0.0 || o_.x_out != 0.0 ? o_.x_in : problem_.x_in();
    x_out_ = o_.x_in != 0.0 || o_.x_out != 0.0 ? o_.x_out : problem_.x_out();
    if (state_.has_fields() && o_.adaptive())
      throw std::invalid_argument("FasMultigrid: a contact state with fields needs a fixed grid (levels > 0)");
    coarsest_ = coarsest_nodes();
    int levels = o_.adaptive() ? 1 : o_.levels;
    if (o_.nodes > 0) levels = levels_for_finest(static_cast<std::size_t>(o_.nodes));
    for (int k = 0; k < levels; ++k) add_level();
    inject_fields();
  }

  EhlResult solve(const std::optional<WarmStart>& warm) {
    const auto start = std::chrono::steady_clock::now();
    EhlResult r;
    r.scheme = o_.describe();
    if (warm) {
      start_from(*warm);
      iterate_to_residual(r);
    } else {
      full_multigrid(r);
      if (o_.stop == StopRule::discretisation_error && std::isfinite(r.error_estimate))
        iterate_to_error(r);
      else
        iterate_to_residual(r);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const auto& l : levels_) r.seconds_per_level.push_back(l->seconds);
    r.levels = static_cast<int>(levels_.size());
    r.work_units = work_units();
    fill_figures(*levels_.back(), r);
    return r;
  }

  [[nodiscard]] std::vector<double> rho_h() {
    Level& fine = *levels_.back();
    update_film(fine);
    update_coefficients(fine);
    std::vector<double> out(fine.n);
    for (std::size_t i = 0; i < fine.n; ++i) out[i] = fine.rho[i] * std::max(fine.H[i], 0.0);
    return out;
  }

 private:
  // --- hierarchy ---------------------------------------------------------------------
  void add_level() {
    const std::size_t nodes = levels_.empty() ? coarsest_ : 2 * levels_.back()->n - 1;
    levels_.push_back(std::make_unique<Level>(nodes, x_in_, x_out_));
  }

  /// The coarsest grid: as given, or the fewest nodes, 32·2^k + 1, whose mesh resolves
  /// both the pressure zone (h ≤ 1/4 of the Hertz half-width in Hertzian scaling; h ≤ the
  /// rigid-isoviscous length in rigid scaling, whose domain spans 43 of them) and the film: the discretisation error of the film, a
  /// difference of O(1) terms (H0, X²/2 and the deformation), is O(h²), so h ≤ √H_est keeps
  /// the coarse film positive (issue 19: at M = 1000 a 41-node coarsest grid has a negative
  /// film, H_est ≈ 2.6e-4 in Hertzian units). H_est is Moes' isoviscous film.
  [[nodiscard]] std::size_t coarsest_nodes() const {
    if (o_.coarsest_nodes > 0) return static_cast<std::size_t>(o_.coarsest_nodes);
    const double h_target = std::min(problem_.hertzian_scaling() ? 0.25 : 1.0, std::sqrt(film_estimate()));
    std::size_t intervals = 32;
    while ((x_out_ - x_in_) / static_cast<double>(intervals) > h_target && intervals < 1024) intervals *= 2;
    return intervals + 1;
  }

  /// For a given finest grid: the levels down to the coarsest grid that is at least as fine
  /// as the sized one (coarsest_ is set to it). n − 1 = (n_0 − 1)·2^(levels − 1).
  int levels_for_finest(std::size_t nodes) {
    std::size_t intervals = nodes - 1;
    int levels = 1;
    while (intervals % 2 == 0 && intervals / 2 >= coarsest_ - 1) {
      intervals /= 2;
      ++levels;
    }
    coarsest_ = intervals + 1;
    if (coarsest_ > max_coarsest_nodes)
      throw InputError(fmt::format("grid.nodes = {}: allowed are (n0 − 1)·2^k + 1 nodes with a coarsest grid "
                                   "n0 ≤ {} (e.g. 2049, 4097, 5121)", nodes, max_coarsest_nodes));
    return levels;
  }

  /// Moes' film from the rigid- and elastic-isoviscous asymptotes (Moes 1992, line contact),
  /// in the problem's film units: the start's H0 and the coarsest grid's film scale.
  [[nodiscard]] double film_estimate() const {
    const auto& d = problem_.data();
    const double M = d.moes_M();
    const double H_moes =
        std::pow(std::pow(3.0 / M, 7.0 / 3.0) + std::pow(2.621 * std::pow(M, -0.2), 7.0 / 3.0), 3.0 / 7.0);
    return H_moes * d.moes_film_scale() / problem_.film_scale();
  }

  /// The transient's (ρ̄H)_old and the thermal factors of the finest grid, injected into
  /// the coarser ones.
  void inject_fields() {
    Level& fine = *levels_.back();
    const auto check = [&](const std::vector<double>& v, const char* name) {
      if (!v.empty() && v.size() != fine.n)
        throw std::invalid_argument(fmt::format("ContactState::{} must hold the finest grid", name));
    };
    check(state_.rho_h_old, "rho_h_old");
    check(state_.flow_factor, "flow_factor");
    check(state_.wedge_factor, "wedge_factor");
    if (state_.time_step > 0.0 && state_.rho_h_old.empty())
      throw std::invalid_argument("ContactState::rho_h_old is needed with a time step");
    if (!state_.rho_h_old.empty()) fine.rho_h_old = state_.rho_h_old;
    if (!state_.flow_factor.empty()) fine.flow_factor = state_.flow_factor;
    if (!state_.wedge_factor.empty()) fine.wedge_factor = state_.wedge_factor;
    for (std::size_t k = levels_.size() - 1; k > 0; --k) {
      Level& f = *levels_[k];
      Level& c = *levels_[k - 1];
      if (!f.rho_h_old.empty()) c.rho_h_old.resize(c.n);
      for (std::size_t I = 0; I < c.n; ++I) {
        if (!f.rho_h_old.empty()) c.rho_h_old[I] = f.rho_h_old[2 * I];
        c.flow_factor[I] = f.flow_factor[2 * I];
        c.wedge_factor[I] = f.wedge_factor[2 * I];
      }
    }
  }

  // --- state -------------------------------------------------------------------------
  void update_film(Level& l) {
    if (o_.direct_deformation)
      l.deformation.apply_direct(l.P, l.W);
    else
      l.deformation.apply(l.P, l.W);
    const double c = problem_.deformation_factor() / pi;
    for (std::size_t i = 0; i < l.n; ++i) l.H[i] = H0_ + 0.5 * state_.curvature * l.X[i] * l.X[i] - c * l.W[i];
    if (!l.film_correction.empty())
      for (std::size_t i = 0; i < l.n; ++i) l.H[i] += l.film_correction[i];
  }

  /// ε = ρ̄H³/(η̄λ) at the nodes and faces (ε_{i+½} the mean of the nodes') and ρ̄, from the
  /// grid's own P and H; ln η̄ rather than η̄, so that ε underflows to 0 where η̄ would
  /// overflow (ᾱP > 709 at a fine-grid Barus spike).
  void update_coefficients(Level& l) {
    const double inv_lambda = 1.0 / problem_.lambda();
    l.eps.resize(l.n);
    l.eps_log_slope.resize(l.n);
    l.rho_slope.resize(l.n);
    for (std::size_t i = 0; i < l.n; ++i) {
      const double rho = problem_.density(l.P[i]);
      const double H = std::max(l.H[i], 0.0);
      l.rho[i] = rho * l.wedge_factor[i];
      l.rho_slope[i] = density_slope(l.P[i]) * l.wedge_factor[i];
      l.eps[i] = l.flow_factor[i] * rho * H * H * H * std::exp(-viscosity_exponent_ * problem_.log_viscosity(l.P[i])) *
                 inv_lambda;
      l.eps_log_slope[i] = eps_log_slope(l.P[i]);
    }
    for (std::size_t i = 0; i + 1 < l.n; ++i) l.eps_face[i] = 0.5 * (l.eps[i] + l.eps[i + 1]);
    eps_face_derivatives(l);
  }

  /// dρ̄/dP by a central difference.
  [[nodiscard]] double density_slope(double P) const {
    const double d = 1e-4 * std::max(1.0, P);
    const double lo = std::max(P - d, 0.0), hi = P + d;
    return (problem_.density(hi) - problem_.density(lo)) / (hi - lo);
  }

  /// d ln(ρ̄/η̄^s)/dP by a central difference (the rheology laws are smooth for P > 0).
  [[nodiscard]] double eps_log_slope(double P) const {
    const double d = 1e-4 * std::max(1.0, P);
    const double lo = std::max(P - d, 0.0), hi = P + d;
    const auto log_ratio = [&](double p) {
      return std::log(problem_.density(p)) - viscosity_exponent_ * problem_.log_viscosity(p);
    };
    return (log_ratio(hi) - log_ratio(lo)) / (hi - lo);
  }

  /// ∂ε_{i+½}/∂H_i and ∂ε_{i+½}/∂H_{i+1} (ε ∝ H³).
  [[nodiscard]] static FilmSensitivity film_sensitivity(const Level& l) {
    FilmSensitivity d;
    d.left.assign(l.n - 1, 0.0);
    d.right.assign(l.n - 1, 0.0);
    for (std::size_t i = 0; i + 1 < l.n; ++i) {  // ε_{i+½} = (ε_i + ε_{i+1})/2, ε ∝ H³
      if (l.H[i] > 0.0) d.left[i] = 1.5 * l.eps[i] / l.H[i];
      if (l.H[i + 1] > 0.0) d.right[i] = 1.5 * l.eps[i + 1] / l.H[i + 1];
    }
    return d;
  }

  [[nodiscard]] ReynoldsCoefficients coefficients(const Level& l) const {
    ReynoldsCoefficients c{l.eps_face, l.rho, l.deformation, l.h, problem_.deformation_factor() / pi, state_.speed,
                           state_.time_step};
    c.rho_dP = &l.rho_slope;
    c.H = &l.H;
    c.eps_face_dP_left = &l.eps_face_dP_left;
    c.eps_face_dP_right = &l.eps_face_dP_right;
    c.P = &l.P;
    return c;
  }

  /// ∂ε_{i+½}/∂P_i and ∂ε_{i+½}/∂P_{i+1} of a live grid, ε_{i+½} = (ε_i + ε_{i+1})/2, from
  /// the slopes d ln ε/dP at the nodes.
  static void eps_face_derivatives(Level& l) {
    l.eps_face_dP_left.resize(l.n - 1);
    l.eps_face_dP_right.resize(l.n - 1);
    for (std::size_t i = 0; i + 1 < l.n; ++i) {
      l.eps_face_dP_left[i] = 0.5 * l.eps[i] * l.eps_log_slope[i];
      l.eps_face_dP_right[i] = 0.5 * l.eps[i + 1] * l.eps_log_slope[i + 1];
    }
  }

  /// The discrete Reynolds operator at interior node i (reynolds_stencil.h).
  [[nodiscard]] double operator_at(const Level& l, std::size_t i) const {
    const double h2 = l.h * l.h;
    double L = (l.eps_face[i - 1] * (l.P[i - 1] - l.P[i]) + l.eps_face[i] * (l.P[i + 1] - l.P[i])) / h2;
    const auto w = wedge_weights(i);
    double wedge = 0.0;
    for (std::size_t m = 0; m < 3 && m <= i; ++m) wedge += w[m] * l.rho[i - m] * l.H[i - m];
    L -= state_.speed * wedge / l.h;
    if (state_.time_step > 0.0) L -= (l.rho[i] * l.H[i] - l.rho_h_old[i]) / state_.time_step;
    return L;
  }

  [[nodiscard]] std::vector<double> residuals(const Level& l) const {
    std::vector<double> r(l.n, 0.0);
    for (std::size_t i = 1; i + 1 < l.n; ++i) r[i] = l.f[i] - operator_at(l, i);
    return r;
  }

  [[nodiscard]] static double integral(const Level& l) {
    return l.h * std::accumulate(l.P.begin(), l.P.end(), 0.0);  // P = 0 at both ends
  }

  /// Residual of the complementarity problem P ≥ 0, r = f − L(P) ≥ 0 (J < 0), P·r = 0:
  /// the mean of |min(P_i·|J_ii|, r_i)| over the interior, scaled by the largest wedge term.
  /// It vanishes exactly at a solution, cavitated nodes included.
  [[nodiscard]] double scaled_residual(Level& l) {
    update_film(l);
    update_coefficients(l);
    const auto c = coefficients(l);
    double sum = 0.0, scale = 1e-300;
    for (std::size_t i = 1; i + 1 < l.n; ++i) {
      scale = std::max(scale, std::abs(l.rho[i] * l.H[i] - l.rho[i - 1] * l.H[i - 1]) / l.h);
      const double r = l.f[i] - operator_at(l, i);
      sum += std::abs(std::min(l.P[i] * std::abs(c.jacobian(i, i)), r));
    }
    return sum / static_cast<double>(l.n - 2) / scale;
  }

  [[nodiscard]] double force_balance(const Level& l) const { return std::abs(integral(l) - l.g) / state_.load; }

  // --- relaxation ----------------------------------------------------------------------
  /// One relaxation sweep (Venner & Lubrecht 2000, §7.3, in one dimension, with the changes
  /// measured in docs/research/ehl-multigrid-rebuild.md): the Jacobi nodes first, each run of
  /// consecutive ones solved simultaneously as a line and its changes distributed with the
  /// zero-sum pattern (−½, 1, −½); then point Gauss–Seidel on the others, which sees the
  /// lines' changes and film. Every change is limited to the exponential's linear range
  /// (limit_change); P ≥ 0. The film of the next nodes follows a Gauss–Seidel change at once
  /// through the kernel's near entries; the full film is recomputed after each pass.
  void relax(Level& l, std::size_t first = 1, std::size_t end = 0) {
    if (end == 0) end = l.n - 1;
    const auto start = std::chrono::steady_clock::now();
    update_film(l);
    update_coefficients(l);
    const auto c = coefficients(l);
    std::vector<double> jacobi_change(l.n, 0.0), jacobi_residual(l.n, 0.0);
    std::vector<char> is_jacobi(l.n, 0);
    for (std::size_t i = first; i < end; ++i) {
      if (poiseuille_dominates(l, c, i)) continue;
      const double r = l.f[i] - operator_at(l, i);
      const double derivative = c.jacobian(i, i) - 0.5 * (c.jacobian(i, i - 1) + c.jacobian(i, i + 1));
      jacobi_change[i] = limit_change(l, i, o_.omega_jacobi * r / derivative);
      jacobi_residual[i] = r;
      is_jacobi[i] = 1;
    }
    solve_jacobi_lines(l, c, is_jacobi, jacobi_residual, jacobi_change);
    for (std::size_t i = 1; i + 1 < l.n; ++i) {
      if (jacobi_change[i] == 0.0) continue;
      l.P[i] += jacobi_change[i];
      if (i > 1) l.P[i - 1] -= 0.5 * jacobi_change[i];
      if (i + 2 < l.n) l.P[i + 1] -= 0.5 * jacobi_change[i];
    }
    for (auto& p : l.P) p = std::max(p, 0.0);
    l.P.front() = l.P.back() = 0.0;
    update_film(l);
    // Gauss–Seidel nodes after the Jacobi lines, so that they see (and answer) the lines'
    // distributed changes and film.
    for (std::size_t i = first; i < end; ++i) {
      if (is_jacobi[i]) continue;
      const double r = l.f[i] - operator_at(l, i);
      const double old = l.P[i];
      l.P[i] = std::max(0.0, old + limit_change(l, i, o_.omega_gauss_seidel * r / gauss_seidel_derivative(c, i)));
      move_film_near(l, i, l.P[i] - old);
    }
    update_film(l);
    node_sweeps_ += static_cast<double>(l.n);
    l.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  /// The scale-free relaxation switch: node i is relaxed by Gauss–Seidel where the Poiseuille
  /// diagonal (ε_{i−½} + ε_{i+½})/h² exceeds κ × the wedge term's own diagonal (the film's
  /// kernel response at frozen ε); elsewhere point Gauss–Seidel is not a smoother and the
  /// node joins a Jacobi line (docs/research/ehl-multigrid-rebuild.md, tenth session).
  [[nodiscard]] bool poiseuille_dominates(const Level& l, const ReynoldsCoefficients& c, std::size_t i) const {
    ReynoldsCoefficients frozen = c;
    frozen.eps_face_dP_left = frozen.eps_face_dP_right = nullptr;
    const double poiseuille = (l.eps_face[i - 1] + l.eps_face[i]) / (l.h * l.h);
    const double wedge = frozen.jacobian(i, i) + poiseuille;
    return !(poiseuille < o_.relaxation_switch * std::abs(wedge));
  }

  /// Runs of consecutive Jacobi nodes solved simultaneously: the band |k − j| ≤ line_band of
  /// the Jacobian of the distributed change (−½, 1, −½), by sparse LU (Venner & Lubrecht's
  /// line relaxation in one dimension, their init_line/solve_line). Point distributive Jacobi
  /// leaves complex modes of |λ| ≈ 0.6 in the contact, the line removes them (eighth session).
  /// Where a run's LU fails or its change is not finite, the point changes stay.
  void solve_jacobi_lines(const Level& l, const ReynoldsCoefficients& c, const std::vector<char>& is_jacobi,
                          const std::vector<double>& residual, std::vector<double>& change) const {
    const auto band = static_cast<std::size_t>(o_.line_band);
    const auto J = [&](std::size_t k, std::size_t j) { return (j == 0 || j + 1 >= l.n) ? 0.0 : c.jacobian(k, j); };
    std::size_t i = 1;
    while (i + 1 < l.n) {
      if (!is_jacobi[i]) { ++i; continue; }
      std::size_t b = i;
      while (b + 2 < l.n && is_jacobi[b + 1]) ++b;
      const std::size_t a = i, m = b - a + 1;
      std::vector<Eigen::Triplet<double>> t;
      for (std::size_t k = a; k <= b; ++k)
        for (std::size_t q = (k >= a + band ? k - band : a); q <= std::min(b, k + band); ++q)
          t.emplace_back(static_cast<int>(k - a), static_cast<int>(q - a),
                         J(k, q) - (0.5 * J(k, q - 1) + 0.5 * J(k, q + 1)));
      Eigen::SparseMatrix<double> A(static_cast<int>(m), static_cast<int>(m));
      A.setFromTriplets(t.begin(), t.end());
      Eigen::VectorXd rhs(static_cast<int>(m));
      for (std::size_t k = a; k <= b; ++k) rhs(static_cast<int>(k - a)) = residual[k];
      Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
      lu.compute(A);
      if (lu.info() == Eigen::Success) {
        const Eigen::VectorXd d = lu.solve(rhs);
        if (d.allFinite())
          for (std::size_t k = a; k <= b; ++k)
            change[k] = limit_change(l, k, o_.omega_jacobi * d(static_cast<int>(k - a)));
      }
      i = b + 1;
    }
  }

  /// Local Newton solve of the pressure spike: the nodes within ±spike_window of it, with
  /// every kernel coupling of the window and ε's film response, H0 fixed, two steps each
  /// halved until the window's complementarity merit falls. The spike is a grid-scale
  /// feature no coarse grid holds (Brandt's local relaxation of a singularity; eighth session:
  /// the W-cycle's factor 0.25 → 0.12 with it).
  void relax_spike(Level& l) {
    constexpr int steps = 2;
    const auto w = static_cast<std::size_t>(o_.spike_window);
    update_film(l);
    update_coefficients(l);
    const auto s = spike_index(l.P);
    const std::size_t a = s > w ? s - w : 1;
    const std::size_t b = std::min(l.n - 2, s + w);
    const std::size_t m = b - a + 1;
    const auto merit = [&]() {
      double sum = 0.0;
      for (std::size_t i = a; i <= b; ++i) {
        const double r = l.f[i] - operator_at(l, i);
        const double part = l.P[i] > 0.0 ? r : std::min(r, 0.0);
        sum += part * part;
      }
      return sum;
    };
    for (int st = 0; st < steps; ++st) {
      const auto c = coefficients(l);
      const auto fs = film_sensitivity(l);
      Eigen::MatrixXd A = Eigen::MatrixXd::Zero(m, m);
      Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
      const double h2 = l.h * l.h;
      for (std::size_t i = a; i <= b; ++i) {
        const double r = l.f[i] - operator_at(l, i);
        const auto row = static_cast<Eigen::Index>(i - a);
        if (l.P[i] <= 0.0 && r / c.jacobian(i, i) <= 0.0) { A(row, row) = 1.0; continue; }
        const double q_minus = (l.P[i - 1] - l.P[i]) / h2, q_plus = (l.P[i + 1] - l.P[i]) / h2;
        const double dH_prev = fs.left[i - 1] * q_minus;
        const double dH_here = fs.right[i - 1] * q_minus + fs.left[i] * q_plus;
        const double dH_next = fs.right[i] * q_plus;
        const auto K = [&](std::size_t k, std::size_t j) { return l.deformation.kernel(k > j ? k - j : j - k); };
        for (std::size_t j = a; j <= b; ++j) {
          const double through_film = -c.film_factor * (dH_prev * K(i - 1, j) + dH_here * K(i, j) + dH_next * K(i + 1, j));
          A(row, static_cast<Eigen::Index>(j - a)) = c.jacobian(i, j) + through_film;
        }
        rhs(row) = r;
      }
      const Eigen::VectorXd x = A.partialPivLu().solve(rhs);
      if (!x.allFinite()) return;
      const std::vector<double> P0 = l.P;
      const double m0 = merit();
      double theta = 1.0;
      for (int hv = 0; hv <= 6; ++hv, theta *= 0.5) {
        for (std::size_t i = a; i <= b; ++i) l.P[i] = std::max(0.0, P0[i] + theta * x(static_cast<Eigen::Index>(i - a)));
        update_film(l);
        update_coefficients(l);
        if (merit() < m0) break;
        if (hv == 6) { l.P = P0; update_film(l); update_coefficients(l); return; }
      }
    }
  }

  /// The outlet's free boundary, a grid-scale feature like the spike: free_boundary_sweeps
  /// extra sweeps over the last free_boundary_window pressurised nodes and a few beyond
  /// (eighth session: (20, 10) on 4097 nodes converges instead of a period-2 oscillation).
  void relax_free_boundary(Level& l) {
    constexpr std::size_t beyond = 4;  // cavitated nodes the free boundary may move into
    const std::size_t last = last_pressurised(l.P);
    const auto w = static_cast<std::size_t>(o_.free_boundary_window);
    const std::size_t a = last > w ? last - w : 1;
    const std::size_t b = std::min(l.n - 1, last + beyond);
    for (int s = 0; s < o_.free_boundary_sweeps; ++s) relax(l, a, b);
  }

  /// ∂L_i/∂P_i with the piezoviscous response of ε_i: ½(dε_i/dP)(P_{i−1} − 2P_i + P_{i+1})/h²
  /// (faces by the mean of the nodes), where it keeps the derivative negative; at the
  /// pressure spike of high L, ε falls by e^{ᾱΔP} and this term is what the frozen-ε
  /// derivative misses.
  [[nodiscard]] static double gauss_seidel_derivative(const ReynoldsCoefficients& c, std::size_t i) {
    const double with_eps = c.jacobian(i, i);
    if (with_eps < 0.0) return with_eps;
    ReynoldsCoefficients frozen = c;
    frozen.eps_face_dP_left = frozen.eps_face_dP_right = nullptr;
    return frozen.jacobian(i, i);
  }

  /// The film of nodes i − 2 … i + 2 after a change δ of P_i: δH_k = −(D/π)K_|k−i|δ (the
  /// nodes the next residuals read; the far film waits for the sweep's FFT).
  void move_film_near(Level& l, std::size_t i, double delta) const {
    const double c = problem_.deformation_factor() / pi;
    for (std::size_t k = i >= 2 ? i - 2 : 0; k <= std::min(l.n - 1, i + 2); ++k)
      l.H[k] -= c * l.deformation.kernel(k > i ? k - i : i - k) * delta;
  }

  /// Newton steps in (P, H0) on the coarsest grid (coarsest_solve.h) until the step no
  /// longer moves H0 or P beyond rounding, at most `steps`.
  void solve_coarsest(Level& l, int steps, double tolerance) {
    const auto start = std::chrono::steady_clock::now();
    double merit = coarsest_merit(l);
    for (int s = 0; s < steps; ++s) {
      const CoarsestStep step =
          coarsest_newton_step(coefficients(l), l.P, residuals(l), film_sensitivity(l), l.g - integral(l));
      node_sweeps_ += dense_step_cost * std::pow(static_cast<double>(l.n), 3);
      // Backtracking: the largest of 1, ½, ¼, … that lowers the merit; none does: the solve
      // keeps its last iterate (strict descent: a Newton step on a live coarse grid can
      // otherwise leave the region where its problem is meaningful, eighth session).
      const std::vector<double> P0 = l.P;
      const double H00 = H0_;
      double theta = 1.0, trial = merit;
      for (int halving = 0; halving <= max_halvings; ++halving, theta *= 0.5) {
        for (std::size_t i = 1; i + 1 < l.n; ++i) l.P[i] = std::max(0.0, P0[i] + theta * step.dP[i]);
        H0_ = H00 + theta * step.dH0;
        trial = coarsest_merit(l);
        if (trial < merit) break;
      }
      if (!(trial < merit)) {
        l.P = P0;
        H0_ = H00;
        break;
      }
      merit = trial;
      double largest = 0.0, size = 1e-300;
      for (std::size_t i = 1; i + 1 < l.n; ++i) {
        largest = std::max(largest, std::abs(l.P[i] - P0[i]));
        size = std::max(size, l.P[i]);
      }
      if (largest <= tolerance * size && std::abs(H0_ - H00) <= tolerance * std::max(std::abs(H0_), 1.0)) break;
    }
    update_film(l);
    l.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  /// Σ of the squared complementarity residuals (r_i where P_i > 0, the negative part of r_i
  /// where P_i = 0) and the squared force balance over h: the merit of the coarsest grid's
  /// Newton steps. Leaves the film and coefficients of the current P.
  [[nodiscard]] double coarsest_merit(Level& l) {
    update_film(l);
    update_coefficients(l);
    node_sweeps_ += static_cast<double>(l.n);
    const auto r = residuals(l);
    double sum = 0.0;
    for (std::size_t i = 1; i + 1 < l.n; ++i) {
      const double part = l.P[i] > 0.0 ? r[i] : std::min(r[i], 0.0);
      sum += part * part;
    }
    const double gap = (l.g - integral(l)) / l.h;
    return sum + gap * gap;
  }

  /// A change of P_i limited to |Δ ln ε_i| = |d ln ε/dP|·|ΔP| ≤ change_limit: a linear model
  /// of ε = ρ̄H³e^{−ᾱP} holds only for |ᾱΔP| of order 1, and larger changes (lines at tiny
  /// ξ, Gauss–Seidel next to the spike, corrections from the spike's restricted residual)
  /// are what ran away (docs/research/ehl-multigrid-rebuild.md, tenth session).
  [[nodiscard]] double limit_change(const Level& l, std::size_t i, double change) const {
    const double s = std::abs(l.eps_log_slope[i]);
    if (s * std::abs(change) <= o_.change_limit) return change;
    return std::copysign(o_.change_limit / s, change);
  }

  // --- multigrid -------------------------------------------------------------------------
  /// One V- or W-cycle from level k: pre-smoothing, the FAS coarse problem solved by γ
  /// cycles of the next level (the coarsest directly), the correction, post-smoothing, then
  /// the local treatments of the spike and the free boundary.
  void cycle(std::size_t k) {
    Level& fine = *levels_[k];
    if (k == 0) {
      solve_coarsest(fine, coarsest_steps_per_visit, coarsest_tolerance);
      return;
    }
    for (int s = 0; s < o_.pre_sweeps; ++s) relax(fine);
    Level& coarse = *levels_[k - 1];
    restrict_problem(fine, coarse);
    const std::vector<double> injected = coarse.P;
    const int gamma = o_.cycle == CycleType::W ? 2 : 1;
    for (int c = 0; c < gamma; ++c) cycle(k - 1);
    correct(coarse, injected, fine);
    for (int s = 0; s < o_.post_sweeps; ++s) relax(fine);
    relax_spike(fine);
    relax_free_boundary(fine);
  }

  /// Correction by linear interpolation, applied only inside the pressurised zone: not on
  /// cavitated nodes nor next to them, and not on the last free_boundary_nodes pressurised
  /// nodes, where the free boundary is the fine grid's to place (eighth session); each
  /// change limited like a relaxation change.
  void correct(const Level& coarse, const std::vector<double>& injected, Level& fine) const {
    std::vector<double> correction(fine.n, 0.0);
    for (std::size_t I = 0; I + 1 < coarse.n; ++I) {
      const double d0 = coarse.P[I] - injected[I];
      const double d1 = coarse.P[I + 1] - injected[I + 1];
      correction[2 * I] = d0;
      correction[2 * I + 1] = 0.5 * (d0 + d1);
    }
    // Where to correct is decided on the pressure before the correction.
    const std::size_t last = last_pressurised(fine.P);
    const auto held = static_cast<std::size_t>(o_.free_boundary_nodes);
    std::vector<char> corrected(fine.n, 0);
    for (std::size_t i = 1; i + 1 < fine.n; ++i)
      corrected[i] = fine.P[i - 1] > 0.0 && fine.P[i] > 0.0 && fine.P[i + 1] > 0.0 && i + held <= last;
    for (std::size_t i = 1; i + 1 < fine.n; ++i)
      if (corrected[i]) fine.P[i] = std::max(0.0, fine.P[i] + limit_change(fine, i, correction[i]));
  }

  /// FAS coarse problem: injected pressure and film, the coarse grid's own (live)
  /// coefficients, f_c = L_c(P̄) + R·r (full weighting; no residual where the fine pressure
  /// is cavitated), g_c = ∫P̄ + (g − ∫P).
  void restrict_problem(Level& fine, Level& coarse) {
    update_film(fine);
    update_coefficients(fine);
    std::vector<double> r = residuals(fine);
    for (std::size_t i = 1; i + 1 < fine.n; ++i)
      if (fine.P[i] <= 0.0) r[i] = 0.0;
    for (std::size_t I = 0; I < coarse.n; ++I) coarse.P[I] = fine.P[2 * I];
    coarse.film_correction.clear();
    update_film(coarse);
    coarse.film_correction.resize(coarse.n);
    for (std::size_t I = 0; I < coarse.n; ++I) {
      coarse.film_correction[I] = fine.H[2 * I] - coarse.H[I];
      coarse.H[I] = fine.H[2 * I];
    }
    update_coefficients(coarse);
    std::fill(coarse.f.begin(), coarse.f.end(), 0.0);
    for (std::size_t I = 1; I + 1 < coarse.n; ++I)
      coarse.f[I] = operator_at(coarse, I) + 0.25 * (r[2 * I - 1] + 2.0 * r[2 * I] + r[2 * I + 1]);
    coarse.g = integral(coarse) + (fine.g - integral(fine));
  }

  /// A grid becomes the finest of the cycles: its own coefficients, no FAS right-hand sides.
  void make_finest(Level& l) {
    l.film_correction.clear();
    std::fill(l.f.begin(), l.f.end(), 0.0);
    l.g = state_.load;
  }

  /// The start on the coarsest grid: the Hertzian guess, then Newton in (P, H0) through a
  /// homotopy in the piezoviscous exponent (η̄^s, s from 0 to 1 in steps that raise ln η̄ at
  /// the Hertz pressure by at most 2), so that the first solve is isoviscous and each next
  /// one starts close to its solution. It costs a few dense solves on the coarsest grid.
  void start_on_coarsest() {
    Level& l = *levels_.front();
    make_finest(l);
    initial_guess(l);
    const double exponent_at_hertz = problem_.log_viscosity(problem_.hertz_pressure() / problem_.pressure_scale());
    const int stages = std::max(1, static_cast<int>(std::ceil(exponent_at_hertz / homotopy_step)));
    for (int s = 0; s <= stages; ++s) {
      viscosity_exponent_ = static_cast<double>(s) / stages;
      solve_coarsest(l, coarsest_steps_per_stage, s == stages ? coarsest_tolerance : homotopy_tolerance);
    }
    viscosity_exponent_ = 1.0;
  }

  /// Full multigrid: each level's solution, interpolated, starts the next, which gets one
  /// cycle. The change of H_c and H_min from one level to the next over 2^p − 1 estimates
  /// the discretisation error; with levels chosen by target_error, levels are added until
  /// the estimate is below it.
  void full_multigrid(EhlResult& r) {
    start_on_coarsest();
    record_fmg_level(r, 0);
    for (std::size_t k = 1;; ++k) {
      if (k == levels_.size()) {
        if (!o_.adaptive() || (k >= 3 && r.error_estimate <= o_.target_error) ||
            static_cast<int>(k) >= o_.max_levels)
          break;
        add_level();
      }
      interpolate_solution(*levels_[k - 1], *levels_[k]);
      make_finest(*levels_[k]);
      relax_spike(*levels_[k]);  // the cubic interpolation of a resolved spike overshoots (eighth session)
      cycle(k);
      record_fmg_level(r, k);
      // With the grid chosen by the error target, a level whose film is still negative (heavy
      // loads on coarse grids: no estimate) is not the end: finer levels may resolve it
      // (tenth session, (1000, 0) positive from 2049 nodes). A fixed grid stops there.
      if (!std::isfinite(r.error_estimate) && !o_.adaptive()) break;
    }
  }

  void record_fmg_level(EhlResult& r, std::size_t k) {
    Level& l = *levels_[k];
    const Watched w = watched(l);
    r.fmg_nodes.push_back(static_cast<double>(l.n));
    r.fmg_H_c.push_back(w.H_c);
    r.fmg_H_min.push_back(w.H_min);
    remember_level_figures(l);
    const std::size_t n = r.fmg_H_c.size();
    if (n < 2) return;
    const double scale = std::pow(2.0, order) - 1.0;
    r.error_estimate = std::max(relative(r.fmg_H_c[n - 1], r.fmg_H_c[n - 2]),
                                relative(r.fmg_H_min[n - 1], r.fmg_H_min[n - 2])) / scale;
    if (!(w.H_min > 0.0)) r.error_estimate = std::numeric_limits<double>::infinity();
  }

  [[nodiscard]] Watched watched(Level& l) {
    update_film(l);
    Watched w;
    w.H_c = film_at_centre(l);
    w.H_min = *std::min_element(l.H.begin(), l.H.end());
    w.H0 = H0_;
    return w;
  }

  /// Cycles until the per-cycle change of H_c, H_min and H0 and the force balance are below
  /// error_fraction of the discretisation-error estimate. The Barus pressure spike is left
  /// out: p_max does not converge with the grid (docs/ehl-model.md).
  void iterate_to_error(EhlResult& r) {
    Level& fine = *levels_.back();
    const double bound = o_.error_fraction * r.error_estimate;
    r.stop_rule = fmt::format("per-cycle change of H_c, H_min, H0 and the force balance below {:g} × the "
                              "discretisation-error estimate {:.2g} (= {:.2g})",
                              o_.error_fraction, r.error_estimate, bound);
    Watched before = watched(fine);
    const double previous_residual = scaled_residual(fine);  // after full multigrid
    for (int c = 0; c < o_.max_cycles; ++c) {
      cycle(levels_.size() - 1);
      ++r.cycles;
      record_residual(r, fine);
      if (diverged(r)) break;
      const Watched now = watched(fine);
      const double change = std::max({relative(now.H_c, before.H_c), relative(now.H_min, before.H_min),
                                      std::abs(now.H0 - before.H0) / std::max(std::abs(now.H_c), 1e-300)});
      before = now;
      // The algebraic error left after a cycle that changed the figures by δ, at a
      // per-cycle factor ρ, is δ·ρ/(1 − ρ); ρ is the larger of the residual's last two
      // factors, so that a stalled iteration (ρ → 1: a fixed point that is not the discrete
      // solution) is never accepted however small its change.
      const double rho = residual_factor(r, previous_residual);
      const double left = rho < 1.0 ? change * rho / (1.0 - rho) : std::numeric_limits<double>::infinity();
      if (left <= bound && r.force_history.back() <= bound) {
        accept(r, fmt::format("converged: the algebraic error left, {:.2g} (per-cycle change {:.2g} at factor {:.2f}), "
                              "is below {:g} of the discretisation-error estimate {:.2g} after {} cycles",
                              left, change, rho, o_.error_fraction, r.error_estimate, r.cycles));
        return;
      }
    }
    reject(r, fmt::format("EHL multigrid did not reach {:g} of its discretisation-error estimate {:.2g} in {} "
                          "cycles (last residual {:.3e}, force balance {:.3e})",
                          o_.error_fraction, r.error_estimate, r.cycles, last(r.residual_history),
                          last(r.force_history)));
  }

  /// Cycles until the scaled residual and the force balance meet the tolerance.
  void iterate_to_residual(EhlResult& r) {
    Level& fine = *levels_.back();
    r.stop_rule = fmt::format("scaled residual and force balance below {:.1e}", o_.tolerance);
    for (int c = 0; c < o_.max_cycles; ++c) {
      cycle(levels_.size() - 1);
      ++r.cycles;
      record_residual(r, fine);
      if (diverged(r)) break;
      if (r.residual_history.back() <= o_.tolerance && r.force_history.back() <= o_.tolerance) {
        accept(r, fmt::format("converged: scaled residual {:.2e} and force balance {:.2e} below {:.1e} after {} "
                              "cycles", r.residual_history.back(), r.force_history.back(), o_.tolerance, r.cycles));
        return;
      }
    }
    reject(r, fmt::format("EHL multigrid did not converge in {} cycles (residual {:.3e}, force balance {:.3e}, "
                          "tolerance {:.1e})", r.cycles, last(r.residual_history), last(r.force_history),
                          o_.tolerance));
  }

  void record_residual(EhlResult& r, Level& fine) {
    r.residual_history.push_back(scaled_residual(fine));
    r.force_history.push_back(force_balance(fine));
    const std::size_t n = r.residual_history.size();
    if (n >= 2 && r.residual_history.front() > 0.0)
      r.convergence_factor = std::pow(r.residual_history.back() / r.residual_history.front(), 1.0 / double(n - 1));
  }

  [[nodiscard]] static double last(const std::vector<double>& v) { return v.empty() ? 0.0 : v.back(); }

  /// The larger of the last two per-cycle factors of the scaled residual (the first cycle's
  /// against the residual after full multigrid).
  [[nodiscard]] static double residual_factor(const EhlResult& r, double after_fmg) {
    const auto& h = r.residual_history;
    const std::size_t n = h.size();
    const double newest = h[n - 1] / (n >= 2 ? h[n - 2] : after_fmg);
    if (n < 2) return newest;
    return std::max(newest, h[n - 2] / (n >= 3 ? h[n - 3] : after_fmg));
  }

  /// A residual or force balance that is not finite, or above 10 (scaled: a first cycle
  /// starts near 1e-2), does not come back.
  [[nodiscard]] static bool diverged(const EhlResult& r) {
    const double residual = r.residual_history.back(), force = r.force_history.back();
    return !(std::isfinite(residual) && std::isfinite(force) && residual <= 10.0 && force <= 10.0);
  }

  void accept(EhlResult& r, std::string message) {
    r.converged = true;
    r.message = std::move(message);
    r.work_units_at_error = work_units();
  }
  static void reject(EhlResult& r, std::string message) {
    r.converged = false;
    r.message = std::move(message);
  }

  [[nodiscard]] double work_units() const { return node_sweeps_ / static_cast<double>(levels_.back()->n); }

  /// A previous solution on the finest grid (the last time step) as the start.
  void start_from(const WarmStart& warm) {
    Level& fine = *levels_.back();
    if (warm.P.size() != fine.n) throw std::invalid_argument("WarmStart::P must hold the finest grid");
    fine.P = warm.P;
    H0_ = warm.H0;
    make_finest(fine);
    update_film(fine);
  }

  /// FMG interpolation: cubic in the interior (4-point), linear next to the ends.
  static void interpolate_solution(const Level& coarse, Level& fine) {
    for (std::size_t I = 0; I < coarse.n; ++I) fine.P[2 * I] = coarse.P[I];
    for (std::size_t I = 0; I + 1 < coarse.n; ++I) {
      const double value =
          I >= 1 && I + 2 < coarse.n
              ? (-coarse.P[I - 1] + 9.0 * coarse.P[I] + 9.0 * coarse.P[I + 1] - coarse.P[I + 2]) / 16.0
              : 0.5 * (coarse.P[I] + coarse.P[I + 1]);
      fine.P[2 * I + 1] = std::max(0.0, value);
    }
  }

  /// Semi-ellipse carrying the load on |X| < 1, H0 from Moes' isoviscous asymptotes
  /// (rigid and elastic) converted to these units.
  void initial_guess(Level& l) {
    const double amplitude = 2.0 * state_.load / pi;
    for (std::size_t i = 0; i < l.n; ++i) l.P[i] = amplitude * std::sqrt(std::max(0.0, 1.0 - l.X[i] * l.X[i]));
    l.P.front() = l.P.back() = 0.0;
    H0_ = 0.0;
    update_film(l);
    double h_in_contact = l.H[0];
    for (std::size_t i = 0; i < l.n; ++i)
      if (std::abs(l.X[i]) < 1.0) h_in_contact = std::min(h_in_contact, l.H[i]);
    H0_ = film_estimate() - h_in_contact;
    update_film(l);
  }

  [[nodiscard]] static double film_at_centre(const Level& l) {
    const double t = (0.0 - l.X.front()) / l.h;
    const auto i0 = std::min(static_cast<std::size_t>(std::floor(t)), l.n - 2);
    const double frac = t - static_cast<double>(i0);
    return (1.0 - frac) * l.H[i0] + frac * l.H[i0 + 1];
  }

  /// h_min and p_max of a full-multigrid level; the previous level's become the coarse ones.
  void remember_level_figures(const Level& l) {
    if (has_level_) {
      coarse_h_min_ = level_h_min_;
      coarse_p_max_ = level_p_max_;
      has_coarse_ = true;
    }
    EhlResult figures;
    fill_figures(l, figures);
    level_h_min_ = figures.h_min;
    level_p_max_ = figures.p_max;
    has_level_ = true;
  }

  void fill_figures(const Level& l, EhlResult& r) const {
    const double hs = problem_.film_scale();
    const double ls = problem_.length_scale();
    const double ps = problem_.pressure_scale();
    r.X = l.X;
    r.P = l.P;
    r.H = l.H;
    r.H0 = H0_;
    const auto imin = static_cast<std::size_t>(std::min_element(l.H.begin(), l.H.end()) - l.H.begin());
    r.h_min = l.H[imin] * hs;
    r.x_h_min = l.X[imin] * ls;
    r.p_max = *std::max_element(l.P.begin(), l.P.end()) * ps;
    r.h_central = film_at_centre(l) * hs;
    // First zero of dP/dX from the inlet (the first pressure maximum).
    r.h_dpdx0 = r.h_central;
    for (std::size_t i = 1; i + 1 < l.n; ++i)
      if (l.P[i] > 0.0 && l.P[i] >= l.P[i - 1] && l.P[i] > l.P[i + 1]) {
        r.h_dpdx0 = l.H[i] * hs;
        break;
      }
    // Newtonian traction: τ = η(u2 − u1)/h − (h/2)dp/dx on surface 1, integrated where the
    // film is pressurised (the cavitated film carries no full-film shear).
    const auto& d = problem_.data();
    double force = 0.0;
    for (std::size_t i = 1; i + 1 < l.n; ++i) {
      if (l.P[i] <= 0.0 || l.H[i] <= 0.0) continue;
      const double h = l.H[i] * hs;
      const double dpdx = (l.P[i + 1] - l.P[i - 1]) / (2.0 * l.h) * ps / ls;
      const double eta = d.viscosity * problem_.viscosity(l.P[i]);
      force += (eta * (d.u2 - d.u1) / h - 0.5 * h * dpdx) * l.h * ls;
    }
    r.friction_force = force;
    r.friction_coefficient = force / d.load_per_length;
    if (has_coarse_) {
      r.coarse_h_min = coarse_h_min_;
      r.coarse_p_max = coarse_p_max_;
      // A coarse film at or below zero (heavy loads on coarse grids) gives a change above 1.
      if (r.h_min > 0.0 && r.p_max > 0.0) {
        r.h_min_change = std::abs(r.h_min - coarse_h_min_) / r.h_min;
        r.p_max_change = std::abs(r.p_max - coarse_p_max_) / r.p_max;
      }
    }
  }

  LineContactProblem problem_;
  EhlOptions o_;
  ContactState state_;
  double x_in_ = 0.0, x_out_ = 0.0;
  std::size_t coarsest_ = 0;  ///< nodes of the coarsest grid
  std::vector<std::unique_ptr<Level>> levels_;
  double H0_ = 0.0;
  double viscosity_exponent_ = 1.0;  ///< s of the start's homotopy η̄^s (1 after the start)
  double node_sweeps_ = 0.0;         ///< work: Σ nodes of every sweep, dense steps by their flops
  double coarse_h_min_ = 0.0, coarse_p_max_ = 0.0, level_h_min_ = 0.0, level_p_max_ = 0.0;
  bool has_level_ = false;   ///< a full-multigrid level was recorded
  bool has_coarse_ = false;  ///< a solution on the next-coarser grid was recorded (full multigrid)
};

FasMultigrid::FasMultigrid(const LineContactProblem& problem, const EhlOptions& options, ContactState state)
    : impl_(std::make_unique<Impl>(problem, options, std::move(state))) {}

FasMultigrid::~FasMultigrid() = default;

EhlResult FasMultigrid::solve(const std::optional<WarmStart>& warm) { return impl_->solve(warm); }

std::vector<double> FasMultigrid::rho_h() { return impl_->rho_h(); }

}  // namespace gearbench::ehl
