#include "fas_multigrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "deformation.h"
#include "line_relaxation.h"

namespace gearbench::ehl {

namespace {
constexpr double pi = std::numbers::pi;
}  // namespace

namespace {
/// One grid of the hierarchy with its unknowns, coefficients and FAS right-hand sides.
struct Level {
  Level(std::size_t nodes, double x_in, double x_out)
      : n(nodes), h((x_out - x_in) / static_cast<double>(nodes - 1)), deformation(nodes, h),
        X(nodes), P(nodes, 0.0), H(nodes, 0.0), W(nodes, 0.0), eps(nodes, 0.0), rho(nodes, 1.0),
        f(nodes, 0.0), flow_factor(nodes, 1.0), wedge_factor(nodes, 1.0) {
    for (std::size_t i = 0; i < n; ++i) X[i] = x_in + static_cast<double>(i) * h;
  }
  std::size_t n;
  double h;
  Deformation deformation;
  std::vector<double> X, P, H, W, eps, rho;
  std::vector<double> f;  ///< FAS right-hand side of the Reynolds equation
  std::vector<double> flow_factor, wedge_factor;  ///< thermal film factors (1: isothermal)
  std::vector<double> rho_h_old;  ///< ρ̄H of the previous time step (transient only)
  /// FAS right-hand side of the film equation on a coarse grid: the injected fine film minus
  /// the coarse film of the injected pressure, so that both grids start from the same film
  /// (Venner & Lubrecht 2000, §6.4; without it the coarse film near the pressure spike
  /// differs from the fine one and the coarse problem drives high-L cases to divergence).
  std::vector<double> film_correction;
  /// Coarse nodes held at the injected fine pressure (options.hold_unresolved): no change,
  /// so no correction, where this grid cannot represent the fine pressure. Empty: none.
  std::vector<char> held;
  double g = 0.0;          ///< FAS right-hand side of the force balance
  double seconds = 0.0;
  std::unique_ptr<LineRelaxation> line;  ///< banded workspace (line relaxation only)
};

}  // namespace

class FasMultigrid::Impl {
 public:
  Impl(const LineContactProblem& problem, const EhlOptions& o, ContactState state)
      : problem_(problem), o_(o), state_(std::move(state)) {
    if (state_.load <= 0.0) state_.load = problem.load();
    const double x_in = o.x_in != 0.0 || o.x_out != 0.0 ? o.x_in : problem.x_in();
    const double x_out = o.x_in != 0.0 || o.x_out != 0.0 ? o.x_out : problem.x_out();
    std::size_t nodes = static_cast<std::size_t>(o.coarsest_nodes);
    for (int k = 0; k < o.levels; ++k) {
      levels_.push_back(std::make_unique<Level>(nodes, x_in, x_out));
      if (o.relaxation == Relaxation::line) levels_.back()->line = std::make_unique<LineRelaxation>(nodes, o.line_band);
      nodes = 2 * nodes - 1;
    }
    if (state_.time_step > 0.0) {
      if (state_.rho_h_old.size() != levels_.back()->n)
        throw std::invalid_argument("ContactState::rho_h_old must hold the finest grid");
      levels_.back()->rho_h_old = state_.rho_h_old;
      for (std::size_t k = levels_.size() - 1; k > 0; --k) {
        auto& coarse = *levels_[k - 1];
        coarse.rho_h_old.resize(coarse.n);
        for (std::size_t I = 0; I < coarse.n; ++I) coarse.rho_h_old[I] = levels_[k]->rho_h_old[2 * I];
      }
    }
    inject_film_factors();
  }

  EhlResult solve(const std::optional<WarmStart>& warm) {
    const auto start = std::chrono::steady_clock::now();
    EhlResult r;
    if (warm) {
      start_from(*warm);
    } else {
      full_multigrid();
    }
    iterate(r);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const auto& l : levels_) r.seconds_per_level.push_back(l->seconds);
    r.work_units = work_units_;
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
  /// A previous solution on the finest grid (the last time step) as the start.
  void start_from(const WarmStart& warm) {
    Level& fine = *levels_.back();
    if (warm.P.size() != fine.n) throw std::invalid_argument("WarmStart::P must hold the finest grid");
    fine.P = warm.P;
    H0_ = warm.H0;
    film_guess_ = warm.film_scale > 0.0 ? warm.film_scale : film_guess_;
    fine.g = state_.load;
    finest_ = levels_.size() - 1;
    update_film(fine);
  }

