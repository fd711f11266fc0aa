// Multigrid line-contact EHL (work in progress) against closed forms: the deformation
// operator against its direct sum and the analytic Hertz deformation, the rigid-isoviscous
// limit against Martin, the dry-contact limit against Hertz, and Moes' film formula.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "check_registry.h"
#include "ehl_check_support.h"
#include "closed_form/ehl_closed_form.h"
#include "ehl/deformation.h"
#include "ehl/fas_multigrid.h"
#include "ehl/line_contact_solver.h"

namespace gearbench::verification {
namespace {

using namespace gearbench::ehl;

const char* section = "Multigrid line-contact EHL (steady, isothermal)";
const char* solver = "ehl";

// --- Deformation -------------------------------------------------------------------------

std::vector<double> semi_ellipse(std::size_t n, double x_in, double h) {
  std::vector<double> P(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = x_in + static_cast<double>(i) * h;
    P[i] = std::sqrt(std::max(0.0, 1.0 - x * x));
  }
  return P;
}

const RegisterCheck fft_vs_direct(CheckSpec{
    .id = "ehl.deformation.fft_vs_direct", .section = section, .solver = solver,
    .reference = "direct O(n²) sum", .quantity = "max |W_fft − W_direct| / max |W| (4097 nodes)",
    .unit = "-", .tolerance = {1e-12, 0},
    .justification = "the same convolution; FFT round-off grows as ε·log n ≈ 1e-15",
    .tier = Tier::fast, .run = [](const CheckContext&) {
      const std::size_t n = 4097;
      const double h = 4.0 / static_cast<double>(n - 1);
      const Deformation d(n, h);
      const auto P = semi_ellipse(n, -2.0, h);
      std::vector<double> a, b;
      d.apply(P, a);
      d.apply_direct(P, b);
      double diff = 0.0, scale = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        diff = std::max(diff, std::abs(a[i] - b[i]));
        scale = std::max(scale, std::abs(b[i]));
      }
      return CheckValue{diff / scale, 0.0};
    }});

// ∫ √(1 − s²)·ln|X − s| ds = (π/2)(X² − ½ − ln 2) for |X| ≤ 1 (the Hertz pressure flattens
// the film). Piecewise-constant cells converge at about h^1.3 here (square-root edges):
// 2.1e-3, 3.6e-4, 5.7e-5 at 257, 1025, 4097 nodes.
const RegisterCheck hertz_deformation(CheckSpec{
    .id = "ehl.deformation.hertz_semi_ellipse", .section = section, .solver = solver,
    .reference = "analytic deformation of the Hertz pressure",
    .quantity = "max deviation inside the contact (4097 nodes on [−2, 2])", .unit = "-",
    .tolerance = {1e-4, 0},
    .justification = "discretisation error ~h^1.3 (square-root edges of the semi-ellipse): 5.7e-5 at h = 1e-3",
    .tier = Tier::fast, .run = [](const CheckContext&) {
      const std::size_t n = 4097;
      const double h = 4.0 / static_cast<double>(n - 1);
      const Deformation d(n, h);
      const auto P = semi_ellipse(n, -2.0, h);
      std::vector<double> W;
      d.apply(P, W);
      double dev = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        const double x = -2.0 + static_cast<double>(i) * h;
        if (std::abs(x) < 1.0) dev = std::max(dev, std::abs(W[i] - 0.5 * M_PI * (x * x - 0.5 - std::log(2.0))));
      }
      return CheckValue{dev, 0.0};
    }});

// --- Rigid-isoviscous limit (Martin) ----------------------------------------------------------

LineContactData rigid_isoviscous() {
  LineContactData d;
  d.reduced_radius = 0.01;
  d.load_per_length = 1e3;
  d.u1 = d.u2 = 1.0;
  d.reduced_modulus = 1e16;  // the rigid limit
  d.viscosity = 0.08;
  d.pressure_viscosity = 0.0;
  d.viscosity_model = ViscosityModel::barus;
  d.density_model = DensityModel::incompressible;
  return d;
}

double martin_constant(int levels) {
  const auto d = rigid_isoviscous();
  const LineContactProblem p(d);
  EhlOptions o;
  o.levels = levels;
  o.max_cycles = 400;
  const auto r = LineContactSolver(p, o).solve();
  return d.load_per_length * r.h_min / (d.viscosity * d.mean_speed() * d.reduced_radius);
}

