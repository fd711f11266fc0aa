// The thirty-ninth session's measurements of the EHL multigrid's factors (research log,
// "Thirty-ninth session"; ../ehl-model.md, "Smoothing and two-grid factors"), on the operators
// linearised at a converged solution through the public warm-start API:
//   ehl_factors M L NODES smooth    one sweep's amplification of the high modes of 32-node windows
//                                   along the pressurised zone (env WIN, NWIN: window, windows);
//   ehl_factors M L NODES twogrid   the eigenvalues of one cycle on NODES and one coarser grid;
//   ehl_factors M L NODES mg        the same with the default hierarchy.
// Env OMJ sets ω_J; FMODES=1 adds each mode's weight in H_min, H_c and H0 (WT: the weight
// threshold, 1e-2). The checks in verification/checks/ehl_smoothing_checks.cpp measure the
// same factors (power iteration instead of full matrices). Build against a tree's libraries:
//   g++ -O2 -std=c++20 -I<tree>/solvers -I/usr/include/eigen3 ehl_factors.cpp
//     <tree>/build/default/solvers/libgearbench_solvers.a <tree>/build/default/solvers/libgearbench_model.a
//     -lfftw3 -lgsl -lgslcblas -llapack -lblas -lfmt
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <vector>
#include <algorithm>
#include <numbers>
#include <complex>
#include <string>
#include <Eigen/Dense>
#include "ehl/line_contact_solver.h"
#include "ehl/fas_multigrid.h"
using namespace gearbench::ehl;
using Vec = std::vector<double>;

