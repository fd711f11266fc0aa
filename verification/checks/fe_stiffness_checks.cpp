// The deal.II finite-element tooth reference (reference/fe_tooth) on its own — the
// cantilever against Timoshenko beam theory, the convergence of the tooth compliance — and
// against the energy method (solvers/stiffness) per mesh position, per gear and for the
// pair: seed 003's 20/25 pair (fast tier), 19/48 m 3.2 and 62/62 m 2 (full tier).
// docs/fe-tooth-model.md explains what the FE compliance means and where the models part.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <mutex>

#include "check_registry.h"
#include "fe_tooth/cantilever.h"
#include "fe_tooth/fe_tooth_stiffness.h"
#include "stiffness/pair_stiffness.h"

namespace gearbench::verification {
namespace {

namespace fe = reference::fe;

const char* section = "Finite-element tooth reference (deal.II)";
const char* solver = "stiffness";

/// FE against the energy method at positions evenly spread over A..E (both ends included;
/// one position: the middle of A..E).
struct Comparison {
  std::vector<double> s;                       ///< path positions [m]
  std::vector<double> fe_pair, em_pair;        ///< pair stiffness [N/m]
  std::vector<double> fe_pair_contact;         ///< FE pair with its own contact flattening [N/m]
  std::array<std::vector<double>, 2> fe_tooth, em_tooth;  ///< tooth compliance [m/N]
  double max_change = 0.0;                     ///< largest last relative change of a solve
  std::vector<double> rates;                   ///< observed rate of each solve's last cycle
  double fe_seconds = 0.0;                     ///< FE time per position (both gears)
  double em_seconds = 0.0;                     ///< energy-method time per position
  double path_mismatch = 0.0;                  ///< |A_FE − A_EM| + |E_FE − E_EM| [m]
  std::string table;                           ///< ConvergenceTable of the first pinion solve
};

Comparison compare(const model::GearPair& pair, const std::array<model::Material, 2>& materials, int positions) {
  fe::FeToothOptions options;
  options.plane_strain = false;  // the energy method's E and G = E/(2(1 + ν)): plane stress
  const fe::FeToothStiffness model(pair, materials, options);
  const geometry::GearPairGeometry g(pair);
  const std::array<double, 2> bore{0.5 * g.radii(0).root, 0.5 * g.radii(1).root};
  const stiffness::PairStiffness energy(g, materials, stiffness::BeamStart::improved, bore, std::nullopt, true);
  Comparison c;
  const auto& path = model.path();
  c.path_mismatch = std::abs(path.A - g.path().A) + std::abs(path.E - g.path().E);
  for (int i = 0; i < positions; ++i)
    c.s.push_back(positions == 1 ? 0.5 * (path.A + path.E) : path.A + (path.E - path.A) * i / (positions - 1));
  const auto fe_result = model.solve(c.s);
  const auto start = std::chrono::steady_clock::now();
  for (const double s : c.s) {
    const auto e = energy.compliance(s);
    for (std::size_t k = 0; k < 2; ++k)
      c.em_tooth[k].push_back((e.tooth[k].bending + e.tooth[k].shear + e.tooth[k].axial + e.foundation[k]) /
                              pair.face_width);
    c.em_pair.push_back(pair.face_width / e.total());
  }
  c.em_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / positions;
  c.table = fe_result.positions.front().tooth[0].fe.table;
  for (const auto& p : fe_result.positions) {
    c.fe_pair.push_back(p.pair_stiffness);
    c.fe_pair_contact.push_back(p.pair_stiffness_fe_contact);
    for (std::size_t k = 0; k < 2; ++k) {
      c.fe_tooth[k].push_back(p.tooth[k].compliance);
      c.max_change = std::max(c.max_change, p.tooth[k].fe.cycles.back().change);
      c.rates.push_back(p.tooth[k].fe.observed_rate);
      c.fe_seconds += p.tooth[k].fe.seconds / positions;
    }
  }
  return c;
}

/// One comparison per named pair, computed once and shared by its checks.
const Comparison& cached(const std::string& name, const std::function<Comparison()>& make) {
  static std::mutex mutex;
  static std::map<std::string, Comparison> cache;
  const std::lock_guard lock(mutex);
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, make()).first;
  return it->second;
}

model::GearPair spur(int z1, int z2, double module_mm, double width_mm) {
  model::GearPair g;
  g.teeth = {z1, z2};
  g.normal_module = module_mm * 1e-3;
  g.normal_pressure_angle = 20.0 * M_PI / 180.0;
  g.face_width = width_mm * 1e-3;
  return g;
}

struct PairCase {
  std::string name;
  Tier tier;
  int positions;
  std::function<Comparison(const CheckContext&)> make;
  double recorded_pair, recorded_tooth;  ///< max |FE/energy − 1| reached (2026-11-22)
};

const std::array<model::Material, 2> steel{model::Material{206e9, 0.3, 7850}, model::Material{206e9, 0.3, 7850}};

const std::vector<PairCase>& pair_cases() {
  static const std::vector<PairCase> cases{
      // Fast tier: one position (the middle of A..E, where seed 003's pair differs most),
      // ~10 s; the ctest gate and `gearbench verify` each pay it once per process.
      {"seed003_mid", Tier::fast, 1,
       [](const CheckContext& ctx) {
         const auto c = ctx.gear_case("seed003_spur_stiffness.json");
         return compare(c.gear_pair, *c.materials, 1);
       },
       0.0876, 0.0999},
      {"seed003", Tier::full, 5,
       [](const CheckContext& ctx) {
         const auto c = ctx.gear_case("seed003_spur_stiffness.json");
         return compare(c.gear_pair, *c.materials, 5);
       },
       0.0876, 0.1100},
      {"z19_48_m3_2", Tier::full, 9, [](const CheckContext&) { return compare(spur(19, 48, 3.2, 16), steel, 9); },
       0.2158, 0.2309},
      {"z62_62_m2", Tier::full, 9, [](const CheckContext&) { return compare(spur(62, 62, 2.0, 20), steel, 9); },
       0.2373, 0.2161},
  };
  return cases;
}

/// Largest |a/b − 1| over the positions and where it occurs.
CheckValue worst_ratio(const Comparison& c, bool pair) {
  double worst = 0.0;
  std::string where;
  nlohmann::json ratios = nlohmann::json::array();
  for (std::size_t i = 0; i < c.s.size(); ++i) {
    nlohmann::json row = {{"s_mm", c.s[i] * 1e3}};
    auto consider = [&](double fe_value, double em_value, const std::string& what) {
      const double d = fe_value / em_value - 1.0;
      row[what] = fe_value / em_value;
      if (std::abs(d) > std::abs(worst)) {
        worst = d;
        where = fmt::format("{} at s = {:.3f} mm", what, c.s[i] * 1e3);
      }
    };
    if (pair) {
      consider(c.fe_pair[i], c.em_pair[i], "pair stiffness");
      row["pair stiffness, FE contact instead of Hertz"] = c.fe_pair_contact[i] / c.em_pair[i];
    } else {
      consider(c.fe_tooth[0][i], c.em_tooth[0][i], "gear 1 compliance");
      consider(c.fe_tooth[1][i], c.em_tooth[1][i], "gear 2 compliance");
    }
    ratios.push_back(row);
  }
  return {std::abs(worst), 0.0, {{"signed_worst", worst}, {"worst", where}, {"fe_over_energy", ratios},
                                 {"fe_seconds_per_position", c.fe_seconds},
                                 {"energy_seconds_per_position", c.em_seconds}}};
}

// The two models differ in physics, not only in discretisation: a beam with a fitted
// foundation (Sainsot's formula is itself a fit to FE of a full body, quoted to a few per
// cent) against a meshed 2D continuum probed on the load line; a tooth is a short beam
// (height ≈ 1.2 × root thickness), where beam theory's shear and root assumptions are
// worth several per cent each. The bands were set before the comparison was run: 10 % for
// the pair stiffness, 20 % per tooth (the pair's common Hertz term, ~1/3 of the pair
// compliance, dilutes tooth differences). docs/fe-tooth-model.md reports the band reached
// and where the models part. Seed 003 lies inside its bands; the 19/48 and 62/62 pairs do
// not (FE stiffer by ~20 %), so each check also records the figure reached, and a drift of
// more than 10 % of it (FE convergence tolerance 0.5 % on a ~10–20 % difference is a few
// per cent of it) is what counts as a regression.
const bool energy_checks = [] {
  for (const auto& pc : pair_cases()) {
    for (const bool pair : {true, false}) {
      Registry::instance().add(CheckSpec{
          .id = fmt::format("fe_tooth.vs_energy.{}.{}", pc.name, pair ? "pair" : "tooth"), .section = section,
          .solver = solver, .reference = "deal.II FE tooth (plane stress, bore r_f/2 clamped)",
          .quantity = fmt::format("max |FE/energy − 1| of the {} over {} positions A..E, {}",
                                  pair ? "pair stiffness" : "tooth compliance (both gears)", pc.positions, pc.name),
          .unit = "-", .tolerance = {pair ? 0.10 : 0.20, 0.0},
          .justification = pair ? "a priori band for two tooth models of different physics (beam + "
                                  "fitted foundation vs 2D continuum); see the comment in the source"
                                : "per tooth the pair's common Hertz term no longer dilutes the difference",
          // The fast tier keeps only seed 003's pair check: each ctest case is its own
          // process, so every FE check there would pay the FE solves again.
          .tier = pair ? pc.tier : Tier::full,
          .run = [pc, pair](const CheckContext& ctx) {
            return worst_ratio(cached(pc.name, [&] { return pc.make(ctx); }), pair);
          },
          .recorded = pair ? pc.recorded_pair : pc.recorded_tooth, .recorded_tolerance = 0.1});
    }
    Registry::instance().add(CheckSpec{
        .id = fmt::format("fe_tooth.convergence.{}", pc.name), .section = section, .solver = "fe_tooth",
        .reference = "its own refinement", .quantity = "largest relative change over the last refinement",
        .unit = "-", .tolerance = {0.005, 0.0},
        .justification = "the issue's convergence bar: < 0.5 % over the last two Kelly refinements",
        .tier = Tier::full, .run = [pc](const CheckContext& ctx) {
          const auto& c = cached(pc.name, [&] { return pc.make(ctx); });
          return CheckValue{c.max_change, 0.0, {{"observed_rates", c.rates}, {"path_mismatch_m", c.path_mismatch}}};
        }});
  }
  return true;
}();

/// Full tier: the FE-versus-energy curves over A..E for every pair, and one convergence table.
const RegisterSection fe_section(SectionSpec{
    .id = "fe_tooth", .tier = Tier::full, .add = [](const CheckContext& ctx, reports::Report& report) {
      for (const auto& pc : pair_cases()) {
        if (pc.positions < 5) continue;
        const auto& c = cached(pc.name, [&] { return pc.make(ctx); });
        const auto s_mm = scaled(c.s, 1e3);
        report.figures.push_back(
            {"fe_tooth_" + pc.name, section, "FE against energy method along A..E, " + pc.name,
             "s from T1 [mm]", "k [1e8 N/m]",
             {{"energy method", s_mm, scaled(c.em_pair, 1e-8)},
              {"FE teeth + Hertz", s_mm, scaled(c.fe_pair, 1e-8)},
              {"FE teeth with FE contact", s_mm, scaled(c.fe_pair_contact, 1e-8)}}});
        if (pc.name == "seed003")
          report.notes.push_back({section, "Convergence of the seed 003 pinion tooth at A (deal.II "
                                           "ConvergenceTable; rate = order in h of the change):\n\n```\n" +
                                               c.table + "```\nFE time per position (both teeth): " +
                                               fmt::format("{:.1f} s; energy method: {:.1f} µs.", c.fe_seconds,
                                                           1e6 * c.em_seconds)});
      }
    }});

// Plane-stress cantilever L/H = 5 under a parabolic end shear, fully clamped end, against
// Timoshenko (bending + shear with Cowper's κ). The shear term is 3 % of the deflection;
// the 2D clamp also restrains the section's warping, which the beam model does not, and
// that is a shear-term effect. So the FE must agree to within the shear term itself.
const RegisterCheck cantilever(CheckSpec{
    .id = "fe_tooth.cantilever_timoshenko", .section = section, .solver = "fe_tooth",
    .reference = "Timoshenko beam (Cowper κ)", .quantity = "FE tip deflection / Timoshenko",
    .unit = "-", .tolerance = {0.0, 0.03},
    .justification = "the shear term (3.0 % at L/H = 5) bounds the end-restraint effect; FE converged to 1e-5",
    .tier = Tier::fast, .run = [](const CheckContext&) {
      fe::ElasticOptions o;
      o.max_cycles = 10;
      o.tolerance = 1e-5;
      const auto r = fe::solve_cantilever(fe::Cantilever{}, o);
      return CheckValue{r.deflection / r.timoshenko, 1.0,
                        {{"shear_share", r.shear / r.timoshenko}, {"observed_rate", r.fe.observed_rate},
                         {"dofs", r.fe.cycles.back().dofs}, {"table", r.fe.table}}};
    }});

}  // namespace
}  // namespace gearbench::verification