// First-order upwind: the load constant converges as O(h); Richardson extrapolation of 641
// and 1281 nodes removes that term. What is left: O(h²) and the load lost beyond X_in = −40
// (4/(4.895·40²) ≈ 5e-4 relative).
const RegisterCheck martin_load(CheckSpec{
    .id = "ehl.martin.load_constant", .section = section, .solver = solver,
    .reference = "Martin (Reynolds outlet), w·h0/(η0·ū·R) = 4.8950",
    .quantity = "load constant, Richardson-extrapolated from 641 and 1281 nodes", .unit = "-",
    .tolerance = {0, 5e-3},
    .justification = "O(h²) remainder after Richardson plus 5e-4 from the truncated inlet",
    .tier = Tier::fast, .run = [](const CheckContext&) {
      const double c5 = martin_constant(5), c6 = martin_constant(6);
      const double c4 = martin_constant(4);
      const double order = observed_order(c4, c5, c6);
      return CheckValue{richardson(c5, c6, 1.0), reference::martin_load_constant,
                        {{"nodes_321_641_1281", {c4, c5, c6}}, {"observed_order", order}}};
    }});

const RegisterCheck martin_order(CheckSpec{
    .id = "ehl.martin.observed_order", .section = section, .solver = solver,
    .reference = "first-order upwind wedge (stated order 1)",
    .quantity = "observed order of the load constant, 321/641/1281 nodes", .unit = "-",
    .tolerance = {0.3, 0},
    .justification = "the wedge term is first-order upwind; the observed order must be near 1",
    .tier = Tier::fast, .run = [](const CheckContext&) {
      const double c4 = martin_constant(4), c5 = martin_constant(5), c6 = martin_constant(6);
      return CheckValue{observed_order(c4, c5, c6), 1.0};
    }});

// --- Transient machinery ----------------------------------------------------------------------

// An implicit-Euler step with nothing changed must return the steady solution at once.
const RegisterCheck transient_identity(CheckSpec{
    .id = "ehl.transient.constant_state", .section = section, .solver = solver,
    .reference = "the steady solution", .quantity = "max |P(step) − P(steady)|, M = 20, L = 5, ΔT = 1",
    .unit = "-", .tolerance = {1e-7, 0},
    .justification = "the squeeze term vanishes for an unchanged film: only the solver tolerance (1e-11 on the residual) remains",
    .tier = Tier::fast, .run = [](const CheckContext&) {
      const LineContactProblem p(LineContactData::from_moes(20.0, 5.0));
      EhlOptions o;
      o.levels = 4;
      o.tolerance = 1e-11;  // both solves far below the check's tolerance
      FasMultigrid steady(p, o, ContactState{});
      const auto s = steady.solve();
      ContactState state;
      state.time_step = 1.0;
      state.rho_h_old = steady.rho_h();
      FasMultigrid step(p, o, state);
      const auto t = step.solve(WarmStart{s.P, s.H0, 0.0});
      double worst = 0.0;
      for (std::size_t i = 0; i < s.P.size(); ++i) worst = std::max(worst, std::abs(t.P[i] - s.P[i]));
      return CheckValue{worst, 0.0, {{"cycles", t.cycles}}};
    }});

// Pure squeeze of a rigid cylinder, isoviscous (υ = 0): ε dP/dX = Ḣ0·X integrates to
// P = −λḢ0/(2H²) and ∫P dX = −λḢ0·π√2/(4H0^(3/2)) on an infinite domain, i.e. w =
// 3√2·π·η·R^(3/2)(−ḣ0)/h0^(3/2) (reference/closed_form). One implicit step from H0 = 1
// must land on that approach speed at the new H0.
const RegisterCheck transient_squeeze(CheckSpec{
    .id = "ehl.transient.rigid_squeeze", .section = section, .solver = solver,
    .reference = "rigid isoviscous squeeze, closed form",
    .quantity = "relative error of Ḣ0 after one implicit step (1281 nodes on [−20, 20])", .unit = "-",
    .tolerance = {3e-3, 0},
    .justification = "1.0e-2, 2.8e-3, 1.0e-3 on 321, 641, 1281 nodes (order ~1.7); the cut "
                     "at |X| = 20 loses ~1e-4 of the load",
    .tier = Tier::fast, .run = [](const CheckContext&) {
      const auto d = rigid_isoviscous();
      const LineContactProblem p(d);
      EhlOptions o;
      o.levels = 6;
      o.x_in = -20.0;
      o.x_out = 20.0;
      const double H0_old = 1.0, dT = 0.5;
      const std::size_t n = static_cast<std::size_t>((o.coarsest_nodes - 1) * (1 << (o.levels - 1)) + 1);
      const double h = 40.0 / static_cast<double>(n - 1);
      ContactState state;
      state.speed = 0.0;
      state.time_step = dT;
      std::vector<double> start(n);
      state.rho_h_old.resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        const double x = -20.0 + static_cast<double>(i) * h;
        state.rho_h_old[i] = H0_old + 0.5 * x * x;
        start[i] = 0.1 / std::pow(state.rho_h_old[i], 2);
      }
      start.front() = start.back() = 0.0;
      FasMultigrid mg(p, o, state);
      const auto r = mg.solve(WarmStart{start, 0.9 * H0_old, H0_old});
      if (!r.converged) throw std::runtime_error("squeeze step did not converge");
      const double rate = (r.H0 - H0_old) / dT;
      const double closed = -4.0 * p.load() * std::pow(r.H0, 1.5) / (p.lambda() * M_PI * std::sqrt(2.0));
      return CheckValue{rate / closed - 1.0, 0.0, {{"H0", r.H0}, {"cycles", r.cycles}}};
    }});

