// Work–precision of GSL odeiv2 on gearbench's spur6 model (seed 003), against the fixed-step
// RK4 reference, on the workload of benchmarks/dynamics_benchmark.cpp (BM_WorkPrecision):
// 100 mesh cycles from the static state, 64 samples a cycle, errors max|v - ref| / p2p(ref)
// against reference::spur6_rk4 at 16384 steps a cycle (force: whole-cycle samples left out).
//
// The GSL march reproduces solvers/dynamics/march.cpp: the production right-hand side
// (Spur6Dynamics::derivative, 15 unknowns) with the pair set of the interval's midpoint,
// a restart (gsl_odeiv2_evolve_reset / step_reset) at every break time, keeping the last step
// size; GSL has no dense output, so every sample time is a step end.
//
// Build: see build.sh. Run: ./gslode [reps]
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/spur6_dynamics.h"
#include "ode/spur6_rk4.h"
#include "support/test_support.h"

using namespace gearbench;

namespace {

constexpr int cycles = 100;
constexpr int samples_per_cycle = 64;
constexpr int reference_steps = 16384;

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Response {
  std::vector<double> te, force;
  long steps = 0, rhs = 0;
  bool failed = false;
  std::string why;
};

struct Problem {
  geometry::GearPairGeometry geometry{testing_support::seed003_pair()};
  std::array<model::Material, 2> materials{model::Material{212e9, 0.289, 7850}, model::Material{212e9, 0.289, 7850}};
  model::OperatingPoint operating{996.0 * M_PI / 30.0, 50.0, 313.15, {0.0, 0.0}};
  std::unique_ptr<dynamics::Spur6Dynamics> d;
  double T = 0.0;
  Problem() {
    dynamics::Spur6Options o;
    o.runup_cycles = 0;
    o.record_cycles = cycles;
    d = std::make_unique<dynamics::Spur6Dynamics>(geometry, materials, operating, o);
    T = d->parameters().pbt / d->parameters().contact_speed;
  }

  // Exactly the benchmark's RK4 run (BM_WorkPrecision_RK4): reference/ode, its own RHS.
  Response rk4(int steps) const {
    const auto& p = d->parameters();
    const auto* dd = d.get();
    const reference::Spur6Parameters r{p.m1, p.m2, p.I1, p.I2, p.rb1, p.rb2, p.k_bearing, p.k_bearing,
                                       p.c_bearing, p.c_bearing, p.T1, p.mu, p.zeta_mesh, p.mean_mesh_stiffness,
                                       p.A, p.C, p.E, p.T1T2, p.pbt, p.contact_speed,
                                       [dd](double x) { return dd->mesh_excitation().pair_stiffness(x); }};
    reference::Spur6State y0{};
    const auto s0 = d->static_state();
    std::copy(s0.begin(), s0.begin() + 12, y0.begin());
    Response out{.steps = long{cycles} * steps, .rhs = 4L * cycles * steps};
    for (const auto& s : reference::spur6_rk4(r, y0, cycles * T, T / steps, T / samples_per_cycle)) {
      out.te.push_back(s.transmission_error);
      out.force.push_back(s.mesh_force);
    }
    out.te.resize(cycles * samples_per_cycle);
    out.force.resize(cycles * samples_per_cycle);
    return out;
  }

