// Involute geometry against the closed forms of reference/closed_form, and the geometry
// figures of the seed studies. Every tolerance here is at the level of floating-point
// rounding: solver and reference evaluate exact formulas along different routes (Newton
// vs Brent for α_wt, path-of-contact construction vs closed-form ε_α), so a difference
// above ~1e-12 relative means one of them has a wrong formula, not a discretisation.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "check_registry.h"
#include "closed_form/involute_closed_form.h"
#include "geometry/gear_pair_geometry.h"
#include "geometry/load_sharing.h"

namespace gearbench::verification {
namespace {

using geometry::GearPairGeometry;

const char* section = "Involute geometry";
const char* solver = "geometry";
const char* closed_form = "closed form (ISO 21771, GSL Brent)";
constexpr double rounding_rel = 1e-11;
const char* rounding_why =
    "exact formulas on two independent routes; only floating-point rounding (~1e-15 "
    "relative, amplified by at most ~1e3 in differences of radii) separates them";

model::GearPair load_pair(const CheckContext& ctx, const std::string& file) {
  return ctx.gear_case(file).gear_pair;
}

struct SeedCase {
  std::string tag;   // id component
  std::string file;  // under cases/
  bool helical;
};

const SeedCase seed_cases[] = {
    {"seed004_spur", "seed004_spur_geometry.json", false},
    {"seed001_wind", "seed001_wind_geometry.json", true},
    {"seed000_herringbone", "seed000_herringbone_geometry.json", true},
};

void register_identity_checks(const SeedCase& c) {
  const std::string id = "geometry." + c.tag + ".";
  auto add = [&](std::string name, std::string quantity, std::string unit, double abs, double rel,
                 std::string why, std::function<CheckValue(const GearPairGeometry&,
                                                           const reference::InvoluteClosedForm&)> f) {
    const std::string file = c.file;
    Registry::instance().add(CheckSpec{
        .id = id + name, .section = section, .solver = solver, .reference = closed_form,
        .quantity = std::move(quantity), .unit = std::move(unit), .tolerance = {abs, rel},
        .justification = std::move(why), .tier = Tier::fast,
        .run = [file, f](const CheckContext& ctx) {
          const auto pair = load_pair(ctx, file);
          return f(GearPairGeometry(pair), reference::involute_closed_form(pair));
        }});
  };

  add("contact_ratio_transverse", "ε_α from path A..E vs closed form", "-", 0, rounding_rel,
      rounding_why, [](const GearPairGeometry& g, const reference::InvoluteClosedForm& r) {
        return CheckValue{g.contact_ratio_transverse(), r.contact_ratio_transverse};
      });
  add("working_pressure_angle", "α_wt (Newton) vs α_wt (Brent)", "deg", 1e-10, 0,
      "both root finders converge to 1e-15 rad; 1e-10 deg leaves room for tan/acos rounding",
      [](const GearPairGeometry& g, const reference::InvoluteClosedForm& r) {
        return CheckValue{g.working_pressure_angle() * 180 / M_PI,
                          r.working_pressure_angle * 180 / M_PI};
      });
  add("center_distance", "centre distance", "mm", 0, rounding_rel, rounding_why,
      [](const GearPairGeometry& g, const reference::InvoluteClosedForm& r) {
        return CheckValue{g.center_distance() * 1e3, r.center_distance * 1e3};
      });
  add("curvature_sum", "max |ρ1 + ρ2 − a·sin α_wt| along A..E", "mm", 0, rounding_rel,
      rounding_why, [](const GearPairGeometry& g, const reference::InvoluteClosedForm& r) {
        double worst_sum = r.line_of_action_length;
        double worst_dev = 0.0;
        const auto& p = g.path();
        for (int i = 0; i <= 200; ++i) {
          const auto k = g.kinematics(p.A + (p.E - p.A) * i / 200.0, 1.0);
          const double dev = std::abs(k.rho1 + k.rho2 - r.line_of_action_length);
          if (dev >= worst_dev) {
            worst_dev = dev;
            worst_sum = k.rho1 + k.rho2;
          }
        }
        return CheckValue{worst_sum * 1e3, r.line_of_action_length * 1e3,
                          {{"max_deviation_mm", worst_dev * 1e3}, {"points", 201}}};
      });
  add("pitch_point", "T1C vs a·sin α_wt·z1/(z1+z2)", "mm", 0, rounding_rel, rounding_why,
      [](const GearPairGeometry& g, const reference::InvoluteClosedForm& r) {
        return CheckValue{g.path().C * 1e3, r.pitch_point_from_T1 * 1e3};
      });
  add("sliding_at_pitch_point", "|u1 − u2|/ū at C (rolling only)", "-", 1e-12, 0,
      "pure rolling at C is exact; 1e-12 is rounding of ω·ρ products",
      [](const GearPairGeometry& g, const reference::InvoluteClosedForm&) {
        const auto k = g.kinematics(g.path().C, 100.0);
        return CheckValue{std::abs(k.sliding) / k.entrainment, 0.0,
                          {{"entrainment_m_s_at_100_rad_s", k.entrainment}}};
      });
  add("zone_lengths", "single + double zone lengths vs path (2−ε_α + 2(ε_α−1))p_bt", "mm", 0,
      rounding_rel, rounding_why,
      [](const GearPairGeometry& g, const reference::InvoluteClosedForm& r) {
        double single = 0.0, dbl = 0.0;
        for (const auto& z : g.contact_zones()) (z.pairs == 1 ? single : dbl) += z.end - z.begin;
        return CheckValue{(single + dbl) * 1e3,
                          (r.single_contact_length + r.double_contact_length) * 1e3,
                          {{"single_mm", single * 1e3}, {"double_mm", dbl * 1e3},
                           {"single_closed_form_mm", r.single_contact_length * 1e3},
                           {"double_closed_form_mm", r.double_contact_length * 1e3}}};
      });
  add("single_zone_length", "single-contact zone B..D vs (2 − ε_α)·p_bt", "mm", 1e-9, rounding_rel,
      rounding_why, [](const GearPairGeometry& g, const reference::InvoluteClosedForm& r) {
        double single = 0.0;
        for (const auto& z : g.contact_zones()) single += z.pairs == 1 ? z.end - z.begin : 0.0;
        return CheckValue{single * 1e3, r.single_contact_length * 1e3};
      });
  if (c.helical) {
    add("contact_ratio_overlap", "ε_β = b·tan β_b/p_bt vs b·sin β/(π m_n)", "-", 0, rounding_rel,
        rounding_why, [](const GearPairGeometry& g, const reference::InvoluteClosedForm& r) {
          return CheckValue{g.contact_ratio_overlap(), r.contact_ratio_overlap};
        });
    // The contact-line length is piecewise linear in the mesh position with at most four
    // kinks per base pitch; the trapezoidal rule is exact on each linear piece and errs by
    // at most |Δslope|·h²/8 per kink, < 1e-7 relative at 4000 intervals.
    add("mean_contact_line_length", "mean contact-line length over a mesh cycle", "mm", 0, 1e-6,
        "trapezoidal mean of a piecewise-linear function: ≤ 4 kinks × |Δslope|·h²/8 < 1e-7 "
        "relative at 4000 intervals",
        [](const GearPairGeometry& g, const reference::InvoluteClosedForm& r) {
          const int n = 4000;
          const double pb = g.base_pitch_transverse();
          double sum = 0.0;
          for (int i = 0; i <= n; ++i) {
            const double w = (i == 0 || i == n) ? 0.5 : 1.0;
            sum += w * g.contact_line_length(g.path().A + pb * i / n);
          }
          const double halves = g.pair().herringbone ? 2.0 : 1.0;
          return CheckValue{sum / n * 1e3, halves * r.mean_contact_line_length * 1e3,
                            {{"intervals", n}}};
        });
  }
}

const bool identity_checks_registered = [] {
  for (const auto& c : seed_cases) register_identity_checks(c);
  return true;
}();

// Seed 004 (Liu et al. 2019, table 1): 22/32 teeth, m 2 mm, α 25°, standard gears.
// The issue states ε_α ≈ 1.454 for this pair; the printed value has three decimals.
const RegisterCheck seed004_contact_ratio(CheckSpec{
    .id = "seed004.contact_ratio_transverse", .section = "Seed reproductions: geometry",
    .solver = solver, .reference = "seed 004 (issue statement, 3 decimals)",
    .quantity = "ε_α of the 22/32, m 2, α 25° pair", .unit = "-", .tolerance = {5e-4, 0},
    .justification = "the stated value 1.454 is rounded to three decimals (±5e-4)",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) {
      const GearPairGeometry g(load_pair(ctx, "seed004_spur_geometry.json"));
      return CheckValue{g.contact_ratio_transverse(), 1.454};
    }});

// Seed 001 (wind-turbine stage, table 1): a = 476 mm printed to the millimetre.
const RegisterCheck seed001_center_distance(CheckSpec{
    .id = "seed001.zero_backlash_center_distance", .section = "Seed reproductions: geometry",
    .solver = solver, .reference = "seed 001 table 1 (printed a = 476 mm)",
    .quantity = "zero-backlash centre distance from x1 + x2 = 1.5131", .unit = "mm",
    .tolerance = {0.5, 0},
    .justification = "the table prints the centre distance to the millimetre (±0.5 mm)",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) {
      auto pair = load_pair(ctx, "seed001_wind_geometry.json");
      const GearPairGeometry g(pair);
      return CheckValue{g.zero_backlash_center_distance() * 1e3, 476.0,
                        {{"working_pressure_angle_deg", g.working_pressure_angle() * 180 / M_PI}}};
    }});

