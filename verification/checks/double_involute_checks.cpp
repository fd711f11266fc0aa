// Double-involute pair of seed 002 (issue 10): the geometry reduces to the ordinary involute
// for a zero step and agrees with the direct construction of reference/construction; the
// oil-film stiffness over the mesh period is compared with the ordinary pair's, and the
// ratio of the two against the ratio a closed-form film law gives on the same contacts.
// Figures: the two rack profiles, the contact-line lengths and the film stiffness over the
// mesh period of both tooth forms.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gsl/gsl_integration.h>
#include <memory>

#include "check_registry.h"
#include "closed_form/ehl_closed_form.h"
#include "construction/double_involute_contact.h"
#include "ehl/oil_film_stiffness.h"
#include "geometry/double_involute.h"
#include "model/json_reader.h"

namespace gearbench::verification {
namespace {

using geometry::DoubleInvolutePair;
using geometry::ToothZone;

const std::string section = "Double-involute gears: contact lines and oil-film stiffness";
const std::string case_file = "seed002_double_involute_oil_film.json";

/// The rack section of the case (the kind's own reader lives in the app; these keys are
/// plain numbers, range-checked by DoubleInvolutePair).
model::DoubleInvoluteRack case_rack(const CheckContext& ctx) {
  const auto j = model::read_json_file(ctx.case_path(case_file)).at("double_involute");
  model::DoubleInvoluteRack r;
  r.tip_tangential_shift = j.at("tip_tangential_shift").get<double>();
  r.root_tangential_shift = j.at("root_tangential_shift").get<double>();
  r.waist_tip_depth = j.at("waist_tip_depth").get<double>();
  r.waist_root_depth = j.at("waist_root_depth").get<double>();
  return r;
}

const RegisterCheck zero_step(CheckSpec{
    .id = "double_involute.zero_step", .section = section, .solver = "geometry.double_involute",
    .reference = "GearPairGeometry::contact_line_length (ordinary involute, ISO 21771)",
    .quantity = "largest relative deviation of L(t) over a mesh period, zero step", .unit = "-",
    .tolerance = {1e-12, 0},
    .justification = "the same clipped lengths summed per zone instead of per pair: rounding only",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto c = ctx.gear_case(case_file);
      const geometry::GearPairGeometry g(c.gear_pair);
      const DoubleInvolutePair ordinary(g, {});
      double worst = 0.0;
      for (int i = 0; i < 200; ++i) {
        const double tau = (i + 0.37) / 200 * g.base_pitch_transverse();
        const double l = g.contact_line_length(g.path().A + tau);
        worst = std::max(worst, std::abs(ordinary.contact_line_length(tau) - l) / l);
      }
      return CheckValue{worst, 0.0};
    }});

const RegisterCheck construction(CheckSpec{
    .id = "double_involute.contact_lines_vs_construction", .section = section,
    .solver = "geometry.double_involute", .reference = "flank/line-of-action intersection slice by slice (reference/construction)",
    .quantity = "largest |L(t) − L_ref(t)| and |L_G2, L_D2 − ref| over 24 instants of a mesh period", .unit = "m",
    .tolerance = {1e-9, 0},
    .justification = "the construction resolves piece ends by bisection and intersections by Brent to ~1e-16 m; "
                     "1e-9 m (1e-8 of a line) is rounding with margin, a wrong step or zone end shows as mm",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto c = ctx.gear_case(case_file);
      const auto rack = case_rack(ctx);
      const geometry::GearPairGeometry g(c.gear_pair);
      const DoubleInvolutePair di(g, rack);
      const reference::DoubleInvoluteConstruction ref(c.gear_pair, rack);
      double worst = 0.0, conjugacy = 0.0;
      for (int i = 0; i < 24; ++i) {
        const double tau = (i + 0.5) / 24 * g.base_pitch_transverse();
        const auto r = ref.at(ref.engagement_angle() + tau / ref.base_radius_pinion());
        double root2 = 0.0, tip2 = 0.0;  // the second pair is the construction's tooth −1
        for (const auto& p : r.pieces)
          if (p.tooth == -1) (p.tip_zone ? tip2 : root2) += p.length;
        worst = std::max({worst, std::abs(di.contact_line_length(tau) - r.total_length),
                          std::abs(di.pair_contact_length(2, ToothZone::root, tau) - root2),
                          std::abs(di.pair_contact_length(2, ToothZone::tip, tau) - tip2)});
        conjugacy = std::max(conjugacy, r.conjugacy_error);
      }
      return CheckValue{worst, 0.0, {{"conjugacy_error_m", conjugacy}, {"step_m", di.step()}}};
    }});

/// The mesh-period film stiffness of the case's stepped pair and of the ordinary pair.
struct Comparison {
  ehl::MeshPeriodOilFilmResult stepped, ordinary;
};

