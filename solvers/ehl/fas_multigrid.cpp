#include "fas_multigrid.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
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
  double p_cap = std::numeric_limits<double>::infinity();  ///< experiment VL_PCAP
  double h_floor = 0.0;  ///< experiment VL_HFLOOR
  std::vector<double> f;         ///< FAS right-hand side of the Reynolds equation
  std::vector<double> flow_factor, wedge_factor;  ///< thermal film factors (1: isothermal)
  std::vector<double> rho_h_old;  ///< ρ̄H of the previous time step (transient only)
  /// A coarse grid takes its coefficients from the finer one (restrict_problem): ε at a
  /// coarse face is the mean of the two fine faces it covers, the Galerkin coarse operator of
  /// the Poiseuille term under linear interpolation and full weighting. Only the film's
  /// own change scales it, as H³ (so that H0 still moves the flow). Recomputing ε from the
  /// injected pressure instead turns a resolved pressure spike into a one-cell spike of
  /// η ∝ e^{ᾱP} on the coarse grid (issue 19: p_max 3.2 → 21.9 → 1.6e5 → NaN down the levels).
  bool frozen = false;
  std::vector<double> eps_face_fine, film_face_fine;
  std::vector<double> rho_fine, pressure_fine;  ///< ρ̄ and P injected from the finer grid
  std::vector<double> rho_slope;                ///< dρ̄/dP at the nodes
  /// d ln ε/dP at the nodes of a live grid (the piezoviscous and density response).
  std::vector<double> eps_log_slope;
  std::vector<double> eps;  ///< ε at the nodes (live grids)
  std::vector<double> eps_face_dP_left, eps_face_dP_right;  ///< ∂ε_{i+½}/∂P_i, ∂ε_{i+½}/∂P_{i+1}
  /// FAS right-hand side of the film equation on a coarse grid: the injected fine film minus
  /// the coarse film of the injected pressure (Venner & Lubrecht 2000, §6.4).
  std::vector<double> film_correction;
  double g = 0.0;  ///< FAS right-hand side of the force balance
  double seconds = 0.0;
};

