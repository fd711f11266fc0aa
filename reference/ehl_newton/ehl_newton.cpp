// Newton–Raphson reference for the steady isothermal line contact (see ehl_newton.h).
//
// Discretisation (docs/ehl-model.md, "Independent numerical reference"):
//  * nodes: line_contact_grid.h, uniform core and a smoothly stretched far inlet;
//  * pressure: piecewise linear, P = 0 at both ends; deformation by the analytically
//    integrated linear elements (line_contact_grid.cpp), the film H_k = H0 + X_k²/2 + Σ_j D_kj·P_j;
//  * Reynolds: finite-volume (flux) form over the cell [X_{i−½}, X_{i+½}] of node i,
//      r_i = { [ε_f·∂P − H_f]_{i+½} − [ε_f·∂P − H_f]_{i−½} } / w_i,   w_i = (X_{i+1} − X_{i−1})/2,
//    Poiseuille flux central (ε_f the mean of its two nodes, ∂P the difference quotient), Couette
//    flux with the face film reconstructed linearly from the two upstream nodes (second-order
//    upwind; on a uniform grid its difference is Venner & Lubrecht's second-order wedge
//    (1.5H_i − 2H_{i−1} + 0.5H_{i−2})/h, REFERENCE-FACTS "Turn 2"; here in flux form on the
//    stretched grid; the first face uses the mean). A central face film leaves an odd–even
//    pressure mode undamped in the Hertz zone where ε → 0 (only H_{i+1} = H_{i−1} is enforced);
//  * cavitation (Reynolds outlet): the complementarity P ≥ 0, −r ≥ 0, P·r = 0 written with the
//    Fischer–Burmeister function, φ(P_i, −r_i/σ_i) = 0, and solved by semismooth Newton
//    (De Luca, Facchinei & Kanzow 1996; see fischer_burmeister below);
//  * unknowns P_1 … P_{n−2} and H0; the force balance Σ q_j·P_j = π/2 closes the system;
//    dense Jacobian, LU with partial pivoting (Eigen), backtracking on ‖F‖₂.
#include "ehl_newton/ehl_newton.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "closed_form/ehl_closed_form.h"
#include "ehl_newton/line_contact_grid.h"

