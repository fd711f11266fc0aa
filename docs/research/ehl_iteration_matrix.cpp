// Linearised iteration matrix of one multigrid cycle around the converged solution:
// column j = (G(x* + δ e_j) − G(x*))/δ over the pressurised nodes and H0; its eigenvalues are
// the asymptotic convergence factors, its eigenvectors show where the slow modes live.
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <vector>
#include <algorithm>
#include <Eigen/Dense>
#include "ehl/line_contact_solver.h"
#include "ehl/fas_multigrid.h"
using namespace gearbench::ehl;
int main(int argc, char** argv) {
  double M = atof(argv[1]), L = atof(argv[2]); int n = atoi(argv[3]); int nc = atoi(argv[4]);
  LineContactProblem p(LineContactData::from_moes(M, L));
  EhlOptions o; o.nodes = n; o.coarsest_nodes = nc; o.stop = StopRule::residual; o.tolerance = 1e-14; o.max_cycles = 600;
  if (getenv("PRE")) o.pre_sweeps = atoi(getenv("PRE"));
  if (getenv("POST")) o.post_sweeps = atoi(getenv("POST"));
  if (getenv("W")) o.cycle = CycleType::W;
  if (getenv("XI")) o.xi_threshold = atof(getenv("XI"));
  if (getenv("OMJ")) o.omega_jacobi = atof(getenv("OMJ"));
  if (getenv("OMGS")) o.omega_gauss_seidel = atof(getenv("OMGS"));
  EhlOptions oref = o;
  if (getenv("REFXI")) oref.xi_threshold = atof(getenv("REFXI"));
  auto ref = FasMultigrid(p, oref, ContactState{}).solve();
  printf("ref: %s\n", ref.message.c_str());
  std::vector<size_t> idx;
  for (size_t i = 1; i + 1 < ref.P.size(); ++i) if (ref.P[i] > 0) idx.push_back(i);
  const size_t m = idx.size() + 1;
  o.max_cycles = 1; o.tolerance = 1e-300;
  auto G = [&](const std::vector<double>& P, double H0) {
    auto r = FasMultigrid(p, o, ContactState{}).solve(WarmStart{P, H0});
    Eigen::VectorXd v(m);
    for (size_t k = 0; k < idx.size(); ++k) v(k) = r.P[idx[k]];
    v(m - 1) = r.H0;
    return v;
  };
  Eigen::VectorXd g0 = G(ref.P, ref.H0);
  Eigen::VectorXd x0(m); for (size_t k = 0; k < idx.size(); ++k) x0(k) = ref.P[idx[k]]; x0(m-1) = ref.H0;
  printf("fixed-point defect |G(x*)-x*| = %.2e\n", (g0 - x0).cwiseAbs().maxCoeff());
  Eigen::MatrixXd T(m, m);
  for (size_t j = 0; j < m; ++j) {
    std::vector<double> P = ref.P; double H0 = ref.H0;
    double d;
    if (j + 1 < m) { d = 1e-6 * std::max(1e-3, P[idx[j]]); P[idx[j]] += d; } else { d = 1e-7; H0 += d; }
    T.col(j) = (G(P, H0) - g0) / d;
  }
  Eigen::EigenSolver<Eigen::MatrixXd> es(T);
  std::vector<std::pair<double, int>> ev;
  for (int k = 0; k < (int)m; ++k) ev.push_back({std::abs(es.eigenvalues()(k)), k});
  std::sort(ev.rbegin(), ev.rend());
  size_t sp = 0; for (size_t i = 0; i < ref.P.size(); ++i) if (ref.P[i] > ref.P[sp]) sp = i;
  printf("nodes %d, pressurised %zu..%zu, spike at %zu (X %.3f), H0 %.5f\n", n, idx.front(), idx.back(), sp, ref.X[sp], ref.H0);
  if (getenv("SHOW")) {
    int k = ev[0].second;
    Eigen::VectorXcd v = es.eigenvectors().col(k);
    double eps_scale = 1.0;
    for (size_t q = 0; q < idx.size(); ++q) if (idx[q] >= 212 * (size_t)n / 257 && idx[q] <= 236 * (size_t)n / 257)
      printf("   node %zu X %.3f P %.4f H %.5f |v| %.3f arg %.2f\n", idx[q], ref.X[idx[q]], ref.P[idx[q]], ref.H[idx[q]], std::abs(v(q)), std::arg(v(q)));
    (void)eps_scale;
  }
  for (int t = 0; t < (getenv("NEV") ? atoi(getenv("NEV")) : 8); ++t) {
    int k = ev[t].second;
    Eigen::VectorXcd v = es.eigenvectors().col(k);
    int am = 0; for (int q = 0; q < (int)m; ++q) if (std::abs(v(q)) > std::abs(v(am))) am = q;
    // spread: how many components hold 90% of the norm
    std::vector<double> a(m); for (int q = 0; q < (int)m; ++q) a[q] = std::norm(v(q));
    std::vector<double> s = a; std::sort(s.rbegin(), s.rend()); double tot = 0; for (double x : s) tot += x;
    double acc = 0; int cnt = 0; while (acc < 0.9 * tot) acc += s[cnt++];
    printf("  |λ| %.3f (λ = %.3f%+.3fi)  peak at %s %s, 90%% of the norm on %d components, H0 share %.2f\n", ev[t].first,
           es.eigenvalues()(k).real(), es.eigenvalues()(k).imag(),
           am + 1 == (int)m ? "H0" : std::to_string(idx[am]).c_str(), am + 1 == (int)m ? "" : ("X " + std::to_string(ref.X[idx[am]])).c_str(), cnt, a[m-1]/tot);
  }
}