/// Experiment: the pressure spike, the last local maximum of P before the outlet's cavitation.
std::size_t spike_index(const std::vector<double>& P) {
  static const bool by_max = std::getenv("VL_SPIKEMAX") != nullptr;
  if (by_max) return static_cast<std::size_t>(std::max_element(P.begin(), P.end()) - P.begin());
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

  [[nodiscard]] static double face_film(const Level& l, std::size_t i) {
    return std::max(0.5 * (l.H[i] + l.H[i + 1]), 0.0);
  }

  /// ε at the faces and ρ̄ at the nodes: from P and H on a live grid (ε_{i+½} the mean of
  /// the nodes'); from the finer grid, scaled by the film's change as H³, on a frozen one.
  void update_coefficients(Level& l) {
    if (l.frozen) {
      for (std::size_t i = 0; i + 1 < l.n; ++i) {
        const double ratio = l.film_face_fine[i] > 0.0 ? face_film(l, i) / l.film_face_fine[i] : 1.0;
        l.eps_face[i] = l.eps_face_fine[i] * ratio * ratio * ratio;
      }
      // ρ̄ of the finer grid, moved linearly with the pressure: the density law is smooth,
      // and the wedge term of a compressible film needs its response (Dowson–Higginson:
      // ρ̄ rises ~25 % over a gigapascal, as much as the film's elastic response on fine grids).
      for (std::size_t i = 0; i < l.n; ++i) l.rho[i] = l.rho_fine[i] + l.rho_slope[i] * (l.P[i] - l.pressure_fine[i]);
      return;
    }
    const double inv_lambda = 1.0 / problem_.lambda();
    l.eps.resize(l.n);
    l.eps_log_slope.resize(l.n);
    l.rho_slope.resize(l.n);
    for (std::size_t i = 0; i < l.n; ++i) {
      const double rho = problem_.density(l.P[i]);
      const double H = std::max(l.H[i], l.h_floor);
      l.rho[i] = rho * l.wedge_factor[i];
      l.rho_slope[i] = density_slope(l.P[i]) * l.wedge_factor[i];
      const double Pv = std::min(l.P[i], l.p_cap);
      l.eps[i] = l.flow_factor[i] * rho * H * H * H * std::exp(-viscosity_exponent_ * problem_.log_viscosity(Pv)) *
                 inv_lambda;
      l.eps_log_slope[i] = l.P[i] < l.p_cap ? eps_log_slope(l.P[i]) : 0.0;
    }
    for (std::size_t i = 0; i + 1 < l.n; ++i)
      l.eps_face[i] = geometric_faces() ? std::sqrt(l.eps[i] * l.eps[i + 1]) : 0.5 * (l.eps[i] + l.eps[i + 1]);
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
    for (std::size_t i = 0; i + 1 < l.n; ++i) {
      if (l.frozen) {  // ε_{i+½} ∝ H̄³, H̄ = (H_i + H_{i+1})/2
        const double H = face_film(l, i);
        if (H > 0.0) d.left[i] = d.right[i] = 1.5 * l.eps_face[i] / H;
      } else {         // ε_{i+½} = (ε_i + ε_{i+1})/2, ε ∝ H³
        const double wl = geometric_faces() ? l.eps_face[i] : l.eps[i];
        const double wr = geometric_faces() ? l.eps_face[i] : l.eps[i + 1];
        if (l.H[i] > l.h_floor) d.left[i] = 1.5 * wl / l.H[i];
        if (l.H[i + 1] > l.h_floor) d.right[i] = 1.5 * wr / l.H[i + 1];
      }
    }
    return d;
  }

  [[nodiscard]] ReynoldsCoefficients coefficients(const Level& l) const {
    ReynoldsCoefficients c{l.eps_face, l.rho, l.deformation, l.h, problem_.deformation_factor() / pi, state_.speed,
                           state_.time_step};
    c.rho_dP = &l.rho_slope;
    c.H = &l.H;
    if (!l.frozen) {
      c.eps_face_dP_left = &l.eps_face_dP_left;
      c.eps_face_dP_right = &l.eps_face_dP_right;
      c.P = &l.P;
    }
    return c;
  }

  /// ∂ε_{i+½}/∂P_i and ∂ε_{i+½}/∂P_{i+1} of a live grid, ε_{i+½} = (ε_i + ε_{i+1})/2, from
  /// the slopes d ln ε/dP at the nodes.
  static void eps_face_derivatives(Level& l) {
    l.eps_face_dP_left.resize(l.n - 1);
    l.eps_face_dP_right.resize(l.n - 1);
    for (std::size_t i = 0; i + 1 < l.n; ++i) {
      const double wl = geometric_faces() ? l.eps_face[i] : l.eps[i];
      const double wr = geometric_faces() ? l.eps_face[i] : l.eps[i + 1];
      l.eps_face_dP_left[i] = 0.5 * wl * l.eps_log_slope[i];
      l.eps_face_dP_right[i] = 0.5 * wr * l.eps_log_slope[i + 1];
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
  /// One relaxation sweep of Venner & Lubrecht's mixed scheme (2000, §7.3, in one
  /// dimension), inlet to outlet: Gauss–Seidel where ξ = ε/h² ≥ ξ_threshold on both faces,
  /// distributive Jacobi with the zero-sum pattern (−½, 1, −½) where it is smaller; each
  /// change is the residual over the derivative of L_i with respect to it (the film's own
  /// response through the kernel included), under-relaxed; P ≥ 0. The film of the next nodes
  /// follows a Gauss–Seidel change at once through the kernel's near entries; the full film
  /// is recomputed after the sweep.
  void relax(Level& l, std::size_t first = 1, std::size_t end = 0) {
    if (end == 0) end = l.n - 1;
    const auto start = std::chrono::steady_clock::now();
    update_film(l);
    update_coefficients(l);
    const auto c = coefficients(l);
    const double h2 = l.h * l.h;
    std::vector<double> jacobi_change(l.n, 0.0), jacobi_residual(l.n, 0.0);
    std::vector<char> is_jacobi(l.n, 0);
    for (std::size_t i = first; i < end; ++i) {
      const double r = l.f[i] - operator_at(l, i);
      static const bool vlmax = std::getenv("VL_MAXXI") != nullptr;
      static const double dom = std::getenv("VL_DOM") ? std::atof(std::getenv("VL_DOM")) : 0.0;
      bool jacobi = (vlmax ? std::max(l.eps_face[i - 1], l.eps_face[i]) : std::min(l.eps_face[i - 1], l.eps_face[i])) / h2 < o_.xi_threshold;
      if (dom > 0.0) {
        // Gauss–Seidel where the Poiseuille diagonal dominates the film's (kernel) response in
        // the wedge term by the factor dom; line Jacobi elsewhere.
        ReynoldsCoefficients frozen = c;
        frozen.eps_face_dP_left = frozen.eps_face_dP_right = nullptr;
        const double pois = (l.eps_face[i - 1] + l.eps_face[i]) / h2;
        const double wedge = frozen.jacobian(i, i) + pois;
        jacobi = pois < dom * std::abs(wedge);
      }
      if (jacobi) {
        const double derivative = c.jacobian(i, i) - 0.5 * (c.jacobian(i, i - 1) + c.jacobian(i, i + 1));
        if (std::getenv("VL_DBG") && !std::isfinite(r / derivative)) fmt::print(stderr, "jac nan n {} i {} r {} d {} P {} H {} eps {} {}\n", l.n, i, r, derivative, l.P[i], l.H[i], l.eps_face[i-1], l.eps_face[i]);
        jacobi_change[i] = limit_change(l, i, o_.omega_jacobi * r / derivative);
        jacobi_residual[i] = r;
        is_jacobi[i] = 1;
        continue;
      }
      static const bool jfirst = std::getenv("VL_JFIRST") != nullptr;
      if (jfirst) continue;
      const double old = l.P[i];
      if (std::getenv("VL_DBG") && !std::isfinite(r / gauss_seidel_derivative(c, i))) fmt::print(stderr, "gs nan n {} i {} r {} d {} P {} H {} eps {} {}\n", l.n, i, r, gauss_seidel_derivative(c, i), l.P[i], l.H[i], l.eps_face[i-1], l.eps_face[i]);
      l.P[i] = std::max(0.0, old + limit_change(l, i, o_.omega_gauss_seidel * r / gauss_seidel_derivative(c, i)));
      if (std::getenv("VL_BLOW") && std::abs(l.P[i] - old) > 5.0) fmt::print(stderr, "blow gs n {} i {} P {:.3e} -> {:.3e} r {:.3e} d {:.3e} xi {:.2e}/{:.2e} H {:.3e}\n", l.n, i, old, l.P[i], r, gauss_seidel_derivative(c, i), l.eps_face[i-1]/h2, l.eps_face[i]/h2, l.H[i]);
      move_film_near(l, i, l.P[i] - old);
    }
    static const int line = std::getenv("VL_LINE") ? std::atoi(std::getenv("VL_LINE")) : 0;
    static const double omega_line = std::getenv("VL_LINE_OMEGA") ? std::atof(std::getenv("VL_LINE_OMEGA")) : o_.omega_jacobi;
    if (line > 0) {
      // Runs of consecutive distributive-Jacobi nodes solved simultaneously: the banded part
      // (|k − j| ≤ line) of the Jacobian of the distributed change (Venner & Lubrecht's line
      // relaxation in one dimension).
      std::size_t i = 1;
      while (i + 1 < l.n) {
        if (!is_jacobi[i]) { ++i; continue; }
        std::size_t b = i;
        while (b + 2 < l.n && is_jacobi[b + 1]) ++b;
        const std::size_t a = i, m = b - a + 1;
        std::vector<Eigen::Triplet<double>> t;
        const auto J = [&](std::size_t k, std::size_t j) { return (j == 0 || j + 1 >= l.n) ? 0.0 : c.jacobian(k, j); };
        for (std::size_t k = a; k <= b; ++k)
          for (std::size_t q = (k >= a + line ? k - line : a); q <= std::min(b, k + line); ++q) {
            static const bool plain = std::getenv("VL_LINE_PLAIN") != nullptr;
            static const bool nospill = std::getenv("VL_NOSPILL") != nullptr;
            const double wl = nospill && !is_jacobi[q - 1] ? 0.0 : 0.5, wr = nospill && !is_jacobi[q + 1] ? 0.0 : 0.5;
            const double v = plain ? J(k, q) : J(k, q) - (wl * J(k, q - 1) + wr * J(k, q + 1));
            t.emplace_back(static_cast<int>(k - a), static_cast<int>(q - a), v);
          }
        Eigen::SparseMatrix<double> A(static_cast<int>(m), static_cast<int>(m));
        A.setFromTriplets(t.begin(), t.end());
        Eigen::VectorXd rhs(static_cast<int>(m));
        for (std::size_t k = a; k <= b; ++k) rhs(static_cast<int>(k - a)) = jacobi_residual[k];
        Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
        lu.compute(A);
        if (lu.info() == Eigen::Success) {
          const Eigen::VectorXd d = lu.solve(rhs);
          static const double limit = std::getenv("VL_LINE_LIMIT") ? std::atof(std::getenv("VL_LINE_LIMIT")) : 0.0;
          double scale = 1.0;
          if (limit > 0.0) {
            double pmax = 0.0;
            for (std::size_t k = a; k <= b; ++k) pmax = std::max(pmax, l.P[k]);
            const double dmax = omega_line * d.cwiseAbs().maxCoeff();
            if (dmax > limit * pmax && dmax > 0.0) scale = limit * pmax / dmax;
          }
          if (d.allFinite())
            for (std::size_t k = a; k <= b; ++k) jacobi_change[k] = limit_change(l, k, scale * omega_line * d(static_cast<int>(k - a)));
        }
        i = b + 1;
      }
    }
    if (std::getenv("VL_BLOW")) {
      for (std::size_t i = 1; i + 1 < l.n; ++i)
        if (std::abs(jacobi_change[i]) > 5.0) fmt::print(stderr, "blow jacobi n {} i {} change {:.3e} P {:.3e} r {:.3e} xi {:.2e}/{:.2e}\n", l.n, i, jacobi_change[i], l.P[i], jacobi_residual[i], l.eps_face[i-1]/h2, l.eps_face[i]/h2);
    }
    static const bool plain_line = std::getenv("VL_LINE_PLAIN") != nullptr && line > 0;
    for (std::size_t i = 1; i + 1 < l.n; ++i) {
      if (jacobi_change[i] == 0.0) continue;
      l.P[i] += jacobi_change[i];
      if (plain_line) continue;
      static const bool nospill = std::getenv("VL_NOSPILL") != nullptr;
      if (i > 1 && !(nospill && !is_jacobi[i - 1])) l.P[i - 1] -= 0.5 * jacobi_change[i];
      if (i + 2 < l.n && !(nospill && !is_jacobi[i + 1])) l.P[i + 1] -= 0.5 * jacobi_change[i];
    }
    for (auto& p : l.P) p = std::max(p, 0.0);
    l.P.front() = l.P.back() = 0.0;
    update_film(l);
    static const bool jfirst = std::getenv("VL_JFIRST") != nullptr;
    if (jfirst) {
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
    }
    node_sweeps_ += static_cast<double>(l.n);
    l.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  /// Local Newton solve over a window around the pressure spike (experiment).
  void relax_spike(Level& l) {
    static const int w = std::getenv("VL_SPIKE") ? std::atoi(std::getenv("VL_SPIKE")) : 0;
    static const int wo = std::getenv("VL_SPIKE_OUT") ? std::atoi(std::getenv("VL_SPIKE_OUT")) : w;
    static const int steps = std::getenv("VL_SPIKE_STEPS") ? std::atoi(std::getenv("VL_SPIKE_STEPS")) : 2;
    if (w <= 0) return;
    update_film(l);
    update_coefficients(l);
    const auto s = spike_index(l.P);
    const std::size_t a = s > static_cast<std::size_t>(w) ? s - w : 1;
    const std::size_t b = std::min(l.n - 2, s + wo);
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
      CoarsestStep step;
      try {
        step = coarsest_newton_step(coefficients(l), l.P, residuals(l), film_sensitivity(l), l.g - integral(l));
      } catch (const std::exception& e) {
        if (std::getenv("VL_CATCH")) break;
        double hmin = 1e300, pmax = 0, emin = 1e300, emax = 0; std::size_t npos = 0;
        for (std::size_t i = 0; i < l.n; ++i) { hmin = std::min(hmin, l.H[i]); pmax = std::max(pmax, l.P[i]); npos += l.P[i] > 0; }
        for (double e : l.eps_face) { emin = std::min(emin, e); emax = std::max(emax, e); }
        fmt::print(stderr, "singular at n {} step {}: Hmin {:.3e} Pmax {:.3e} npos {} eps [{:.2e}, {:.2e}] H0 {:.4f} frozen {}\n", l.n, s, hmin, pmax, npos, emin, emax, H0_, l.frozen);
        throw;
      }
      node_sweeps_ += dense_step_cost * std::pow(static_cast<double>(l.n), 3);
      static const double trust = std::getenv("VL_TRUST") ? std::atof(std::getenv("VL_TRUST")) : 0.0;
      if (trust > 0.0) {
        double pmax = 0.0, dpmax = 0.0;
        for (std::size_t i = 1; i + 1 < l.n; ++i) { pmax = std::max(pmax, l.P[i]); dpmax = std::max(dpmax, std::abs(step.dP[i])); }
        const double hs = film_estimate();
        double scale = 1.0;
        if (std::abs(step.dH0) > trust * hs) scale = std::min(scale, trust * hs / std::abs(step.dH0));
        if (dpmax > trust * std::max(pmax, 1e-3 * state_.load)) scale = std::min(scale, trust * std::max(pmax, 1e-3 * state_.load) / dpmax);
        for (auto& d : step.dP) d *= scale;
        step.dH0 *= scale;
      }
      // Backtracking (Armijo-free): the largest of 1, ½, ¼, … that lowers the merit.
      const std::vector<double> P0 = l.P;
      const double H00 = H0_;
      double theta = 1.0, trial = merit;
      for (int halving = 0; halving <= max_halvings; ++halving, theta *= 0.5) {
        for (std::size_t i = 1; i + 1 < l.n; ++i) l.P[i] = std::max(0.0, P0[i] + theta * step.dP[i]);
        H0_ = H00 + theta * step.dH0;
        trial = coarsest_merit(l);
        if (trial < merit) break;
      }
      static const bool strict = std::getenv("VL_STRICT") != nullptr;
      if (strict && !(trial < merit)) {  // no descent: keep the last iterate
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

  /// Experiment VL_ALIM = c: a change of P_i limited to |Δ ln ε_i| ≤ c (the piezoviscous
  /// response is exponential; a linear model of it holds for |ᾱΔP| of order 1).
  static double limit_change(const Level& l, std::size_t i, double change) {
    static const double c = std::getenv("VL_ALIM") ? std::atof(std::getenv("VL_ALIM")) : 0.0;
    if (c <= 0.0 || l.eps_log_slope.size() != l.n) return change;
    const double s = std::abs(l.eps_log_slope[i]);
    if (s * std::abs(change) <= c) return change;
    return std::copysign(c / s, change);
  }
  static bool geometric_faces() {
    static const bool g = std::getenv("VL_GEO") != nullptr;
    return g;
  }
  // --- multigrid -------------------------------------------------------------------------
  static double sigma() {
    static const double s = std::getenv("VL_SIGMA") ? std::atof(std::getenv("VL_SIGMA")) : 1.0;
    return s;
  }
  void cycle(std::size_t k) {
    Level& fine = *levels_[k];
    static const std::size_t cycle_min = std::getenv("VL_CYCLE_MIN") ? std::atoi(std::getenv("VL_CYCLE_MIN")) : 0;
    if (k > 0 && fine.n <= cycle_min && k + 1 < levels_.size()) {
      solve_coarsest(fine, coarsest_steps_per_visit, coarsest_tolerance);
      return;
    }
    if (k == 0) {
      static const int crelax = std::getenv("VL_CRELAX") ? std::atoi(std::getenv("VL_CRELAX")) : 0;
      static const double hfact = std::getenv("VL_HFACT") ? std::atof(std::getenv("VL_HFACT")) : 0.05;
      if (crelax > 0 && levels_.size() > 1) {
        for (int s = 0; s < crelax / 2; ++s) relax(fine);
        H0_ += hfact * (integral(fine) - fine.g);
        for (int s = 0; s < crelax / 2; ++s) relax(fine);
        return;
      }
      solve_coarsest(fine, coarsest_steps_per_visit, coarsest_tolerance);
      return;
    }
    static const bool trace = std::getenv("VL_TRACE") != nullptr;
    const auto show = [&](const char* what) {
      if (!trace) return;
      const double sr = scaled_residual(fine);
      const auto r = residuals(fine);
      std::size_t iw = 1; double worst = 0.0;
      for (std::size_t i = 1; i + 1 < fine.n; ++i) {
        const double part = fine.P[i] > 0.0 ? std::abs(r[i]) : std::abs(std::min(r[i], 0.0));
        if (part > worst) { worst = part; iw = i; }
      }
      std::size_t last = 0; for (std::size_t i = 0; i < fine.n; ++i) if (fine.P[i] > 0) last = i;
      const auto sp = spike_index(fine.P);
      fmt::print(stderr, "  L{} n{} {:>6}: res {:.2e} worst {:.2e} at {} (spike {} P {:.3f}, last {}) H0 {:.6f}\n", k, fine.n, what, sr, worst, iw, sp, fine.P[sp], last, H0_);
    };
    const auto nan_check = [&](const char* what) {
      static bool reported = false;
      if (reported) return;
      for (std::size_t i = 0; i < fine.n; ++i)
        if (!std::isfinite(fine.P[i]) || !std::isfinite(fine.H[i]) || std::abs(fine.P[i]) > 100.0 || std::abs(H0_) > 100.0) {
          fmt::print(stderr, "NaN first at level {} (n {}) after {} node {}\n", k, fine.n, what, i);
          reported = true;
          return;
        }
    };
    nan_check("entry");
    if (k + 1 == levels_.size()) show("start");
    for (int s = 0; s < o_.pre_sweeps; ++s) relax(fine);
    nan_check("pre");
    if (k + 1 == levels_.size()) show("pre");
    static const std::size_t resdump = std::getenv("VL_RESDUMP") ? std::atoi(std::getenv("VL_RESDUMP")) : 0;
    if (fine.n == resdump) {
      update_film(fine); update_coefficients(fine);
      const auto r = residuals(fine);
      std::vector<std::size_t> idx(fine.n);
      for (std::size_t i = 0; i < fine.n; ++i) idx[i] = i;
      std::sort(idx.begin(), idx.end(), [&](auto a, auto b) { return std::abs(fine.P[a] > 0 ? r[a] : std::min(r[a], 0.0)) > std::abs(fine.P[b] > 0 ? r[b] : std::min(r[b], 0.0)); });
      fmt::print(stderr, "resdump n {} spike {} Pmax {:.3f}:", fine.n, spike_index(fine.P), *std::max_element(fine.P.begin(), fine.P.end()));
      for (int q = 0; q < 12; ++q) fmt::print(stderr, " {}:{:.1e}(P{:.2f},xi{:.0e})", idx[q], r[idx[q]], fine.P[idx[q]], fine.eps_face[idx[q]] / (fine.h * fine.h));
      fmt::print(stderr, "\n");
    }
    Level& coarse = *levels_[k - 1];
    restrict_problem(fine, coarse);
    const std::vector<double> injected = coarse.P;
    const int gamma = o_.cycle == CycleType::W ? 2 : 1;
    const double H0_before = H0_;
    for (int c = 0; c < gamma; ++c) cycle(k - 1);
    H0_ = H0_before + (H0_ - H0_before) / sigma();
    static const double h0damp = std::getenv("VL_H0DAMP") ? std::atof(std::getenv("VL_H0DAMP")) : 1.0;
    if (k + 1 == levels_.size()) H0_ = H0_before + h0damp * (H0_ - H0_before);
    static const double clsf = std::getenv("VL_CLS") ? std::atof(std::getenv("VL_CLS")) : 0.0;
    if (clsf > 0.0) {
      const std::vector<double> P0 = fine.P;
      const double H0_after = H0_;
      H0_ = H0_before;
      const double m0 = scaled_residual(fine);
      node_sweeps_ += static_cast<double>(fine.n);
      double theta = 1.0;
      for (int t = 0; t < 5; ++t, theta *= 0.5) {
        fine.P = P0;
        H0_ = H0_before + theta * (H0_after - H0_before);
        correct(coarse, injected, fine, theta);
        const double m1 = scaled_residual(fine);
        node_sweeps_ += static_cast<double>(fine.n);
        if (std::isfinite(m1) && m1 <= clsf * m0) break;
        if (t == 4) { fine.P = P0; H0_ = H0_before; }
      }
      static const bool tr = std::getenv("VL_CLSTRACE") != nullptr;
      if (tr && theta < 1.0) fmt::print(stderr, "cls n {} theta {}\n", fine.n, theta);
    } else
      correct(coarse, injected, fine, 1.0);
    nan_check("corr");
    if (k + 1 == levels_.size()) show("corr");
    static const bool pre = std::getenv("VL_SPIKE_PRE") != nullptr;
    if (pre) relax_spike(fine);
    for (int s = 0; s < o_.post_sweeps; ++s) relax(fine);
    nan_check("post");
    if (!pre) relax_spike(fine);
    nan_check("spike");
    static const int local = std::getenv("VL_LOCAL") ? std::atoi(std::getenv("VL_LOCAL")) : 0;
    static const int local_w = std::getenv("VL_LOCAL_W") ? std::atoi(std::getenv("VL_LOCAL_W")) : 16;
    if (local > 0) {
      std::size_t last = 0;
      for (std::size_t i = 0; i < fine.n; ++i) if (fine.P[i] > 0.0) last = i;
      const std::size_t a = last > static_cast<std::size_t>(local_w) ? last - local_w : 1;
      const std::size_t b = std::min(fine.n - 1, last + 4);
      for (int s = 0; s < local; ++s) relax(fine, a, b);
    }
    if (k + 1 == levels_.size()) show("post");
  }

  /// Correction by linear interpolation, applied only inside the pressurised zone: not on
  /// cavitated nodes nor next to them, where the free boundary is the fine grid's to place.
  static void correct(const Level& coarse, const std::vector<double>& injected, Level& fine, double theta) {
    std::vector<double> correction(fine.n, 0.0);
    for (std::size_t I = 0; I + 1 < coarse.n; ++I) {
      const double d0 = (coarse.P[I] - injected[I]) / sigma();
      const double d1 = (coarse.P[I + 1] - injected[I + 1]) / sigma();
      correction[2 * I] = d0;
      correction[2 * I + 1] = 0.5 * (d0 + d1);
      static const double odi = std::getenv("VL_ODI") ? std::atof(std::getenv("VL_ODI")) : -1.0;
      if (odi > 0.0) {
        const double a = fine.eps_face[2 * I], b = fine.eps_face[2 * I + 1];
        if (std::min(a, b) / (fine.h * fine.h) >= odi && a + b > 0) correction[2 * I + 1] = (a * d0 + b * d1) / (a + b);
      }
    }
    std::vector<char> interior(fine.n, 0);
    for (std::size_t i = 1; i + 1 < fine.n; ++i)
      interior[i] = fine.P[i - 1] > 0.0 && fine.P[i] > 0.0 && fine.P[i + 1] > 0.0;
    static const int nc = std::getenv("VL_NOCORR") ? std::atoi(std::getenv("VL_NOCORR")) : -1;
    static const int nc_out = std::getenv("VL_NOCORR_OUT") ? std::atoi(std::getenv("VL_NOCORR_OUT")) : nc;
    if (nc >= 0) {
      const auto sp = spike_index(fine.P);
      for (std::size_t i = 1; i + 1 < fine.n; ++i)
        if (i + nc >= sp && i <= sp + static_cast<std::size_t>(nc_out)) interior[i] = 0;
    }
    static const int fbm = std::getenv("VL_FBM") ? std::atoi(std::getenv("VL_FBM")) : 0;
    if (fbm > 0) {
      std::size_t last = 0;
      for (std::size_t i = 0; i < fine.n; ++i) if (fine.P[i] > 0.0) last = i;
      for (std::size_t i = 1; i + 1 < fine.n; ++i) if (i + static_cast<std::size_t>(fbm) > last) interior[i] = 0;
    }
    for (std::size_t i = 1; i + 1 < fine.n; ++i)
      if (interior[i]) fine.P[i] = std::max(0.0, fine.P[i] + limit_change(fine, i, theta * correction[i]));
  }

  /// FAS coarse problem: injected pressure and film, coefficients from the fine grid,
  /// f_c = L_c(P̄) + R·r (full weighting; no residual where the fine pressure is cavitated),
  /// g_c = ∫P̄ + (g − ∫P).
  void restrict_problem(Level& fine, Level& coarse) {
    update_film(fine);
    update_coefficients(fine);
    std::vector<double> r = residuals(fine);
    for (std::size_t i = 1; i + 1 < fine.n; ++i)
      if (fine.P[i] <= 0.0) r[i] = 0.0;
    static const int nores = std::getenv("VL_NORES") ? std::atoi(std::getenv("VL_NORES")) : -1;
    if (nores >= 0) {
      const auto sp = spike_index(fine.P);
      for (std::size_t i = 1; i + 1 < fine.n; ++i)
        if (i + nores >= sp && i <= sp + static_cast<std::size_t>(nores)) r[i] = 0.0;
    }
    static const bool live = std::getenv("VL_LIVE") != nullptr;
    static const bool fw = std::getenv("VL_FW") != nullptr;
    for (std::size_t I = 0; I < coarse.n; ++I) {
      const std::size_t i = 2 * I;
      const bool inside = I > 0 && I + 1 < coarse.n && fine.P[i - 1] > 0.0 && fine.P[i] > 0.0 && fine.P[i + 1] > 0.0;
      coarse.P[I] = (fw && inside) ? 0.25 * (fine.P[i - 1] + 2.0 * fine.P[i] + fine.P[i + 1]) : fine.P[i];
    }
    static const int shave = std::getenv("VL_SHAVE") ? std::atoi(std::getenv("VL_SHAVE")) : 0;
    if (shave > 0) {
      // The spike is a grid-scale feature: the coarse state passes below it (FAS stays
      // consistent for any restricted state; the correction is taken relative to it).
      const auto sp = spike_index(fine.P);
      const std::size_t Ia = sp > static_cast<std::size_t>(shave) + 2 ? (sp - shave) / 2 - 1 : 0;
      const std::size_t Ib = std::min(coarse.n - 1, (sp + shave + 1) / 2 + 1);
      for (std::size_t I = Ia + 1; I < Ib; ++I) {
        const double t = static_cast<double>(I - Ia) / static_cast<double>(Ib - Ia);
        coarse.P[I] = std::min(coarse.P[I], (1.0 - t) * coarse.P[Ia] + t * coarse.P[Ib]);
      }
    }
    coarse.film_correction.clear();
    update_film(coarse);
    coarse.film_correction.resize(coarse.n);
    for (std::size_t I = 0; I < coarse.n; ++I) {
      coarse.film_correction[I] = fine.H[2 * I] - coarse.H[I];
      coarse.H[I] = fine.H[2 * I];
      coarse.rho[I] = fine.rho[2 * I];
    }
    if (live) {
      coarse.frozen = false;
      static const double pcap = std::getenv("VL_PCAP") ? std::atof(std::getenv("VL_PCAP")) : 0.0;
      if (pcap > 0.0) coarse.p_cap = pcap * *std::max_element(coarse.P.begin(), coarse.P.end());
      static const double hfloor = std::getenv("VL_HFLOOR") ? std::atof(std::getenv("VL_HFLOOR")) : 0.0;
      if (hfloor > 0.0) coarse.h_floor = hfloor * std::max(0.0, *std::min_element(coarse.H.begin(), coarse.H.end()));
      static const double hfloor_fine = std::getenv("VL_HFLOOR_FINE") ? std::atof(std::getenv("VL_HFLOOR_FINE")) : 0.0;
      if (hfloor_fine > 0.0) {
        const Level& finest = *levels_.back();
        coarse.h_floor = std::max(coarse.h_floor, hfloor_fine * std::max(0.0, *std::min_element(finest.H.begin(), finest.H.end())));
      }
      update_coefficients(coarse);
      std::fill(coarse.f.begin(), coarse.f.end(), 0.0);
      for (std::size_t I = 1; I + 1 < coarse.n; ++I)
        coarse.f[I] = operator_at(coarse, I) + sigma() * 0.25 * (r[2 * I - 1] + 2.0 * r[2 * I] + r[2 * I + 1]);
      coarse.g = integral(coarse) + sigma() * (fine.g - integral(fine));
      return;
    }
    coarse.frozen = true;
    coarse.rho_fine = coarse.rho;
    coarse.pressure_fine = coarse.P;
    coarse.rho_slope.resize(coarse.n);
    for (std::size_t I = 0; I < coarse.n; ++I) coarse.rho_slope[I] = fine.rho_slope[2 * I];
    coarse.eps_face_fine.resize(coarse.n - 1);
    coarse.film_face_fine.resize(coarse.n - 1);


    for (std::size_t I = 0; I + 1 < coarse.n; ++I) {
      coarse.eps_face_fine[I] = 0.5 * (fine.eps_face[2 * I] + fine.eps_face[2 * I + 1]);
      static const double harm = std::getenv("VL_HARM") ? std::atof(std::getenv("VL_HARM")) : -1.0;
      if (harm > 0.0) {
        const double a = fine.eps_face[2 * I], b = fine.eps_face[2 * I + 1];
        const double h2 = fine.h * fine.h;
        if (std::min(a, b) / h2 >= harm && a > 0 && b > 0) coarse.eps_face_fine[I] = 2.0 * a * b / (a + b);
      }
      coarse.film_face_fine[I] = face_film(coarse, I);

    }
    update_coefficients(coarse);
    std::fill(coarse.f.begin(), coarse.f.end(), 0.0);
    for (std::size_t I = 1; I + 1 < coarse.n; ++I)
      coarse.f[I] = operator_at(coarse, I) + 0.25 * (r[2 * I - 1] + 2.0 * r[2 * I] + r[2 * I + 1]);
    coarse.g = integral(coarse) + (fine.g - integral(fine));
  }

  /// A grid becomes the finest of the cycles: its own coefficients, no FAS right-hand sides.
  void make_finest(Level& l) {
    l.frozen = false;
    l.p_cap = std::numeric_limits<double>::infinity();
    l.h_floor = 0.0;
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
    if (std::getenv("VL_WU")) fmt::print(stderr, "start: {:.0f} node sweeps on {} nodes\n", node_sweeps_, levels_.front()->n);
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
      static const bool film_shift = std::getenv("VL_FILMSHIFT") != nullptr;
      if (film_shift) {
        // The film, not H0, is what carries over between grids: the deformation's
        // discretisation error is mostly a uniform offset, which H0 absorbs.
        update_film(*levels_[k - 1]);
        update_film(*levels_[k]);
        H0_ += film_at_centre(*levels_[k - 1]) - film_at_centre(*levels_[k]);
        update_film(*levels_[k]);
      }
      static const bool fmg_spike = std::getenv("VL_FMGSPIKE") != nullptr;
      if (fmg_spike) relax_spike(*levels_[k]);
      cycle(k);
      record_fmg_level(r, k);
      if (std::getenv("VL_WU")) {
        const auto& lk = *levels_[k];
        const auto sp = spike_index(lk.P);
        fmt::print(stderr, "fmg level {} ({} nodes): {:.0f} node sweeps, Hc {:.5f} Hmin {:.5f} H0 {:.5f} spike {} P {:.3f} Pmax {:.3f} res {:.2e}\n", k, lk.n, node_sweeps_, r.fmg_H_c.back(), r.fmg_H_min.back(), H0_, sp, lk.P[sp], *std::max_element(lk.P.begin(), lk.P.end()), scaled_residual(*levels_[k]));
      }
      static const bool keep = std::getenv("VL_KEEPNEG") != nullptr;
      if (!std::isfinite(r.error_estimate) && !(keep && o_.adaptive())) break;
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
      anderson_cycle();
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

  /// Anderson mixing of the cycle as a fixed-point map x -> G(x), x = (P, H0) (experiment).
  struct AndersonState { std::vector<Eigen::VectorXd> x, g; };
  AndersonState aa_;
  void anderson_cycle() {
    static const int depth = std::getenv("VL_AA") ? std::atoi(std::getenv("VL_AA")) : 0;
    Level& fine = *levels_.back();
    const auto n = static_cast<Eigen::Index>(fine.n);
    Eigen::VectorXd x(n + 1);
    for (Eigen::Index i = 0; i < n; ++i) x(i) = fine.P[i];
    x(n) = H0_;
    cycle(levels_.size() - 1);
    if (depth <= 0) return;
    Eigen::VectorXd gx(n + 1);
    for (Eigen::Index i = 0; i < n; ++i) gx(i) = fine.P[i];
    gx(n) = H0_;
    aa_.x.push_back(x);
    aa_.g.push_back(gx);
    if (aa_.x.size() > static_cast<std::size_t>(depth) + 1) { aa_.x.erase(aa_.x.begin()); aa_.g.erase(aa_.g.begin()); }
    const std::size_t k = aa_.x.size();
    if (k < 2) return;
    const auto f = [&](std::size_t j) -> Eigen::VectorXd { return aa_.g[j] - aa_.x[j]; };
    Eigen::MatrixXd dF(n + 1, k - 1), dG(n + 1, k - 1);
    for (std::size_t j = 0; j + 1 < k; ++j) { dF.col(j) = f(j + 1) - f(j); dG.col(j) = aa_.g[j + 1] - aa_.g[j]; }
    const Eigen::VectorXd gamma = dF.colPivHouseholderQr().solve(f(k - 1));
    Eigen::VectorXd xn = aa_.g[k - 1] - dG * gamma;
    for (Eigen::Index i = 0; i < n; ++i) fine.P[i] = std::max(0.0, xn(i));
    fine.P.front() = fine.P.back() = 0.0;
    H0_ = xn(n);
    aa_.g.back() = xn;  // hmm: keep G history consistent? (keep raw g instead)
    aa_.g.back() = gx;
    update_film(fine);
  }

  /// Cycles until the scaled residual and the force balance meet the tolerance.
  void iterate_to_residual(EhlResult& r) {
    Level& fine = *levels_.back();
    r.stop_rule = fmt::format("scaled residual and force balance below {:.1e}", o_.tolerance);
    for (int c = 0; c < o_.max_cycles; ++c) {
      anderson_cycle();
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
      double value;
      static const bool clamp = std::getenv("VL_CLAMP") != nullptr;
      if (I >= 1 && I + 2 < coarse.n) {
        value = (-coarse.P[I - 1] + 9.0 * coarse.P[I] + 9.0 * coarse.P[I + 1] - coarse.P[I + 2]) / 16.0;
        if (clamp) value = std::clamp(value, std::min(coarse.P[I], coarse.P[I + 1]), std::max(coarse.P[I], coarse.P[I + 1]));
      } else
        value = 0.5 * (coarse.P[I] + coarse.P[I + 1]);
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