// Figures and notes: curvature and sliding along the path for seed 004, contact-line
// length over a mesh cycle for the helical seeds, and what the seed 001 table implies.
const RegisterSection geometry_section(SectionSpec{
    .id = "geometry", .tier = Tier::fast, .add = [](const CheckContext& ctx, reports::Report& report) {
      const GearPairGeometry spur(load_pair(ctx, "seed004_spur_geometry.json"));
      const auto& p = spur.path();
      reports::Series rho1{"ρ1 pinion", {}, {}}, rho2{"ρ2 wheel", {}, {}}, red{"R reduced", {}, {}};
      reports::Series srr{"slide-to-roll u_s/ū", {}, {}}, share{"ISO load share X_Γ", {}, {}};
      const geometry::IsoLoadSharing iso;
      for (int i = 0; i <= 100; ++i) {
        const double s = p.A + (p.E - p.A) * i / 100.0;
        const auto k = spur.kinematics(s, 1000.0 * M_PI / 30.0);
        for (auto* series : {&rho1, &rho2, &red, &srr, &share}) series->x.push_back(s * 1e3);
        rho1.y.push_back(k.rho1 * 1e3);
        rho2.y.push_back(k.rho2 * 1e3);
        red.y.push_back(k.reduced_radius * 1e3);
        srr.y.push_back(k.slide_to_roll);
        share.y.push_back(iso.share(spur, s));
      }
      report.figures.push_back({"geometry_seed004_curvature", section,
                                "Seed 004 pair (22/32, m 2, α 25°): radii of curvature along A..E",
                                "position from T1 [mm]", "radius [mm]", {rho1, rho2, red}});
      report.figures.push_back({"geometry_seed004_sliding", section,
                                "Seed 004 pair at 1000 rpm: slide-to-roll ratio and ISO load share",
                                "position from T1 [mm]", "[-]", {srr, share}});

      std::vector<reports::Series> lines;
      for (const auto& [label, file] :
           {std::pair{"seed 001 wind gear (β 10°, b 320 mm)", "seed001_wind_geometry.json"},
            std::pair{"seed 000 herringbone (β 24.43°, 2 × 55 mm)", "seed000_herringbone_geometry.json"}}) {
        const GearPairGeometry g(load_pair(ctx, file));
        reports::Series s{label, {}, {}};
        for (int i = 0; i <= 400; ++i) {
          const double frac = 2.0 * i / 400.0;  // two mesh cycles
          s.x.push_back(frac);
          s.y.push_back(g.contact_line_length(g.path().A + frac * g.base_pitch_transverse()) /
                        g.pair().face_width / (g.pair().herringbone ? 2.0 : 1.0));
        }
        lines.push_back(std::move(s));
      }
      report.figures.push_back({"geometry_contact_lines", section,
                                "Total contact-line length per face width over two mesh cycles",
                                "mesh position [base pitches]", "L / b [-]", lines});

      const GearPairGeometry wind(load_pair(ctx, "seed001_wind_geometry.json"));
      const auto& w = wind.radii(0);
      const auto& w2 = wind.radii(1);
      report.notes.push_back({"Seed reproductions: geometry", fmt::format(
          "**Seed 001 table 1 consistency.** The printed centre distance a = 476 mm agrees with "
          "the shifts x1 + x2 = 1.5131: the zero-backlash centre distance is {:.4f} mm "
          "(α_wt = {:.4f}°). The wheel tip diameter printed as 626.35 mm lies {:.3f} mm from "
          "d + 2m_n(1 + x2) = {:.3f} mm. The pinion tip diameter printed as 309.903 mm cannot "
          "be right: it is below the pinion's reference diameter {:.3f} mm and base diameter "
          "{:.3f} mm, while d + 2m_n(1 + x1) = {:.3f} mm — the printed digits are a "
          "transposition of 395.903. The seed 001 case therefore derives both tip diameters "
          "from the shifts; a case with the printed 309.903 mm is rejected (exit 2, key "
          "gear_pair.tip_diameter_mm[0]).",
          wind.zero_backlash_center_distance() * 1e3, wind.working_pressure_angle() * 180 / M_PI,
          std::abs(626.35 - 2e3 * w2.tip), 2e3 * w2.tip, 2e3 * w.reference, 2e3 * w.base,
          2e3 * w.tip)});
    }});

}  // namespace
}  // namespace gearbench::verification