int main(int argc, char** argv) {
  const double M = atof(argv[1]), L = atof(argv[2]);
  const int n = atoi(argv[3]);
  const char* what = argc > 4 ? argv[4] : "smooth";
  LineContactProblem p(LineContactData::from_moes(M, L));
  EhlOptions o; o.nodes = n; o.stop = StopRule::residual; o.tolerance = 1e-11; o.max_cycles = 200;
  auto ref = FasMultigrid(p, o, ContactState{}).solve();
  if (!ref.converged) { printf("ref not converged: %s\n", ref.message.c_str()); return 1; }
  const double h = ref.X[1] - ref.X[0];
  size_t first = 0, last = 0;
  for (size_t i = 1; i + 1 < ref.P.size(); ++i) if (ref.P[i] > 0) { if (!first) first = i; last = i; }
  if (std::string(what) == "smooth") {
    EhlOptions s; s.nodes = n; s.single_grid = true; s.stop = StopRule::residual; s.tolerance = 1e-300; s.max_cycles = 1;
    if (getenv("OMJ")) s.omega_jacobi = atof(getenv("OMJ"));
    s.x_in = o.domain_in(p); s.x_out = o.domain_out(p);
    auto sweep = [&](const Vec& P) { return FasMultigrid(p, s, ContactState{}).solve(WarmStart{P, ref.H0}).P; };
    const Vec g0 = sweep(ref.P);
    const int W = atoi(getenv("WIN") ? getenv("WIN") : "32"), inner = 4;
    const double pmax = *std::max_element(ref.P.begin(), ref.P.end());
    const int windows = atoi(getenv("NWIN") ? getenv("NWIN") : "24");
    printf("# (M %g, L %g) %d nodes, h %.4g, pressurised %zu..%zu (X %.3f..%.3f)\n", M, L, n, h, first, last, ref.X[first], ref.X[last]);
    printf("# X_c  eps/h^2  P  mu_max  mu_mean  (high modes k = W/2+1..W of a %d-node window)\n", W);
    for (int w = 0; w < windows; ++w) {
      const size_t a = first + 2 + (size_t)((double)w / (windows - 1) * (double)(last - first - W - 4));
      double mu_max = 0, mu_sum = 0; int cnt = 0;
      for (int k = W / 2 + 1; k <= W; ++k) {
        Vec P = ref.P; Vec e(W);
        const double d = 1e-6 * pmax;
        for (int j = 0; j < W; ++j) { e[j] = std::sin(k * std::numbers::pi * (j + 1) / (W + 1)); P[a + j] += d * e[j]; }
        bool ok = true; for (int j = 0; j < W; ++j) ok = ok && P[a + j] > 0;
        if (!ok) continue;
        const Vec g = sweep(P);
        double num = 0, den = 0;
        for (int j = inner; j < W - inner; ++j) { const double se = (g[a + j] - g0[a + j]) / d; num += se * se; den += e[j] * e[j]; }
        const double mu = std::sqrt(num / den);
        mu_max = std::max(mu_max, mu); mu_sum += mu; ++cnt;
      }
      const size_t c = a + W / 2;
      const double eps = p.density(ref.P[c]) * std::pow(ref.H[c], 3) / (std::exp(p.log_viscosity(ref.P[c])) * p.lambda());
      printf("%8.4f %10.3e %8.4f %7.3f %7.3f\n", ref.X[c], eps / (h * h), ref.P[c], mu_max, cnt ? mu_sum / cnt : NAN);
    }
    return 0;
  }
  // Iteration matrix of one cycle over the pressurised nodes and H0.
  EhlOptions c = o; c.max_cycles = 1; c.tolerance = 1e-300;
  if (std::string(what) == "twogrid") c.coarsest_nodes = (n - 1) / 2 + 1;
  if (getenv("NOACC")) c.acceleration_depth = 0;
  if (getenv("OMJ")) c.omega_jacobi = atof(getenv("OMJ"));
  std::vector<size_t> idx;
  for (size_t i = 1; i + 1 < ref.P.size(); ++i) if (ref.P[i] > 0) idx.push_back(i);
  const size_t m = idx.size() + 1;
  auto G = [&](const Vec& P, double H0) {
    auto r = FasMultigrid(p, c, ContactState{}).solve(WarmStart{P, H0});
    Eigen::VectorXd v(m);
    for (size_t k = 0; k < idx.size(); ++k) v(k) = r.P[idx[k]];
    v(m - 1) = r.H0;
    return std::pair{v, r.levels};
  };
  auto [g0, levels] = G(ref.P, ref.H0);
  Eigen::MatrixXd T(m, m);
  for (size_t j = 0; j < m; ++j) {
    Vec P = ref.P; double H0 = ref.H0, d;
    if (j + 1 < m) { d = 1e-6 * std::max(1e-3, P[idx[j]]); P[idx[j]] += d; } else { d = 1e-7; H0 += d; }
    T.col(j) = (G(P, H0).first - g0) / d;
  }
  Eigen::EigenSolver<Eigen::MatrixXd> es(T, true);
  if (getenv("FMODES")) {
    // film sensitivity: dH_i = dH0 - (D/pi) sum_j K_ij dP_j, K_ij = int over cell j of ln|X_i - X'|
    const double D = p.deformation_factor();
    auto F = [](double x) { return x == 0 ? 0.0 : x * std::log(std::abs(x)) - x; };
    auto K = [&](size_t i, size_t j) { const double a = ref.X[j] - h / 2, b = ref.X[j] + h / 2; return F(ref.X[i] - a) - F(ref.X[i] - b); };
    // check the kernel: H_i - H_0node differences
    size_t imin = 0; for (size_t i = 1; i + 1 < ref.H.size(); ++i) if (ref.P[i] > 0 || true) if (ref.H[i] < ref.H[imin] && ref.X[i] > 0) imin = i;
    size_t ic = std::lower_bound(ref.X.begin(), ref.X.end(), 0.0) - ref.X.begin();
    auto Hof = [&](size_t i) { double s = ref.H0 + 0.5 * ref.X[i] * ref.X[i]; for (size_t j = 0; j < ref.P.size(); ++j) s -= D / M_PI * K(i, j) * ref.P[j]; return s; };
    printf("# kernel check: H[imin] %.6e vs %.6e, H[ic] %.6e vs %.6e\n", ref.H[imin], Hof(imin), ref.H[ic], Hof(ic));
    Eigen::MatrixXcd V = es.eigenvectors();
    Eigen::MatrixXcd Wl = V.inverse();
    auto fvec = [&](size_t i) { Eigen::VectorXd f(m); for (size_t k = 0; k < idx.size(); ++k) f(k) = -D / M_PI * K(i, idx[k]); f(m - 1) = 1.0; return f; };
    struct Fn { const char* name; Eigen::VectorXd f; };
    std::vector<Fn> fns = {{"H_min", fvec(imin)}, {"H_c", fvec(ic)}, {"H0", Eigen::VectorXd::Unit(m, m - 1)}};
    for (auto& fn : fns) {
      std::vector<std::pair<double, int>> w;  // weight of mode k into f
      double wmax = 0;
      for (int k = 0; k < (int)m; ++k) { double c = std::abs(fn.f.cast<std::complex<double>>().dot(V.col(k))) * Wl.row(k).norm(); w.push_back({c, k}); wmax = std::max(wmax, c); }
      // largest |lambda| among modes with weight > 1e-3 wmax
      std::vector<std::pair<double, int>> top;
      for (auto& [c, k] : w) if (c > (getenv("WT") ? atof(getenv("WT")) : 1e-2) * wmax) top.push_back({std::abs(es.eigenvalues()(k)), k});
      std::sort(top.rbegin(), top.rend());
      printf("  %s: ", fn.name);
      for (int t = 0; t < 5 && t < (int)top.size(); ++t) {
        int k = top[t].second; Eigen::VectorXcd v = V.col(k); int am = 0; for (int q = 0; q < (int)m; ++q) if (std::abs(v(q)) > std::abs(v(am))) am = q;
        double c = 0; for (auto& pr : w) if (pr.second == k) c = pr.first;
        printf("|l| %.3f (w %.2f, X %.3f)  ", top[t].first, c / wmax, am + 1 == (int)m ? NAN : ref.X[idx[am]]);
      }
      printf("\n");
    }
  }
  std::vector<std::pair<double, int>> ev;
  for (int k = 0; k < (int)m; ++k) ev.push_back({std::abs(es.eigenvalues()(k)), k});
  std::sort(ev.rbegin(), ev.rend());
  printf("# %s (M %g, L %g) %d nodes, %d levels, %zu unknowns\n", what, M, L, n, levels, m);
  int fam = 0; for (auto& e : ev) if (std::abs(e.first - 0.3606) < 0.003) ++fam;
  printf("  %d eigenvalues within 0.003 of 0.361\n", fam);
  int shown = 0;
  for (int t = 0; t < (int)m && shown < 6; ++t) {
    if (std::abs(ev[t].first - 0.3606) < 0.003) continue; ++shown;
    const int k = ev[t].second;
    Eigen::VectorXcd v = es.eigenvectors().col(k);
    int am = 0; for (int q = 0; q < (int)m; ++q) if (std::abs(v(q)) > std::abs(v(am))) am = q;
    printf("  |lambda| %.3f (%.3f%+.3fi) peak %s X %.3f\n", ev[t].first, es.eigenvalues()(k).real(), es.eigenvalues()(k).imag(),
           am + 1 == (int)m ? "H0" : "P", am + 1 == (int)m ? NAN : ref.X[idx[am]]);
  }
}