  void full_multigrid() {
    initial_guess(*levels_.front());
    levels_.front()->g = state_.load;
    solve_coarsest(*levels_.front(), 20);
    if (levels_.size() == 2) snapshot_coarse(*levels_.front());
    // Full multigrid: interpolate each converged level to the next and cycle there.
    for (std::size_t k = 1; k < levels_.size(); ++k) {
      interpolate_solution(*levels_[k - 1], *levels_[k]);
      levels_[k]->g = state_.load;
      levels_[k]->film_correction.clear();
      levels_[k]->held.clear();
      std::fill(levels_[k]->f.begin(), levels_[k]->f.end(), 0.0);
      finest_ = k;
      for (int c = 0; c < 2; ++c) cycle(k);
      if (k + 2 == levels_.size()) snapshot_coarse(*levels_[k]);  // the next-to-finest grid
    }
    finest_ = levels_.size() - 1;
  }

  /// Cycles on the finest grid until the residual and the force balance meet the tolerance.
  void iterate(EhlResult& r) {
    Level& fine = *levels_.back();
    for (int c = 0; c < o_.max_cycles; ++c) {
      cycle(finest_);
      ++r.cycles;
      r.residual_history.push_back(scaled_residual(fine));
      r.force_history.push_back(std::abs(integral(fine) - state_.load) / state_.load);
      if (diverged(r.residual_history.back(), r.force_history.back())) break;
      if (r.residual_history.back() <= o_.tolerance && r.force_history.back() <= o_.tolerance) {
        r.converged = true;
        break;
      }
    }
  }

  /// A residual or force balance that is not finite, or above 10 (scaled: a first cycle
  /// starts near 1e-2), does not come back; stopping lets the next fallback start sooner.
  [[nodiscard]] static bool diverged(double residual, double force) {
    return !(std::isfinite(residual) && std::isfinite(force) && residual <= 10.0 && force <= 10.0);
  }

