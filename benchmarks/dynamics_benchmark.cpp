// Dynamics benchmarks: the work–precision study of the integrators (docs/dynamics-model.md,
// "Integrators: work–precision") and the production default against the fixed-step RK4
// reference side by side.
//
// Two problems, each 100 mesh cycles from the static state, sampled 64 times a cycle:
// - spur6: seed 003's pair (20/25, m 2 mm), 996 rpm, 50 N·m, μ 0.06;
// - herringbone12: seed 000's pair (17/44, m_n 6 mm, β 24.43°), 2000 rpm, 309 N·m, μ 0.05,
//   mesh-in impacts.
// Error of a run: max |δ − δ_ref| / p2p(δ_ref) and max |F − F_ref| / p2p(F_ref) over all
// samples (both halves for herringbone12), δ_ref and F_ref from the RK4 reference at 16384
// steps a cycle (order 4: ~1/16 of the error at 8192, below 1e-8 of the peak-to-peak).
//
// BM_WorkPrecision/<model>/<method>/<rtol exponent> and BM_WorkPrecision_RK4/<model>/<steps a
// cycle> report te_error and force_error with their time; BM_DefaultVsRK4/<model> times the
// default integrator and RK4 at the step that reaches the same accuracy in one loop and
// reports the speed-up.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <map>
#include <string>

#include "dynamics/herringbone12_dynamics.h"
#include "dynamics/spur6_dynamics.h"
#include "ode/herringbone12_rk4.h"
#include "ode/spur6_rk4.h"
#include "support/test_support.h"

namespace {

using namespace gearbench;

constexpr int cycles = 100;
constexpr int reference_steps = 16384;  ///< RK4 steps a cycle of the runs errors are measured against

/// The sampled transmission error and mesh force of a run (halves one after the other).
struct Response {
  std::vector<double> te, force;
  long steps = 0, rhs_evaluations = 0;
};

/// atol = 1e-6·rtol: the deflections are micrometres, so the absolute tolerance keeps the
/// same relative meaning for them as rtol has for the larger components.
dynamics::IntegratorOptions integrator(dynamics::IntegratorMethod method, double rtol) {
  dynamics::IntegratorOptions o;
  o.method = method;
  o.relative_tolerance = rtol;
  o.absolute_tolerance = 1e-6 * rtol;
  return o;
}

struct SpurProblem {
  geometry::GearPairGeometry geometry{testing_support::seed003_pair()};
  std::array<model::Material, 2> materials{model::Material{212e9, 0.289, 7850}, model::Material{212e9, 0.289, 7850}};
  model::OperatingPoint operating{996.0 * M_PI / 30.0, 50.0, 313.15, {0.0, 0.0}};

  [[nodiscard]] dynamics::Spur6Options options(const dynamics::IntegratorOptions& i) const {
    dynamics::Spur6Options o;
    o.runup_cycles = 0;
    o.record_cycles = cycles;
    o.integrator = i;
    return o;
  }
  /// A function running production with `i` (the model built outside the timed part, as for rk4).
  [[nodiscard]] std::function<Response()> production(const dynamics::IntegratorOptions& i) const {
    auto d = std::make_shared<dynamics::Spur6Dynamics>(geometry, materials, operating, options(i));
    return [d] {
      const auto r = d->solve();
      return Response{r.transmission_error, r.mesh_force, r.steps, r.rhs_evaluations};
    };
  }
  /// A function running RK4 at `steps` a cycle (the set-up outside the timed part).
  [[nodiscard]] std::function<Response()> rk4(int steps) const {
    auto d = std::make_shared<dynamics::Spur6Dynamics>(geometry, materials, operating, options({}));
    return [d, steps] {
      const auto& p = d->parameters();
      const reference::Spur6Parameters r{p.m1, p.m2, p.I1, p.I2, p.rb1, p.rb2, p.k_bearing, p.k_bearing,
                                         p.c_bearing, p.c_bearing, p.T1, p.mu, p.zeta_mesh, p.mean_mesh_stiffness,
                                         p.A, p.C, p.E, p.T1T2, p.pbt, p.contact_speed,
                                         [&d](double x) { return d->mesh_excitation().pair_stiffness(x); }};
      const double T = p.pbt / p.contact_speed;
      reference::Spur6State y0{};
      const auto s0 = d->static_state();
      std::copy(s0.begin(), s0.begin() + 12, y0.begin());
      Response out{.steps = long{cycles} * steps, .rhs_evaluations = 4L * cycles * steps};
      for (const auto& s : reference::spur6_rk4(r, y0, cycles * T, T / steps, T / 64.0)) {
        out.te.push_back(s.transmission_error);
        out.force.push_back(s.mesh_force);
      }
      out.te.resize(cycles * 64);  // production records [0, 100 T)
      out.force.resize(cycles * 64);
      return out;
    };
  }
};

struct HerringboneProblem {
  model::GearPair pair = [] {
    model::GearPair g;
    g.teeth = {17, 44};
    g.normal_module = 6e-3;
    g.normal_pressure_angle = 18.334317 * M_PI / 180.0;
    g.helix_angle = 24.43 * M_PI / 180.0;
    g.face_width = 55e-3;
    g.herringbone = model::Herringbone{58e-3};
    return g;
  }();
  geometry::GearPairGeometry geometry{pair};
  std::array<model::Material, 2> materials{model::Material{206e9, 0.3, 7850}, model::Material{206e9, 0.3, 7850}};
  model::OperatingPoint operating{2000.0 * M_PI / 30.0, 309.09, 313.15, {0.0, 0.0}};

