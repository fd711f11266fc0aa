// The EHL kinds through the gearbench executable: the line contact, the transient, the oil-film
// stiffness (spur and double involute) and the thermal point and path each run on a small case,
// validate their input (exit 2 naming the key) and report non-convergence (exit 3, diagnostics
// still written, with the converged/message/summary status every kind carries).
#include <gtest/gtest.h>
#include <algorithm>

#include <functional>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_support.h"

namespace {

using nlohmann::json;
using namespace gearbench::testing_support;

/// The sum of a JSON array of numbers.
double sum_of(const json& values) {
  double sum = 0.0;
  for (const auto& v : values) sum += v.get<double>();
  return sum;
}

/// A result's work by part adds up to its work units, and the coarsest grid's start did some.
void expect_work_by_part_adds_up(const json& diagnostics) {
  const double total = diagnostics["work_units"].get<double>();
  double parts = 0.0;
  for (const auto& [part, wu] : diagnostics["work_units_by_part"].items()) parts += wu.get<double>();
  EXPECT_NEAR(parts, total, 1e-9 * total);
  EXPECT_GT(diagnostics["work_units_by_part"]["start"].get<double>(), 0.0);
}

TEST(Cli, EhlLineRunsAndReportsNonConvergence) {
  const auto o = run_gearbench("run " GEARBENCH_SOURCE_DIR "/cases/ehl_moes_M20_L10.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  for (const char* key : {"h_central_m", "h_min_m", "x_h_min_m", "p_max_Pa", "friction_coefficient", "profile"})
    EXPECT_TRUE(r.contains(key)) << key;
  EXPECT_NEAR(r["moes"]["M"].get<double>(), 20.0, 1e-9);
  EXPECT_TRUE(r["diagnostics"]["converged"].get<bool>());
  EXPECT_GT(r["diagnostics"]["residual_history"].size(), 0u);

  // One cycle a level cannot bring the algebraic error to 1e-6 of the discretisation error (a
  // 0.1 % target, used before, is reached in one cycle since the thirteenth session): exit 3, one
  // error line, the diagnostics still written to -o.
  auto j = read_case("ehl_moes_M20_L10");
  j["grid"]["max_cycles"] = 1;
  j["grid"]["error_fraction"] = 1e-6;
  const auto out = temp_path("ehl_unconverged.json").string();
  const auto failed = run_gearbench("run " + write_case("ehl_one_cycle", j.dump()) + " -o " + out);
  EXPECT_EQ(failed.exit_code, 3) << failed.err;
  // Slow builds (sanitizers) also print the progress lines; the error is the one "error:" line.
  EXPECT_NE(failed.err.find("error: EHL multigrid did not reach 1e-06 of its discretisation-error estimate"),
            std::string::npos) << failed.err;
  EXPECT_NE(failed.err.find("in 1 cycles"), std::string::npos) << failed.err;
  EXPECT_EQ(failed.err.find("error:"), failed.err.rfind("error:")) << failed.err;
  std::ifstream diag(out);
  const auto d = json::parse(diag);
  EXPECT_FALSE(d["diagnostics"]["converged"].get<bool>());
  EXPECT_EQ(d["diagnostics"]["residual_history"].size(), 1u);
  fs::remove(out);
}

// Heavy loads on the default grid: the film changes by tens of per cent from the next-coarser
// grid, and the result says so; a converged point does not carry the note.
TEST(Cli, EhlLineSaysWhenTheFilmIsNotGridConverged) {
  // A fixed grid too coarse for the 1 % target: the result says so, with the estimate.
  const auto coarse = run_gearbench(
      "run " + write_case("ehl_coarse", R"({"kind": "ehl_line", "moes": {"M": 20, "L": 10}, "grid": {"nodes": 161}})"));
  ASSERT_EQ(coarse.exit_code, 0) << coarse.err;
  const auto c = json::parse(coarse.out);
  EXPECT_GT(c["diagnostics"]["discretisation_error"]["estimate"].get<double>(), 0.01);
  EXPECT_NE(c["notes"].dump().find("is above the target"), std::string::npos) << c["notes"].dump();

  // The default chooses its grid by the target and meets it.
  const auto light = run_gearbench("run " + write_case("ehl_light", R"({"kind": "ehl_line", "moes": {"M": 20, "L": 10}})"));
  ASSERT_EQ(light.exit_code, 0) << light.err;
  const auto l = json::parse(light.out);
  EXPECT_LE(l["diagnostics"]["discretisation_error"]["estimate"].get<double>(), 0.01);
  EXPECT_EQ(l["notes"].dump().find("is above the target"), std::string::npos);
}

// Issue 20: at high sliding a piezoviscous Newtonian film "carries" a shear force far above
// the normal load (μ = 1.06e5 once, exit 0); the friction is withheld and the note says why.
TEST(Cli, EhlLineWithholdsANewtonianTractionAboveTheLoad) {
  const auto o = run_gearbench("run " + write_case("ehl_sliding", R"({"kind": "ehl_line",
      "contact": {"reduced_radius_m": 0.00551, "load_per_length_N_per_m": 250750,
                  "surface_speeds_m_per_s": [0.0569, 0.9737], "reduced_modulus_Pa": 2.2637e11},
      "lubricant": {"viscosity_Pa_s": 0.08, "pressure_viscosity_1_per_GPa": 24.8, "roelands_z": 0.68},
      "grid": {"nodes": 161}})"));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  EXPECT_TRUE(r["friction_coefficient"].is_null());
  EXPECT_TRUE(r["friction_force_per_length_N_per_m"].is_null());
  EXPECT_GT(r["h_min_m"].get<double>(), 0.0);
  EXPECT_NE(r["notes"].dump().find("would exceed the normal load"), std::string::npos) << r["notes"].dump();
}

// The same for the isothermal comparison of a thermal point at more sliding than the case's.
TEST(Cli, ThermalPointWithholdsTheIsothermalNewtonianTractionAboveTheLoad) {
  auto j = read_case("tehl_point_sliding");
  j["contact"]["surface_speeds_m_per_s"] = {2.5, 1.0687};
  const auto o = run_gearbench("run " + write_case("tehl_sliding", j.dump()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  EXPECT_TRUE(r["isothermal"]["friction_coefficient"].is_null());
  EXPECT_TRUE(r["friction_coefficient"].is_number());  // the thermal film's own stays in range
  EXPECT_NE(r["notes"].dump().find("isothermal solution's Newtonian traction would exceed"), std::string::npos)
      << r["notes"].dump();
}

TEST(Cli, EhlLineBadInput) {
  const std::pair<std::string, std::string> cases[] = {
      {R"({"kind": "ehl_line", "moes": {"M": 20, "L": 10}, "contact": {}})", "give either \"moes\" or"},
      {R"({"kind": "ehl_line", "moes": {"M": 0, "L": 10}})", "moes.M = 0: allowed range is [0.001, 10000]"},
      {R"({"kind": "ehl_line", "moes": {"M": 1000, "L": 25}})", "ᾱ = α·p_h = 315"},
      {R"({"kind": "ehl_line", "contact": {"reduced_radius_m": 0.01, "load_per_length_N_per_m": 1e5,
          "surface_speeds_m_per_s": [0, 0], "reduced_modulus_Pa": 2.2e11},
          "lubricant": {"viscosity_Pa_s": 0.04, "pressure_viscosity_1_per_GPa": 20}})",
       "the entrainment speed must be positive"},
      {R"({"kind": "ehl_line", "moes": {"M": 20, "L": 10}, "grid": {"nodes": 2004}})",
       "grid.nodes = 2004: allowed are (n0 − 1)·2^k + 1 nodes"},
      {R"({"kind": "ehl_line", "moes": {"M": 1000, "L": 0}, "grid": {"nodes": 1025}})",
       "grid.nodes = 1025: too coarse for the film at this load"},
      {R"({"kind": "ehl_line", "moes": {"M": 20, "L": 10}, "grid": {"nodes": 641, "levels": 5}})",
       "grid.nodes: give either nodes or levels (with coarsest_nodes), not both"},
      {R"({"kind": "ehl_line", "moes": {"M": 20, "L": 10}, "grid": {"levels": 5}})",
       "grid.levels = 5: needs grid.coarsest_nodes in [9, 1025] (or give nodes instead)"},
      {R"({"kind": "ehl_line", "moes": {"M": 20, "L": 10}, "grid": {"relaxation": "newton"}})", "grid.relaxation"},
      {R"({"kind": "ehl_line", "contact": {"reduced_radius_m": 0.01, "load_per_length_N_per_m": 1e5,
          "surface_speeds_m_per_s": [1, 1], "reduced_modulus_Pa": 2.2e11},
          "lubricant": {"viscosity_Pa_s": 6e-5, "pressure_viscosity_1_per_GPa": 20}})",
       "lubricant.viscosity_Pa_s = 6e-05: allowed is > 6.31e-05 Pa*s"},
  };
  int n = 0;
  for (const auto& [text, expected] : cases) {
    const auto o = run_gearbench("run " + write_case("ehl_bad_" + std::to_string(n++), text));
    EXPECT_EQ(o.exit_code, 2) << text << "\n" << o.err;
    EXPECT_NE(o.err.find(expected), std::string::npos) << o.err;
  }
}

