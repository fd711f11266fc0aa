// Transient EHL along the path of contact: the seed 004 reproduction (film and pressure
// from A to E), its time-step convergence, and the report's figures of the mesh; and the steady
// solver's default answer at the same pair's contacts against their converged films.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <optional>

#include "check_registry.h"
#include "ehl_check_support.h"
#include "ehl/transient_mesh_ehl.h"
#include "geometry/gear_pair_geometry.h"
#include "support/convergence.h"

namespace gearbench::verification {
namespace {

using namespace gearbench::ehl;

const std::string section = "Seed 004: transient EHL along the path of contact";
const std::string solver = "ehl.transient_mesh";

/// The seed 004 contact data (table 1): E 206 GPa, ν 0.3, η0 0.08 Pa·s, Roelands z 0.68.
struct Seed004 {
  model::GearCase gear_case;
  LineContactData fluid;
};

Seed004 seed004(const CheckContext& ctx) {
  auto c = ctx.gear_case("seed004_transient_ehl.json");
  const auto fluid = LineContactData::from_gear_media(*c.materials, *c.lubricant);
  return {std::move(c), fluid};
}

/// Seed 004's march; each step stops at its discretisation error, or at a residual tolerance
/// when one is given.
TransientMeshResult run_seed004(const CheckContext& ctx, int steps, int levels,
                                std::optional<double> residual_tolerance = std::nullopt,
                                const std::string& load_sharing = "equal") {
  const auto s = seed004(ctx);
  const geometry::GearPairGeometry g(s.gear_case.gear_pair);
  TransientMeshOptions o;
  o.steps = steps;
  o.load_sharing = load_sharing;
  o.grid.nodes = 40 * (1 << (levels - 1)) + 1;  // levels above a 41-node coarsest grid
  if (residual_tolerance) {
    o.grid.stop = StopRule::residual;
    o.grid.tolerance = *residual_tolerance;
  }
  auto r = TransientMeshEhl(g, *s.gear_case.operating, s.fluid, o).run();
  if (!r.converged) throw std::runtime_error("seed 004 transient EHL: " + r.summary());
  return r;
}

/// The case as it is in cases/ (200 steps, 641 nodes), run once per process.
const TransientMeshResult& seed_run(const CheckContext& ctx) {
  static std::map<std::string, TransientMeshResult> cache;
  auto it = cache.find(ctx.cases_dir);
  if (it == cache.end()) it = cache.emplace(ctx.cases_dir, run_seed004(ctx, 200, 5)).first;
  return it->second;
}

const TransientMeshStep& step_nearest(const TransientMeshResult& r, double s) {
  return *std::min_element(r.steps.begin(), r.steps.end(), [s](const auto& a, const auto& b) {
    return std::abs(a.position - s) < std::abs(b.position - s);
  });
}

/// Local pressure maxima above a tenth of the profile's maximum.
int pressure_peaks(const TransientMeshProfile& p) {
  const double top = *std::max_element(p.p.begin(), p.p.end());
  int peaks = 0;
  for (std::size_t i = 1; i + 1 < p.p.size(); ++i)
    if (p.p[i] > 0.1 * top && p.p[i] > p.p[i - 1] && p.p[i] >= p.p[i + 1]) ++peaks;
  return peaks;
}

double pitch_point(const CheckContext& ctx) {
  return geometry::GearPairGeometry(seed004(ctx).gear_case.gear_pair).path().C;
}

const RegisterCheck p_max_check(CheckSpec{
    .id = "seed004.transient.p_max", .section = section, .solver = solver,
    .reference = "seed 004 (≈ 1.335 GPa near the double→single switch)",
    .quantity = "maximum film pressure over the mesh", .unit = "GPa", .tolerance = {0.0, 0.03},
    .justification = "3 %: the seed's figure is read from a plot, and it does not give its grid or time step",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) {
      const auto& r = seed_run(ctx);
      const geometry::GearPairGeometry g(seed004(ctx).gear_case.gear_pair);
      return CheckValue{r.p_max * 1e-9, 1.335,
                        {{"position_m", r.p_max_position}, {"B_m", g.path().B},
                         {"hertz_pressure_at_B_GPa", step_nearest(r, g.path().B).hertz_pressure * 1e-9}}};
    },
    // Second-order multigrid, 641 nodes (eleventh session): 1.399, 1.408, 1.563 GPa on 321, 641,
    // 1281 nodes: the Barus spike at B sharpens with the grid and does not converge (docs/ehl-model.md).
    // Eighteenth session: 1.399 GPa on 641 nodes, the inlet now growing with the film (a longer
    // domain, so a coarser mesh at the spike).
    .recorded = 1.3990, .recorded_tolerance = 0.005});

const RegisterCheck p_max_place(CheckSpec{
    .id = "seed004.transient.p_max_position", .section = section, .solver = solver,
    .reference = "seed 004 (the maximum sits at the double→single switch B)",
    .quantity = "distance of the pressure maximum from B, in Hertz half-widths b_C", .unit = "-",
    .tolerance = {4.0, 0},
    .justification = "the film answers the load step at B while the oil crosses the inlet and the contact, "
                     "about four Hertz half-widths",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) {
      const auto& r = seed_run(ctx);
      const geometry::GearPairGeometry g(seed004(ctx).gear_case.gear_pair);
      return CheckValue{std::abs(r.p_max_position - g.path().B) / r.reference_half_width, 0.0};
    }});

