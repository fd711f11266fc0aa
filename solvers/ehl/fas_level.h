#pragma once
// One grid of the FAS multigrid's hierarchy (fas_multigrid_impl.h): its unknowns, coefficients
// and FAS right-hand sides. FasMultigrid::Impl computes on it (fas_level.cpp and the rest).
#include <cstddef>
#include <vector>

#include "deformation.h"

namespace gearbench::ehl {

struct FasLevel {
  FasLevel(std::size_t nodes, double x_in, double x_out)
      : n(nodes), h((x_out - x_in) / static_cast<double>(nodes - 1)), deformation(nodes, h),
        X(nodes), P(nodes, 0.0), H(nodes, 0.0), W(nodes, 0.0), rho(nodes, 1.0), eps_face(nodes - 1, 0.0),
        f(nodes, 0.0), flow_factor(nodes, 1.0), wedge_factor(nodes, 1.0), cavitated_on_finer(nodes, 0) {
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
  /// On a coarse grid, the nodes whose finer-grid node is cavitated: they stay at zero, so
  /// that the coarse correction lives in the finer grid's pressurised set and the free
  /// boundary is the finest grid's to move (truncated multigrid for obstacle problems:
  /// Kornhuber 1994; Gräser & Kornhuber 2009). Left free, such a node sits exactly at its
  /// complementarity switch (its restricted residual is zero there) and flips between
  /// cavitated and pressurised from one cycle to the next: factor 0.69 at (2, 10) on 2049
  /// nodes, 0.04–0.2 held (docs/research/ehl-multigrid-rebuild.md, twelfth session).
  std::vector<char> cavitated_on_finer;
  /// What the film H was last computed from by update_film (the whole grid's deformation):
  /// valid until a window's film or a node's film is moved, or its FAS correction changes.
  struct FilmSource {
    std::vector<double> P;
    double H0 = 0.0;
    bool valid = false;
  } film_of;
  double g = 0.0;  ///< FAS right-hand side of the force balance
  double seconds = 0.0;
};

}  // namespace gearbench::ehl