  [[nodiscard]] dynamics::Herringbone12Options options(const dynamics::IntegratorOptions& i) const {
    dynamics::Herringbone12Options o;
    o.mesh.friction.friction_coefficient = 0.05;
    o.mesh_in_impact = true;  // the study's workload: restarts at every pulse (docs, "Integrators")
    o.impact_held_velocity = true;  // the pulses of eq. 6 as printed, as when the study was recorded
    o.runup_cycles = 0;
    o.record_cycles = cycles;
    o.integrator = i;
    return o;
  }
  [[nodiscard]] std::function<Response()> production(const dynamics::IntegratorOptions& i) const {
    auto d = std::make_shared<dynamics::Herringbone12Dynamics>(geometry, materials, operating, options(i));
    return [d] {
      const auto r = d->solve();
      Response out{.steps = r.steps, .rhs_evaluations = r.rhs_evaluations};
      for (std::size_t h = 0; h < 2; ++h) {
        out.te.insert(out.te.end(), r.transmission_error[h].begin(), r.transmission_error[h].end());
        out.force.insert(out.force.end(), r.mesh_force[h].begin(), r.mesh_force[h].end());
      }
      return out;
    };
  }
  [[nodiscard]] std::function<Response()> rk4(int steps) const {
    auto d = std::make_shared<dynamics::Herringbone12Dynamics>(geometry, materials, operating, options({}));
    return [d, steps] {
      const auto& p = d->parameters();
      const auto& mesh = d->mesh();
      const reference::Herringbone12Parameters r{
          p.m_p, p.m_g, p.I_p, p.I_g, p.R_p, p.R_g, p.beta_b, p.k_radial, p.c_radial, p.k_axial_p, p.c_axial_p,
          p.k_axial_g, p.c_axial_g, p.k_groove, p.c_groove, p.k_twist, p.c_twist, p.T_p, p.T_g,
          p.mean_mesh_stiffness, p.mesh_damping, p.impact_force, p.impact_duration, p.period, p.clock_offset,
          [&mesh](double tau) {
            const auto m = mesh.at(tau, tau);
            return reference::HalfMeshValue{m.stiffness, m.chi_pinion, m.chi_wheel};
          }};
      reference::Herringbone12State y0{};
      const auto s0 = d->static_state();
      std::copy(s0.begin(), s0.begin() + 24, y0.begin());
      const auto run = reference::herringbone12_rk4(r, y0, cycles * p.period, p.period / steps, p.period / 64.0);
      Response out{.steps = long{cycles} * steps, .rhs_evaluations = 4L * cycles * steps};
      for (std::size_t h = 0; h < 2; ++h)
        for (const auto& s : run) {
          out.te.push_back(s.delta[h]);
          out.force.push_back(s.force[h]);
        }
      return out;
    };
  }
};

const SpurProblem& spur() {
  static const SpurProblem p;
  return p;
}
const HerringboneProblem& herringbone() {
  static const HerringboneProblem p;
  return p;
}

/// The tight-tolerance run errors are measured against, computed once per model.
const Response& reference_run(const std::string& model) {
  static std::map<std::string, Response> runs;
  if (!runs.contains(model)) runs[model] = (model == "spur6" ? spur().rk4(reference_steps) : herringbone().rk4(reference_steps))();
  return runs[model];
}

/// max |v − ref| / p2p(ref) over the samples; with `skip_mesh_starts` the samples at whole
/// mesh cycles (every 64th) are left out: a pair enters exactly there and the force jumps,
/// so production (the pair set of the interval ending there) and RK4 (the pair set starting
/// there) each give one side of the jump.
double relative_error(const std::vector<double>& v, const std::vector<double>& ref, bool skip_mesh_starts = false) {
  if (v.size() != ref.size()) return INFINITY;
  const auto [lo, hi] = std::minmax_element(ref.begin(), ref.end());
  double worst = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!skip_mesh_starts || i % 64 != 0) worst = std::max(worst, std::abs(v[i] - ref[i]));
  return worst / (*hi - *lo);
}

void report_errors(benchmark::State& state, const std::string& model, const Response& r) {
  const auto& ref = reference_run(model);
  state.counters["te_error"] = relative_error(r.te, ref.te);
  state.counters["force_error"] = relative_error(r.force, ref.force, true);
  state.counters["steps_per_cycle"] = static_cast<double>(r.steps) / cycles;
  state.counters["rhs_per_cycle"] = static_cast<double>(r.rhs_evaluations) / cycles;
}