const RegisterCheck h_min_check(CheckSpec{
    .id = "seed004.transient.h_min", .section = section, .solver = solver,
    .reference = "seed 004 (minimum film 0.30–0.38 µm)",
    .quantity = "minimum film over the mesh", .unit = "µm", .tolerance = {0.04, 0},
    .justification = "the seed gives a band, 0.34 ± 0.04 µm",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) {
      const auto& r = seed_run(ctx);
      return CheckValue{r.h_min * 1e6, 0.34, {{"position_m", r.h_min_position}}};
    },
    // 0.3076, 0.3113, 0.3129 µm on 321, 641, 1281 nodes: 641 nodes within ~1 % of the grid limit
    // (the first-order solver's 0.3174 sat above it).
    .recorded = 0.3113, .recorded_tolerance = 0.005});

const RegisterCheck h_c_check(CheckSpec{
    .id = "seed004.transient.h_central_pitch", .section = section, .solver = solver,
    .reference = "seed 004 (central film 0.35–0.45 µm)",
    .quantity = "central film at the pitch point", .unit = "µm", .tolerance = {0.05, 0},
    .justification = "the seed gives a band, 0.40 ± 0.05 µm",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) {
      const auto& r = seed_run(ctx);
      return CheckValue{step_nearest(r, pitch_point(ctx)).h_central * 1e6, 0.40,
                        {{"h_central_range_um", {r.h_central_min * 1e6, r.h_central_max * 1e6}}}};
    },
    // 0.3890, 0.3913, 0.3919 µm on 321, 641, 1281 nodes (order ~1.9): 641 nodes within 0.2 % of
    // the grid limit (the first-order solver's 0.3994 sat 2 % above it).
    .recorded = 0.3913, .recorded_tolerance = 0.005});

const RegisterCheck second_peak(CheckSpec{
    .id = "seed004.transient.second_peak", .section = section, .solver = solver,
    .reference = "seed 004 (a second pressure peak throughout the mesh)",
    .quantity = "profiles at A, B, C, D, E without a second pressure peak", .unit = "-",
    .tolerance = {0.0, 0},
    .justification = "the pressure spike of a piezoviscous contact: every profile must show it",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) {
      const auto& r = seed_run(ctx);
      int missing = 0;
      nlohmann::json peaks = nlohmann::json::object();
      for (const auto& p : r.profiles) {
        peaks[p.point] = pressure_peaks(p);
        if (pressure_peaks(p) < 2) ++missing;
      }
      return CheckValue{static_cast<double>(missing), 0.0, {{"peaks", peaks}}};
    }});