  /// The thermal factors of the finest grid, injected into the coarser ones.
  void inject_film_factors() {
    if (state_.flow_factor.empty() && state_.wedge_factor.empty()) return;
    Level& fine = *levels_.back();
    if (state_.flow_factor.size() != fine.n || state_.wedge_factor.size() != fine.n)
      throw std::invalid_argument("ContactState film factors must hold the finest grid");
    fine.flow_factor = state_.flow_factor;
    fine.wedge_factor = state_.wedge_factor;
    for (std::size_t k = levels_.size() - 1; k > 0; --k) {
      auto& coarse = *levels_[k - 1];
      for (std::size_t I = 0; I < coarse.n; ++I) {
        coarse.flow_factor[I] = levels_[k]->flow_factor[2 * I];
        coarse.wedge_factor[I] = levels_[k]->wedge_factor[2 * I];
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
    const double kappa = state_.curvature;
    for (std::size_t i = 0; i < l.n; ++i) l.H[i] = H0_ + 0.5 * kappa * l.X[i] * l.X[i] - c * l.W[i];
    if (!l.film_correction.empty())
      for (std::size_t i = 0; i < l.n; ++i) l.H[i] += l.film_correction[i];
  }

  void update_coefficients(Level& l) {
    const double inv_lambda = 1.0 / problem_.lambda();
    for (std::size_t i = 0; i < l.n; ++i) {
      const double rho = problem_.density(l.P[i]);
      const double H = std::max(l.H[i], 0.0);
      l.rho[i] = rho * l.wedge_factor[i];
      l.eps[i] = l.flow_factor[i] * rho * H * H * H / problem_.viscosity(l.P[i]) * inv_lambda;
    }
  }

  /// Reynolds operator at interior node i: central Poiseuille, first-order upwind wedge
  /// (scaled by the entrainment speed υ), and for a time step ΔT the implicit-Euler squeeze
  /// term −(ρ̄H − (ρ̄H)_old)/ΔT.
  [[nodiscard]] double operator_at(const Level& l, std::size_t i) const {
    const double em = 0.5 * (l.eps[i - 1] + l.eps[i]);
    const double ep = 0.5 * (l.eps[i] + l.eps[i + 1]);
    double L = (em * (l.P[i - 1] - l.P[i]) + ep * (l.P[i + 1] - l.P[i])) / (l.h * l.h) -
               state_.speed * (l.rho[i] * l.H[i] - l.rho[i - 1] * l.H[i - 1]) / l.h;
    if (state_.time_step > 0.0) L -= (l.rho[i] * l.H[i] - l.rho_h_old[i]) / state_.time_step;
    return L;
  }

  [[nodiscard]] static double integral(const Level& l) {
    return l.h * std::accumulate(l.P.begin(), l.P.end(), 0.0);  // P = 0 at both ends
  }

  /// ∂L_i/∂P_i: Poiseuille diagonal and the film's own response −(D/π)K.
  [[nodiscard]] double diagonal(const Level& l, std::size_t i) const {
    const double em = 0.5 * (l.eps[i - 1] + l.eps[i]);
    const double ep = 0.5 * (l.eps[i] + l.eps[i + 1]);
    const double c = problem_.deformation_factor() / pi;
    const double K0 = l.deformation.kernel(0), K1 = l.deformation.kernel(1);
    double J = -(em + ep) / (l.h * l.h) + state_.speed * c * (l.rho[i] * K0 - l.rho[i - 1] * K1) / l.h;
    if (state_.time_step > 0.0) J += c * l.rho[i] * K0 / state_.time_step;
    return J;
  }

  /// Residual of the complementarity problem P ≥ 0, r = f − L(P) ≥ 0 (J < 0), P·r = 0:
  /// the mean of |min(P_i·|J_i|, r_i)| over the interior, scaled by the largest wedge term.
  /// It vanishes exactly at a solution, cavitated nodes included.
  [[nodiscard]] double scaled_residual(Level& l) {
    update_film(l);
    update_coefficients(l);
    double sum = 0.0, scale = 1e-300;
    for (std::size_t i = 1; i + 1 < l.n; ++i) {
      scale = std::max(scale, std::abs(l.rho[i] * l.H[i] - l.rho[i - 1] * l.H[i - 1]) / l.h);
      const double r = l.f[i] - operator_at(l, i);
      sum += std::abs(std::min(l.P[i] * std::abs(diagonal(l, i)), r));
    }
    return sum / static_cast<double>(l.n - 2) / scale;
  }

  // --- relaxation ------------------------------------------------------------------------
  /// One relaxation sweep of Venner & Lubrecht's mixed scheme (2000, §7.3): Gauss–Seidel
  /// where ε/h² ≥ ξ on both faces, distributive Jacobi with the pattern (−¼, 1, −¼) where
  /// it is smaller; under-relaxed, P ≥ 0 after every change, then the film is recomputed in
  /// full by the FFT convolution. Line or point by point as the options say.
  void relax(Level& l) {
    const auto start = std::chrono::steady_clock::now();
    update_film(l);
    update_coefficients(l);
    if (l.line)
      relax_line(l);
    else
      relax_point(l);
    l.P.front() = l.P.back() = 0.0;
    for (auto& p : l.P) p = std::max(p, 0.0);
    update_film(l);
    work_units_ += static_cast<double>(l.n) / static_cast<double>(levels_.back()->n);
    l.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  [[nodiscard]] bool jacobi_node(const Level& l, std::size_t i) const {
    const double em = 0.5 * (l.eps[i - 1] + l.eps[i]);
    const double ep = 0.5 * (l.eps[i] + l.eps[i + 1]);
    return std::min(em, ep) / (l.h * l.h) < o_.xi_threshold;
  }

  /// All changes at once from the banded Jacobian (line_relaxation.h).
  void relax_line(Level& l) {
    std::vector<double> residual(l.n, 0.0);
    std::vector<char> jacobi(l.n, 0);
    for (std::size_t i = 1; i + 1 < l.n; ++i) {
      residual[i] = l.f[i] - operator_at(l, i);
      jacobi[i] = jacobi_node(l, i);
    }
    const ReynoldsCoefficients c{l.eps, l.rho, l.deformation, l.h, problem_.deformation_factor() / pi,
                                 state_.speed, state_.time_step};
    const auto dP = l.line->change(c, l.P, residual, jacobi, o_.omega_gauss_seidel, o_.omega_jacobi, l.held);
    for (std::size_t i = 1; i + 1 < l.n; ++i) l.P[i] += dP[i];
  }

  /// Node by node with the Jacobian diagonal (Poiseuille stencil and the film's own response
  /// through K0, K1); the film of the next nodes is moved at once after a Gauss–Seidel change,
  /// the distributive Jacobi changes are applied after the sweep.
  void relax_point(Level& l) {
    const double c = problem_.deformation_factor() / pi;
    std::vector<double> jacobi_change(l.n, 0.0);
    for (std::size_t i = 1; i + 1 < l.n; ++i) {
      if (!l.held.empty() && l.held[i]) continue;
      const double residual = l.f[i] - operator_at(l, i);
      if (!jacobi_node(l, i)) {
        const double old = l.P[i];
        l.P[i] = std::max(0.0, old + o_.omega_gauss_seidel * residual / diagonal(l, i));
        const double delta = l.P[i] - old;
        l.H[i - 1] -= c * l.deformation.kernel(1) * delta;
        for (std::size_t j = i; j < std::min(l.n, i + 3); ++j) l.H[j] -= c * l.deformation.kernel(j - i) * delta;
      } else {
        jacobi_change[i] = o_.omega_jacobi * residual / distributive_diagonal(l, i);
      }
    }
    for (std::size_t i = 1; i + 1 < l.n; ++i) {
      if (jacobi_change[i] == 0.0) continue;
      l.P[i] += jacobi_change[i];
      l.P[i - 1] -= 0.25 * jacobi_change[i];
      l.P[i + 1] -= 0.25 * jacobi_change[i];
    }
  }

  /// ∂L_i/∂δ for the distributive change (−¼, 1, −¼) centred on i.
  [[nodiscard]] double distributive_diagonal(const Level& l, std::size_t i) const {
    const double em = 0.5 * (l.eps[i - 1] + l.eps[i]);
    const double ep = 0.5 * (l.eps[i] + l.eps[i + 1]);
    const double c = problem_.deformation_factor() / pi;
    const double K0 = l.deformation.kernel(0), K1 = l.deformation.kernel(1), K2 = l.deformation.kernel(2);
    double J = -1.25 * (em + ep) / (l.h * l.h) +
               state_.speed * c * (l.rho[i] * (K0 - 0.5 * K1) - l.rho[i - 1] * (K1 - 0.25 * K0 - 0.25 * K2)) / l.h;
    if (state_.time_step > 0.0) J += c * l.rho[i] * (K0 - 0.5 * K1) / state_.time_step;
    return J;
  }

  // --- multigrid -------------------------------------------------------------------------
  void solve_coarsest(Level& l, int repeats) {
    for (int r = 0; r < repeats; ++r) {
      for (int s = 0; s < o_.coarsest_sweeps; ++s) relax(l);
      // In Hertzian units the load responds to H0 at O(1) whatever M (the deformation
      // absorbs the change); in rigid units it responds as w ∝ 1/h0, on the film's scale.
      const double scale = problem_.hertzian_scaling() ? 1.0 : film_guess_;
      H0_ += o_.h0_damping * scale * (integral(l) - l.g) / state_.load;
    }
    update_film(l);
  }

  void cycle(std::size_t k) {
    Level& fine = *levels_[k];
    if (k == 0) {
      solve_coarsest(fine, 1);
      return;
    }
    for (int s = 0; s < o_.pre_sweeps; ++s) relax(fine);
    Level& coarse = *levels_[k - 1];
    restrict_problem(fine, coarse);
    const std::vector<double> injected = coarse.P;
    const int gamma = o_.cycle == CycleType::W ? 2 : 1;
    for (int c = 0; c < gamma; ++c) cycle(k - 1);
    // Correction by linear interpolation, applied only inside the pressurised zone: not on
    // cavitated nodes nor next to them, where the free boundary is the fine grid's to place
    // (correcting there set up a limit cycle of the outlet on fine grids).
    std::vector<double> correction(fine.n, 0.0);
    for (std::size_t I = 0; I + 1 < coarse.n; ++I) {
      const double d0 = coarse.P[I] - injected[I];
      const double d1 = coarse.P[I + 1] - injected[I + 1];
      correction[2 * I] = d0;
      correction[2 * I + 1] = 0.5 * (d0 + d1);
    }
    std::vector<char> interior(fine.n, 0);
    for (std::size_t i = 1; i + 1 < fine.n; ++i)
      interior[i] = fine.P[i - 1] > 0.0 && fine.P[i] > 0.0 && fine.P[i + 1] > 0.0;
    for (std::size_t i = 1; i + 1 < fine.n; ++i)
      if (interior[i]) fine.P[i] = std::max(0.0, fine.P[i] + correction[i]);
    fine.P.front() = fine.P.back() = 0.0;
    for (int s = 0; s < o_.post_sweeps; ++s) relax(fine);
  }

  /// FAS coarse problem: injected pressure and film, f_c = L_c(P̄) + R·r (full weighting; no
  /// residual where the fine pressure is cavitated), g_c = ∫P̄ + (g − ∫P).
  void restrict_problem(Level& fine, Level& coarse) {
    update_film(fine);
    update_coefficients(fine);
    std::vector<double> r(fine.n, 0.0);
    for (std::size_t i = 1; i + 1 < fine.n; ++i)
      r[i] = fine.P[i] > 0.0 ? fine.f[i] - operator_at(fine, i) : 0.0;
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
    hold_unresolved(coarse);
  }

  /// With options.hold_unresolved, marks the coarse nodes whose injected pressure has a
  /// second difference above half its value: the pressure varies there on the scale of this
  /// grid's mesh (a spike narrower than the mesh, the foot of the outlet), and a coarse
  /// change would be interpolated into the fine grid as an error. The fine grid's relaxation
  /// alone converges those nodes. Measured on the 15-case suite (641–5121 nodes, M 1–1000,
  /// L 0–20) for thresholds 0.2, 0.5, 1, 2, 4: 0.5 converged 14, the others 13.
  void hold_unresolved(Level& coarse) const {
    coarse.held.clear();
    if (!o_.hold_unresolved) return;
    constexpr double threshold = 0.5;
    coarse.held.assign(coarse.n, 0);
    for (std::size_t I = 1; I + 1 < coarse.n; ++I) {
      const double second_difference = std::abs(coarse.P[I - 1] - 2.0 * coarse.P[I] + coarse.P[I + 1]);
      coarse.held[I] = coarse.P[I] > 0.0 && second_difference > threshold * coarse.P[I];
    }
  }

  /// FMG interpolation: cubic in the interior (4-point), linear next to the ends.
  static void interpolate_solution(const Level& coarse, Level& fine) {
    for (std::size_t I = 0; I < coarse.n; ++I) fine.P[2 * I] = coarse.P[I];
    for (std::size_t I = 0; I + 1 < coarse.n; ++I) {
      double value;
      if (I >= 1 && I + 2 < coarse.n)
        value = (-coarse.P[I - 1] + 9.0 * coarse.P[I] + 9.0 * coarse.P[I + 1] - coarse.P[I + 2]) / 16.0;
      else
        value = 0.5 * (coarse.P[I] + coarse.P[I + 1]);
      fine.P[2 * I + 1] = std::max(0.0, value);
    }
  }

  void initial_guess(Level& l) {
    // Semi-ellipse carrying the load on |X| < 1, H0 from the film of the rigid-isoviscous
    // and elastic-isoviscous asymptotes (Moes) converted to these units.
    const double amplitude = 2.0 * state_.load / pi;
    for (std::size_t i = 0; i < l.n; ++i) l.P[i] = amplitude * std::sqrt(std::max(0.0, 1.0 - l.X[i] * l.X[i]));
    l.P.front() = l.P.back() = 0.0;
    H0_ = 0.0;
    update_film(l);
    double h_in_contact = l.H[0];
    for (std::size_t i = 0; i < l.n; ++i)
      if (std::abs(l.X[i]) < 1.0) h_in_contact = std::min(h_in_contact, l.H[i]);
    const double M = problem_.data().moes_M();
    const double H_moes = std::pow(std::pow(3.0 / M, 7.0 / 3.0) + std::pow(2.621 * std::pow(M, -0.2), 7.0 / 3.0), 3.0 / 7.0);
    const double h_guess = H_moes * problem_.data().moes_film_scale();
    film_guess_ = h_guess / problem_.film_scale();
    H0_ = film_guess_ - h_in_contact;
    update_film(l);
  }

  void snapshot_coarse(const Level& l) {
    EhlResult tmp;
    fill_figures(l, tmp);
    coarse_h_min_ = tmp.h_min;
    coarse_p_max_ = tmp.p_max;
    has_coarse_ = true;
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
    // Film at X = 0 by linear interpolation.
    const double t = (0.0 - l.X.front()) / l.h;
    const auto i0 = std::min(static_cast<std::size_t>(std::floor(t)), l.n - 2);
    const double frac = t - static_cast<double>(i0);
    r.h_central = ((1.0 - frac) * l.H[i0] + frac * l.H[i0 + 1]) * hs;
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
      if (l.P[i] <= 0.0 || l.H[i] <= 0.0) continue;  // no full film: no Couette–Poiseuille shear
      const double h = l.H[i] * hs;
      const double dpdx = (l.P[i + 1] - l.P[i - 1]) / (2.0 * l.h) * ps / ls;
      const double eta = d.viscosity * problem_.viscosity(l.P[i]);
      force += (eta * (d.u2 - d.u1) / h - 0.5 * h * dpdx) * l.h * ls;
    }
    r.friction_force = force;
    r.friction_coefficient = force / d.load_per_length;
    r.coarse_h_min = coarse_h_min_;
    r.coarse_p_max = coarse_p_max_;
    // A coarse film at or below zero (heavy loads on coarse grids) gives a change above 1.
    if (has_coarse_ && r.h_min > 0.0 && r.p_max > 0.0) {
      r.h_min_change = std::abs(r.h_min - coarse_h_min_) / r.h_min;
      r.p_max_change = std::abs(r.p_max - coarse_p_max_) / r.p_max;
    }
  }

  const LineContactProblem& problem_;
  const EhlOptions& o_;
  ContactState state_;
  std::vector<std::unique_ptr<Level>> levels_;
  std::size_t finest_ = 0;
  double H0_ = 0.0;
  double film_guess_ = 1.0;  ///< expected film in these units (Moes' isoviscous asymptotes)
  double work_units_ = 0.0;
  double coarse_h_min_ = 0.0, coarse_p_max_ = 0.0;
  bool has_coarse_ = false;  ///< a solution on the next-coarser grid was recorded (full multigrid)
};


FasMultigrid::FasMultigrid(const LineContactProblem& problem, const EhlOptions& options, ContactState state)
    : impl_(std::make_unique<Impl>(problem, options, std::move(state))) {}

FasMultigrid::~FasMultigrid() = default;

EhlResult FasMultigrid::solve(const std::optional<WarmStart>& warm) { return impl_->solve(warm); }

std::vector<double> FasMultigrid::rho_h() { return impl_->rho_h(); }

}  // namespace gearbench::ehl
