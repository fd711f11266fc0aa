// Grid and elastic influence coefficients of the Newton line-contact reference.
#include "ehl_newton/line_contact_grid.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gearbench::reference::ehl_newton_grid {
namespace {

// Antiderivatives of the log kernel (elementary, by parts): F0′(u) = ln|u|,
// F1′(u) = u·ln|u|; both are continuous at u = 0 with F0(0) = F1(0) = 0.
double F0(double u) { return u == 0.0 ? 0.0 : u * std::log(std::abs(u)) - u; }
double F1(double u) { return u == 0.0 ? 0.0 : 0.5 * u * u * std::log(std::abs(u)) - 0.25 * u * u; }

}  // namespace

std::vector<double> stretched_grid(int nodes, double x_in, double x_core, double x_out,
                                   double core_fraction) {
  if (nodes < 5 || !(x_in < x_core && x_core < x_out) || !(core_fraction > 0.0 && core_fraction <= 1.0))
    throw std::invalid_argument("ehl_newton: grid needs ≥ 5 nodes, x_in < x_core < x_out, 0 < core_fraction ≤ 1");
  const double t_c = 1.0 - core_fraction;
  const double k = (x_out - x_core) / core_fraction;  // dX/dt on the core
  const double A = t_c > 0.0 ? (x_core - k * t_c - x_in) / std::pow(t_c, 4) : 0.0;
  if (A < 0.0)
    throw std::invalid_argument("ehl_newton: inlet x_in too close to the core for the stretched grid");
  std::vector<double> X(static_cast<std::size_t>(nodes));
  for (int i = 0; i < nodes; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(nodes - 1);
    const double d = t_c - t;
    X[static_cast<std::size_t>(i)] = d > 0.0 ? x_core - k * d - A * d * d * d * d : x_core - k * d;
  }
  X.front() = x_in;
  X.back() = x_out;
  return X;
}

// On the element [a, b] (h = b − a) the pressure is P_a·N_a + P_b·N_b with N_a = (b − X′)/h,
// N_b = (X′ − a)/h. With u = X′ − x, u_a = a − x, u_b = b − x, I0 = ∫ ln|u| du and
// I1 = ∫ u·ln|u| du over [u_a, u_b]:
//   ∫ N_a ln|x − X′| dX′ = (u_b·I0 − I1)/h,   ∫ N_b ln|x − X′| dX′ = (I1 − u_a·I0)/h.
// Exact for the piecewise-linear pressure: the kernel's singularity is integrated analytically,
// in the manner of Houpert & Hamrock, J. Tribol. 108 (1986) 411 (whose elements are quadratic;
// these linear-element integrals are derived here and tested against the Hertz deformation).
void deformation_row(const std::vector<double>& X, double x, double* row) {
  const std::size_t n = X.size();
  for (std::size_t j = 0; j < n; ++j) row[j] = 0.0;
  for (std::size_t e = 0; e + 1 < n; ++e) {
    const double ua = X[e] - x, ub = X[e + 1] - x, h = X[e + 1] - X[e];
    const double I0 = F0(ub) - F0(ua), I1 = F1(ub) - F1(ua);
    row[e] -= (ub * I0 - I1) / (h * std::numbers::pi);
    row[e + 1] -= (I1 - ua * I0) / (h * std::numbers::pi);
  }
}

Eigen::MatrixXd deformation_matrix(const std::vector<double>& X) {
  const auto n = static_cast<Eigen::Index>(X.size());
  Eigen::MatrixXd Dt(n, n);  // column i holds the row of node i (column-major storage)
  for (Eigen::Index i = 0; i < n; ++i) deformation_row(X, X[static_cast<std::size_t>(i)], Dt.col(i).data());
  return Dt.transpose();
}

std::vector<double> trapezoid_weights(const std::vector<double>& X) {
  const std::size_t n = X.size();
  std::vector<double> q(n, 0.0);
  for (std::size_t e = 0; e + 1 < n; ++e) {
    q[e] += 0.5 * (X[e + 1] - X[e]);
    q[e + 1] += 0.5 * (X[e + 1] - X[e]);
  }
  return q;
}

}  // namespace gearbench::reference::ehl_newton_grid