// Implicit Euler is first order in time: the central film at one instant, 1/5 of the way from
// A to E, on 50, 100 and 200 steps (321 nodes, each step solved to 1e-9 so that the solver's
// own error stays below the 4e-5 relative change between the step sizes). Before B the load
// is constant and the radius and speed change smoothly; after B the time at which the load
// step is felt varies by up to a step with the step count, which hides the order.
const RegisterCheck time_order(CheckSpec{
    .id = "ehl.transient.time_order", .section = section, .solver = solver,
    .reference = "implicit Euler (first order)",
    .quantity = "observed order of the central film 1/5 of the way from A to E",
    .unit = "-", .tolerance = {0.35, 0},
    .justification = "first order expected; ±0.35 for the pre-asymptotic range of three coarse step sizes",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) {
      std::vector<double> h;
      for (int steps : {50, 100, 200})
        h.push_back(run_seed004(ctx, steps, 4, 1e-9).steps.at(static_cast<std::size_t>(steps / 5)).h_central);
      return CheckValue{observed_order(h[0], h[1], h[2]), 1.0, {{"h_central_m", h}}};
    }});

/// The largest relative difference of H_c and H_min over the steps of seed 004's march at the
/// default stop (most steps warm from the previous ones) from the same march with every step
/// solved by full multigrid to a residual of 1e-10: the algebraic error the path carries.
CheckValue warm_step_drift(const CheckContext& ctx, int steps, int levels, const std::string& load_sharing) {
  const auto warm = run_seed004(ctx, steps, levels, std::nullopt, load_sharing);
  const auto tight = run_seed004(ctx, steps, levels, 1e-10, load_sharing);
  double h_central = 0.0, h_min = 0.0;
  for (std::size_t n = 0; n < warm.steps.size(); ++n) {
    h_central = std::max(h_central, std::abs(warm.steps[n].h_central / tight.steps[n].h_central - 1.0));
    h_min = std::max(h_min, std::abs(warm.steps[n].h_min / tight.steps[n].h_min - 1.0));
  }
  return CheckValue{std::max(h_central, h_min), 0.0,
                    {{"h_central", h_central}, {"h_min", h_min}, {"full_multigrid_steps", warm.full_multigrid_steps},
                     {"work_units_per_step", warm.work_units / static_cast<double>(warm.steps.size())}}};
}

// The transient's steps start warm from the previous two and stop at a tenth of a carried
// estimate (TransientMeshEhl::run); their algebraic errors add up through the squeeze term.
// The path's drift must stay below a quarter of the grid's own discretisation error of h_min
// (seed 004 on 321, 641 and 1281 nodes: 0.3076, 0.3113, 0.3129 µm, so 1.7 % on 321 nodes and
// 0.5 % on 641). Two marches the thirty-first session found hardest: 50 steps on 321 nodes
// through the load step at B (measured 2.2e-3; full multigrid at every step 2.9e-3; without the
// carried factor's floor 2.2e-2), and ISO load sharing on 641 nodes in 200 steps (5.9e-4; full
// multigrid at every step 7.4e-4; with the first warm cycle accepted alone 2.0e-3).
const RegisterCheck warm_drift_load_step(CheckSpec{
    .id = "ehl.transient.warm_drift_load_step", .section = section, .solver = solver,
    .reference = "the same march, every step by full multigrid to a residual of 1e-10",
    .quantity = "largest relative difference of H_c and H_min over the steps, seed 004, 50 steps, 321 nodes",
    .unit = "-", .tolerance = {4.3e-3, 0},
    .justification = "a quarter of the 321-node grid's discretisation error of h_min (1.7 %)",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) { return warm_step_drift(ctx, 50, 4, "equal"); }});

const RegisterCheck warm_drift_iso(CheckSpec{
    .id = "ehl.transient.warm_drift_iso", .section = section, .solver = solver,
    .reference = "the same march, every step by full multigrid to a residual of 1e-10",
    .quantity = "largest relative difference of H_c and H_min over the steps, seed 004 with ISO load sharing, "
                "200 steps, 641 nodes",
    .unit = "-", .tolerance = {1.25e-3, 0},
    .justification = "a quarter of the 641-node grid's discretisation error of h_min (0.5 %)",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) { return warm_step_drift(ctx, 200, 5, "iso"); }});

