// The two grid-scale features no coarse grid holds, treated locally on the fine grid (Brandt's
// local relaxation of singularities): the Barus pressure spike and the outlet's free boundary
// (docs/research/ehl-multigrid-rebuild.md, eighth session).
#include "fas_multigrid_impl.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <unsupported/Eigen/IterativeSolvers>

#include "coarsest_solve.h"
#include "kernel_jacobian.h"

namespace gearbench::ehl {

double FasMultigrid::Impl::spike_half_width_in_X() const {
  return o_.spike_half_width * problem_.hertz_half_width() / problem_.length_scale();
}

double FasMultigrid::Impl::krylov_solve_cost(const KernelJacobian& J, int iterations) {
  const double band = BandPreconditioner::solve_cost(J);
  const double solves = iterations == 0 ? band : (iterations + 1.0) * (J.product_cost() + band);
  return solves / multiply_adds_per_sweep;
}

bool FasMultigrid::Impl::piezoviscous() const {
  return problem_.log_viscosity_slope(problem_.hertz_pressure() / problem_.pressure_scale()) != 0.0;
}

FasMultigrid::Impl::NodeRange FasMultigrid::Impl::relax_spike(Level& l) {
  // Isoviscous (L = 0), the window's Newton steps were a fifth of the work on 16385 nodes and
  // did nothing the cycle needs: without them 2–36 % fewer WU at L = 0 over M 1–1000 on the
  // default grid and 641 … 16385 nodes, under both stop rules, every point converged, the
  // algebraic error at most 0.36 of the rule's bound (thirtieth session).
  if (!piezoviscous()) {
    const std::size_t s = spike_index(l.P);
    return {s, s};
  }
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
    node_sweeps_.spike += window_film_cost(hi - lo + 1, hi - lo + 1);
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
    KernelJacobian J(l.deformation, c.film_factor, a, m);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m));
    for (std::size_t i = a; i <= b; ++i) {
      const double r = l.f[i] - operator_at(l, i);
      if (stays_cavitated(l.P[i], r, c.jacobian(i, i))) continue;  // an identity row
      const ReynoldsRow row = reynolds_row(c, fs, l.P, i);
      J.set_row(i, row.dL_dH, row.band);
      rhs(static_cast<Eigen::Index>(i - a)) = r;
    }
    node_sweeps_.spike += BandPreconditioner::factorize_cost(J) / multiply_adds_per_sweep;
    Eigen::VectorXd x;
    if (m <= BandPreconditioner::band_width + 1) {  // the band is the whole matrix: solved directly
      x = BandPreconditioner().compute(J).solve(rhs);
      node_sweeps_.spike += krylov_solve_cost(J, 0);
    } else {
      Eigen::GMRES<KernelJacobian, BandPreconditioner> gmres;
      gmres.setTolerance(spike_krylov_tolerance);
      gmres.setMaxIterations(spike_krylov_iterations);
      gmres.set_restart(spike_krylov_iterations);
      gmres.compute(J);
      x = gmres.solve(rhs);
      node_sweeps_.spike += krylov_solve_cost(J, static_cast<int>(gmres.iterations()));
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
  node_sweeps_.free_boundary += window_film_cost(hi - lo + 1, changed.last - changed.first + 1);
  const FilmBase base{l.P, l.H};
  for (int s = 0; s < o_.free_boundary_sweeps; ++s) relax(l, a, b, &base);
}

}  // namespace gearbench::ehl
