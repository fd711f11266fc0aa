// ISO/TR 15144-1 method B on seed 001 (cases/seed001_micropitting.json): the paper's statements
// about the ISO film (minimum at A, a jump at the pitch point C), its FZG reference-test
// pressure, a cross-check of the TR's film groups against the Dowson–Higginson reference of
// reference/closed_form/ehl_closed_form, and a report section with the seven-point series and
// S_λ. The paper prints no ISO numbers for the wind gear (its figures 1–3 are not readable
// here), so the series are recorded in the report, not checked against the paper.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "check_registry.h"
#include "closed_form/ehl_closed_form.h"
#include "micropitting/iso15144_micropitting.h"
#include "geometry/gear_pair_geometry.h"
#include "micropitting/iso15144_case.h"
#include "model/json_reader.h"

namespace gearbench::verification {
namespace {

namespace iso = micropitting::iso15144;

const char* section = "Micropitting, ISO/TR 15144-1 method B (seed 001)";
const char* solver = "iso15144 (reference/closed_form)";
const char* seed_file = "seed001_micropitting.json";

micropitting::MicropittingCase seed_case(const CheckContext& ctx) {
  const auto json = model::read_json_file(ctx.case_path(seed_file));
  model::ObjectReader root(json, "");
  root.string("kind");
  root.optional_string("description");
  const auto gear_case = model::read_gear_case(root);
  auto mc = micropitting::read_micropitting(root, gear_case, "micropitting_iso");
  root.finish();
  return mc;
}

iso::Assessment seed_assessment(const CheckContext& ctx) {
  const auto mc = seed_case(ctx);
  return iso::assess(mc.gear, mc.test, mc.material_factor);
}

nlohmann::json lambda_series(const iso::Result& r) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& y : r.points) j[y.name] = y.lambda;
  return j;
}

const RegisterCheck film_min_at_A(CheckSpec{
    .id = "seed001.iso15144.film_min_at_A", .section = section, .solver = solver,
    .reference = "seed 001 (minimum film of the unmodified wind gear at A)",
    .quantity = "1 if the smallest λ_GF,Y of A..E is at A", .unit = "-", .tolerance = {0, 0},
    .justification = "a yes/no statement of the paper", .tier = Tier::fast,
    .run = [](const CheckContext& ctx) {
      const auto a = seed_assessment(ctx);
      return CheckValue{a.gear.lambda_min_at == "A" ? 1.0 : 0.0, 1.0,
                        {{"lambda_GF", lambda_series(a.gear)}, {"S_lambda", a.S_lambda}}};
    }});

// The seed describes the jump for its fig. 1, the ISO/TR 15144-1 Annex B example, whose
// flash temperatures exceed 100 K away from C. The wind gear under the planetary reading of
// its load (the case description) has flash temperatures of 10–41 K, and its film at C stands
// only ~6 % above B and D: recorded as missed, with that reason.
const RegisterCheck film_jump_at_C(CheckSpec{
    .id = "seed001.iso15144.film_jump_at_C", .section = section, .solver = solver,
    .reference = "seed 001 (ISO film at C markedly above the neighbouring points: no flash temperature)",
    .quantity = "h_C / max(h_B, h_D), a marked jump: 1.1 … 1.5", .unit = "-", .tolerance = {0.2, 0},
    .justification = "the paper's statement is qualitative; 10–50 % above the neighbours counts as the jump it "
                     "describes (flash temperature 0 at C, >100 K elsewhere in its fig. 1 example)",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto a = seed_assessment(ctx);
      const auto& p = a.gear.points;
      return CheckValue{p[3].h / std::max(p[2].h, p[4].h), 1.3,
                        {{"flash_temperature_B_K", p[2].flash_temperature},
                         {"flash_temperature_D_K", p[4].flash_temperature}}};
    },
    .recorded = 1.0632, .recorded_tolerance = 0.01});