void add_mesh_figures(const CheckContext& ctx, reports::Report& report) {
  const auto& r = seed_run(ctx);
  std::vector<double> s, hc, hmin, pmax, ph;
  for (const auto& st : r.steps) {
    s.push_back(st.position * 1e3);
    hc.push_back(st.h_central * 1e6);
    hmin.push_back(st.h_min * 1e6);
    pmax.push_back(st.p_max * 1e-9);
    ph.push_back(st.hertz_pressure * 1e-9);
  }
  report.figures.push_back({"seed004_film_along_mesh", section, "Film along the path of contact (A → E)",
                            "contact position on the line of action [mm]", "film [µm]",
                            {{"central", s, hc}, {"minimum", s, hmin}}});
  report.figures.push_back({"seed004_pressure_along_mesh", section, "Maximum pressure along the path of contact",
                            "contact position on the line of action [mm]", "pressure [GPa]",
                            {{"EHL maximum", s, pmax}, {"Hertz", s, ph}}});
  // The work of each step, by how it started (TransientMeshEhl::run).
  reports::Series by_full_multigrid{.label = "full multigrid", .style = "points pt 7 ps 1.2"};
  reports::Series warm{.label = "warm from the previous steps", .style = "points pt 1 ps 0.6"};
  for (const auto& st : r.steps) {
    auto& series = st.full_multigrid ? by_full_multigrid : warm;
    series.x.push_back(st.position * 1e3);
    series.y.push_back(st.work_units);
  }
  report.figures.push_back({"seed004_work_along_mesh", section, "Work units of each time step along the path",
                            "contact position on the line of action [mm]", "work units [finest-grid sweeps]",
                            {by_full_multigrid, warm}});
  std::vector<reports::Series> pressure, film;
  for (const auto& p : r.profiles) {
    pressure.push_back({p.point, scaled(p.x, 1e3), scaled(p.p, 1e-9)});
    film.push_back({p.point, scaled(p.x, 1e3), scaled(p.h, 1e6)});
  }
  report.figures.push_back({"seed004_pressure_profiles", section, "Pressure at A, B, C, D, E", "x [mm]",
                            "p [GPa]", pressure});
  report.figures.push_back({"seed004_film_profiles", section, "Film at A, B, C, D, E", "x [mm]", "h [µm]",
                            film, true});
  report.notes.push_back({section, fmt::format(
      "One contact travels from A to E in {} implicit-Euler steps (ΔT = {:.3f} in units of b_C/ū_C, 641 "
      "nodes, {} cycles in all, {:.1f} WU a step, {} steps by full multigrid and the others warm from the "
      "previous two, {:.2f} s), half the load in the double-contact zones. The maximum "
      "pressure, {:.3f} GPa, sits at the double→single switch B where the load doubles; the seed reads "
      "≈ 1.335 GPa there. The Hertz pressure at B is {:.3f} GPa, so the difference is the EHL pressure "
      "spike and the squeeze response to the sudden load step, which an isothermal model with equal "
      "load sharing makes sharper than the seed's (thermal friction, its own load sharing). The minimum "
      "film, {:.3f} µm, lies in the seed's 0.30–0.38 µm band; the central film at the pitch point, "
      "{:.3f} µm, in its 0.35–0.45 µm band. Over the whole path the central film runs from {:.3f} to "
      "{:.3f} µm: the top is the oil trapped by the load step at B, squeezed out over a few Hertz widths.",
      r.steps.size() - 1, r.dimensionless_time_step, r.total_cycles,
      r.work_units / static_cast<double>(r.steps.size()), r.full_multigrid_steps, r.seconds, r.p_max * 1e-9,
      step_nearest(r, geometry::GearPairGeometry(seed004(ctx).gear_case.gear_pair).path().B).hertz_pressure * 1e-9,
      r.h_min * 1e6, step_nearest(r, pitch_point(ctx)).h_central * 1e6, r.h_central_min * 1e6,
      r.h_central_max * 1e6)});
}

// ---- the steady solver's default answer at seed 004's contacts ---------------------------
// The map checks (ehl_multigrid_checks.cpp) hold the default answer on Moes points: Barus,
// incompressible. A gear's contacts are Roelands and compressible, and there H_min converges at
// order → 1 (successive changes of the discrete solutions shrink by 2.81, 2.65, 2.42, 2.56,
// 2.21, 2.09 from 513 to 32769 nodes at the pitch point), below the 1.5 the estimate assumes
// (fas_multigrid_impl.h), so the estimate under-reads the error by 17–29 % (forty-first
// session; the error includes the inlet's deficit).