// A short march (8 steps, 161 nodes) runs through; bad input exits 2 naming the key; a step
// that cannot converge exits 3 with the steps so far in -o.
TEST(Cli, EhlTransientRunsAndValidates) {
  const auto seed = read_case("seed004_transient_ehl");
  auto small = seed;
  small["time_steps"] = 24;
  small["grid"] = {{"nodes", 161}};
  const auto o = run_gearbench("run " + write_case("ehl_transient_small", small.dump()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  EXPECT_EQ(r["steps"]["h_min_m"].size(), 25u);
  for (const char* point : {"A", "B", "C", "D", "E"}) EXPECT_TRUE(r["profiles"].contains(point)) << point;
  EXPECT_GT(r["p_max_Pa"].get<double>(), r["reference"]["hertz_pressure_Pa"].get<double>() * 0.8);
  // The steps' work by part adds up to their work units; the spike and the start did some.
  const auto& work = r["diagnostics"];
  expect_work_by_part_adds_up(work);
  EXPECT_GT(work["work_units_by_part"]["spike"].get<double>(), 0.0);
  EXPECT_LT(work["work_units_iterating"].get<double>(), work["work_units"].get<double>());
  // Each step's work and start: they add up to the diagnostics'. The steady first step and the
  // first transient one are solved by full multigrid, and at least one later step warm.
  const auto& series = r["steps"];
  const auto by_full_multigrid = std::count(series["full_multigrid"].begin(), series["full_multigrid"].end(), true);
  EXPECT_NEAR(sum_of(series["work_units"]), work["work_units"].get<double>(), 1e-9 * work["work_units"].get<double>());
  EXPECT_EQ(by_full_multigrid, work["full_multigrid_steps"].get<int>());
  EXPECT_TRUE(series["full_multigrid"][0].get<bool>() && series["full_multigrid"][1].get<bool>());
  EXPECT_LT(by_full_multigrid, 25);

  expect_patches_refused(small, {
      {R"("time_steps": 2)", "time_steps = 2: allowed range is [4, 100000]"},
      {R"("load_sharing": "stiffness")", "load_sharing"},
      {R"("gear_pair": {"teeth": [22, 32], "normal_module_mm": 2.0, "normal_pressure_angle_deg": 25.0,
          "face_width_mm": 20.0, "helix_angle_deg": 15})", "the pair is helical"},
      {R"("rheology": {"viscosity_model": "eyring"})", "rheology.viscosity_model"},
  }, "ehl_transient_bad");
  auto no_oil = small;
  no_oil.erase("lubricant");
  const auto b = run_gearbench("run " + write_case("ehl_transient_no_oil", no_oil.dump()));
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find("lubricant: missing required key"), std::string::npos) << b.err;

  auto stuck = small;
  stuck["grid"]["max_cycles"] = 1;  // after each step's full multigrid: no step meets 1e-12 in one cycle
  stuck["grid"]["tolerance"] = 1e-12;
  const auto out = temp_path("ehl_transient_unconverged.json").string();
  const auto failed = run_gearbench("run " + write_case("ehl_transient_stuck", stuck.dump()) + " -o " + out);
  EXPECT_EQ(failed.exit_code, 3) << failed.err;
  EXPECT_NE(failed.err.find("did not converge"), std::string::npos) << failed.err;
  std::ifstream diag(out);
  const auto d = json::parse(diag);
  EXPECT_FALSE(d["diagnostics"]["converged"].get<bool>());
  fs::remove(out);

  // 1000/1000 teeth (issue 20): a rigid-isoviscous contact (p_max ~0.15 MPa). The first-order
  // solver failed its force balance there; the rebuilt one (issue 19) converges. Step 0 is a
  // steady solve at A under half the load: Martin's film 4.895·η0·ū·R/w within 4 % (−2.6 %
  // measured on 161 nodes; the steady default grid gives −0.3 %).
  auto huge = small;
  huge["time_steps"] = 4;
  huge["gear_pair"]["teeth"] = {1000, 1000};
  const auto h = run_gearbench("run " + write_case("ehl_transient_1000_teeth", huge.dump()));
  ASSERT_EQ(h.exit_code, 0) << h.err;
  const auto steps = json::parse(h.out)["steps"];
  const double eta0 = seed["lubricant"]["viscosity_Pa_s"].get<double>();
  const double martin = 4.895 * eta0 * steps["entrainment_m_per_s"][0].get<double>() *
                        steps["reduced_radius_m"][0].get<double>() / steps["load_per_length_N_per_m"][0].get<double>();
  EXPECT_NEAR(steps["h_min_m"][0].get<double>() / martin, 1.0, 0.04);
}