// The paper's test-gear pressure at A came from method A (a loaded-contact analysis, with
// Kissling's data); method B's load sharing of an unmodified spur pair (X_A = 1/3) at the
// paper's 265.1 N·m (FZG load stage 10, 0.35 m arm) gives 12 % less: 1293.7 MPa with the
// case's E = 200 GPa, 1313 MPa with 206 GPa; the paper's value needs X_A ≈ 0.42. Recorded,
// not tuned.
const RegisterCheck test_pressure_A(CheckSpec{
    .id = "seed001.iso15144.reference_test_p_H_A", .section = section, .solver = solver,
    .reference = "seed 001 (FZG C-GF, SKS 10: p_H at A = 1476.2 MPa, 265.1 N·m)",
    .quantity = "Hertzian pressure at A of the FZG C-type test gear, method B", .unit = "MPa",
    .tolerance = {0.05, 0}, .justification = "the paper prints 0.1 MPa",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto a = seed_assessment(ctx);
      const auto& A = a.reference_test.points[0];
      return CheckValue{A.p_dyn * 1e-6, 1476.2,
                        {{"load_sharing_factor_A", A.load_share}, {"rho_n_A_mm", A.rho_n * 1e3},
                         {"lambda_GFT", a.lambda_GFT}}};
    },
    .recorded = 1293.6898, .recorded_tolerance = 1e-6});

// The TR's film (4) with S_GF = 1 is Dowson & Higginson's 1.6·G^0.6·U^0.7·W^−0.13; the
// project's Dowson–Higginson reference is the later 2.65·G^0.54·U^0.7·W^−0.13. With the same U
// (mean speed), W (load per length over E′R) and G their ratio is exactly (1.6/2.65)·G^0.06,
// so this checks that the TR's groups, built from the gear data here, are the ones the EHL
// references use (a sum speed for U would be 2^0.7 = 1.62 off).
const RegisterCheck film_groups(CheckSpec{
    .id = "seed001.iso15144.film_groups_vs_dowson_higginson", .section = section, .solver = solver,
    .reference = "Dowson–Higginson H_min (reference/closed_form/ehl_closed_form)",
    .quantity = "h_C(TR)/h_DH(2.65) ÷ (1.6/2.65)·G^0.06 at the pitch point", .unit = "-",
    .tolerance = {0, 1e-10}, .justification = "exact identity of two formula routes: rounding only",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto mc = seed_case(ctx);
      const auto r = iso::evaluate(mc.gear);
      const auto& c = r.points[3];
      const auto& g = mc.gear;
      const double K = g.K_A * g.K_v * g.K_Halpha * g.K_Hbeta;
      const double w = K * r.tangential_force * c.load_share /
                       (g.pair.face_width * std::cos(r.transverse_pressure_angle) * std::cos(r.base_helix_angle));
      const reference::LineContact lc{c.rho_n, w, c.v_r1, c.v_r2, r.reduced_modulus, r.eta_M, r.alpha_M};
      const double ratio = c.h / reference::dowson_higginson_h_min(lc);
      return CheckValue{ratio / (1.6 / 2.65 * std::pow(r.materials_parameter, 0.06)), 1.0,
                        {{"h_C_m", c.h}, {"G_M", r.materials_parameter}}};
    }});

// The reference derives its own path of contact; the production geometry must put A..E at the
// same places (distances from T1), or a TEHL-vs-ISO comparison point by point compares
// different contacts.
const RegisterCheck path_points(CheckSpec{
    .id = "seed001.iso15144.path_points_vs_geometry", .section = section, .solver = "geometry",
    .reference = solver, .quantity = "max |position of A..E| difference, reference vs solvers/geometry",
    .unit = "mm", .tolerance = {1e-9, 0},
    .justification = "the same exact construction on two routes: rounding only (~1e-13 mm on 200 mm)",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto mc = seed_case(ctx);
      const auto r = iso::evaluate(mc.gear);
      const geometry::GearPairGeometry g(mc.gear.pair);
      const auto& p = g.path();
      const std::array<double, 7> solver_points = {p.A, p.AB, p.B, p.C, p.D, p.DE, p.E};
      double worst = 0.0;
      for (std::size_t i = 0; i < solver_points.size(); ++i)
        worst = std::max(worst, std::abs(r.points[i].position - solver_points[i]));
      return CheckValue{worst * 1e3, 0.0};
    }});