/// The seed 004 contact at `position` along the path, carrying the whole pinion load (the
/// single-contact zone's, the heaviest a contact sees).
LineContactData contact_at(const Seed004& s, const geometry::GearPairGeometry& g, double position) {
  const auto& op = *s.gear_case.operating;
  const auto k = g.kinematics(position, op.pinion_speed);
  LineContactData d = s.fluid;
  d.reduced_radius = k.reduced_radius;
  d.u1 = k.u1;
  d.u2 = k.u2;
  d.load_per_length = op.pinion_torque / g.radii(0).base / s.gear_case.gear_pair.face_width;
  return d;
}

/// The default answer's relative errors at A, halfway A–C, C, halfway C–E and E against each
/// contact's converged film (ehl_check_support.h), solved once per process.
const std::vector<FilmError>& contact_errors(const CheckContext& ctx) {
  static std::map<std::string, std::vector<FilmError>> cache;
  auto it = cache.find(ctx.cases_dir);
  if (it != cache.end()) return it->second;
  const auto s = seed004(ctx);
  const geometry::GearPairGeometry g(s.gear_case.gear_pair);
  const auto& path = g.path();
  std::vector<FilmError> errors;
  for (const double position : {path.A, 0.5 * (path.A + path.C), path.C, 0.5 * (path.C + path.E), path.E}) {
    const LineContactProblem p(contact_at(s, g, position));
    const auto r = LineContactSolver(p, EhlOptions{}).solve();
    const auto ref = converged_film(p);
    errors.push_back({p.data().moes_M(), p.data().moes_L(), static_cast<double>(r.X.size()),
                      r.h_central / ref.h_central - 1.0, r.h_min / ref.h_min - 1.0, r.error_estimate});
  }
  return cache.emplace(ctx.cases_dir, std::move(errors)).first->second;
}

CheckValue worst_contact_error(const CheckContext& ctx) { return worst_film_error(contact_errors(ctx)); }

const std::string contacts_reference =
    "each contact's film converged in grid and domain (32769 nodes, the inlet at 1.5 times the default distance; "
    "verification/checks/ehl_check_support.h)";
const std::string contacts_quantity =
    "largest relative error of h_c and h_min of the default answer at seed 004's contacts A, halfway A–C, C, "
    "halfway C–E and E under the whole pinion load (Roelands z 0.68, Dowson–Higginson)";

const RegisterCheck contacts_accuracy(CheckSpec{
    .id = "ehl.seed004_contacts.default_accuracy", .section = steady_ehl_section, .solver = "ehl",
    .reference = contacts_reference, .quantity = contacts_quantity, .unit = "-", .tolerance = {0.01, 0},
    .justification = "issue 19: the default answer within 1 % of its grid-converged film, here at the contacts a "
                     "gear user solves; the reference's own error is ≤ 3e-4 (inlet) and ≤ 1.5e-4 (grid)",
    .tier = Tier::fast, .run = worst_contact_error});

// Not met: recorded as missed at the figure reached (forty-first session: 0.53–0.64 % at
// estimates of 0.43–0.50 %, all on 1025 nodes), so that the report says so. With H_min's order
// taken as 1 the default goes to 2049 nodes here (0.25–0.31 %), but the stop rule's claim breaks
// on the maps (1.27 at (100, 10) on the default grid, 1.24 at (10, 5) on 16385 nodes): not kept.
const RegisterCheck contacts_within_target(CheckSpec{
    .id = "ehl.seed004_contacts.default_within_target", .section = steady_ehl_section, .solver = "ehl",
    .reference = "grid.target_error 0.5 %, plus the inlet's deficit (≤ 0.1 %) and the reference's error (≤ 0.015 %)",
    .quantity = contacts_quantity, .unit = "-", .tolerance = {0.0062, 0},
    .justification = "the default's stop promises an estimated error below 0.5 %, as ehl.multigrid."
                     "map_default_within_target holds it on the Moes map; above, the estimate under-reads H_min",
    .tier = Tier::fast, .run = worst_contact_error, .recorded = 0.00639, .recorded_tolerance = 0.05});

const RegisterSection transient_section(SectionSpec{.id = "seed004_transient", .tier = Tier::fast,
                                                    .add = add_mesh_figures});

}  // namespace
}  // namespace gearbench::verification
