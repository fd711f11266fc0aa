// The EHL multigrid itself (issue 19): one scheme over the (M, L) map at the default
// settings, the default answer within 1 % of the grid-converged film, second order on three
// Moes points, and the per-cycle convergence factor against Venner & Lubrecht's.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "check_registry.h"
#include "ehl_check_support.h"
#include "closed_form/ehl_closed_form.h"
#include "ehl/line_contact_solver.h"
#include "model/errors.h"

namespace gearbench::verification {
namespace {

using namespace gearbench::ehl;

const char* section = steady_ehl_section;
const char* solver = "ehl";

struct Point {
  double M, L;
};

/// The in-range points of the map on `nodes` (0: the default grid) that do not converge, of
/// those the grid's validation accepts.
CheckValue unconverged_points(int nodes) {
  int failures = 0, points = 0;
  double worst_work = 0.0;
  nlohmann::json failed = nlohmann::json::array(), work = nlohmann::json::array(),
                 refused = nlohmann::json::array();
  for (const auto& pt : moes_map(nodes)) {
    if (!pt.in_range) continue;
    if (pt.refused) {
      refused.push_back({pt.M, pt.L});
      continue;
    }
    ++points;
    worst_work = std::max(worst_work, pt.work_units);
    work.push_back({pt.M, pt.L, pt.work_units});
    if (!pt.converged) {
      ++failures;
      failed.push_back({pt.M, pt.L});
    }
  }
  return CheckValue{static_cast<double>(failures), 0.0,
                    {{"points", points}, {"failed_M_L", failed}, {"refused_M_L", refused},
                     {"largest_work_units", worst_work}, {"work_units_M_L", work}}};
}

const RegisterCheck map_default(CheckSpec{
    .id = "ehl.multigrid.map_default", .section = section, .solver = solver,
    .reference = "issue 19: every in-range (M, L) converges from scratch with one scheme",
    .quantity = "points of M 1–1000 × L 0–25 (step 2.5, ᾱ ≤ 40), default settings, that do not converge",
    .unit = "points", .tolerance = {0, 0},
    .justification = "the default solver has no fallback: a point that does not converge is a failure",
    .tier = Tier::fast, .run = [](const CheckContext&) { return unconverged_points(0); }});

/// The map on a fixed grid: 0 points that do not converge, of those the grid resolves.
void add_fixed_map_check(int nodes, Tier tier) {
  Registry::instance().add(CheckSpec{
      .id = fmt::format("ehl.multigrid.map_{}_nodes", nodes), .section = section, .solver = solver,
      .reference = "issue 19: every in-range (M, L) converges from scratch on every N from 257 to 16385 whose grid "
                   "resolves the film (the validator refuses the rest, exit 2)",
      .quantity = fmt::format("points of M 1–1000 × L 0–25 (step 2.5, ᾱ ≤ 40) on {} nodes, of those whose film the "
                              "grid resolves (h ≤ {:g}·√H_est), that do not converge or end without a film (h_min ≤ 0)",
                              nodes, finest_film_spacing),
      .unit = "points", .tolerance = {0, 0},
      .justification = "one scheme on a fixed grid: a point that does not converge, or whose converged film is not "
                       "positive, is a failure; the points refused as too coarse for the film are listed in "
                       "refused_M_L (at M ≥ 20 a grid coarser than that ends 10 % to 53 × off, half of them below zero; "
                       "docs/ehl-model.md)",
      .tier = tier, .run = [nodes](const CheckContext&) { return unconverged_points(nodes); }});
}

// Issue 19's verification: the full map on 641, 2561 and 16385 nodes, 0 failures (the WU of
// every point in the diagnostics and in the report's tables, ehl_checks.cpp), and on the range's
// coarser grids, cheap enough for the fast tier. Until the thirty-third session a converged
// film ≤ 0 counted as converged: on 257, 513 and 641 nodes the heaviest loads at L ≤ 2.5 ended
// with a negative film (M ≥ 200, M ≥ 500 and M = 1000), no algorithm's doing but the grid's.
// Since the thirty-fourth such grids are refused up front (ehl::refuse_grid_not_resolving_film),
// as `gearbench run` refuses them, and a film ≤ 0 on the grids accepted would fail here.
const bool fixed_map_checks = [] {
  for (int nodes : fixed_map_grids) add_fixed_map_check(nodes, Tier::full);
  for (int nodes : coarse_map_grids) add_fixed_map_check(nodes, Tier::fast);
  return true;
}();

// Seven contacts × inlets at 1, 1.3, 1.77 and 2.5 times the default distance × 641, 1281 and
// 2561 nodes × both stops (168 solves, ~6 s). It caught what one default solve does not: chord
// steps counted whole let (7.3, 12.1) stall at 2.5 times its inlet, and a start without the
// inlet's flux failed on long inlets (seventeenth and eighteenth sessions, docs/research/ehl-multigrid-sessions.md).
const RegisterCheck robustness_sweep(CheckSpec{
    .id = "ehl.multigrid.robustness_sweep", .section = section, .solver = solver,
    .reference = "issue 19: one scheme converges from scratch, whatever the domain and grid",
    .quantity = "solves of (M, L) = (10, 0), (20, 10), (10, 17.5), (5, 20), (50, 10), (7.3, 12.1), (3, 15) on "
                "inlets 1–2.5 times the default, 641/1281/2561 nodes, both stops, that do not converge",
    .unit = "solves", .tolerance = {0, 0},
    .justification = "no fallback: a solve that does not converge is a failure",
    .tier = Tier::fast, .run = [](const CheckContext&) {
      constexpr Point contacts[] = {{10, 0}, {20, 10}, {10, 17.5}, {5, 20}, {50, 10}, {7.3, 12.1}, {3, 15}};
      int failures = 0, solves = 0;
      double work = 0.0;
      nlohmann::json failed = nlohmann::json::array();
      for (const auto& pt : contacts) {
        const LineContactProblem p(LineContactData::from_moes(pt.M, pt.L));
        for (double factor : {1.0, 1.3, 1.77, 2.5})
          for (int nodes : {641, 1281, 2561})
            for (StopRule stop : {StopRule::discretisation_error, StopRule::residual}) {
              EhlOptions o;
              o.nodes = nodes;
              o.x_in = factor * p.x_in();
              o.x_out = p.x_out();
              o.stop = stop;
              if (stop == StopRule::residual) o.tolerance = 1e-9;
              const auto r = LineContactSolver(p, o).try_solve();
              ++solves;
              work += r.work_units;
              if (!r.converged) {
                ++failures;
                failed.push_back({{"M", pt.M}, {"L", pt.L}, {"inlet_factor", factor}, {"nodes", nodes},
                                  {"message", r.message}});
              }
            }
      }
      return CheckValue{static_cast<double>(failures), 0.0,
                        {{"solves", solves}, {"failed", failed}, {"work_units_total", work}}};
    }});

/// Each in-range point's default film against converged_film: the relative errors of H_c and
/// H_min, solved once per process (two checks read them).
const std::vector<FilmError>& map_errors() {
  static const std::vector<FilmError> errors = [] {
    std::vector<FilmError> out;
    for (const auto& pt : moes_map()) {
      if (!pt.in_range) continue;
      if (!pt.converged)
        throw std::runtime_error(fmt::format("the default solve of ({:g}, {:g}) did not converge", pt.M, pt.L));
      const auto d = LineContactData::from_moes(pt.M, pt.L);
      const auto ref = converged_film(LineContactProblem(d));
      out.push_back({pt.M, pt.L, pt.nodes, pt.H_c / (ref.h_central * moes_units(d)) - 1.0,
                     pt.H_min / (ref.h_min * moes_units(d)) - 1.0, pt.error_estimate});
    }
    return out;
  }();
  return errors;
}

CheckValue worst_map_error() { return worst_film_error(map_errors()); }

const RegisterCheck map_accuracy(CheckSpec{
    .id = "ehl.multigrid.map_default_accuracy", .section = section, .solver = solver,
    .reference = "the film converged in grid and domain: 32769 nodes, the inlet at 1.5 times the default distance",
    .quantity = "largest relative error of H_c and H_min over the M 1–1000 × L 0–25 map (ᾱ ≤ 40), default settings",
    .unit = "-", .tolerance = {0.01, 0},
    .justification = "issue 19: the default answer within 1 % of its grid-converged film, at every in-range point; "
                     "the reference's own error is ≤ 4e-4 (inlet ≤ 3e-4, grid ≤ 1e-4), so a 1 % bound is the "
                     "issue's with that margin. Before the inlet grew with the film, (5, 25) and (3, 20) were 1.2 % "
                     "thin",
    .tier = Tier::full, .run = [](const CheckContext&) { return worst_map_error(); }});

// The default grid is refined until its estimate is below grid.target_error (0.5 %); the estimate
// leaves out the inlet's deficit (≤ 1e-3 by LineContactProblem::x_in), and the reference has its
// own ≤ 4e-4: an error above 0.5 % + 0.1 % + 0.04 % is an estimate that under-reads.
const RegisterCheck map_within_target(CheckSpec{
    .id = "ehl.multigrid.map_default_within_target", .section = section, .solver = solver,
    .reference = "grid.target_error 0.5 %, plus the inlet's deficit (≤ 0.1 %) and the reference's error (≤ 0.04 %)",
    .quantity = "largest relative error of H_c and H_min over the map, default settings, against the film converged "
                "in grid and domain",
    .unit = "-", .tolerance = {0.0064, 0},
    .justification = "the default's stop promises an estimated error below 0.5 %; measured 0.39 % at worst. With "
                     "H_min's error estimated at H_c's order 2 (H_min converges at 1.5–1.9), (10, 22.5) stopped on "
                     "513 nodes estimating 0.46 % for 0.77 %, which this fails",
    .tier = Tier::full, .run = [](const CheckContext&) { return worst_map_error(); }});

/// Each in-range point's film on `nodes` (0: the default grid) against the discrete solution of
/// its own finest grid (a scaled residual of 1e-8, the algebraic error's reference), over
/// error_fraction × the solve's own estimate: the stop rule's claim, that the algebraic error it
/// leaves is below that bound. Points refused, unconverged or without an estimate (the residual
/// rule stopped them, and they claim none) are left out.
struct AlgebraicErrorShare {
  double worst = 0.0;
  Point where{};
  nlohmann::json points = nlohmann::json::array();
};

AlgebraicErrorShare algebraic_error_shares(int nodes) {
  const double fraction = EhlOptions{}.error_fraction;
  AlgebraicErrorShare shares;
  for (const auto& pt : moes_map(nodes)) {
    if (!pt.in_range || pt.refused || !pt.converged || !std::isfinite(pt.error_estimate)) continue;
    const auto d = LineContactData::from_moes(pt.M, pt.L);
    EhlOptions o;
    o.nodes = static_cast<int>(pt.nodes);
    o.stop = StopRule::residual;
    o.tolerance = 1e-8;  // 1e-10 stalls at (500, 2.5) on 16385 nodes, its figures equal to 8 digits
    const auto discrete = LineContactSolver(LineContactProblem(d), o).solve();
    const double units = moes_units(d);
    const double error = std::max(std::abs(pt.H_c / (discrete.h_central * units) - 1.0),
                                  std::abs(pt.H_min / (discrete.h_min * units) - 1.0));
    const double share = error / (fraction * pt.error_estimate);
    shares.points.push_back({pt.M, pt.L, pt.nodes, error, pt.error_estimate, share});
    if (share > shares.worst) {
      shares.worst = share;
      shares.where = {pt.M, pt.L};
    }
  }
  return shares;
}

constexpr const char* share_columns = "M, L, nodes, algebraic error of H_c or H_min (the larger), the solve's "
                                      "estimate, their ratio over error_fraction";

CheckValue worst_algebraic_error_share() {
  const auto shares = algebraic_error_shares(0);
  return CheckValue{shares.worst, 0.0,
                    {{"worst_M_L", {shares.where.M, shares.where.L}},
                     {"columns", share_columns},
                     {"points", shares.points}}};
}

/// The same claim on every fixed grid of the maps (coarse_map_grids and fixed_map_grids).
CheckValue worst_fixed_grid_algebraic_error_share() {
  double worst = 0.0;
  nlohmann::json where, grids = nlohmann::json::object();
  for (const auto& grid : {std::span<const int>(coarse_map_grids), std::span<const int>(fixed_map_grids)})
    for (int nodes : grid) {
      const auto shares = algebraic_error_shares(nodes);
      grids[std::to_string(nodes)] = shares.points;
      if (shares.worst > worst) {
        worst = shares.worst;
        where = {shares.where.M, shares.where.L, nodes};
      }
    }
  return CheckValue{worst, 0.0, {{"worst_M_L_nodes", where}, {"columns", share_columns}, {"grids", grids}}};
}

// Twenty-third session: with ρ the residual's factor alone the ratio reached 1.20 at (10, 20)
// (H_min contracting at 0.126 a cycle where the residual did at 0.073); with the figures' own
// factor beside it, 0.66 at worst, median 0.05. Thirty-sixth: 0.74 → 0.45, the rule watching the
// pressurised film beside the figures.
const RegisterCheck map_algebraic_error(CheckSpec{
    .id = "ehl.multigrid.map_algebraic_error", .section = section, .solver = solver,
    .reference = "each point's finest grid solved to a scaled residual of 1e-8 (its discrete solution)",
    .quantity = "largest algebraic error of H_c and H_min at the default settings over error_fraction × the "
                "solve's own discretisation-error estimate, M 1–1000 × L 0–25 (ᾱ ≤ 40)",
    .unit = "-", .tolerance = {1.0, 0},
    .justification = "issue 19 item 5: the solve stops when the algebraic error it leaves is below error_fraction "
                     "(0.1) of its estimate; a ratio above 1 is a stop rule that does not keep its claim. The "
                     "reference's own algebraic error is below 1e-7 of the film (1e-8 against 1e-10 where both converge), "
                     "the smallest bound 6e-5",
    .tier = Tier::full, .run = [](const CheckContext&) { return worst_algebraic_error_share(); }});

// Thirty-fifth session: on the fixed grids the claim did not hold, worst 2.69 at (10, 17.5) on
// 16385 nodes, where the cycle after full multigrid took H_min from 2.1e-6 to 2.2e-5 off its
// discrete solution while its change read a contraction of 0.13. Thirty-sixth: the rule watches
// the film over the pressurised zone beside the figures (the spike's film, unconverged, carries
// its error to H_min); worst per grid 257 nodes 0.13, 513 0.21, 641 0.69, 1025 0.64, 2049 0.87,
// 2561 1.65 (5, 7.5), 16385 0.74. At (5, 7.5) on 2561 nodes H_min's error falls 0.5 in the cycle
// accepted where every measure read ≤ 0.22. Thirty-seventh: every setting measured (free-boundary
// sweeps, W depth, the spike solve's order, fewer cycles below the finest) moves the worst grid
// and leaves it at 1.0–1.7: early change ratios run below the finest level's slow (spike) mode.
// Thirty-eighth: the level's own factor read over its last two cycles, as the residual's is
// (fas_stop.cpp): 257 0.13, 513 0.21, 641 0.69, 1025 0.64, 2049 0.87 (2, 5), 2561 0.54, 16385 0.58
// (and 4097 0.63, 8193 0.60 outside this check); (5, 7.5) on 2561 nodes 0.09 (research log).
const RegisterCheck fixed_grid_algebraic_error(CheckSpec{
    .id = "ehl.multigrid.fixed_grid_algebraic_error", .section = section, .solver = solver,
    .reference = "each point's grid solved to a scaled residual of 1e-8 (its discrete solution)",
    .quantity = "largest algebraic error of H_c and H_min over error_fraction × the solve's own "
                "discretisation-error estimate, M 1–1000 × L 0–25 (ᾱ ≤ 40) on the maps' fixed grids (257, 513, "
                "641, 1025, 2049, 2561 and 16385 nodes) where they resolve the film",
    .unit = "-", .tolerance = {1.0, 0},
    .justification = "the stop rule's claim, as ehl.multigrid.map_algebraic_error holds it on the default grid: a "
                     "ratio above 1 is an answer further from its grid's discrete solution than the solve says. "
                     "The reference's own algebraic error is below 1e-7 of the film",
    .tier = Tier::full, .run = [](const CheckContext&) { return worst_fixed_grid_algebraic_error_share(); }});

/// The grids on which the observed order is asymptotic at the order points (eleventh session):
/// 257/513/1025 is not at (2, 10), where H_c's order reads 2.46, 2.29, 1.83, 1.89 on the
/// successive windows 257 … 8193.
const std::vector<int> asymptotic_series{1025, 2049, 4097};

/// The default solve of (M, L) against the grid-converged film of the 1025/2049/4097 series.
CheckValue default_accuracy(double M, double L) {
  const auto d = LineContactData::from_moes(M, L);
  const LineContactProblem p(d);
  const auto r = LineContactSolver(p, EhlOptions{}).solve();
  const auto s = grid_series(M, L, asymptotic_series);
  const double order_c = observed_order(s.H_c), order_min = observed_order(s.H_min);
  const double H_c = richardson(s.H_c, order_c), H_min = richardson(s.H_min, order_min);
  const double error = std::max(std::abs(r.h_central * moes_units(d) / H_c - 1.0),
                                std::abs(r.h_min * moes_units(d) / H_min - 1.0));
  return CheckValue{error, 0.0,
                    {{"default_nodes", r.X.size()}, {"default_work_units", r.work_units},
                     {"default_cycles", r.cycles}, {"error_estimate", r.error_estimate},
                     {"H_c_default", r.h_central * moes_units(d)}, {"H_c_converged", H_c},
                     {"H_min_default", r.h_min * moes_units(d)}, {"H_min_converged", H_min},
                     {"order_H_c", order_c}, {"order_H_min", order_min}, {"series_nodes", s.nodes}}};
}

constexpr Point accuracy_points[] = {{10, 0}, {20, 10}, {10, 17.5}};

const bool accuracy_checks = [] {
  for (const auto& pt : accuracy_points)
    Registry::instance().add(CheckSpec{
        .id = fmt::format("ehl.multigrid.default_accuracy_M{:g}_L{:g}", pt.M, pt.L), .section = section,
        .solver = solver, .reference = "the grid-converged film (Richardson, observed order, 1025/2049/4097 nodes)",
        .quantity = fmt::format("max relative error of H_c and H_min at the default settings, M = {:g}, L = {:g}",
                                pt.M, pt.L),
        .unit = "-", .tolerance = {0.01, 0},
        .justification = "issue 19: the default answer within 1 % of the grid-converged film. grid.target_error "
                         "is 0.5 %: the default run adds levels until its own estimate (from converged levels) "
                         "is below it, a factor 2 of margin for an estimate",
        .tier = Tier::fast, .run = [pt](const CheckContext&) { return default_accuracy(pt.M, pt.L); }});
  return true;
}();

constexpr Point order_points[] = {{10, 0}, {20, 5}, {2, 10}};

const bool order_checks = [] {
  for (const auto& pt : order_points)
    Registry::instance().add(CheckSpec{
        .id = fmt::format("ehl.grid_convergence.order_M{:g}_L{:g}", pt.M, pt.L), .section = section,
        .solver = solver, .reference = "second-order wedge and Poiseuille terms (stated order 2)",
        .quantity = fmt::format("observed order of H_c, 1025/2049/4097 nodes, M = {:g}, L = {:g}", pt.M, pt.L),
        .unit = "-", .tolerance = {0.35, 0},
        .justification = "the discretisation is second order in the interior (first order only at the "
                         "first interior node and at the free boundary, where P ≈ 0); measured 2.01, 2.00 and "
                         "1.87 at the three points on these grids (1.83 at (2, 10) in the eleventh session), so "
                         "2 ± 0.35; a first-order scheme gives ~1",
        .tier = Tier::fast, .run = [pt](const CheckContext&) {
          const auto s = grid_series(pt.M, pt.L, asymptotic_series);
          return CheckValue{observed_order(s.H_c), 2.0,
                            {{"nodes", s.nodes}, {"H_c", s.H_c}, {"H_min", s.H_min},
                             {"p_max_over_p_h", s.p_max}, {"order_H_min", observed_order(s.H_min)},
                             {"richardson_H_c", richardson(s.H_c, 2.0)},
                             {"richardson_H_min", richardson(s.H_min, 2.0)}}};
        }});
  return true;
}();

constexpr Point factor_points[] = {{10, 0}, {20, 10}, {2, 10}, {1, 0}};

// Venner & Lubrecht's line-contact multigrid reaches 0.1–0.2 a cycle. This W(2,1) design read
// 0.23–0.38 while the coarse grids could flip the free boundary (eleventh session); with the
// coarse nodes held at zero where the fine grid cavitates, 0.04–0.14 at these points on 2049
// nodes (twelfth session, docs/research/ehl-multigrid-rebuild.md). With W only on the two levels above the coarsest
// grid and V above (twenty-seventh session), 0.06, 0.19, 0.19, 0.08: cheaper cycles (less work
// to 1e-9 at all four points) at a factor near the band's top.
const RegisterCheck smoothing(CheckSpec{
    .id = "ehl.multigrid.convergence_factor", .section = section, .solver = solver,
    .reference = "Venner & Lubrecht 2000: 0.1–0.2 per cycle with their line-contact smoother",
    .quantity = "worst mean per-cycle factor of the scaled residual at (M, L) = (10, 0), (20, 10), (2, 10), (1, 0), "
                "2049 nodes, to 1e-9",
    .unit = "-", .tolerance = {0.1, 0},
    .justification = "their band's top, 0.2, or better: 0.1 ± 0.1; a factor above 0.2 is a multigrid that lost "
                     "part of its coarse-grid correction (0.69 at (2, 10) when the coarse free boundary flipped)",
    .tier = Tier::fast, .run = [](const CheckContext&) {
      double worst = 0.0;
      nlohmann::json points = nlohmann::json::array(), factors = nlohmann::json::array(),
                     work = nlohmann::json::array();
      for (const auto& pt : factor_points) {
        const LineContactProblem p(LineContactData::from_moes(pt.M, pt.L));
        EhlOptions o;
        o.nodes = 2049;
        o.stop = StopRule::residual;
        o.tolerance = 1e-9;
        const auto r = LineContactSolver(p, o).solve();
        worst = std::max(worst, r.convergence_factor);
        points.push_back({pt.M, pt.L});
        factors.push_back(r.convergence_factor);
        work.push_back(r.work_units);
      }
      return CheckValue{worst, 0.1, {{"M_L", points}, {"factors", factors}, {"work_units", work}}};
    }});

constexpr Point work_points[] = {{10, 0}, {20, 10}, {10, 17.5}};
constexpr int work_grids[] = {257, 1025, 4097, 16385};
constexpr int work_figure_grids[] = {257, 513, 1025, 2049, 4097, 8193, 16385};

/// The default solve at one of issue 19's benchmark points on a fixed finest grid, solved once
/// per process: the work check and the report's work figure read the same solves.
const EhlResult& benchmark_solve(const Point& pt, int nodes) {
  static std::map<std::tuple<double, double, int>, EhlResult> solves;
  const auto key = std::tuple{pt.M, pt.L, nodes};
  auto found = solves.find(key);
  if (found == solves.end()) {
    const LineContactProblem p(LineContactData::from_moes(pt.M, pt.L));
    EhlOptions o;
    o.nodes = nodes;
    found = solves.emplace(key, LineContactSolver(p, o).solve()).first;
  }
  return found->second;
}

/// The benchmark's steady solves (BM_EhlSteadySolve*) at the default settings: the largest
/// work, and each solve's work by part and the stop rule's share (EhlResult::work_by_part).
CheckValue work_to_error() {
  double largest = 0.0;
  nlohmann::json solves = nlohmann::json::array();
  for (const auto& pt : work_points)
    for (const int n : work_grids) {
      const EhlResult& r = benchmark_solve(pt, n);
      const EhlWork& w = r.work_by_part;
      largest = std::max(largest, r.work_units);
      solves.push_back({pt.M, pt.L, n, r.work_units, r.work_units_iterating, w.start, w.relaxation, w.restriction,
                        w.coarsest, w.spike, w.free_boundary, w.interpolation, w.acceleration});
    }
  return CheckValue{largest, 0.0,
                    {{"columns", "M, L, nodes, WU, of them after full multigrid's cycles, then by part: start, "
                                 "relaxation, restriction, coarsest, spike, free boundary, interpolation, "
                                 "acceleration"},
                     {"solves", solves}}};
}

// Issue 19's target, not met: recorded as missed at the figure reached (thirtieth session), so
// that the report says so and a change of that figure by more than 5 % either way fails until
// it is recorded anew. Full multigrid with one cycle a level takes 16–19 WU on 4097–16385 nodes;
// the stop rule's further cycles 13–34 (docs/research/ehl-multigrid-sessions.md, "Thirtieth session").
// Thirty-sixth session: 74.61 → 91.27 ((10, 17.5) on 257 nodes), the stop rule watching the film
// over the pressurised zone, whose cycles the figures alone had accepted with H_min up to 2.7 ×
// the rule's bound off its discrete solution.
const RegisterCheck work_target(CheckSpec{
    .id = "ehl.multigrid.work_to_error", .section = section, .solver = solver,
    .reference = "issue 19: at most 20 work units to the discretisation error at every N",
    .quantity = "largest work of the default solve at (M, L) = (10, 0), (20, 10), (10, 17.5) on 257, 1025, 4097 "
                "and 16385 nodes",
    .unit = "WU", .tolerance = {20.0, 0},
    .justification = "the issue's bound: 0 ± 20 WU. Counted in sweeps of the finest grid, every level and stage "
                     "included (restriction as a sweep of the coarse grid, dense steps by their flops)",
    .tier = Tier::fast, .run = [](const CheckContext&) { return work_to_error(); },
    .recorded = 91.27, .recorded_tolerance = 0.05});

/// The figure of issue 19's work target: each benchmark point's whole solve and, within it, full
/// multigrid's one cycle a level (the work before the stop rule's further cycles,
/// EhlResult::work_units_iterating), against the grid, with the 20 WU.
void add_work_figure(reports::Report& report) {
  std::vector<reports::Series> series;
  int colour = 1;
  for (const auto& pt : work_points) {
    reports::Series whole{.label = fmt::format("M = {:g}, L = {:g}: the solve", pt.M, pt.L),
                          .style = fmt::format("linespoints pt 7 lc {}", colour)};
    reports::Series fmg{.label = fmt::format("M = {:g}, L = {:g}: full multigrid, one cycle a level", pt.M, pt.L),
                        .style = fmt::format("linespoints pt 6 dt 2 lc {}", colour)};
    for (const int n : work_figure_grids) {
      const EhlResult& r = benchmark_solve(pt, n);
      whole.x.push_back(n);
      whole.y.push_back(r.work_units);
      fmg.x.push_back(n);
      fmg.y.push_back(r.work_units - r.work_units_iterating);
    }
    series.push_back(std::move(whole));
    series.push_back(std::move(fmg));
    ++colour;
  }
  series.push_back({.label = "issue 19's target", .x = {257, 16385}, .y = {20, 20}, .style = "lines dt 3 lc black"});
  report.figures.push_back({.id = "ehl_work_to_error", .section = section,
                            .title = "Work to the discretisation error, default settings",
                            .xlabel = "finest-grid nodes", .ylabel = "work units [finest-grid sweeps]",
                            .series = std::move(series), .log_x = true});
}

const RegisterSection work_section(SectionSpec{
    .id = "ehl_work", .tier = Tier::fast, .add = [](const CheckContext&, reports::Report& report) {
      add_work_figure(report);
      report.notes.push_back({section,
                              "**Work to the discretisation error** (figure `ehl_work_to_error`, issue 19's "
                              "benchmark points on 257 … 16385 nodes): solid, the default solve; dashed, full "
                              "multigrid with one cycle a level within it. The gap between them is the stop "
                              "rule's evidence, one to three further cycles on each level, "
                              "which the rule needs because the cycles contract by 0.06–0.27 where accepting a "
                              "level's full-multigrid cycle at a tenth of the error estimate needs ≤ 0.03 "
                              "(docs/ehl-model.md, \"Convergence, accuracy and work today\")."});
    }});

}  // namespace

CheckValue worst_film_error(const std::vector<FilmError>& errors) {
  const auto worst = std::max_element(errors.begin(), errors.end(),
                                      [](const FilmError& a, const FilmError& b) { return a.worst() < b.worst(); });
  nlohmann::json points = nlohmann::json::array();
  for (const auto& e : errors) points.push_back({e.M, e.L, e.nodes, e.H_c, e.H_min, e.estimate});
  return CheckValue{worst->worst(), 0.0,
                    {{"worst_M_L", {worst->M, worst->L}},
                     {"columns", "M, L, default nodes, error of H_c, error of H_min, the default's estimate"},
                     {"points", points}}};
}

ConvergedFilm converged_film(const LineContactProblem& p) {
  EhlOptions o;
  o.nodes = 32769;
  o.x_in = 1.5 * p.x_in();
  o.x_out = p.x_out();
  o.max_cycles = 200;
  const auto r = LineContactSolver(p, o).solve();
  return {r.h_central, r.h_min};
}

GridSeries grid_series(double M, double L, const std::vector<int>& nodes) {
  const auto d = LineContactData::from_moes(M, L);
  const LineContactProblem p(d);
  GridSeries g;
  for (int n : nodes) {
    EhlOptions o;
    o.nodes = n;
    o.error_fraction = 0.01;
    o.max_cycles = 200;
    const auto r = LineContactSolver(p, o).solve();
    g.nodes.push_back(static_cast<double>(r.X.size()));
    g.H_c.push_back(r.h_central * moes_units(d));
    g.H_min.push_back(r.h_min * moes_units(d));
    g.p_max.push_back(r.p_max / p.hertz_pressure());
    g.work_units.push_back(r.work_units);
  }
  return g;
}

namespace {

/// One point of the map: out of range (ᾱ > 40 with Barus, refused by the validation) or solved
/// on `nodes` (0: the default grid).
MapPoint solve_map_point(double M, double L, int nodes) {
  MapPoint pt{.M = M, .L = L};
  std::optional<LineContactProblem> p;
  try {
    p.emplace(LineContactData::from_moes(M, L));
  } catch (const InputError&) {
    return pt;
  }
  pt.in_range = true;
  EhlOptions o;
  o.nodes = nodes;
  pt.refused = !grid_accepted(*p, o);
  if (pt.refused) return pt;
  const auto r = LineContactSolver(*p, o).try_solve();
  pt.converged = r.converged;
  pt.cycles = r.cycles;
  pt.nodes = static_cast<double>(r.X.size());
  pt.work_units = r.work_units;
  pt.error_estimate = r.error_estimate;
  const double units = moes_units(p->data());
  pt.H = r.h_dpdx0 * units;
  pt.H_c = r.h_central * units;
  pt.H_min = r.h_min * units;
  return pt;
}

}  // namespace

const std::vector<MapPoint>& moes_map(int nodes) {
  static std::map<int, std::vector<MapPoint>> maps;
  auto cached = maps.find(nodes);
  if (cached == maps.end()) {
    std::vector<MapPoint> points;
    for (double M : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0})
      for (int k = 0; k <= 10; ++k) points.push_back(solve_map_point(M, 2.5 * k, nodes));
    cached = maps.emplace(nodes, std::move(points)).first;
  }
  return cached->second;
}

}  // namespace gearbench::verification
