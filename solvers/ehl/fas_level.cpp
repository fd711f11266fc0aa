// The state of one grid level: the film by the deformation integral, the coefficients ε and ρ̄
// from the level's own P and H, the discrete Reynolds operator (reynolds_stencil.h), its residuals
// and the force balance.
#include "fas_multigrid_impl.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gearbench::ehl {

void FasMultigrid::Impl::update_film(Level& l) {
  // The film of the pressure it was last computed from, untouched since (film_of): a relaxation
  // starts by updating the film that the one before it ended with.
  if (l.film_of.valid && l.film_of.H0 == H0_ && l.film_of.P == l.P) return;
  if (o_.direct_deformation)
    l.deformation.apply_direct(l.P, l.W);
  else
    l.deformation.apply(l.P, l.W);
  const double c = problem_.deformation_factor() / pi;
  for (std::size_t i = 0; i < l.n; ++i) l.H[i] = H0_ + 0.5 * state_.curvature * l.X[i] * l.X[i] - c * l.W[i];
  if (!l.film_correction.empty())
    for (std::size_t i = 0; i < l.n; ++i) l.H[i] += l.film_correction[i];
  l.film_of.P = l.P;
  l.film_of.H0 = H0_;
  l.film_of.valid = true;
}

void FasMultigrid::Impl::update_film_window(Level& l, const FilmBase& base, std::size_t lo, std::size_t hi,
                                            NodeRange changed) const {
  l.film_of.valid = false;
  const double c = problem_.deformation_factor() / pi;
  for (std::size_t k = lo; k <= hi; ++k) {
    double shift = 0.0;
    for (std::size_t j = changed.first; j <= changed.last; ++j)
      shift += l.deformation.kernel(k > j ? k - j : j - k) * (l.P[j] - base.P[j]);
    l.H[k] = base.H[k] - c * shift;
  }
}

void FasMultigrid::Impl::update_node_coefficients(Level& l, std::size_t i) const {
  const double P = l.P[i];
  const double rho = problem_.density(P), rho_slope = problem_.density_slope(P);
  const double H = std::max(l.H[i], 0.0);
  l.rho[i] = rho * l.wedge_factor[i];
  l.rho_slope[i] = rho_slope * l.wedge_factor[i];
  l.eps[i] = l.flow_factor[i] * rho * H * H * H * std::exp(-viscosity_exponent_ * problem_.log_viscosity(P)) *
             (1.0 / problem_.lambda());
  // d ln(ρ̄/η̄^s)/dP from the laws' own derivatives (central differences before the fifteenth
  // session: two more Roelands powers a node, 8 % of an isothermal solve's instructions).
  l.eps_log_slope[i] = rho_slope / rho - viscosity_exponent_ * problem_.log_viscosity_slope(P);
}

void FasMultigrid::Impl::update_coefficients(Level& l) {
  l.eps.resize(l.n);
  l.eps_log_slope.resize(l.n);
  l.rho_slope.resize(l.n);
  l.eps_face_dP_left.resize(l.n - 1);
  l.eps_face_dP_right.resize(l.n - 1);
  update_coefficients_window(l, 0, l.n - 1);
}

void FasMultigrid::Impl::update_coefficients_window(Level& l, std::size_t lo, std::size_t hi) {
  for (std::size_t i = lo; i <= hi; ++i) update_node_coefficients(l, i);
  for (std::size_t i = lo; i < hi; ++i) {
    l.eps_face[i] = 0.5 * (l.eps[i] + l.eps[i + 1]);
    l.eps_face_dP_left[i] = 0.5 * l.eps[i] * l.eps_log_slope[i];
    l.eps_face_dP_right[i] = 0.5 * l.eps[i + 1] * l.eps_log_slope[i + 1];
  }
}

FilmSensitivity FasMultigrid::Impl::film_sensitivity(const Level& l) {
  FilmSensitivity d;
  d.left.assign(l.n - 1, 0.0);
  d.right.assign(l.n - 1, 0.0);
  for (std::size_t i = 0; i + 1 < l.n; ++i) {  // ε_{i+½} = (ε_i + ε_{i+1})/2, ε ∝ H³
    if (l.H[i] > 0.0) d.left[i] = 1.5 * l.eps[i] / l.H[i];
    if (l.H[i + 1] > 0.0) d.right[i] = 1.5 * l.eps[i + 1] / l.H[i + 1];
  }
  return d;
}

ReynoldsCoefficients FasMultigrid::Impl::coefficients(const Level& l) const {
  ReynoldsCoefficients c{l.eps_face, l.rho, l.deformation, l.h, problem_.deformation_factor() / pi, state_.speed,
                         state_.time_step};
  c.rho_dP = &l.rho_slope;
  c.H = &l.H;
  c.eps_face_dP_left = &l.eps_face_dP_left;
  c.eps_face_dP_right = &l.eps_face_dP_right;
  c.P = &l.P;
  return c;
}

double FasMultigrid::Impl::operator_at(const Level& l, std::size_t i) const {
  const double h2 = l.h * l.h;
  double L = (l.eps_face[i - 1] * (l.P[i - 1] - l.P[i]) + l.eps_face[i] * (l.P[i + 1] - l.P[i])) / h2;
  const auto w = wedge_weights(i);
  double wedge = 0.0;
  for (std::size_t m = 0; m < 3 && m <= i; ++m) wedge += w[m] * l.rho[i - m] * l.H[i - m];
  L -= state_.speed * wedge / l.h;
  if (state_.time_step > 0.0) L -= (l.rho[i] * l.H[i] - l.rho_h_old[i]) / state_.time_step;
  return L;
}

std::vector<double> FasMultigrid::Impl::residuals(const Level& l) const {
  std::vector<double> r(l.n, 0.0);
  for (std::size_t i = 1; i + 1 < l.n; ++i) r[i] = l.f[i] - operator_at(l, i);
  return r;
}

double FasMultigrid::Impl::integral(const Level& l) {
  return l.h * std::accumulate(l.P.begin(), l.P.end(), 0.0);  // P = 0 at both ends
}

double FasMultigrid::Impl::scaled_residual(Level& l) {
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

void FasMultigrid::Impl::make_finest(Level& l) {
  l.film_correction.clear();
  l.film_of.valid = false;
  std::fill(l.f.begin(), l.f.end(), 0.0);
  std::fill(l.cavitated_on_finer.begin(), l.cavitated_on_finer.end(), 0);
  l.g = state_.load;
}

double FasMultigrid::Impl::film_at_centre(const Level& l) {
  const double t = (0.0 - l.X.front()) / l.h;
  const auto i0 = std::min(static_cast<std::size_t>(std::floor(t)), l.n - 2);
  const double frac = t - static_cast<double>(i0);
  return (1.0 - frac) * l.H[i0] + frac * l.H[i0 + 1];
}

}  // namespace gearbench::ehl