  // δ and F_m of the production model at a sample (F_m from the wheel's x equation:
  // m2·ẍ2 = F_m − c·ẋ2 − k·x2).
  void record(Response& out, double t, double t_mid, const double* y) const {
    const auto& p = d->parameters();
    double dy[15];
    d->derivative(t, t_mid, y, dy);
    out.te.push_back(y[0] + p.rb1 * y[2] - y[3] - p.rb2 * y[5]);
    out.force.push_back(p.m2 * dy[6 + 3] + p.c_bearing * y[6 + 3] + p.k_bearing * y[3]);
  }
};

struct RhsContext {
  const dynamics::Spur6Dynamics* d;
  double t_mid;
  long evals;
};

int gsl_rhs(double t, const double y[], double dydt[], void* params) {
  auto* c = static_cast<RhsContext*>(params);
  ++c->evals;
  c->d->derivative(t, c->t_mid, y, dydt);
  return GSL_SUCCESS;
}

// The production march's shape (solvers/dynamics/march.cpp) with a GSL step function
// `advance(t, target, y)` that must end exactly at target.
bool sample_stops = true;  // false: step only onto break times (timing bound; errors not comparable)

template <class Advance, class Restart>
Response march(const Problem& P, RhsContext& ctx, Advance&& advance, Restart&& restart) {
  Response out;
  const double t_end = cycles * P.T, dt_s = P.T / samples_per_cycle, tiny = 1e-9 * dt_s;
  const std::size_t samples = std::size_t{cycles} * samples_per_cycle;
  std::vector<double> breaks = P.d->break_times(0.0, t_end);
  breaks.push_back(t_end);
  std::vector<double> y = P.d->static_state();
  out.te.reserve(samples);
  out.force.reserve(samples);
  std::size_t next = 0;
  double a = 0.0;
  for (const double b : breaks) {
    ctx.t_mid = 0.5 * (a + b);
    restart();
    double t = a;
    for (; next < samples; ++next) {
      const double ts = static_cast<double>(next) * dt_s;
      if (ts > b + tiny) break;
      const double target = std::min(ts, b);
      if (!sample_stops && target < b - tiny) continue;
      if (target > t + tiny) {
        if (!advance(t, target, y.data(), out)) return out;
        t = target;
      }
      P.record(out, ts, ctx.t_mid, y.data());
    }
    if (b > t + tiny) {
      if (!advance(t, b, y.data(), out)) return out;
    }
    a = b;
  }
  return out;
}

// Adaptive GSL: stepper + standard control (D_i = atol + rtol·|y_i|, max norm) + evolve.
Response gsl_adaptive(const Problem& P, const gsl_odeiv2_step_type* type, double rtol, double atol) {
  RhsContext ctx{P.d.get(), 0.0, 0};
  gsl_odeiv2_system sys{gsl_rhs, nullptr, 15, &ctx};
  // The driver object only ties step, control and evolve together (msadams needs it); the
  // stepping is done by gsl_odeiv2_evolve_apply below.
  gsl_odeiv2_driver* drv = gsl_odeiv2_driver_alloc_standard_new(&sys, type, P.T / 1000.0, atol, rtol, 1.0, 0.0);
  gsl_odeiv2_step* s = drv->s;
  gsl_odeiv2_control* c = drv->c;
  gsl_odeiv2_evolve* e = drv->e;
  double h = P.T / 1000.0;  // first step; then kept across restarts, as production does
  long steps = 0;
  auto advance = [&](double t0, double t1, double* y, Response& out) {
    double t = t0;
    while (t < t1) {
      const int st = gsl_odeiv2_evolve_apply(e, c, s, &sys, &t, t1, &h, y);
      ++steps;
      if (st != GSL_SUCCESS || steps > 50000000) {
        out.failed = true;
        out.why = std::string("evolve status ") + gsl_strerror(st);
        return false;
      }
    }
    return true;
  };
  auto restart = [&] {
    gsl_odeiv2_evolve_reset(e);
    gsl_odeiv2_step_reset(s);
  };
  Response out = march(P, ctx, advance, restart);
  out.steps = steps;  // accepted steps (evolve_apply retries rejected ones inside)
  out.rhs = ctx.evals;
  gsl_odeiv2_driver_free(drv);
  return out;
}

// The same GSL stepper and control driven by a plain loop instead of gsl_odeiv2_evolve_apply:
// f at the step's end (dydt_out) is the next step's first stage (dydt_in), so an accepted
// rk8pd step costs 13 evaluations, not evolve's 14 (it re-evaluates f at the start of every
// call) and a rejected one 12.
Response gsl_loop(const Problem& P, const gsl_odeiv2_step_type* type, double rtol, double atol) {
  RhsContext ctx{P.d.get(), 0.0, 0};
  gsl_odeiv2_system sys{gsl_rhs, nullptr, 15, &ctx};
  gsl_odeiv2_step* s = gsl_odeiv2_step_alloc(type, 15);
  gsl_odeiv2_control* c = gsl_odeiv2_control_standard_new(atol, rtol, 1.0, 0.0);
  double h = P.T / 1000.0;
  long steps = 0, rejected = 0;
  double y0[15], yerr[15], din[15], dout[15];
  bool din_ok = false;
  auto advance = [&](double t0, double t1, double* y, Response& out) {
    double t = t0;
    while (t < t1) {
      const bool final = h >= t1 - t;
      double hh = final ? t1 - t : h;
      std::copy(y, y + 15, y0);
      if (!din_ok) {
        gsl_rhs(t, y, din, &ctx);
        din_ok = true;
      }
      int st = gsl_odeiv2_step_apply(s, t, hh, y, yerr, din, dout, &sys);
      if (st != GSL_SUCCESS) {
        out.failed = true;
        out.why = "step_apply failed";
        return false;
      }
      double hnew = hh;
      if (gsl_odeiv2_control_hadjust(c, s, y, yerr, dout, &hnew) == GSL_ODEIV_HADJ_DEC) {
        std::copy(y0, y0 + 15, y);
        h = hnew;
        if (++rejected > 10000000 || h < 1e-15 * P.T) {
          out.failed = true;
          out.why = "step size underflow";
          return false;
        }
        continue;
      }
      ++steps;
      t = final ? t1 : t + hh;
      std::copy(dout, dout + 15, din);
      if (!final) h = hnew;
    }
    return true;
  };
  auto restart = [&] {
    gsl_odeiv2_step_reset(s);
    din_ok = false;
  };
  Response out = march(P, ctx, advance, restart);
  out.steps = steps;
  out.rhs = ctx.evals;
  if (std::getenv("GSLODE_VERBOSE")) std::fprintf(stderr, "  rejected/cycle %.1f\n", static_cast<double>(rejected) / cycles);
  gsl_odeiv2_control_free(c);
  gsl_odeiv2_step_free(s);
  return out;
}

// Fixed-step GSL stepper (no error control): equal steps of at most T/n between the
// breakpoints (breaks and sample times), as reference/ode does for RK4.
Response gsl_fixed(const Problem& P, const gsl_odeiv2_step_type* type, int n) {
  RhsContext ctx{P.d.get(), 0.0, 0};
  gsl_odeiv2_system sys{gsl_rhs, nullptr, 15, &ctx};
  gsl_odeiv2_step* s = gsl_odeiv2_step_alloc(type, 15);
  double yerr[15];
  const double dt = P.T / n;
  long steps = 0;
  auto advance = [&](double t0, double t1, double* y, Response&) {
    const auto k = static_cast<long>(std::max(1.0, std::ceil((t1 - t0) / dt - 1e-9)));
    const double h = (t1 - t0) / static_cast<double>(k);
    for (long i = 0; i < k; ++i) gsl_odeiv2_step_apply(s, t0 + static_cast<double>(i) * h, h, y, yerr, nullptr, nullptr, &sys);
    steps += k;
    return true;
  };
  auto restart = [&] { gsl_odeiv2_step_reset(s); };
  Response out = march(P, ctx, advance, restart);
  out.steps = steps;
  out.rhs = ctx.evals;
  gsl_odeiv2_step_free(s);
  return out;
}

// Classical RK4 on the production right-hand side in the same march (to price the RHS).
Response rk4_production(const Problem& P, int n) {
  RhsContext ctx{P.d.get(), 0.0, 0};
  const double dt = P.T / n;
  long steps = 0;
  auto advance = [&](double t0, double t1, double* y, Response&) {
    const auto k = static_cast<long>(std::max(1.0, std::ceil((t1 - t0) / dt - 1e-9)));
    const double h = (t1 - t0) / static_cast<double>(k);
    double k1[15], k2[15], k3[15], k4[15], z[15];
    for (long i = 0; i < k; ++i) {
      const double t = t0 + static_cast<double>(i) * h;
      gsl_rhs(t, y, k1, &ctx);
      for (int j = 0; j < 15; ++j) z[j] = y[j] + 0.5 * h * k1[j];
      gsl_rhs(t + 0.5 * h, z, k2, &ctx);
      for (int j = 0; j < 15; ++j) z[j] = y[j] + 0.5 * h * k2[j];
      gsl_rhs(t + 0.5 * h, z, k3, &ctx);
      for (int j = 0; j < 15; ++j) z[j] = y[j] + h * k3[j];
      gsl_rhs(t + h, z, k4, &ctx);
      for (int j = 0; j < 15; ++j) y[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    }
    steps += k;
    return true;
  };
  Response out = march(P, ctx, advance, [] {});
  out.steps = steps;
  out.rhs = ctx.evals;
  return out;
}

// max |v − ref| / p2p(scale) over the samples (scale: the RK4-16384 reference, as the benchmark).
double relative_error(const std::vector<double>& v, const std::vector<double>& ref, bool skip_mesh_starts,
                      const std::vector<double>* scale = nullptr) {
  if (v.size() != ref.size()) return INFINITY;
  const auto [lo, hi] = std::minmax_element(scale ? scale->begin() : ref.begin(), scale ? scale->end() : ref.end());
  double worst = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!skip_mesh_starts || i % samples_per_cycle != 0) worst = std::max(worst, std::abs(v[i] - ref[i]));
  return worst / (*hi - *lo);
}

int reps = 5;

// Runs f `reps` times, returns the last response and the minimum CPU time [ms].
std::pair<Response, double> timed(const std::function<Response()>& f) {
  Response r;
  double best = INFINITY;
  for (int i = 0; i < reps; ++i) {
    const double t0 = cpu_seconds();
    r = f();
    best = std::min(best, cpu_seconds() - t0);
    if (r.failed) break;
  }
  return {r, 1e3 * best};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) reps = std::atoi(argv[1]);
  const std::string only = argc > 2 ? argv[2] : "";
  gsl_set_error_handler_off();
  const Problem P;
  const Response ref = P.rk4(reference_steps);
  const Response ref8 = gsl_fixed(P, gsl_odeiv2_step_rk8pd, 2048);  // tight: production RHS, 8th order
  const Response ref8b = gsl_fixed(P, gsl_odeiv2_step_rk8pd, 4096);
  std::printf("# spur6 seed 003, %d cycles, T = %.6e s, %zu samples, ref RK4 %d steps/cycle\n", cycles, P.T,
              ref.te.size(), reference_steps);
  std::printf("# ref8 = rk8pd fixed 2048/cycle on the production RHS: vs rk8pd 4096 te %.2e force %.2e; "
              "vs RK4-16384 te %.2e force %.2e\n",
              relative_error(ref8.te, ref8b.te, false), relative_error(ref8.force, ref8b.force, true),
              relative_error(ref.te, ref8.te, false, &ref.te), relative_error(ref.force, ref8.force, true, &ref.force));
  std::printf("%-14s %-8s %10s %12s %10s %10s %10s %10s %9s %9s\n", "method", "param", "steps/cyc", "rhs/cyc",
              "te_err", "force_err", "te_err8", "force_err8", "cpu_ms", "ns/rhs");
  auto line = [&](const char* method, const std::string& param, const std::pair<Response, double>& rt) {
    const auto& [r, ms] = rt;
    if (r.failed) {
      std::printf("%-14s %-8s FAILED (%s)\n", method, param.c_str(), r.why.c_str());
      std::fflush(stdout);
      return;
    }
    const bool full = r.te.size() == ref.te.size();
    std::printf("%-14s %-8s %10.1f %12.1f %10.2e %10.2e %10.2e %10.2e %9.1f %9.1f\n", method, param.c_str(),
                static_cast<double>(r.steps) / cycles, static_cast<double>(r.rhs) / cycles,
                full ? relative_error(r.te, ref.te, false) : NAN, full ? relative_error(r.force, ref.force, true) : NAN,
                full ? relative_error(r.te, ref8.te, false, &ref.te) : NAN,
                full ? relative_error(r.force, ref8.force, true, &ref.force) : NAN, ms,
                1e6 * ms / static_cast<double>(r.rhs));
    std::fflush(stdout);
  };
  auto want = [&](const std::string& k) { return only.empty() || only.find(k) != std::string::npos; };