namespace gearbench::reference {
namespace {

using std::numbers::pi;
using Eigen::Index;
using Eigen::VectorXd;
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

constexpr double load = pi / 2.0;  // ∫P dX of the Hertz semi-ellipse

/// One Moes point on one grid.
struct Contact {
  std::vector<double> X, q;  // nodes and trapezoid weights
  RowMatrix D;               // elastic operator (n×n; empty when rigid)
  double M = 0.0, L = 0.0, lambda = 0.0, alpha = 0.0;
  bool rigid = false;
  [[nodiscard]] Index n() const { return static_cast<Index>(X.size()); }
};

// λ̄ = 3π²/(8M²), ᾱ = L·√(M/2π) (docs/research/ehl.md §5, REFERENCE-FACTS "Dimensionless links").
double lambda_bar(double M) { return 3.0 * pi * pi / (8.0 * M * M); }
double alpha_bar(double M, double L) { return L * std::sqrt(M / (2.0 * pi)); }

Contact make_contact(double M, double L, int nodes, const EhlNewtonOptions& o) {
  const EhlNewtonDomain d = ehl_newton_domain(M, o.rigid);
  Contact c;
  c.X = ehl_newton_grid::stretched_grid(nodes, std::isnan(o.x_in) ? d.x_in : o.x_in,
                                        std::isnan(o.x_core) ? d.x_core : o.x_core,
                                        std::isnan(o.x_out) ? d.x_out : o.x_out, o.core_fraction);
  c.q = ehl_newton_grid::trapezoid_weights(c.X);
  if (!o.rigid) c.D = ehl_newton_grid::deformation_matrix(c.X);
  c.M = M;
  c.L = L;
  c.lambda = lambda_bar(M);
  c.alpha = alpha_bar(M, L);
  c.rigid = o.rigid;
  return c;
}

/// Pressure (with the zero end values), film and ε = H³/(η̄λ̄) of the unknowns z = (P_1 … P_{n−2}, H0).
struct Fields {
  VectorXd P, H, eps;
  double H0 = 0.0;
};

Fields fields(const Contact& c, const VectorXd& z) {
  const Index n = c.n();
  Fields f;
  f.P = VectorXd::Zero(n);
  f.P.segment(1, n - 2) = z.head(n - 2);
  f.H0 = z(n - 2);
  f.H.resize(n);
  for (Index k = 0; k < n; ++k) f.H(k) = f.H0 + 0.5 * c.X[k] * c.X[k];
  if (!c.rigid) f.H.noalias() += c.D * f.P;
  f.eps.resize(n);
  for (Index k = 0; k < n; ++k)
    f.eps(k) = f.H(k) * f.H(k) * f.H(k) * std::exp(-c.alpha * f.P(k)) / c.lambda;  // Barus η̄ = e^{ᾱP}
  return f;
}

double spacing(const Contact& c, Index i) { return c.X[i + 1] - c.X[i]; }  // Δ_i = X_{i+1} − X_i

/// Linear-upwind face film at X_{i+½}: H_f = (1 + β_i)H_i − β_i·H_{i−1}, β_i = Δ_i/(2Δ_{i−1});
/// the first face takes the mean. Returns the weights on (H_{i−1}, H_i, H_{i+1}).
std::array<double, 3> face_film_weights(const Contact& c, Index i) {
  if (i == 0) return {0.0, 0.5, 0.5};
  const double beta = spacing(c, i) / (2.0 * spacing(c, i - 1));
  return {-beta, 1.0 + beta, 0.0};
}

double face_film(const Contact& c, const Fields& f, Index i) {
  const auto w = face_film_weights(c, i);
  return (i > 0 ? w[0] * f.H(i - 1) : 0.0) + w[1] * f.H(i) + w[2] * f.H(i + 1);
}

/// Reynolds residual r_i (flux form, per unit cell width) at interior node i.
double reynolds(const Contact& c, const Fields& f, Index i) {
  const double gp = (f.P(i + 1) - f.P(i)) / spacing(c, i), gm = (f.P(i) - f.P(i - 1)) / spacing(c, i - 1);
  const double ep = 0.5 * (f.eps(i) + f.eps(i + 1)), em = 0.5 * (f.eps(i - 1) + f.eps(i));
  const double w = 0.5 * (c.X[i + 1] - c.X[i - 1]);
  return (ep * gp - em * gm - face_film(c, f, i) + face_film(c, f, i - 1)) / w;
}

/// Row scales σ_i = 1 + (ε_{i+½}/Δ_i + ε_{i−½}/Δ_{i−1})/w_i, 1 plus the Poiseuille diagonal
/// of ∂r_i/∂P_i: where the Poiseuille term dominates, −r_i/σ_i is in pressure units as P_i is.
/// The complementarity φ(P_i, −r_i/σ_i) = 0 is equivalent to that of (P_i, −r_i) for σ_i > 0;
/// unscaled, the far inlet (ε ~ 1e11 at M = 1) swamps the merit function and the rigid
/// solve stalls at its second step.
VectorXd row_scales(const Contact& c, const Fields& f) {
  const Index n = c.n();
  VectorXd s = VectorXd::Zero(n);
  for (Index i = 1; i < n - 1; ++i) {
    const double ep = 0.5 * (f.eps(i) + f.eps(i + 1)), em = 0.5 * (f.eps(i - 1) + f.eps(i));
    s(i) = 1.0 + (ep / spacing(c, i) + em / spacing(c, i - 1)) / (0.5 * (c.X[i + 1] - c.X[i - 1]));
  }
  return s;
}

/// Fischer–Burmeister function φ(a, b) = a + b − √(a² + b²): zero exactly when a ≥ 0, b ≥ 0,
/// a·b = 0 (Fischer, Optimization 24 (1992) 269), and ½φ² is continuously differentiable, so
/// the Newton direction is a descent direction of ½‖F‖² (De Luca, Facchinei & Kanzow,
/// Math. Program. 75 (1996) 407).
double fischer_burmeister(double a, double b) { return a + b - std::hypot(a, b); }

/// ∂φ/∂a and ∂φ/∂b; at (0, 0) the element (1 − 1/√2, 1 − 1/√2) of the generalized Jacobian.
std::pair<double, double> fischer_burmeister_derivatives(double a, double b) {
  const double r = std::hypot(a, b);
  if (r == 0.0) return {1.0 - std::numbers::sqrt2 / 2.0, 1.0 - std::numbers::sqrt2 / 2.0};
  return {1.0 - a / r, 1.0 - b / r};
}

/// F = (φ(P_i, −r_i/σ_i) for i = 1 … n−2, Σ q_j P_j − π/2), σ frozen for one Newton step.
VectorXd residual(const Contact& c, const Fields& f, const VectorXd& sigma) {
  const Index n = c.n();
  VectorXd F(n - 1);
  for (Index i = 1; i < n - 1; ++i) F(i - 1) = fischer_burmeister(f.P(i), -reynolds(c, f, i) / sigma(i));
  double integral = 0.0;
  for (Index j = 0; j < n; ++j) integral += c.q[j] * f.P(j);
  F(n - 2) = integral - load;
  return F;
}

/// Row of −∂r_i/∂z: explicit dependence on P_{i−1}, P_i, P_{i+1} (Poiseuille difference and
/// η̄(P) in ε) plus Σ_k (∂r_i/∂H_k)(∂H_k/∂z) with ∂H_k/∂P_j = D_kj, ∂H_k/∂H0 = 1.
void reynolds_jacobian_row(const Contact& c, const Fields& f, Index i, double* row) {
  const Index n = c.n(), m = n - 1;
  std::fill(row, row + m, 0.0);
  const double dp = spacing(c, i), dm = spacing(c, i - 1);
  const double gp = (f.P(i + 1) - f.P(i)) / dp, gm = (f.P(i) - f.P(i - 1)) / dm;
  const double ep = 0.5 * (f.eps(i) + f.eps(i + 1)), em = 0.5 * (f.eps(i - 1) + f.eps(i));
  // ∂(Poiseuille)/∂ε_k for k = i−1, i, i+1 (face ε is the mean of its nodes).
  const double de[3] = {-0.5 * gm, 0.5 * (gp - gm), 0.5 * gp};
  double dP[3] = {em / dm, -ep / dp - em / dm, ep / dp};  // ∂/∂P_{i−1}, P_i, P_{i+1}
  double dH[4] = {0.0, 0.0, 0.0, 0.0};                    // ∂/∂H_{i−2}, H_{i−1}, H_i, H_{i+1}
  for (int s = 0; s < 3; ++s) {
    const Index k = i - 1 + s;
    dH[s + 1] += de[s] * 3.0 * f.eps(k) / f.H(k);  // ∂ε/∂H = 3ε/H
    dP[s] += de[s] * (-c.alpha * f.eps(k));        // ∂ε/∂P = −ᾱε (Barus)
  }
  const auto wp = face_film_weights(c, i), wm = face_film_weights(c, i - 1);
  for (int s = 0; s < 3; ++s) {
    dH[s + 1] -= wp[s];  // −H_f(i+½), weights on H_{i−1}, H_i, H_{i+1}
    dH[s] += wm[s];      // +H_f(i−½), weights on H_{i−2}, H_{i−1}, H_i
  }
  const double w = 0.5 * (c.X[i + 1] - c.X[i - 1]);
  for (int s = 0; s < 3; ++s) {
    const Index k = i - 1 + s;
    if (k >= 1 && k <= n - 2) row[k - 1] -= dP[s] / w;
  }
  for (int s = 0; s < 4; ++s) {
    const Index k = i - 2 + s;
    if (k < 0 || dH[s] == 0.0) continue;
    const double a = -dH[s] / w;
    if (!c.rigid)
      for (Index j = 1; j < n - 1; ++j) row[j - 1] += a * c.D(k, j);
    row[m - 1] += a;  // H0
  }
}

/// The semismooth Newton matrix: row i is φ_a·e_i + φ_b·(−∂r_i/∂z)/σ_i; the last row is the
/// force balance.
RowMatrix jacobian(const Contact& c, const Fields& f, const VectorXd& sigma) {
  const Index n = c.n(), m = n - 1;
  RowMatrix J = RowMatrix::Zero(m, m);
  for (Index i = 1; i < n - 1; ++i) {
    const auto [da, db] = fischer_burmeister_derivatives(f.P(i), -reynolds(c, f, i) / sigma(i));
    reynolds_jacobian_row(c, f, i, J.row(i - 1).data());
    J.row(i - 1) *= db / sigma(i);
    J(i - 1, i - 1) += da;
  }
  for (Index j = 1; j < n - 1; ++j) J(m - 1, j - 1) = c.q[j];
  return J;
}

struct Outcome {
  bool converged = false;
  VectorXd z;
  int iterations = 0;
  std::vector<double> history;  // max |F| before each iteration and at the end
};

bool film_positive(const Fields& f) { return f.H.minCoeff() > 0.0; }

/// Damped Newton: full step when it lowers ‖F‖₂ (Armijo, 1e-4), else halve down to 1/256.
/// The row scales σ are those of the current iterate, the same for the step and its trials.
Outcome newton(const Contact& c, VectorXd z, const EhlNewtonOptions& o) {
  Outcome out;
  Fields f = fields(c, z);
  if (!film_positive(f)) return out;
  for (int it = 0;; ++it) {
    const VectorXd sigma = row_scales(c, f);
    const VectorXd F = residual(c, f, sigma);
    out.history.push_back(F.lpNorm<Eigen::Infinity>());
    if (!std::isfinite(out.history.back())) return out;
    if (out.history.back() < o.tolerance) {
      out.converged = true;
      out.iterations = it;
      out.z = std::move(z);
      return out;
    }
    if (it == o.max_iterations) return out;
    const VectorXd step = Eigen::PartialPivLU<Eigen::MatrixXd>(jacobian(c, f, sigma)).solve(-F);
    bool accepted = false;
    for (double t = 1.0; t >= 1.0 / 256.0 && !accepted; t *= 0.5) {
      const VectorXd trial = z + t * step;
      Fields ft = fields(c, trial);
      if (!film_positive(ft)) continue;
      if (residual(c, ft, sigma).norm() <= (1.0 - 1e-4 * t) * F.norm()) {
        z = trial;
        f = std::move(ft);
        accepted = true;
      }
    }
    if (!accepted) return out;
  }
}

/// Newton at the target ᾱ from z0; when it fails, continuation in ᾱ from 0 in steps of ᾱ/8,
/// a failed step halved (down to ᾱ/512). Steps growing by 1.5 after a success failed at
/// M = 10, L = 17.5 (ᾱ = 22, where the pressure spike forms, ᾱ ≈ 11 → 16.5) and cost more.
Outcome solve_continued(Contact& c, const VectorXd& z0, const EhlNewtonOptions& o, int& solves) {
  const double target = c.alpha;
  solves = 1;
  Outcome out = newton(c, z0, o);
  if (out.converged || target == 0.0) return out;
  c.alpha = 0.0;
  ++solves;
  Outcome last = newton(c, z0, o);
  if (!last.converged) {
    c.alpha = target;
    return last;
  }
  double reached = 0.0, step = target / 8.0;
  while (reached < target && step >= target / 512.0) {
    c.alpha = reached + step > target * (1.0 - 1e-9) ? target : reached + step;
    ++solves;
    Outcome next = newton(c, last.z, o);
    if (next.converged) {
      reached = c.alpha;
      last = std::move(next);
    } else {
      step *= 0.5;
    }
  }
  c.alpha = target;
  if (reached < target) last.converged = false;
  return last;
}

/// H(x) = H0 + x²/2 + Σ_j c_j(x)·P_j anywhere, exact for the piecewise-linear pressure.
double film_at(const Contact& c, const Fields& f, double x) {
  double H = f.H0 + 0.5 * x * x;
  if (!c.rigid) {
    std::vector<double> row(c.X.size());
    ehl_newton_grid::deformation_row(c.X, x, row.data());
    for (std::size_t j = 0; j < row.size(); ++j) H += row[j] * f.P(static_cast<Index>(j));
  }
  return H;
}

/// Minimum of the exact film on [X_{m−1}, X_{m+1}] around the nodal minimum m (golden section).
std::pair<double, double> film_minimum(const Contact& c, const Fields& f) {
  Index m = 1;
  for (Index k = 1; k < c.n() - 1; ++k)
    if (f.H(k) < f.H(m)) m = k;
  double a = c.X[m - 1], b = c.X[m + 1];
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  double h1 = film_at(c, f, x1), h2 = film_at(c, f, x2);
  while (b - a > 1e-12 * (1.0 + std::abs(a))) {
    if (h1 < h2) {
      b = x2; x2 = x1; h2 = h1; x1 = b - g * (b - a); h1 = film_at(c, f, x1);
    } else {
      a = x1; x1 = x2; h1 = h2; x2 = a + g * (b - a); h2 = film_at(c, f, x2);
    }
  }
  const double x = 0.5 * (a + b);
  return {x, film_at(c, f, x)};
}

EhlNewtonResult make_result(const Contact& c, const Outcome& out, int solves) {
  EhlNewtonResult r;
  r.M = c.M;
  r.L = c.L;
  r.nodes = static_cast<int>(c.n());
  r.converged = out.converged;
  r.iterations = out.iterations;
  r.solves = solves;
  r.residual_history = out.history;
  r.residual = out.history.empty() ? std::numeric_limits<double>::infinity() : out.history.back();
  if (!out.converged) return r;
  const Fields f = fields(c, out.z);
  const double to_moes = 8.0 * c.M / pi;  // H_M = (8M/π)·H (ehl_newton.h)
  r.H0 = f.H0;
  r.H_c = to_moes * film_at(c, f, 0.0);
  const auto [x_min, h_min] = film_minimum(c, f);
  r.X_min = x_min;
  r.H_min = to_moes * h_min;
  Index peak = 0;
  f.P.maxCoeff(&peak);
  r.p_max = f.P(peak);
  for (Index k = peak; k < c.n(); ++k)
    if (f.P(k) == 0.0) {
      r.x_cavitation = c.X[k];
      break;
    }
  r.X = c.X;
  r.P.assign(f.P.data(), f.P.data() + f.P.size());
  r.H.assign(f.H.data(), f.H.data() + f.H.size());
  return r;
}

/// The unknowns of a start: interior pressures and H0.
VectorXd unknowns(const std::vector<double>& P, double H0) {
  const auto n = static_cast<Index>(P.size());
  VectorXd z(n - 1);
  for (Index i = 1; i < n - 1; ++i) z(i - 1) = P[i];
  z(n - 2) = H0;
  return z;
}

/// Rigid start: a bell P ∝ (1 + ξ²)^−2 upstream of X = 0 (ξ = X/s, s = √(2H0)), scaled to the
/// load, with H0 from Moes' H_RI = 3/M (the film at the pressure peak, Martin) divided by
/// h*/h0 = 1.225748 (docs/research/ehl.md §4), in the Hertzian scaling H = H_M·π/(8M). Not P = 0:
/// there the rigid film's H0 has no effect on the residual and the Jacobian is singular.
VectorXd rigid_start(const Contact& c) {
  const double H0 = 3.0 / c.M * pi / (8.0 * c.M) / 1.225748, s = std::sqrt(2.0 * H0);
  std::vector<double> P(c.X.size(), 0.0);
  double integral = 0.0;
  for (std::size_t k = 1; k + 1 < P.size(); ++k) {
    const double xi = c.X[k] / s;
    P[k] = xi < 0.0 ? 1.0 / ((1.0 + xi * xi) * (1.0 + xi * xi)) : 0.0;
    integral += c.q[k] * P[k];
  }
  for (double& p : P) p *= load / integral;
  return unknowns(P, H0);
}

/// Elastic start: the Hertz semi-ellipse, whose deformation −(1/2)(X² − 1/2 − ln 2) flattens
/// the film to H0 + 1/4 + (ln 2)/2 on |X| < 1 (Johnson, Contact Mechanics, 1985, §5.6), with
/// that film set to Moes' central film (reference/closed_form) in the Hertzian scaling.
VectorXd hertz_start(const Contact& c) {
  std::vector<double> P(c.X.size());
  for (std::size_t k = 0; k < P.size(); ++k) P[k] = std::sqrt(std::max(0.0, 1.0 - c.X[k] * c.X[k]));
  const double H = moes_H(c.M, c.L) * pi / (8.0 * c.M);
  return unknowns(P, H - 0.25 - 0.5 * std::log(2.0));
}

/// The rigid-isoviscous solution as the start of an elastic contact at small M: the same
/// pressure, H0 shifted so that the film at the nodal minimum is unchanged.
VectorXd start_from_rigid(const Contact& c, const EhlNewtonOptions& o) {
  EhlNewtonOptions ro = o;
  ro.rigid = true;
  Contact rigid = c;
  rigid.rigid = true;
  rigid.alpha = 0.0;
  const Outcome out = newton(rigid, rigid_start(rigid), ro);
  if (!out.converged) return hertz_start(c);
  const Fields fr = fields(rigid, out.z);
  Index m = 0;
  fr.H.minCoeff(&m);
  const double deformation = (c.D.row(m) * fr.P)(0);
  VectorXd z = out.z;
  z(c.n() - 2) -= deformation;
  return z;
}

/// Linear interpolation of a solution onto the nested grid of 2n − 1 nodes.
VectorXd refine(const EhlNewtonResult& coarse) {
  const std::size_t n = coarse.P.size();
  std::vector<double> P(2 * n - 1);
  for (std::size_t k = 0; k < n; ++k) P[2 * k] = coarse.P[k];
  for (std::size_t k = 0; k + 1 < n; ++k) P[2 * k + 1] = 0.5 * (coarse.P[k] + coarse.P[k + 1]);
  return unknowns(P, coarse.H0);
}

void validate(double M, double L, int nodes) {
  if (!(M > 0.0) || !(L >= 0.0) || nodes < 5)
    throw std::invalid_argument("ehl_newton: needs M > 0, L ≥ 0 and at least 5 nodes");
}

EhlNewtonResult solve_from(double M, double L, int nodes, const EhlNewtonOptions& o, const VectorXd* start) {
  validate(M, L, nodes);
  Contact c = make_contact(M, L, nodes, o);
  const VectorXd z0 = start ? *start : o.rigid ? rigid_start(c) : M < 5.0 ? start_from_rigid(c, o) : hertz_start(c);
  int solves = 0;
  const Outcome out = solve_continued(c, z0, o, solves);
  return make_result(c, out, solves);
}

}  // namespace

EhlNewtonDomain ehl_newton_domain(double M, bool rigid) {
  const double s = 1.3865 / M;
  if (rigid) return {-100.0 * s, -3.0 * s, 1.5 * s};
  return {-(4.5 + 100.0 * s), -(1.5 + 3.0 * s), 1.5 + 1.5 * s};
}

EhlNewtonResult ehl_newton_line_contact(double M, double L, int nodes, const EhlNewtonOptions& options) {
  return solve_from(M, L, nodes, options, nullptr);
}

double ehl_newton_martin_constant(const EhlNewtonResult& r) { return 2.0 * r.M * r.H_min; }

RichardsonValue richardson_observed(double v1, double v2, double v3) {
  const double ratio = (v1 - v2) / (v2 - v3);
  if (!(ratio > 1.0)) return {v3, std::numeric_limits<double>::quiet_NaN(), std::abs(v3 - v2)};
  const double p = std::log2(ratio);
  const double value = v3 + (v3 - v2) / (std::pow(2.0, p) - 1.0);
  return {value, p, std::abs(value - v3)};
}

EhlNewtonGridStudy ehl_newton_grid_study(double M, double L, int coarse_nodes, const EhlNewtonOptions& options) {
  EhlNewtonGridStudy s;
  s.solves[0] = solve_from(M, L, coarse_nodes, options, nullptr);
  for (std::size_t g = 1; g < 3; ++g) {
    const auto& coarse = s.solves[g - 1];
    const int nodes = 2 * coarse.nodes - 1;
    const VectorXd z0 = coarse.converged ? refine(coarse) : VectorXd();
    s.solves[g] = solve_from(M, L, nodes, options, coarse.converged ? &z0 : nullptr);
  }
  s.converged = s.solves[0].converged && s.solves[1].converged && s.solves[2].converged;
  const auto& [a, b, c] = s.solves;
  s.H_c = richardson_observed(a.H_c, b.H_c, c.H_c);
  s.H_min = richardson_observed(a.H_min, b.H_min, c.H_min);
  return s;
}

}  // namespace gearbench::reference