/// The case's instants, points per piece and perturbation.
ehl::MeshPeriodOilFilmOptions case_options(const CheckContext& ctx) {
  const auto j = model::read_json_file(ctx.case_path(case_file));
  ehl::MeshPeriodOilFilmOptions o;
  o.samples = j.at("mesh_samples").get<int>();
  o.points_per_piece = j.at("points_per_piece").get<int>();
  o.perturbation = j.at("perturbation").get<double>();
  return o;
}

Comparison compare(const CheckContext& ctx) {
  const auto c = ctx.gear_case(case_file);
  const geometry::GearPairGeometry g(c.gear_pair);
  const DoubleInvolutePair stepped(g, case_rack(ctx)), ordinary(g, {});
  const auto fluid = ehl::LineContactData::from_gear_media(*c.materials, *c.lubricant);
  return {ehl::MeshPeriodOilFilm(stepped, *c.operating, fluid, case_options(ctx)).solve(),
          ehl::MeshPeriodOilFilm(ordinary, *c.operating, fluid, case_options(ctx)).solve()};
}

/// The same mean over the same contacts and quadrature with the Dowson–Toyoda central film
/// h_c ∝ w^−0.10 instead of the EHL solves: k_oil = −dw/dh_c = w/(0.10·h_c).
double closed_form_mean(const CheckContext& ctx, const DoubleInvolutePair& pair) {
  const auto c = ctx.gear_case(case_file);
  const auto& g = pair.geometry();
  const auto o = case_options(ctx);
  const auto fluid = ehl::LineContactData::from_gear_media(*c.materials, *c.lubricant);
  const double beta_b = g.base_helix_angle();
  const double force = c.operating->pinion_torque / (g.radii(0).base * std::cos(beta_b));
  const std::unique_ptr<gsl_integration_glfixed_table, decltype(&gsl_integration_glfixed_table_free)> table(
      gsl_integration_glfixed_table_alloc(static_cast<std::size_t>(o.points_per_piece)),
      &gsl_integration_glfixed_table_free);
  double mean = 0.0;
  for (int i = 0; i < o.samples; ++i) {
    const double tau = (i + 0.5) / o.samples * g.base_pitch_transverse();
    const double w = force / pair.contact_line_length(tau);
    auto k_oil = [&](double s) {
      const auto k = g.kinematics(s, c.operating->pinion_speed);
      const reference::LineContact lc{k.reduced_radius_normal, w, k.u1, k.u2, fluid.reduced_modulus,
                                      fluid.viscosity, fluid.pressure_viscosity};
      return w / (0.10 * reference::dowson_toyoda_h_c(lc));
    };
    for (const auto& p : pair.contact_pieces(tau)) {
      if (beta_b == 0.0) {
        mean += p.length * k_oil(p.s_begin) / o.samples;
        continue;
      }
      for (std::size_t j = 0; j < table->n; ++j) {
        double s = 0.0, weight = 0.0;
        gsl_integration_glfixed_point(p.s_begin, p.s_end, j, &s, &weight, table.get());
        mean += weight / std::sin(beta_b) * k_oil(s) / o.samples;
      }
    }
  }
  return mean;
}

const RegisterCheck film_ratio(CheckSpec{
    .id = "double_involute.film_stiffness_ratio", .section = section, .solver = "ehl.oil_film_stiffness (mesh period)",
    .reference = "the same ratio with the Dowson–Toyoda central film on the same contacts",
    .quantity = "mean film stiffness over the mesh period, double involute over ordinary involute", .unit = "-",
    .tolerance = {0, 0.05},
    .justification = "the two forms' films differ in load per length (×1.6) and in where they sit on the path; "
                     "the EHL film's load exponent (−0.10…−0.15) and speed/radius exponents differ from "
                     "Dowson–Toyoda's by a few hundredths, which moves a ratio of such contacts by a few %",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto r = compare(ctx);
      for (const auto* res : {&r.stepped, &r.ordinary})
        for (const auto& m : res->instants)
          if (!std::isfinite(m.film_stiffness) || m.film_stiffness <= 0.0)
            throw std::runtime_error(fmt::format("film stiffness {} at t = {} s", m.film_stiffness, m.time));
      const auto c = ctx.gear_case(case_file);
      const geometry::GearPairGeometry g(c.gear_pair);
      const DoubleInvolutePair stepped(g, case_rack(ctx)), ordinary(g, {});
      auto range = [](const ehl::MeshPeriodOilFilmResult& res) {
        const auto [lo, hi] = std::minmax_element(res.instants.begin(), res.instants.end(),
                                                  [](auto& a, auto& b) { return a.film_stiffness < b.film_stiffness; });
        return std::vector<double>{lo->film_stiffness, hi->film_stiffness};
      };
      return CheckValue{r.stepped.mean_film_stiffness / r.ordinary.mean_film_stiffness,
                        closed_form_mean(ctx, stepped) / closed_form_mean(ctx, ordinary),
                        {{"double_involute_mean_N_per_m", r.stepped.mean_film_stiffness},
                         {"involute_mean_N_per_m", r.ordinary.mean_film_stiffness},
                         {"double_involute_range_N_per_m", range(r.stepped)},
                         {"involute_range_N_per_m", range(r.ordinary)},
                         {"ehl_solves", r.stepped.solves + r.ordinary.solves},
                         {"seconds", r.stepped.seconds + r.ordinary.seconds}}};
    }});