  if (want("rk4"))
    for (int n : {1024, 2048, 2896, 4096, 8192, 16384}) line("RK4(ref/ode)", std::to_string(n), timed([&] { return P.rk4(n); }));
  if (want("rk4p"))
    for (int n : {2048, 4096, 8192}) line("RK4(prodRHS)", std::to_string(n), timed([&] { return rk4_production(P, n); }));
  if (want("rk8fix"))
    for (int n : {64, 96, 128, 192, 256, 384, 512, 768})
      line("rk8pd(fixed)", std::to_string(n), timed([&] { return gsl_fixed(P, gsl_odeiv2_step_rk8pd, n); }));
  struct M {
    const char* name;
    const gsl_odeiv2_step_type* type;
  };
  for (const M m : {M{"rk8pd", gsl_odeiv2_step_rk8pd}, M{"rkck", gsl_odeiv2_step_rkck}, M{"rkf45", gsl_odeiv2_step_rkf45},
                    M{"msadams", gsl_odeiv2_step_msadams}}) {
    if (!want(m.name)) continue;
    const int kmax = m.type == gsl_odeiv2_step_rk8pd ? 10 : (m.type == gsl_odeiv2_step_msadams ? 10 : 9);
    for (int k = 4; k <= kmax; ++k) {
      const double rtol = std::pow(10.0, -k);
      char param[16];
      std::snprintf(param, sizeof param, "1e-%d", k);
      line(m.name, param, timed([&] { return gsl_adaptive(P, m.type, rtol, 1e-6 * rtol); }));
    }
  }
  for (const M m : {M{"rk8pd", gsl_odeiv2_step_rk8pd}, M{"rkck", gsl_odeiv2_step_rkck}}) {
    if (!want(std::string(m.name) + "/loop")) continue;
    for (int k = 4; k <= (m.type == gsl_odeiv2_step_rk8pd ? 10 : 9); ++k) {
      const double rtol = std::pow(10.0, -k);
      line((std::string(m.name) + "/loop").c_str(), "1e-" + std::to_string(k),
           timed([&] { return gsl_loop(P, m.type, rtol, 1e-6 * rtol); }));
    }
  }
  if (want("nosample")) {  // rk8pd stepping onto break times only: what the 64 sample stops cost
    sample_stops = false;
    for (int k : {5, 6, 7}) {
      const double rtol = std::pow(10.0, -k);
      line("rk8pd(nosamp)", "1e-" + std::to_string(k), timed([&] { return gsl_adaptive(P, gsl_odeiv2_step_rk8pd, rtol, 1e-6 * rtol); }));
    }
    sample_stops = true;
  }
  return 0;
}