// --- Grid convergence -------------------------------------------------------------------------
// M = 10, L = 0 on 257 … 8193 nodes (33 coarsest nodes, 4 … 9 levels).

const RegisterCheck grid_convergence(CheckSpec{
    .id = "ehl.grid_convergence.order", .section = section, .solver = solver,
    .reference = "first-order upwind wedge (stated order 1)",
    .quantity = "observed order of H_c, 2049/4097/8193 nodes, M = 10, L = 0", .unit = "-",
    .tolerance = {0.15, 0},
    .justification = "first-order scheme in its asymptotic range: the order of the last three "
                     "grids must be 1 within the drift seen between successive triples",
    .tier = Tier::fast, .run = [](const CheckContext&) {
      const auto g = grid_series(10.0, 0.0, 33);
      return CheckValue{observed_order(g.H_c), 1.0,
                        {{"nodes", g.nodes}, {"H_c", g.H_c}, {"H_min", g.H_min}, {"p_max_over_p_h", g.p_max},
                         {"order_H_min", observed_order(g.H_min)}, {"order_p_max", observed_order(g.p_max)},
                         {"richardson", {{"H_c", first_order_richardson(g.H_c)}, {"H_min", first_order_richardson(g.H_min)},
                                         {"p_max_over_p_h", first_order_richardson(g.p_max)}}}}};
    }});

// --- Hertz limit and Moes ---------------------------------------------------------------------

EhlResult solve_moes(double M, double L) {
  const LineContactProblem p(LineContactData::from_moes(M, L));
  EhlOptions o;
  o.levels = 5;
  return LineContactSolver(p, o).solve();
}

const RegisterCheck hertz_limit(CheckSpec{
    .id = "ehl.hertz_limit", .section = section, .solver = solver,
    .reference = "Hertz semi-ellipse", .quantity = "max |P − √(1 − X²)| for |X| ≤ 0.9 at M = 100, L = 0",
    .unit = "-", .tolerance = {0.03, 0},
    .justification = "an isoviscous film at M = 100 perturbs the dry pressure by O(film/deformation); "
                     "1.7e-2 observed, falling with M",
    .tier = Tier::fast, .run = [](const CheckContext&) {
      const auto r = solve_moes(100.0, 0.0);
      double dev = 0.0;
      for (std::size_t i = 0; i < r.X.size(); ++i)
        if (std::abs(r.X[i]) <= 0.9) dev = std::max(dev, std::abs(r.P[i] - std::sqrt(1.0 - r.X[i] * r.X[i])));
      return CheckValue{dev, 0.0, {{"cycles", r.cycles}}};
    }});

struct MoesPoint {
  double M, L;
};
const MoesPoint moes_points[] = {{10, 0}, {20, 10}, {50, 5}, {100, 10}};

const bool moes_checks = [] {
  for (const auto& pt : moes_points)
    Registry::instance().add(CheckSpec{
        .id = fmt::format("ehl.moes.M{}_L{}", pt.M, pt.L), .section = section, .solver = solver,
        .reference = "Moes film formula (film at dp/dx = 0)",
        .quantity = fmt::format("H = (h/R)·U_Σ^(−1/2) at M = {}, L = {} (641 nodes)", pt.M, pt.L),
        .unit = "-", .tolerance = {0, 0.1},
        .justification = "Moes' fit to numerical solutions is good to a few per cent; the "
                         "first-order scheme at 641 nodes adds up to ~5 % (the Martin load "
                         "constant is 6 % high there), so ±10 %",
        .tier = Tier::fast, .run = [pt](const CheckContext&) {
          const auto d = LineContactData::from_moes(pt.M, pt.L);
          const auto r = solve_moes(pt.M, pt.L);
          return CheckValue{r.h_dpdx0 * moes_units(d), reference::moes_H(pt.M, pt.L),
                            {{"cycles", r.cycles}, {"work_units", r.work_units}}};
        }});
  return true;
}();

// --- Where the solver converges today -----------------------------------------------------

