// The two grid-scale features no coarse grid holds, treated locally on the fine grid (Brandt's
// local relaxation of singularities): the Barus pressure spike and the outlet's free boundary
// (docs/research/ehl-multigrid-rebuild.md, eighth session).
#include "fas_multigrid_impl.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <unsupported/Eigen/IterativeSolvers>

#include "spike_jacobian.h"

namespace gearbench::ehl {

double FasMultigrid::Impl::spike_half_width_in_X() const {
  return o_.spike_half_width * problem_.hertz_half_width() / problem_.length_scale();
}

double FasMultigrid::Impl::spike_krylov_cost(const SpikeJacobian& J, int iterations) {
  const auto m = static_cast<double>(J.rows());
  const double width = std::min(m, 2.0 * SpikeBandPreconditioner::band_width + 1.0);  // of a row of the band
  const double band = 5.0 * m * width + std::min(m * m * m / 3.0, m * width * width / 2.0);  // entries, LU
  const double triangular = 2.0 * m * width;
  const double solves = iterations == 0 ? triangular : (iterations + 1.0) * (J.product_cost() + triangular);
  return (band + solves) / multiply_adds_per_sweep;
}

FasMultigrid::Impl::NodeRange FasMultigrid::Impl::relax_spike(Level& l) {
  constexpr int steps = 2;
  constexpr std::size_t fewest_nodes = 4;  // either side: the window measured best in nodes (eighth session)
  const auto w = std::max(fewest_nodes, static_cast<std::size_t>(std::ceil(spike_half_width_in_X() / l.h)));
  update_coefficients(l);  // the film is current (relax_spike's precondition)
  const auto s = spike_index(l.P);
  const std::size_t a = s > w ? s - w : 1;
  const std::size_t b = std::min(l.n - 2, s + w);
  const std::size_t m = b - a + 1;
  // A trial changes P on a … b only: its film and coefficients are updated on the nodes the
  // window's operator reads (the film two nodes upstream, ε one either side).
  const FilmBase base{l.P, l.H};
  const std::size_t lo = a >= 3 ? a - 3 : 0, hi = std::min(l.n - 1, b + 2);
  const auto refresh = [&] {
    update_film_window(l, base, lo, hi);
    update_coefficients_window(l, lo, hi);
    node_sweeps_ += window_film_cost(hi - lo + 1, hi - lo + 1);
  };
  const auto merit = [&]() {
    double sum = 0.0;
    for (std::size_t i = a; i <= b; ++i) {
      const double r = l.f[i] - operator_at(l, i);
      const double part = complementarity_residual(l.P[i], r);
      sum += part * part;
    }
    return sum;
  };
  bool descending = true;  // a step that no halving makes descend ends the solve
  for (int st = 0; st < steps && descending; ++st) {
    const auto c = coefficients(l);
    const auto fs = film_sensitivity(l);
    SpikeJacobian J(l.deformation, c.film_factor, a, m);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m));
    const double h2 = l.h * l.h;
    for (std::size_t i = a; i <= b; ++i) {
      const double r = l.f[i] - operator_at(l, i);
      if (stays_cavitated(l.P[i], r, c.jacobian(i, i))) continue;  // an identity row
      // ∂L_i/∂H_k, k = i−2 … i+1: the wedge's and ε's (ε ∝ H³) film response.
      const auto wedge = c.film_derivative(i);
      const double q_minus = (l.P[i - 1] - l.P[i]) / h2, q_plus = (l.P[i + 1] - l.P[i]) / h2;
      const std::array<double, 4> dL_dH{wedge[2], wedge[1] + fs.left[i - 1] * q_minus,
                                        wedge[0] + fs.right[i - 1] * q_minus + fs.left[i] * q_plus,
                                        fs.right[i] * q_plus};
      std::array<double, 5> band{};
      for (std::size_t t = 0; t < 5; ++t)
        if (i + t >= 2) band[t] = c.local_jacobian(i, i + t - 2);
      J.set_row(i, dL_dH, band);
      rhs(static_cast<Eigen::Index>(i - a)) = r;
    }
    Eigen::VectorXd x;
    if (m <= SpikeBandPreconditioner::band_width + 1) {  // the band is the whole matrix: solved directly
      x = SpikeBandPreconditioner().compute(J).solve(rhs);
      node_sweeps_ += spike_krylov_cost(J, 0);
    } else {
      Eigen::GMRES<SpikeJacobian, SpikeBandPreconditioner> gmres;
      gmres.setTolerance(spike_krylov_tolerance);
      gmres.setMaxIterations(spike_krylov_iterations);
      gmres.set_restart(spike_krylov_iterations);
      gmres.compute(J);
      x = gmres.solve(rhs);
      node_sweeps_ += spike_krylov_cost(J, static_cast<int>(gmres.iterations()));
    }
    if (!x.allFinite()) break;
    const std::vector<double> P0 = l.P;
    const double m0 = merit();
    double theta = 1.0;
    for (int hv = 0; hv <= 6; ++hv, theta *= 0.5) {
      for (std::size_t i = a; i <= b; ++i) l.P[i] = std::max(0.0, P0[i] + theta * x(static_cast<Eigen::Index>(i - a)));
      refresh();
      if (merit() < m0) break;
      if (hv == 6) {
        l.P = P0;
        descending = false;
      }
    }
  }
  return {a, b};
}

void FasMultigrid::Impl::relax_free_boundary(Level& l, const FilmBase& before, NodeRange changed) {
  constexpr std::size_t beyond = 4;  // cavitated nodes the free boundary may move into
  const std::size_t last = last_pressurised(l.P);
  const auto w = static_cast<std::size_t>(o_.free_boundary_window);
  const std::size_t a = last > w ? last - w : 1;
  const std::size_t b = std::min(l.n - 1, last + beyond);
  // The window's film with the spike's changes: the nodes its sweeps read (as in relax()).
  const std::size_t lo = a >= 3 ? a - 3 : 0, hi = std::min(l.n - 1, b + 2);
  update_film_window(l, before, lo, hi, changed);
  node_sweeps_ += window_film_cost(hi - lo + 1, changed.last - changed.first + 1);
  const FilmBase base{l.P, l.H};
  for (int s = 0; s < o_.free_boundary_sweeps; ++s) relax(l, a, b, &base);
}

}  // namespace gearbench::ehl