// Two positions on a coarse grid run through; bad input exits 2 naming the key.
TEST(Cli, OilFilmStiffnessRunsAndValidates) {
  auto small = read_case("oil_film_stiffness_spur");
  small["positions"] = 2;
  small["grid"] = {{"nodes", 161}};
  const auto o = run_gearbench("run " + write_case("oil_film_small", small.dump()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  ASSERT_EQ(r["points"]["oil_film_stiffness_N_per_m"].size(), 2u);
  for (const auto& k : r["points"]["oil_film_stiffness_N_per_m"]) EXPECT_GT(k.get<double>(), 0.0);
  for (const auto& f : r["points"]["film_compliance_share"]) {
    EXPECT_GT(f.get<double>(), 0.0);
    EXPECT_LT(f.get<double>(), 1.0);
  }
  // Each position's three solves did work, and the positions' add up to the diagnostics'.
  for (const auto& wu : r["points"]["work_units"]) EXPECT_GT(wu.get<double>(), 0.0);
  EXPECT_NEAR(sum_of(r["points"]["work_units"]), r["diagnostics"]["work_units"].get<double>(),
              1e-9 * r["diagnostics"]["work_units"].get<double>());
  expect_patches_refused(small, {
      {R"("perturbation": 0.5)", "perturbation = 0.5: allowed"},
      {R"("positions": 0)", "positions = 0: allowed range is [1, 10000]"},
      {R"("load_sharing": "stiffness")", "load_sharing"},
  }, "oil_film_bad");
}

// The double-involute form of the kind on a coarse grid (two instants, one Gauss point per
// piece): both tooth forms come back with a positive film stiffness at every instant, the
// zones leave the gap at the pitch point, and rack mistakes name their key.
TEST(Cli, OilFilmStiffnessDoubleInvoluteRunsAndValidates) {
  auto small = read_case("seed002_double_involute_oil_film");
  small["mesh_samples"] = 2;
  small["points_per_piece"] = 1;
  small["grid"] = {{"nodes", 161}};
  const auto o = run_gearbench("run " + write_case("double_involute_small", small.dump()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  for (const char* form : {"double_involute", "involute"}) {
    const auto& k = r[form]["instants"]["film_stiffness_N_per_m"];
    ASSERT_EQ(k.size(), 2u) << form;
    for (const auto& v : k) EXPECT_GT(v.get<double>(), 0.0) << form;
    EXPECT_GT(r[form]["work_units"].get<double>(), 0.0) << form;
    EXPECT_NEAR(sum_of(r[form]["instants"]["work_units"]), r[form]["work_units"].get<double>(),
                1e-9 * r[form]["work_units"].get<double>()) << form;
  }
  EXPECT_NEAR(r["diagnostics"]["work_units"].get<double>(),
              r["double_involute"]["work_units"].get<double>() + r["involute"]["work_units"].get<double>(),
              1e-9 * r["diagnostics"]["work_units"].get<double>());
  EXPECT_GT(r["mean_film_stiffness_ratio"].get<double>(), 0.0);
  EXPECT_LT(r["geometry"]["root_zone_m"][1].get<double>(), r["geometry"]["tip_zone_m"][0].get<double>());
  expect_patches_refused(small, {
      {R"("double_involute": {"waist_root_depth": 0.1})", "double_involute.waist_root_depth = 0.1: allowed range is"},
      {R"("double_involute": {"root_tangential_shift": 0.3})", "double_involute.root_tangential_shift = 0.3"},
      {R"("tooth_form": "involute")", "double_involute: the rack section is read only with tooth_form"},
      {R"("tooth_form": "stepped")", "tooth_form"},
      {R"("mesh_samples": 0)", "mesh_samples = 0: allowed range is [1, 10000]"},
      {R"("gear_pair": {"helix_angle_deg": 0})", "no tooth pair is in contact"},
  }, "double_involute_bad");
  // A thick oil (0.86 Pa s: M 1.7, L 27) on this grid gives a film that is *thicker* at the
  // higher of the two loads, whereas Moes' film thins (d ln H/d ln M = −0.05 there): the solves'
  // first-order errors differ by more than the 0.2 % response. Found by the mutation campaign
  // (issue 20) as a negative film stiffness with exit 0; it must be exit 3 naming the cause.
  auto thick = small;
  thick["mesh_samples"] = 1;
  thick["lubricant"]["viscosity_Pa_s"] = 0.86;
  const auto t = run_gearbench("run " + write_case("double_involute_thick_oil", thick.dump()));
  EXPECT_EQ(t.exit_code, 3) << t.err;
  EXPECT_NE(t.err.find("is not thinner than at w(1 − δ)"), std::string::npos) << t.err;
}

// Issue 21: every kind's result carries "converged" (bool), "message" (one sentence: what
// stopped the solve) and "summary" (the line the CLI prints on stderr) at the top level; a forced
// non-convergence gives converged false, a message naming what did not converge, and exit 3 with
// the result written to -o.
void expect_solve_status(const json& r, bool converged, const std::string& message_part) {
  ASSERT_TRUE(r.contains("converged") && r["converged"].is_boolean()) << r.dump().substr(0, 300);
  ASSERT_TRUE(r.contains("message") && r["message"].is_string());
  ASSERT_TRUE(r.contains("summary") && r["summary"].is_string());
  EXPECT_EQ(r["converged"].get<bool>(), converged) << r["message"];
  EXPECT_FALSE(r["summary"].get<std::string>().empty());
  EXPECT_NE(r["message"].get<std::string>().find(message_part), std::string::npos) << r["message"];
}

/// Runs `c` with -o; the exit code, stderr and the result written.
struct StatusRun {
  int exit_code;
  std::string err;
  json result;
};
StatusRun run_to_file(const std::string& name, const json& c) {
  const auto out = temp_path(name + ".json").string();
  const auto o = run_gearbench("run " + write_case(name, c.dump()) + " -o " + out);
  std::ifstream in(out);
  StatusRun r{o.exit_code, o.err, json::parse(in)};
  fs::remove(out);
  return r;
}

/// Runs `c`: it converges (exit 0, the status with `ok_part`, its summary on stderr); then with
/// `force` applied it does not (exit 3, the status with `fail_part`, the message on stderr).
StatusRun expect_converges_then_fails(const std::string& name, json c, const std::string& ok_part,
                                      const std::function<void(json&)>& force, const std::string& fail_part) {
  const auto ok = run_to_file(name, c);
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  expect_solve_status(ok.result, true, ok_part);
  EXPECT_NE(ok.err.find("gearbench: " + ok.result.value("summary", std::string("?"))), std::string::npos) << ok.err;
  force(c);
  auto failed = run_to_file(name + "_forced", c);
  EXPECT_EQ(failed.exit_code, 3) << failed.err;
  expect_solve_status(failed.result, false, fail_part);
  EXPECT_NE(failed.err.find(failed.result.value("message", std::string("?"))), std::string::npos) << failed.err;
  return failed;
}

/// One cycle to a residual of 1e-12: no EHL solve gets there.
void one_cycle(json& c) {
  c["grid"]["max_cycles"] = 1;
  c["grid"]["tolerance"] = 1e-12;
}

TEST(Cli, EhlTransientResultCarriesConvergedMessageAndSummary) {
  auto small = read_case("seed004_transient_ehl");
  small["time_steps"] = 4;
  small["grid"] = {{"nodes", 161}};
  const auto failed = expect_converges_then_fails("status_transient", small, "converged: all 5 time steps",
                                                  one_cycle, "time step 0 of 4 did not converge");
  EXPECT_FALSE(failed.result["diagnostics"]["converged"].get<bool>());  // the old key stays
}

TEST(Cli, OilFilmStiffnessResultCarriesConvergedMessageAndSummary) {
  auto small = read_case("oil_film_stiffness_spur");
  small["positions"] = 1;
  small["grid"] = {{"nodes", 161}};
  const auto failed =
      expect_converges_then_fails("status_oil_film", small, "converged: the EHL solves at all 1 positions", one_cycle,
                                  "position 1 of 1: oil-film stiffness: the EHL solve at s =");
  EXPECT_NE(failed.result["message"].get<std::string>().find("did not converge in 1 cycles"), std::string::npos);
}

TEST(Cli, OilFilmStiffnessDoubleInvoluteResultCarriesConvergedMessageAndSummary) {
  auto small = read_case("seed002_double_involute_oil_film");
  small["mesh_samples"] = 1;
  small["points_per_piece"] = 1;
  small["grid"] = {{"nodes", 161}};
  one_cycle(small);
  const auto failed = run_to_file("status_double_involute_stuck", small);
  EXPECT_EQ(failed.exit_code, 3) << failed.err;
  expect_solve_status(failed.result, false, "double involute: instant 1 of 1:");
}

TEST(Cli, ThermalPointResultCarriesConvergedMessageAndSummary) {
  auto point = read_case("tehl_point_sliding");
  point["grid"] = {{"nodes", 161}};
  expect_converges_then_fails("status_tehl_point", point, "converged: the temperature and h_min settled",
                              [](json& c) { c["thermal"] = {{"max_iterations", 1}}; },
                              "did not converge in max_iterations = 1 iterations");
}

TEST(Cli, ThermalPathResultCarriesConvergedMessageAndSummary) {
  auto path = read_case("seed001_tehl_path");
  path["grid"] = {{"nodes", 161}};
  path.erase("micropitting");
  path["thermal"]["max_iterations"] = 1;  // point A cannot settle in one iteration
  const auto failed = run_to_file("status_tehl_path_capped", path);
  EXPECT_EQ(failed.exit_code, 3) << failed.err;
  expect_solve_status(failed.result, false, "thermal EHL at point A of the path");
  EXPECT_NE(failed.result["message"].get<std::string>().find("max_iterations = 1"), std::string::npos);
  EXPECT_EQ(failed.result["points"].size(), 1u);  // the points up to the one that failed
}

// Thermal EHL: a point contact and the seed 001 path run on small grids (161 nodes); bad
// input exits 2 naming the key; an iteration cap that is too small exits 3 with the
// diagnostics in -o.
TEST(Cli, ThermalEhlRunsAndValidates) {
  auto point = read_case("tehl_point_sliding");
  point["grid"] = {{"nodes", 161}};
  const auto o = run_gearbench("run " + write_case("tehl_point_small", point.dump()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  EXPECT_LT(r["h_min_m"].get<double>(), r["isothermal"]["h_min_m"].get<double>());
  EXPECT_GT(r["temperature_rise_max_K"].get<double>(), 10.0);
  EXPECT_TRUE(r.contains("friction_coefficient_eyring"));
  EXPECT_EQ(r["temperature_field"]["film_K"].size(), r["profile"]["x_m"].size());
  // The stop's tolerances as used (161 nodes: no nested grid, the isothermal estimate).
  EXPECT_GE(r["diagnostics"]["stop"]["film_tolerance_used"].get<double>(), 1e-5);
  EXPECT_GT(r["diagnostics"]["stop"]["h_min_error_estimate"].get<double>(), 0.0);
  expect_work_by_part_adds_up(r["diagnostics"]);

  expect_patches_refused(point, {
      {R"("lubricant": {"nu40_mm2_s": 320})", "give either viscosity_Pa_s"},
      {R"("inlet_temperature_K": 100)", "inlet_temperature_K = 100: allowed range is [200, 600]"},
      {R"("solids": {"density_kg_m3": [7850]})", "solids.density_kg_m3"},
      {R"("thermal": {"heat_sources": "radiation"})", "thermal.heat_sources"},
      {R"("thermal": {"film_nodes": 2})", "thermal.film_nodes = 2"},
      {R"("thermal": {"stop": "residual"})", "thermal.stop = \"residual\": allowed values are discretisation_error, tolerance"},
      {R"("rheology": "bingham")", "rheology = \"bingham\": allowed values are newtonian, eyring"},
      {R"("rheology": "eyring", "lubricant": {"eyring_stress_MPa": null})", "lubricant.eyring_stress_MPa"},
      {R"("rheology": "eyring", "lubricant": {"eyring_stress_MPa": 0})", "lubricant.eyring_stress_MPa = 0"},
  }, "tehl_bad");

  auto capped = point;
  capped["thermal"] = {{"max_iterations", 1}};
  const auto out = temp_path("tehl_unconverged.json").string();
  const auto failed = run_gearbench("run " + write_case("tehl_capped", capped.dump()) + " -o " + out);
  EXPECT_EQ(failed.exit_code, 3) << failed.err;
  std::ifstream diag(out);
  EXPECT_FALSE(json::parse(diag)["diagnostics"]["converged"].get<bool>());
  fs::remove(out);

  auto path = read_case("seed001_tehl_path");
  path["grid"] = {{"nodes", 161}};
  const auto p = run_gearbench("run " + write_case("tehl_path_small", path.dump()));
  ASSERT_EQ(p.exit_code, 0) << p.err;
  const auto rp = json::parse(p.out);
  EXPECT_EQ(rp["points"].size(), 7u);
  EXPECT_EQ(rp["minimum_film_point"], "A");
  EXPECT_NE(p.err.find("thermal EHL point E (7/7)"), std::string::npos) << p.err;
  // Issue 21: the path's own status beside each point's diagnostics.
  expect_solve_status(rp, true, "converged: the thermal EHL at all 7 points");
  EXPECT_NE(p.err.find("gearbench: " + rp["summary"].get<std::string>()), std::string::npos) << p.err;
}

}  // namespace