void add_convergence_table(reports::Report& report) {
  const auto g = grid_series(10.0, 0.0, 33);
  ConvergenceTable table("nodes", {"H_c", "H_min", "p_max/p_h"});
  for (std::size_t i = 0; i < g.nodes.size(); ++i) table.add_row(g.nodes[i], {g.H_c[i], g.H_min[i], g.p_max[i]});
  report.notes.push_back({section, fmt::format(
      "**Grid convergence** at M = 10, L = 0 (Moes H = {:.4f}), in Moes units and p/p_h:\n\n{}\n"
      "Richardson values of the two finest grids (first order): H_c {:.6f}, H_min {:.6f}, p_max/p_h {:.6f}.\n",
      reference::moes_H(10.0, 0.0), table.markdown(), first_order_richardson(g.H_c),
      first_order_richardson(g.H_min), first_order_richardson(g.p_max))});
}

void add_profile_figures(reports::Report& report) {
  std::vector<reports::Series> pressure, film;
  for (const auto& [M, L] : {std::pair{20.0, 10.0}, std::pair{100.0, 5.0}, std::pair{10.0, 0.0}}) {
    const auto r = solve_moes(M, L);
    const std::string label = fmt::format("M = {}, L = {}", M, L);
    pressure.push_back({label, r.X, r.P});
    std::vector<double> H = r.H;
    const double h_min = *std::min_element(H.begin(), H.end());
    for (auto& h : H) h /= h_min;
    film.push_back({label, r.X, H});
  }
  report.figures.push_back({"ehl_pressure", section, "Dimensionless pressure P = p/p_h (641 nodes)",
                            "X = x/b", "P", pressure});
  report.figures.push_back({"ehl_film", section, "Film shape H/H_min (641 nodes)", "X = x/b", "H / H_min",
                            film, true});
}

const RegisterSection ehl_section(SectionSpec{
    .id = "ehl", .tier = Tier::fast, .add = [](const CheckContext&, reports::Report& report) {
      add_profile_figures(report);
      add_convergence_table(report);
      std::string rows;
      double last_M = -1.0;
      for (const auto& pt : moes_map()) {
        if (pt.M != last_M) rows += fmt::format("{}| {} |", last_M < 0.0 ? "" : "\n", pt.M);
        last_M = pt.M;
        const std::string attempt = pt.attempts > 1 ? fmt::format(" (attempt {})", pt.attempts) : "";
        rows += !pt.in_range   ? std::string(" out of range (ᾱ > 40) |")
                : pt.converged ? fmt::format(" {} cycles{}, H {:.3f} (Moes {:.3f}) |", pt.cycles, attempt, pt.H,
                                             reference::moes_H(pt.M, pt.L))
                               : std::string(" **not converged** |");
      }
      report.notes.push_back({section, fmt::format(
          "**Where the steady solver converges (issue 3).** The FAS solver (641 nodes, W(2,2) cycles, "
          "line relaxation with under-relaxation 0.3/0.2, the fine film injected into the coarse film "
          "equation) is held to 1e-8 on the scaled complementarity residual and the force balance "
          "within 200 cycles. A failed solve is repeated from scratch with the coarse nodes of an "
          "unresolved pressure spike held; then ω_J 0.1; then ξ = 100; then ξ = 100 from an 81-node "
          "coarsest grid (one level fewer); then point relaxation; then V-cycles; and last by "
          "continuation in α (solved at α/2, then α raised in adaptive steps, each started from the "
          "last solution). The attempt is shown when it was not the first; attempt 8 is the "
          "continuation. Every in-range point converges (check ehl.relaxation.map_641_nodes). Out of "
          "range means ᾱ = α·p_h > 40 with Barus (a viscosity "
          "ratio over e^40), which the input validation refuses (REFERENCE-FACTS).\n\n"
          "| M | L = 0 | L = 5 | L = 10 | L = 15 | L = 20 | L = 22.5 | L = 25 |\n"
          "|---|---|---|---|---|---|---|---|\n{}\n", rows)});
    }});

}  // namespace

GridSeries grid_series(double M, double L, int coarsest_nodes) {
  const auto d = LineContactData::from_moes(M, L);
  const LineContactProblem p(d);
  GridSeries g;
  for (int levels = 4; levels <= 9; ++levels) {
    EhlOptions o;
    o.levels = levels;
    o.coarsest_nodes = coarsest_nodes;
    const auto r = LineContactSolver(p, o).solve();
    g.nodes.push_back(static_cast<double>(r.X.size()));
    g.H_c.push_back(r.h_central * moes_units(d));
    g.H_min.push_back(r.h_min * moes_units(d));
    g.p_max.push_back(r.p_max / p.hertz_pressure());
  }
  return g;
}

}  // namespace gearbench::verification