void add_figures(const CheckContext& ctx, reports::Report& report) {
  const auto c = ctx.gear_case(case_file);
  const auto rack = case_rack(ctx);
  std::vector<reports::Series> profiles;
  for (const auto& [name, r] : {std::pair{"double involute", rack}, std::pair{"ordinary involute", model::DoubleInvoluteRack{}}}) {
    std::vector<double> x, y;
    for (const auto& p : geometry::rack_profile(r, c.gear_pair).flank) {
      x.push_back(p.x);
      y.push_back(p.y);
    }
    profiles.push_back({name, x, y});
  }
  report.figures.push_back({"double_involute_rack", section, "Basic rack flank (seed 002 fig. 1) against the ordinary rack",
                            "along the datum line from the tooth centre [m_n]", "height above the datum line [m_n]",
                            profiles});

  const geometry::GearPairGeometry g(c.gear_pair);
  const DoubleInvolutePair stepped(g, rack), ordinary(g, {});
  std::vector<double> tg, l_di, l_inv, lg2, ld2;  // the geometry on a fine grid (no EHL)
  for (int i = 0; i <= 200; ++i) {
    const double tau = i / 200.0 * g.base_pitch_transverse();
    tg.push_back(i / 200.0);
    l_di.push_back(stepped.contact_line_length(tau) * 1e3);
    l_inv.push_back(ordinary.contact_line_length(tau) * 1e3);
    lg2.push_back(stepped.pair_contact_length(2, ToothZone::root, tau) * 1e3);
    ld2.push_back(stepped.pair_contact_length(2, ToothZone::tip, tau) * 1e3);
  }
  report.figures.push_back({"double_involute_contact_lines", section, "Contact-line lengths over one mesh period",
                            "t / mesh period", "length [mm]",
                            {{"L(t), double involute", tg, l_di}, {"L(t), ordinary involute", tg, l_inv},
                             {"L_G2(t), 2nd pair root zone", tg, lg2}, {"L_D2(t), 2nd pair tip zone", tg, ld2}}});

  const auto r = compare(ctx);
  std::vector<double> t, k_di, k_inv, k2_di, k2_inv;
  for (std::size_t i = 0; i < r.stepped.instants.size(); ++i) {
    const auto& a = r.stepped.instants[i];
    const auto& b = r.ordinary.instants[i];
    t.push_back(a.time / r.stepped.period);
    k_di.push_back(a.film_stiffness * 1e-6);
    k_inv.push_back(b.film_stiffness * 1e-6);
    k2_di.push_back(a.pair2_film_stiffness * 1e-6);
    k2_inv.push_back(b.pair2_film_stiffness * 1e-6);
  }
  report.figures.push_back({"double_involute_oil_film", section, "Oil-film stiffness over one mesh period",
                            "t / mesh period", "film stiffness [N/µm]",
                            {{"double involute, all pairs", t, k_di}, {"ordinary involute, all pairs", t, k_inv},
                             {"double involute, 2nd pair", t, k2_di}, {"ordinary involute, 2nd pair", t, k2_inv}}});
  report.notes.push_back({section, fmt::format(
      "Case {} (gearbench's choice: the seed's fragment gives no gear data). The step δ = {:.3f} mm on the line of "
      "action, zones {:.2f} + {:.2f} base pitches, waist radius ρ_g* = {:.3f}. Over the mesh period the "
      "double-involute film stiffness averages {:.0f} N/µm against {:.0f} N/µm for the ordinary pair "
      "(ratio {:.3f}): its contact lines are shorter ({:.1f}–{:.1f} mm against {:.1f}–{:.1f} mm), so each "
      "carries more load, and the film stiffens faster than linearly with load (k ∝ w^1.1). The tooth "
      "(bending, Hertz) stiffness of the stepped tooth is not modelled, so the film is not put in series here. "
      "{} + {} EHL solves, {:.1f} s.",
      case_file, stepped.step() * 1e3, stepped.zone_contact_ratio(ToothZone::root),
      stepped.zone_contact_ratio(ToothZone::tip), geometry::waist_radius(rack, c.gear_pair.normal_pressure_angle),
      r.stepped.mean_film_stiffness * 1e-6, r.ordinary.mean_film_stiffness * 1e-6,
      r.stepped.mean_film_stiffness / r.ordinary.mean_film_stiffness, *std::min_element(l_di.begin(), l_di.end()),
      *std::max_element(l_di.begin(), l_di.end()), *std::min_element(l_inv.begin(), l_inv.end()),
      *std::max_element(l_inv.begin(), l_inv.end()), r.stepped.solves, r.ordinary.solves,
      r.stepped.seconds + r.ordinary.seconds)});
}

const RegisterSection double_involute_section(SectionSpec{.id = "double_involute", .tier = Tier::fast,
                                                          .add = add_figures});

}  // namespace
}  // namespace gearbench::verification