std::string point_table(const iso::Result& r) {
  std::string t =
      "| point | ρ_n [mm] | X_Y | p_dyn [MPa] | v_g [m/s] | θ_fl [K] | θ_B [K] | S_GF | h_Y [µm] | λ_GF,Y |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& y : r.points)
    t += fmt::format("| {} | {:.2f} | {:.4f} | {:.1f} | {:.4f} | {:.1f} | {:.1f} | {:.4f} | {:.4f} | {:.4f} |\n",
                     y.name, y.rho_n * 1e3, y.load_share, y.p_dyn * 1e-6, y.v_g, y.flash_temperature,
                     y.contact_temperature, y.sliding_parameter, y.h * 1e6, y.lambda);
  return t;
}

const RegisterSection report_section(SectionSpec{
    .id = "iso15144", .tier = Tier::fast, .add = [](const CheckContext& ctx, reports::Report& report) {
      const auto a = seed_assessment(ctx);
      std::vector<double> x, gear_h, test_h;
      std::vector<std::string> labels;
      for (std::size_t i = 0; i < a.gear.points.size(); ++i) {
        x.push_back(static_cast<double>(i));
        labels.push_back(a.gear.points[i].name);
        gear_h.push_back(a.gear.points[i].h * 1e6);
        test_h.push_back(a.reference_test.points[i].h * 1e6);
      }
      reports::Figure f{"iso15144_seed001_film", section,
                        "ISO/TR 15144-1 method B local film h_Y: seed 001 wind gear and its FZG C-GF reference test",
                        "contact point", "h_Y [µm]", {{"wind gear", x, gear_h}, {"FZG C-GF test, SKS 10", x, test_h}}};
      f.xtic_labels = labels;
      f.points = true;
      report.figures.push_back(f);
      report.notes.push_back(
          {section,
           fmt::format("Seed 001, ISO/TR 15144-1 method B (cases/seed001_micropitting.json; the choices the seed "
                       "leaves open are in the case description). Wind gear: μ_m = {:.4f}, H_V = {:.4f}, "
                       "θ_M = {:.1f} K, ε_α = {:.4f}, ε_β = {:.4f}.\n\n{}\nReference test (FZG C-GF/8.3/90, SKS 10, "
                       "same oil): μ_m = {:.4f}, θ_M = {:.1f} K.\n\n{}\nλ_GF,min = {:.4f} at {}, λ_GFT = {:.4f}, "
                       "λ_GFP = 1.4·λ_GFT = {:.4f}, **S_λ = {:.4f}**. The load is the planetary reading of the seed's "
                       "table (p_dyn = {:.0f} MPa at C): read literally, 2470 kW at 20 r/min on one 21/35 mesh "
                       "gives p_dyn ≈ 3.7 GPa at C and 4.9 GPa at A (λ_GF,min = 0.0066, S_λ = 0.040), beyond what "
                       "a case-hardened flank carries, so the power and speed are taken as the stage input (planet "
                       "carrier) with three planets and a fixed 91-tooth ring (gearbench's assumptions; the case "
                       "description has the numbers). The paper gives the ISO series only in its figures 1–3.",
                       a.gear.friction_coefficient, a.gear.loss_factor, a.gear.bulk_temperature,
                       a.gear.contact_ratio_transverse, a.gear.contact_ratio_overlap, point_table(a.gear),
                       a.reference_test.friction_coefficient, a.reference_test.bulk_temperature,
                       point_table(a.reference_test), a.gear.lambda_min, a.gear.lambda_min_at, a.lambda_GFT,
                       a.lambda_GFP, a.S_lambda, a.gear.points[3].p_dyn * 1e-6)});
    }});

}  // namespace
}  // namespace gearbench::verification
