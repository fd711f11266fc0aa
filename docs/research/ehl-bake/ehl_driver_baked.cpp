#include <cstdio>
#include <cmath>
#include <cstdlib>
#include "ehl/line_contact_solver.h"
using namespace gearbench::ehl;
int main(int argc, char** argv) {
  double M = atof(argv[1]), L = atof(argv[2]);
  EhlOptions o;
  if (argc > 3) { int v = atoi(argv[3]); if (v > 20) o.nodes = v; else o.levels = v; }
  if (argc > 4) o.coarsest_nodes = atoi(argv[4]);
  if (argc > 5) o.omega_gauss_seidel = atof(argv[5]);
  if (argc > 6) o.omega_jacobi = atof(argv[6]);
  // argv[7] (ξ) has no meaning after the bake: the relaxation switch is κ (EhlOptions::relaxation_switch)
  if (argc > 8 && atof(argv[8]) > 0) { o.stop = StopRule::residual; o.tolerance = atof(argv[8]); }
  if (getenv("W")) o.cycle = CycleType::W;
  if (getenv("PRE")) o.pre_sweeps = atoi(getenv("PRE"));
  if (getenv("POST")) o.post_sweeps = atoi(getenv("POST"));
  LineContactProblem p(LineContactData::from_moes(M, L));
  auto r = LineContactSolver(p, o).try_solve();
  const auto& d = p.data();
  double to_moes = 1.0 / (d.reduced_radius * std::sqrt(d.viscosity * (d.u1 + d.u2) / (d.reduced_modulus * d.reduced_radius)));
  printf("M %g L %g: %s\n  %s\n  Hc %.6f Hmin %.6f  WU %.1f WU@err %.1f factor %.3f est %.3g\n  fmg:", M, L, r.message.c_str(), r.summary().c_str(),
         r.h_central * to_moes, r.h_min * to_moes, r.work_units, r.work_units_at_error, r.convergence_factor, r.error_estimate);
  for (size_t i = 0; i < r.fmg_nodes.size(); ++i) printf(" %g:%.5f/%.5f", r.fmg_nodes[i], r.fmg_H_c[i], r.fmg_H_min[i]);
  printf("\n  res:");
  for (double x : r.residual_history) printf(" %.1e", x);
  printf("\n");
}
