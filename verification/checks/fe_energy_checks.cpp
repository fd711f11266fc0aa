// The deal.II finite-element tooth reference (reference/fe_tooth) against the energy method
// (solvers/stiffness) on healthy teeth, per mesh position, per gear and for the pair: seed
// 003's 20/25 pair (fast tier: the middle of A..E), 19/48 m 3.2, 62/62 m 2 and two pairs of
// the ISO 6336 test set (full tier). The energy method runs with its default, the generated
// trochoid fillet, and with the circular arc beside it; at the middle of A..E the gap is
// split into the tooth alone (FE with a rigid body against the beam: bending + shear +
// axial) and the body (the rest against the Sainsot foundation). docs/fe-tooth-model.md
// explains what the FE compliance means and where the models part.
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <functional>

#include "check_registry.h"
#include "fe_cache.h"
#include "fe_tooth/fe_tooth_stiffness.h"
#include "stiffness/pair_stiffness.h"
#include "stiffness_pairs.h"

namespace gearbench::verification {
namespace {

namespace fe = reference::fe;

const char* section = "Finite-element tooth reference (deal.II)";
const char* solver = "stiffness";

constexpr stiffness::ToothModel arc{stiffness::BeamStart::improved, stiffness::Fillet::circular_arc};

/// The energy method along the positions: pair stiffness [N/m] and, per gear, the tooth's
/// compliance [m/N] and its parts (beam = bending + shear + axial, and foundation). The
/// `_at_probe` figures integrate the beam only up to the FE's probe Q, the load line's
/// crossing of the centre line (ToothCompliance::centre_line_point): like for like with the FE.
struct EnergyCurve {
  std::vector<double> pair, pair_at_probe;
  std::array<std::vector<double>, 2> tooth, beam, foundation, tooth_at_probe, beam_at_probe;
};

EnergyCurve energy_curve(const model::GearPair& pair, const std::array<model::Material, 2>& materials,
                         stiffness::ToothModel tooth_model, const std::vector<double>& positions) {
  const geometry::GearPairGeometry g(pair);
  const std::array<double, 2> bore{0.5 * g.radii(0).root, 0.5 * g.radii(1).root};
  const stiffness::PairStiffness energy(g, materials, tooth_model, bore, std::nullopt, true);
  EnergyCurve curve;
  for (const double s : positions) {
    const auto e = energy.compliance(s);
    double at_probe = e.hertz / pair.face_width;
    for (std::size_t k = 0; k < 2; ++k) {
      const int gear = static_cast<int>(k);
      curve.beam[k].push_back(e.tooth[k].sum() / pair.face_width);
      curve.foundation[k].push_back(e.foundation[k] / pair.face_width);
      curve.tooth[k].push_back(curve.beam[k].back() + curve.foundation[k].back());
      curve.beam_at_probe[k].push_back(energy.tooth(gear).centre_line_point(energy.roll_angle(gear, s)).sum() /
                                       pair.face_width);
      curve.tooth_at_probe[k].push_back(curve.beam_at_probe[k].back() + curve.foundation[k].back());
      at_probe += curve.tooth_at_probe[k].back();
    }
    curve.pair.push_back(pair.face_width / e.total());
    curve.pair_at_probe.push_back(1.0 / at_probe);
  }
  return curve;
}

/// FE against the energy method at positions evenly spread over A..E (both ends included;
/// one position: the middle of A..E; an odd count always holds the middle).
struct Comparison {
  std::vector<double> s;                       ///< path positions [m]
  std::vector<double> fe_pair;                 ///< pair stiffness [N/m]
  std::vector<double> fe_pair_contact;         ///< FE pair with its own contact flattening [N/m]
  std::array<std::vector<double>, 2> fe_tooth;  ///< tooth compliance [m/N]
  EnergyCurve trochoid, arc;                   ///< the energy method with each fillet
  double max_change = 0.0;                     ///< largest last relative change of a solve
  std::vector<double> rates;                   ///< observed rate of each solve's last cycle
  double fe_seconds = 0.0;                     ///< FE time per position (both gears)
  double em_seconds = 0.0;                     ///< energy-method time per position
  double path_mismatch = 0.0;                  ///< |A_FE − A_EM| + |E_FE − E_EM| [m]
  std::string table;                           ///< ConvergenceTable of the first pinion solve
};

fe::FeToothOptions plane_stress(bool rigid_body) {
  fe::FeToothOptions options;
  options.plane_stress = true;  // the energy method's E and G = E/(2(1 + ν)): plane stress
  options.rigid_body = rigid_body;
  return options;
}

Comparison compare(const model::GearPair& pair, const std::array<model::Material, 2>& materials, int positions) {
  const fe::FeToothStiffness model(pair, materials, plane_stress(false));
  const geometry::GearPairGeometry g(pair);
  Comparison c;
  const auto& path = model.path();
  c.path_mismatch = std::abs(path.A - g.path().A) + std::abs(path.E - g.path().E);
  for (int i = 0; i < positions; ++i)
    c.s.push_back(positions == 1 ? 0.5 * (path.A + path.E) : path.A + (path.E - path.A) * i / (positions - 1));
  const auto fe_result = model.solve(c.s);
  const auto start = std::chrono::steady_clock::now();
  c.trochoid = energy_curve(pair, materials, stiffness::ToothModel{}, c.s);
  c.em_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / positions;
  c.arc = energy_curve(pair, materials, arc, c.s);
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

struct PairCase {
  std::string name;
  Tier tier;
  int positions;
  std::function<std::pair<model::GearPair, std::array<model::Material, 2>>(const CheckContext&)> gears;
  /// max |FE/energy − 1| reached with the generated fillet (2026-11-25) where the a-priori
  /// band is missed; 0: inside it (every tooth check: 11–14 % against 20 %).
  double recorded_pair, recorded_tooth;
};

std::pair<model::GearPair, std::array<model::Material, 2>> seed003_gears(const CheckContext& ctx) {
  const auto c = ctx.gear_case("seed003_spur_stiffness.json");
  return {c.gear_pair, *c.materials};
}

const std::vector<PairCase>& pair_cases() {
  static const std::vector<PairCase> cases{
      // Fast tier: one position (the middle of A..E), ~10 s; the ctest gate and `gearbench
      // verify` each pay it once per process.
      {"seed003_mid", Tier::fast, 1, seed003_gears, 0.1127, 0.0},
      {"seed003", Tier::full, 5, seed003_gears, 0.1127, 0.0},
      {"z19_48_m3_2", Tier::full, 9, [](const CheckContext&) { return std::pair{spur_pair(19, 48, 3.2, 16), steel206}; },
       0.1093, 0.0},
      {"z62_62_m2", Tier::full, 9, [](const CheckContext&) { return std::pair{spur_pair(62, 62, 2.0, 20), steel206}; },
       0.1034, 0.0},
      // Two pairs of the ISO 6336 comparison set (stiffness_checks.cpp): a shifted pinion with
      // R_f below R_b, and 40/80 with R_f above it; 5 positions each (the FE's cost).
      {"iso_z25_50_x0.3_0", Tier::full, 5,
       [](const CheckContext&) { return std::pair{spur_pair(25, 50, 2.0, 20, 0.3, 0.0), steel206}; }, 0.1183, 0.0},
      {"iso_z40_80", Tier::full, 5, [](const CheckContext&) { return std::pair{spur_pair(40, 80, 2.0, 20), steel206}; },
       0.1055, 0.0},
  };
  return cases;
}

const Comparison& comparison(const PairCase& pc, const CheckContext& ctx) {
  return cached(pc.name, [&] {
    const auto [pair, materials] = pc.gears(ctx);
    return compare(pair, materials, pc.positions);
  });
}

/// Largest |FE/energy − 1| over the positions (pair stiffness, or both teeth's compliances)
/// and where it occurs.
struct Gap {
  double worst = 0.0;  ///< signed
  std::string where;
  nlohmann::json ratios = nlohmann::json::array();
};

Gap gap(const Comparison& c, const EnergyCurve& em, bool pair, bool at_probe = false) {
  const auto& em_pair = at_probe ? em.pair_at_probe : em.pair;
  const auto& em_tooth = at_probe ? em.tooth_at_probe : em.tooth;
  Gap g;
  for (std::size_t i = 0; i < c.s.size(); ++i) {
    nlohmann::json row = {{"s_mm", c.s[i] * 1e3}};
    auto consider = [&](double fe_value, double em_value, const std::string& what) {
      const double d = fe_value / em_value - 1.0;
      row[what] = fe_value / em_value;
      if (std::abs(d) > std::abs(g.worst)) {
        g.worst = d;
        g.where = fmt::format("{} at s = {:.3f} mm", what, c.s[i] * 1e3);
      }
    };
    if (pair) {
      consider(c.fe_pair[i], em_pair[i], "pair stiffness");
      row["pair stiffness, FE contact instead of Hertz"] = c.fe_pair_contact[i] / em_pair[i];
    } else {
      consider(c.fe_tooth[0][i], em_tooth[0][i], "gear 1 compliance");
      consider(c.fe_tooth[1][i], em_tooth[1][i], "gear 2 compliance");
    }
    g.ratios.push_back(row);
  }
  return g;
}

CheckValue worst_ratio(const Comparison& c, bool pair, bool at_probe = false) {
  const Gap g = gap(c, c.trochoid, pair, at_probe), circular = gap(c, c.arc, pair, at_probe);
  return {std::abs(g.worst), 0.0, {{"signed_worst", g.worst}, {"worst", g.where}, {"fe_over_energy", g.ratios},
                                   {"circular_arc_signed_worst", circular.worst},
                                   {"circular_arc_fe_over_energy", circular.ratios},
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
// and where the models part, component by component: on the generated fillet the body
// agrees with Sainsot's foundation within 3 % and the remaining 10–12 % of the pair is the
// beam's (the FE tooth alone is 29–37 % stiffer than bending + shear + axial; 14–23 % of the
// beam lies above the probe's section, and with the beam integrated to it the pair is within
// 2.6–4.8 %, checked below as `pair_at_probe`). Where a band is missed the check
// records the figure reached with the generated fillet, and a drift of more than 10 % of it
// (FE convergence tolerance 0.5 % on a ~10–20 % difference is a few per cent of it) is what
// counts as a regression.
const bool energy_checks = [] {
  for (const auto& pc : pair_cases()) {
    for (const bool pair : {true, false}) {
      const double recorded = pair ? pc.recorded_pair : pc.recorded_tooth;
      Registry::instance().add(CheckSpec{
          .id = fmt::format("fe_tooth.vs_energy.{}.{}", pc.name, pair ? "pair" : "tooth"), .section = section,
          .solver = solver, .reference = "deal.II FE tooth (plane stress, bore r_f/2 clamped)",
          .quantity = fmt::format("max |FE/energy − 1| of the {} over {} positions A..E, {}, generated fillet",
                                  pair ? "pair stiffness" : "tooth compliance (both gears)", pc.positions, pc.name),
          .unit = "-", .tolerance = {pair ? 0.10 : 0.20, 0.0},
          .justification = pair ? "a priori band for two tooth models of different physics (beam + "
                                  "fitted foundation vs 2D continuum); see the comment in the source"
                                : "per tooth the pair's common Hertz term no longer dilutes the difference",
          // The fast tier keeps only seed 003's pair check: each ctest case is its own
          // process, so every FE check there would pay the FE solves again.
          .tier = pair ? pc.tier : Tier::full,
          .run = [pc, pair](const CheckContext& ctx) { return worst_ratio(comparison(pc, ctx), pair); },
          .recorded = recorded > 0.0 ? std::optional<double>(recorded) : std::nullopt,
          .recorded_tolerance = 0.1});
    }
    // Like for like: the FE probes Q, where the load line crosses the centre line, and the
    // energy method's beam integrated to Q is the beam's own displacement of that point. The
    // a-priori 10 % band of the pair stands unchanged; the shear of the piece between Q's
    // section and the load's (14–21 % of the beam at mid-path) is then in neither model.
    Registry::instance().add(CheckSpec{
        .id = fmt::format("fe_tooth.vs_energy.{}.pair_at_probe", pc.name), .section = section, .solver = solver,
        .reference = "deal.II FE tooth (plane stress, bore r_f/2 clamped)",
        .quantity = fmt::format("max |FE/energy − 1| of the pair stiffness over {} positions A..E, {}, generated "
                                "fillet, the beam integrated to the FE's probe section", pc.positions, pc.name),
        .unit = "-", .tolerance = {0.10, 0.0},
        .justification = "the pair's a-priori band, with both models' tooth compliance taken at the same point",
        .tier = Tier::full,
        .run = [pc](const CheckContext& ctx) { return worst_ratio(comparison(pc, ctx), true, true); }});
    Registry::instance().add(CheckSpec{
        .id = fmt::format("fe_tooth.convergence.{}", pc.name), .section = section, .solver = "fe_tooth",
        .reference = "its own refinement", .quantity = "largest relative change over the last refinement",
        .unit = "-", .tolerance = {0.005, 0.0},
        .justification = "the issue's convergence bar: < 0.5 % over the last two Kelly refinements",
        .tier = Tier::full, .run = [pc](const CheckContext& ctx) {
          const auto& c = comparison(pc, ctx);
          return CheckValue{c.max_change, 0.0, {{"observed_rates", c.rates}, {"path_mismatch_m", c.path_mismatch}}};
        }});
  }
  return true;
}();

/// The gap at the middle of A..E split by component, per gear: the FE tooth alone (body
/// inside the root circle 1000× stiffer) against the beam (bending + shear + axial), and
/// the FE body (total − tooth alone) against the Sainsot foundation, for both fillets.
struct Split {
  std::array<double, 2> fe_total{}, fe_tooth_alone{};
  std::array<double, 2> beam{}, beam_at_probe{}, foundation{}, beam_arc{}, foundation_arc{};
};

Split split_at_middle(const PairCase& pc, const CheckContext& ctx) {
  const auto& c = comparison(pc, ctx);
  const std::size_t mid = c.s.size() / 2;
  const auto [pair, materials] = pc.gears(ctx);
  const fe::FeToothStiffness rigid(pair, materials, plane_stress(true));
  Split s;
  for (std::size_t k = 0; k < 2; ++k) {
    s.fe_total[k] = c.fe_tooth[k][mid];
    s.fe_tooth_alone[k] = rigid.tooth_compliance(static_cast<int>(k), c.s[mid]).compliance;
    s.beam[k] = c.trochoid.beam[k][mid];
    s.beam_at_probe[k] = c.trochoid.beam_at_probe[k][mid];
    s.foundation[k] = c.trochoid.foundation[k][mid];
    s.beam_arc[k] = c.arc.beam[k][mid];
    s.foundation_arc[k] = c.arc.foundation[k][mid];
  }
  return s;
}

std::string gap_table(const CheckContext& ctx) {
  std::string rows;
  for (const auto& pc : pair_cases()) {
    if (pc.positions < 5) continue;
    const auto& c = comparison(pc, ctx);
    rows += fmt::format("| {} | {} | {:+.1f} % | {:+.1f} % | {:+.1f} % | {:+.1f} % | {:+.1f} % | {:+.1f} % |\n",
                        pc.name, c.s.size(), 100 * gap(c, c.arc, true).worst, 100 * gap(c, c.trochoid, true).worst,
                        100 * gap(c, c.trochoid, true, true).worst, 100 * gap(c, c.arc, false).worst,
                        100 * gap(c, c.trochoid, false).worst, 100 * gap(c, c.trochoid, false, true).worst);
  }
  return "**FE against the energy method**, largest FE/energy − 1 over A..E (plane stress, bore r_f/2; "
         "pair = FE teeth + Hertz; 'to Q': the beam integrated to the FE's probe section):\n\n| pair | positions | "
         "pair, arc | pair, trochoid | pair, trochoid, to Q | tooth, arc | tooth, trochoid | tooth, trochoid, to Q "
         "|\n|---|---|---|---|---|---|---|---|\n" + rows;
}

std::string split_table(const CheckContext& ctx) {
  std::string rows;
  for (const auto& pc : pair_cases()) {
    if (pc.positions < 5) continue;
    const auto [pair, materials] = pc.gears(ctx);
    const Split s = cached("split_" + pc.name, [&] { return split_at_middle(pc, ctx); });
    for (std::size_t k = 0; k < 2; ++k) {
      const double fe_body = s.fe_total[k] - s.fe_tooth_alone[k];
      rows += fmt::format("| {} z {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.2f} : {:.2f} |\n",
                          pc.name, pair.teeth[k], s.fe_total[k] / (s.beam[k] + s.foundation[k]),
                          s.fe_total[k] / (s.beam_arc[k] + s.foundation_arc[k]), s.fe_tooth_alone[k] / s.beam[k],
                          s.fe_tooth_alone[k] / s.beam_at_probe[k], fe_body / s.foundation[k], fe_body / s.foundation_arc[k],
                          s.beam[k] / (s.beam[k] + s.foundation[k]), s.foundation[k] / (s.beam[k] + s.foundation[k]));
    }
  }
  return "**The gap by component** at the middle of A..E, FE/energy per tooth: the FE tooth alone (body "
         "inside the root circle 1000× stiffer) against the beam (bending + shear + axial, generated fillet), "
         "the same beam integrated only to the FE's probe section Q, "
         "the FE body (total − tooth alone) against the Sainsot foundation on each fillet:\n\n"
         "| gear | tooth, trochoid | tooth, arc | tooth alone / beam | tooth alone / beam to Q | "
         "body / foundation (trochoid) | body / foundation (arc) | beam : foundation |\n"
         "|---|---|---|---|---|---|---|---|\n" + rows;
}

/// Full tier: the FE-versus-energy curves over A..E for every pair, the gap tables, and one
/// convergence table.
const RegisterSection fe_section(SectionSpec{
    .id = "fe_tooth", .tier = Tier::full, .add = [](const CheckContext& ctx, reports::Report& report) {
      for (const auto& pc : pair_cases()) {
        if (pc.positions < 5) continue;
        const auto& c = comparison(pc, ctx);
        const auto s_mm = scaled(c.s, 1e3);
        report.figures.push_back(
            {"fe_tooth_" + pc.name, section, "FE against energy method along A..E, " + pc.name,
             "s from T1 [mm]", "k [1e8 N/m]",
             {{"energy method, generated fillet", s_mm, scaled(c.trochoid.pair, 1e-8)},
              {"energy method, circular arc", s_mm, scaled(c.arc.pair, 1e-8)},
              {"FE teeth + Hertz", s_mm, scaled(c.fe_pair, 1e-8)},
              {"FE teeth with FE contact", s_mm, scaled(c.fe_pair_contact, 1e-8)}}});
        if (pc.name == "seed003")
          report.notes.push_back({section, "Convergence of the seed 003 pinion tooth at A (deal.II "
                                           "ConvergenceTable; rate = order in h of the change):\n\n```\n" +
                                               c.table + "```\nFE time per position (both teeth): " +
                                               fmt::format("{:.1f} s; energy method: {:.1f} µs.", c.fe_seconds,
                                                           1e6 * c.em_seconds)});
      }
      report.notes.push_back({section, gap_table(ctx)});
      report.notes.push_back({section, split_table(ctx)});
    }});

}  // namespace
}  // namespace gearbench::verification