void work_precision(benchmark::State& state, const std::string& model, dynamics::IntegratorMethod method) {
  const auto options = integrator(method, std::pow(10.0, -static_cast<double>(state.range(0))));
  reference_run(model);
  const auto run = model == "spur6" ? spur().production(options) : herringbone().production(options);
  Response r;
  try {
    for (auto _ : state) r = run();
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());  // a tolerance the method cannot meet is a point of the study
    return;
  }
  report_errors(state, model, r);
}

void work_precision_rk4(benchmark::State& state, const std::string& model) {
  const auto run = model == "spur6" ? spur().rk4(static_cast<int>(state.range(0)))
                                    : herringbone().rk4(static_cast<int>(state.range(0)));
  reference_run(model);
  Response r;
  for (auto _ : state) r = run();
  report_errors(state, model, r);
}

/// The default integrator and RK4 at `rk4_steps` a cycle, alternately in one loop; both on
/// a model built beforehand (the mesh excitation is their common input), so that the ratio is
/// that of the integrations.
void default_vs_rk4(benchmark::State& state, const std::string& model, int rk4_steps) {
  const auto run = model == "spur6" ? spur().rk4(rk4_steps) : herringbone().rk4(rk4_steps);
  const auto production = model == "spur6" ? spur().production({}) : herringbone().production({});
  const auto& ref = reference_run(model);
  double t_default = 0.0, t_rk4 = 0.0;
  Response a, b;
  using clock = std::chrono::steady_clock;
  for (auto _ : state) {
    const auto t0 = clock::now();
    a = production();
    const auto t1 = clock::now();
    b = run();
    t_default += std::chrono::duration<double>(t1 - t0).count();
    t_rk4 += std::chrono::duration<double>(clock::now() - t1).count();
  }
  state.counters["speedup_vs_rk4"] = t_rk4 / t_default;
  state.counters["default_ms"] = 1e3 * t_default / static_cast<double>(state.iterations());
  state.counters["rk4_ms"] = 1e3 * t_rk4 / static_cast<double>(state.iterations());
  state.counters["default_te_error"] = relative_error(a.te, ref.te);
  state.counters["rk4_te_error"] = relative_error(b.te, ref.te);
  state.counters["default_force_error"] = relative_error(a.force, ref.force, true);
  state.counters["rk4_force_error"] = relative_error(b.force, ref.force, true);
}

const bool registered = [] {
  using dynamics::IntegratorMethod;
  for (const std::string model : {"spur6", "herringbone12"}) {
    for (const auto& m : dynamics::integrator_methods()) {
      const auto method = m.method;
      auto* b = benchmark::RegisterBenchmark(fmt::format("BM_WorkPrecision/{}/{}", model, m.key).c_str(),
                                             [model, method](benchmark::State& s) { work_precision(s, model, method); });
      b->DenseRange(method == IntegratorMethod::bogacki_shampine ? 5 : 4, method == IntegratorMethod::bogacki_shampine ? 8 : 10)
          ->Unit(benchmark::kMillisecond)->Iterations(1);
    }
    benchmark::RegisterBenchmark(fmt::format("BM_WorkPrecision_RK4/{}", model).c_str(),
                                 [model](benchmark::State& s) { work_precision_rk4(s, model); })
        ->RangeMultiplier(2)->Range(256, 8192)->Unit(benchmark::kMillisecond)->Iterations(1);
  }
  // RK4 at the step of about the default's accuracy (GSL rk8pd at rtol 1e-7; study: spur6
  // 2.9e-8 against RK4's 3.0e-8 at 8192 steps a cycle; herringbone12 9.4e-11 against 6.2e-11
  // at 8192).
  benchmark::RegisterBenchmark("BM_DefaultVsRK4/spur6", [](benchmark::State& s) { default_vs_rk4(s, "spur6", 8192); })
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_DefaultVsRK4/herringbone12",
                               [](benchmark::State& s) { default_vs_rk4(s, "herringbone12", 8192); })
      ->Unit(benchmark::kMillisecond);
  // The pairs `gearbench bench` turns into side-by-side ratios (X over X_baseline).
  benchmark::RegisterBenchmark("BM_Spur6Dynamics", [](benchmark::State& s) {
    for (auto _ : s) benchmark::DoNotOptimize(spur().production({})().te.size());  // set-up included
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_Spur6Dynamics_baseline", [](benchmark::State& s) {
    const auto run = spur().rk4(4096);
    for (auto _ : s) benchmark::DoNotOptimize(run().te.size());
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_Herringbone12Dynamics", [](benchmark::State& s) {
    for (auto _ : s) benchmark::DoNotOptimize(herringbone().production({})().te.size());  // set-up included
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_Herringbone12Dynamics_baseline", [](benchmark::State& s) {
    const auto run = herringbone().rk4(1024);
    for (auto _ : s) benchmark::DoNotOptimize(run().te.size());
  })->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace
