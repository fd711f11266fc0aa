// The deal.II finite-element tooth reference (reference/fe_tooth) on its own (the
// cantilever against Timoshenko beam theory) and with the seed 003 pitch crack as a slit
// against the energy method's cracked tooth (stiffness loss against crack length). The
// healthy teeth against the energy method: fe_energy_checks.cpp. docs/fe-tooth-model.md
// explains what the FE compliance means and where the models part.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <functional>

#include "check_registry.h"
#include "fe_cache.h"
#include "fe_tooth/cantilever.h"
#include "fe_tooth/fe_tooth_stiffness.h"
#include "stiffness/pair_stiffness.h"

namespace gearbench::verification {
namespace {

namespace fe = reference::fe;

const char* section = "Finite-element tooth reference (deal.II)";
const char* solver = "stiffness";

// ---- Cracked tooth (seed 003: pitch crack at 45°, q = 0, 1, 2, 2.5 mm, pinion) ----

/// Pair-stiffness loss 1 − k(q)/k(0) against crack length, FE slit against the energy
/// method's limiting-line crack, at positions s (the wheel stays healthy).
struct CrackSweep {
  std::vector<double> lengths;                   ///< q [m]
  std::vector<double> s;                         ///< path positions [m]
  std::vector<std::vector<double>> fe_loss, em_loss;  ///< [length][position]
  std::vector<std::vector<double>> fe_tooth;     ///< pinion tooth compliance [m/N] [length][position]
  double max_change = 0.0;                       ///< largest last relative change of a solve
  double fe_tolerance = 0.0;                     ///< the FE solves' relative tolerance
  double min_probe_to_crack = 1.0;               ///< closest probe to the slit [m]
  double fe_seconds = 0.0;
};

/// The cracked tooth is compared on seed 003's own tooth model, the circular-arc fillet, as
/// the seed 003 crack reproduction in stiffness_checks.cpp.
constexpr stiffness::ToothModel seed003_tooth{stiffness::BeamStart::improved, stiffness::Fillet::circular_arc};

CrackSweep crack_sweep(const model::GearCase& gc, const std::vector<double>& lengths,
                       const std::function<std::vector<double>(const fe::ContactPath&)>& positions, double tolerance) {
  const auto& pair = gc.gear_pair;
  const auto& materials = *gc.materials;
  const double angle = 45.0 * M_PI / 180.0;  // seed 003, section 1.3: β = 45°
  const geometry::GearPairGeometry g(pair);
  const std::array<double, 2> bore{0.5 * g.radii(0).root, 0.5 * g.radii(1).root};
  CrackSweep c;
  c.lengths = lengths;
  c.fe_tolerance = tolerance;
  std::vector<double> fe_pair0, em_pair0, wheel;
  std::vector<fe::ToothCompliance> healthy_pinion;
  for (const double q : lengths) {
    fe::FeToothOptions o;
    o.plane_stress = true;  // as the healthy comparison: the energy method's E and G
    o.fe.tolerance = tolerance;
    if (q > 0.0) o.crack = fe::ToothCrack{0, q, angle};
    const fe::FeToothStiffness model(pair, materials, o);
    if (c.s.empty()) c.s = positions(model.path());
    std::optional<stiffness::GearCrack> crack;
    if (q > 0.0) crack = stiffness::GearCrack{{stiffness::Crack::Type::pitch, q, angle}, 0};
    const stiffness::PairStiffness energy(g, materials, seed003_tooth, bore, crack, true);
    std::vector<double> fe_loss, em_loss, tooth;
    for (std::size_t i = 0; i < c.s.size(); ++i) {
      const auto pinion = model.tooth_compliance(0, c.s[i], false, 0.0, q > 0.0 ? &healthy_pinion[i] : nullptr);
      if (q == 0.0) {
        healthy_pinion.push_back(pinion);
        wheel.push_back(model.tooth_compliance(1, c.s[i]).compliance);
      }
      c.max_change = std::max(c.max_change, pinion.fe.cycles.back().change);
      c.fe_seconds += pinion.seconds;
      if (pinion.cracked) c.min_probe_to_crack = std::min(c.min_probe_to_crack, pinion.probe_to_crack);
      const double hertz = fe::hertz_line_compliance(materials[0], materials[1], pair.face_width);
      const double fe_pair = 1.0 / (pinion.compliance + wheel[i] + hertz);
      const double em_pair = pair.face_width / energy.compliance(c.s[i]).total();
      if (q == 0.0) {
        fe_pair0.push_back(fe_pair);
        em_pair0.push_back(em_pair);
      }
      tooth.push_back(pinion.compliance);
      fe_loss.push_back(1.0 - fe_pair / fe_pair0[i]);
      em_loss.push_back(1.0 - em_pair / em_pair0[i]);
    }
    c.fe_loss.push_back(fe_loss);
    c.em_loss.push_back(em_loss);
    c.fe_tooth.push_back(tooth);
  }
  return c;
}

const std::vector<double> seed003_cracks{0.0, 1e-3, 2e-3, 2.5e-3};

/// Fast tier: one position, the pinion's highest point of single-tooth contact (A + p_b),
/// where the crack acts in both models and one tooth pair carries the load; FE tolerance
/// 1 % (coarse: it stops a Kelly cycle or two before the 0.5 % bar). Full tier: 5 positions
/// A..E at the 0.5 % bar.
const CrackSweep& crack_sweep_cached(const CheckContext& ctx, bool full) {
  return cached(full ? "crack_full" : "crack_fast", [&] {
    const auto gc = ctx.gear_case("seed003_spur_stiffness.json");
    if (!full)
      return crack_sweep(gc, seed003_cracks, [](const fe::ContactPath& p) { return std::vector<double>{p.A + p.base_pitch}; },
                         0.01);
    return crack_sweep(gc, seed003_cracks, [](const fe::ContactPath& p) {
      std::vector<double> s;
      for (int i = 0; i < 5; ++i) s.push_back(p.A + (p.E - p.A) * i / 4);
      return s;
    }, 0.005);
  });
}

nlohmann::json crack_table(const CrackSweep& c) {
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t k = 0; k < c.lengths.size(); ++k)
    for (std::size_t i = 0; i < c.s.size(); ++i)
      rows.push_back({{"crack_mm", c.lengths[k] * 1e3}, {"s_mm", c.s[i] * 1e3},
                      {"fe_pair_loss", c.fe_loss[k][i]}, {"energy_pair_loss", c.em_loss[k][i]},
                      {"fe_pinion_compliance_m_per_N", c.fe_tooth[k][i]}});
  return {{"rows", rows}, {"max_last_change", c.max_change}, {"min_probe_to_crack_mm", 1e3 * c.min_probe_to_crack},
          {"fe_seconds", c.fe_seconds}};
}

/// Steps q_k → q_{k+1} at which the FE pinion compliance fails to grow by more than the FE
/// tolerance (relative), at every position: growth within the FE's own error proves nothing.
CheckValue fe_non_monotonic(const CrackSweep& c) {
  int bad = 0;
  for (std::size_t i = 0; i < c.s.size(); ++i)
    for (std::size_t k = 1; k < c.lengths.size(); ++k)
      bad += c.fe_tooth[k][i] > c.fe_tooth[k - 1][i] * (1.0 + c.fe_tolerance) ? 0 : 1;
  auto d = crack_table(c);
  d["fe_tolerance"] = c.fe_tolerance;
  return {static_cast<double>(bad), 0.0, d};
}

/// Largest |FE loss − energy loss| of the pair stiffness over lengths and positions where
/// the energy method's crack acts (its loss > 0: the load above the mouth), with the worst
/// named. Below the mouth the energy method has no crack by construction (seed 003); the
/// FE's loss there is in the rows and in docs/fe-tooth-model.md.
CheckValue crack_loss_gap(const CrackSweep& c) {
  double worst = 0.0;
  std::string where;
  nlohmann::json per_length = nlohmann::json::array();
  for (std::size_t k = 1; k < c.lengths.size(); ++k) {
    double band = 0.0;
    for (std::size_t i = 0; i < c.s.size(); ++i) {
      if (!(c.em_loss[k][i] > 0.0)) continue;
      const double d = c.fe_loss[k][i] - c.em_loss[k][i];
      band = std::max(band, std::abs(d));
      if (std::abs(d) > std::abs(worst)) {
        worst = d;
        where = fmt::format("q = {:.1f} mm at s = {:.3f} mm", c.lengths[k] * 1e3, c.s[i] * 1e3);
      }
    }
    per_length.push_back({{"crack_mm", c.lengths[k] * 1e3}, {"max_abs_loss_difference", band}});
  }
  auto d = crack_table(c);
  d["signed_worst"] = worst;
  d["worst"] = where;
  d["band_per_length"] = per_length;
  return {std::abs(worst), 0.0, d};
}

// Monotonic loss: a longer slit removes material from the load path, so the FE compliance
// must grow with q (Castigliano: cutting a body never stiffens it). Exact count, tolerance 0:
// a step counts as growth only when it exceeds the FE tolerance, so the order shown is not
// FE error (at A + p_b the steps grow it by 3.6, 38 and 42 % against the 1 % tolerance).
// FE against the energy method: the loss is a difference within each model, so the healthy
// pair's common-mode parts (Hertz, foundation) cancel to first order; the a priori band is
// 5 points of pair stiffness (a third of seed 003's headline 14.3 % loss), set before the
// comparison ran. The energy method's limiting-line rule (the cracked side carries nothing
// above the line y = h_c) and the slit (material above the crack still carries load around
// it, but the crack tip concentrates strain) part in both directions; the band reached per
// length is in the diagnostics and docs/fe-tooth-model.md. Over A..E (full tier) the band
// is missed at E with 2.5 mm (FE 56 % against 67 %: the rule thins every section from the
// crack tip up to the tooth tip, while the slit cuts only the sections between its tip and
// its mouth, and the load at E bends the uncut ones above the mouth); the check records
// 0.102, and a drift of > 15 % of it (0.5 % FE tolerance on compliances that differ by a
// factor 3) counts as a regression.
const bool crack_checks = [] {
  for (const bool full : {false, true}) {
    const std::string tag = full ? "seed003_AE" : "seed003_hpstc";
    Registry::instance().add(CheckSpec{
        .id = "fe_tooth.crack." + tag + ".monotonic", .section = section, .solver = "fe_tooth",
        .reference = "Castigliano: a longer cut is never stiffer",
        .quantity = "steps q → q' (0, 1, 2, 2.5 mm) where the FE pinion compliance does not grow by more "
                    "than the FE tolerance",
        .unit = "-", .tolerance = {0.0, 0.0},
        .justification = "exact (Castigliano), once each step must exceed the FE tolerance: the order is then "
                         "not discretisation error",
        .tier = full ? Tier::full : Tier::fast,
        .run = [full](const CheckContext& ctx) { return fe_non_monotonic(crack_sweep_cached(ctx, full)); }});
    Registry::instance().add(CheckSpec{
        .id = "fe_tooth.crack." + tag + ".vs_energy", .section = section, .solver = solver,
        .reference = "deal.II FE tooth with the crack as a slit (gmsh Plugin(Crack))",
        .quantity = "max |FE − energy| pair-stiffness loss 1 − k(q)/k(0), q = 1, 2, 2.5 mm, pitch crack 45°",
        .unit = "-", .tolerance = {0.05, 0.0},
        .justification = "a priori band: the loss is a difference within each model; see the source comment",
        .tier = full ? Tier::full : Tier::fast,
        .run = [full](const CheckContext& ctx) { return crack_loss_gap(crack_sweep_cached(ctx, full)); },
        .recorded = full ? std::optional<double>(0.1020) : std::nullopt, .recorded_tolerance = 0.15});
  }
  return true;
}();

/// The loaded, cracked tooth (seed 003 pinion, 2.5 mm crack, load at A + p_b): the FE
/// solution sampled on a grid and drawn at its deformed position, coloured by von Mises.
reports::Figure stress_picture(const CheckContext& ctx) {
  const auto gc = ctx.gear_case("seed003_spur_stiffness.json");
  fe::FeToothOptions o;
  o.plane_stress = true;
  o.fe.tolerance = 0.01;
  o.crack = fe::ToothCrack{0, 2.5e-3, 45.0 * M_PI / 180.0};
  const fe::FeToothStiffness model(gc.gear_pair, *gc.materials, o);
  const double m = gc.gear_pair.normal_module;
  const auto c = model.tooth_compliance(0, model.path().A + model.path().base_pitch, false, m / 25);
  double u_max = 0.0;
  for (const auto& f : c.fe.field) u_max = std::max(u_max, std::hypot(f.displacement[0], f.displacement[1]));
  const double magnify = u_max > 0.0 ? 0.1 * m / u_max : 0.0;  // largest displacement drawn as 0.1 m_n
  reports::Series field{"FE, plane stress", {}, {}, {}};
  for (const auto& f : c.fe.field) {
    // Tooth upright: its centre line (x) vertical, the loaded flank (y > 0) on the left.
    field.x.push_back(-1e3 * (f.point[1] + magnify * f.displacement[1]));
    field.y.push_back(1e3 * (f.point[0] + magnify * f.displacement[0]));
    field.z.push_back(std::log10(std::max(f.von_mises, 1.0) * 1e-6));
  }
  return {.id = "fe_tooth_crack_von_mises", .section = section,
          .title = fmt::format("Seed 003 pinion, 2.5 mm pitch crack, {:.0f} N/mm at A + p_b; displacement x{:.0f}",
                               o.load_per_width * 1e-3, magnify),
          .xlabel = "across the tooth [mm]", .ylabel = "along the centre line [mm]", .series = {field},
          .colour_label = "log10 von Mises [MPa]"};
}

/// Fast tier: the FE-versus-energy crack curve (the fast checks' sweep, computed once) and
/// the picture of the loaded cracked tooth.
const RegisterSection crack_section(SectionSpec{
    .id = "fe_tooth_crack", .tier = Tier::fast, .add = [](const CheckContext& ctx, reports::Report& report) {
      const auto& c = crack_sweep_cached(ctx, false);
      const auto q_mm = scaled(c.lengths, 1e3);
      std::vector<double> fe_loss, em_loss;
      for (std::size_t k = 0; k < c.lengths.size(); ++k) {
        fe_loss.push_back(100.0 * c.fe_loss[k][0]);
        em_loss.push_back(100.0 * c.em_loss[k][0]);
      }
      report.figures.push_back({.id = "fe_tooth_crack_loss", .section = section,
                                .title = fmt::format("Pair stiffness loss against crack length, seed 003 at "
                                                     "s = {:.3f} mm (A + p_b), pitch crack 45 deg",
                                                     c.s[0] * 1e3),
                                .xlabel = "crack length q [mm]", .ylabel = "1 - k(q)/k(0) [%]",
                                .series = {{"energy method (limiting line)", q_mm, em_loss},
                                           {"FE, crack as a slit", q_mm, fe_loss}},
                                .points = true});
      report.figures.push_back(stress_picture(ctx));
    }});

/// Full tier: the loss along A..E per crack length, FE against the energy method.
const RegisterSection crack_path_section(SectionSpec{
    .id = "fe_tooth_crack_path", .tier = Tier::full, .add = [](const CheckContext& ctx, reports::Report& report) {
      const auto& c = crack_sweep_cached(ctx, true);
      reports::Figure f{.id = "fe_tooth_crack_loss_AE", .section = section,
                        .title = "Pair stiffness loss along A..E, seed 003 pinion, pitch crack 45 deg",
                        .xlabel = "s from T1 [mm]", .ylabel = "1 - k(q)/k(0) [%]", .points = true};
      for (std::size_t k = 1; k < c.lengths.size(); ++k) {
        f.series.push_back({fmt::format("energy, {:.1f} mm", c.lengths[k] * 1e3), scaled(c.s, 1e3),
                            scaled(c.em_loss[k], 100.0), {}});
        f.series.push_back({fmt::format("FE, {:.1f} mm", c.lengths[k] * 1e3), scaled(c.s, 1e3),
                            scaled(c.fe_loss[k], 100.0), {}});
      }
      report.figures.push_back(f);
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
