// The CLI contract, end to end through the gearbench executable: results on stdout, and
// for every class of bad input a one-line `error:` naming the key, and exit code 2.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

struct Outcome {
  int exit_code;
  std::string out;
  std::string err;
};

/// Runs gearbench; its stdout goes to `stdout_to` when given (then `out` stays empty).
Outcome run_gearbench(const std::string& args, const std::string& stdout_to = "") {
  const auto dir = fs::temp_directory_path();
  const auto out_file = dir / ("gb_cli_out_" + std::to_string(::getpid()));
  const auto err_file = dir / ("gb_cli_err_" + std::to_string(::getpid()));
  const std::string command = std::string("'") + GEARBENCH_EXE + "' " + args + " >'" +
                              (stdout_to.empty() ? out_file.string() : stdout_to) + "' 2>'" + err_file.string() + "'";
  const int status = std::system(command.c_str());
  auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  Outcome o{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out_file), slurp(err_file)};
  fs::remove(out_file);
  fs::remove(err_file);
  return o;
}

/// A temporary path unique to this test process (ctest runs tests in parallel, and several
/// builds may test at once).
fs::path temp_path(const std::string& name) {
  return fs::temp_directory_path() / ("gb_" + name + "_" + std::to_string(::getpid()));
}

std::string write_case(const std::string& name, const std::string& text) {
  const auto path = temp_path("case_" + name + ".json");
  std::ofstream(path) << text;
  return path.string();
}

json seed004() {
  std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/seed004_spur_geometry.json");
  return json::parse(in);
}

TEST(Cli, Seed004GeometryPrintsContactRatio) {
  const auto o = run_gearbench("run " GEARBENCH_SOURCE_DIR "/cases/seed004_spur_geometry.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  EXPECT_NEAR(r["contact_ratio_transverse"].get<double>(), 1.454, 5e-4);
  for (const char* key : {"center_distance_mm", "working_pressure_angle_deg", "base_pitch_transverse_mm",
                          "contact_ratio_overlap", "contact_ratio_total", "base_radius_mm",
                          "tip_radius_mm", "root_radius_mm"})
    EXPECT_TRUE(r.contains(key)) << key;
  for (const char* point : {"T2", "A", "B", "C", "D", "E"})
    EXPECT_TRUE(r["line_of_action_mm"].contains(point)) << point;
  EXPECT_EQ(r["profile"]["slide_to_roll"].size(), 51u);
  EXPECT_EQ(r["profile"]["entrainment_m_s"].size(), 51u);
}

TEST(Cli, OutputFileAndVersion) {
  const auto out = temp_path("cli_result.json").string();
  const auto o = run_gearbench("run " GEARBENCH_SOURCE_DIR "/cases/seed000_herringbone_geometry.json -o " + out);
  ASSERT_EQ(o.exit_code, 0) << o.err;
  std::ifstream in(out);
  const auto r = json::parse(in);
  EXPECT_GT(r["contact_ratio_overlap"].get<double>(), 1.0);
  EXPECT_TRUE(r.contains("contact_lines"));
  fs::remove(out);
  const auto v = run_gearbench("--version");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_EQ(v.out.rfind("gearbench ", 0), 0u) << v.out;
  EXPECT_NE(v.out.find("(git "), std::string::npos);
}

struct BadCase {
  std::string name;
  std::function<void(json&)> edit;  // applied to the seed 004 case
  std::string expected;             // substring of the error line
};

class BadInput : public testing::TestWithParam<BadCase> {};

/// Exit 2, nothing on stdout, and on stderr one line: `error: ` and the expected text.
void expect_one_error_line(const Outcome& o, const std::string& expected) {
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_EQ(o.err.rfind("error: ", 0), 0u) << o.err;
  EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << "one line: " << o.err;
  EXPECT_NE(o.err.find(expected), std::string::npos) << o.err;
  EXPECT_TRUE(o.out.empty());
}

TEST_P(BadInput, ExitTwoWithKeyNamed) {
  auto j = seed004();
  GetParam().edit(j);
  expect_one_error_line(run_gearbench("run " + write_case(GetParam().name, j.dump())), GetParam().expected);
}

const BadCase bad_cases[] = {
    {"unknown_key", [](json& j) { j["gear_pair"]["teeht"] = 3; },
     "gear_pair.teeht: unknown key (did you mean 'teeth'?)"},
    {"unknown_top_key", [](json& j) { j["operatin"] = j["operating"]; },
     "operatin: unknown key (did you mean 'operating'?)"},
    {"missing_key", [](json& j) { j["gear_pair"].erase("face_width_mm"); },
     "gear_pair.face_width_mm: missing required key"},
    {"missing_kind", [](json& j) { j.erase("kind"); }, "kind: missing required key"},
    {"unknown_kind", [](json& j) { j["kind"] = "geometri"; }, "(did you mean 'geometry'?)"},
    {"wrong_type", [](json& j) { j["gear_pair"]["teeth"] = "22"; },
     "gear_pair.teeth = \"22\": must be an array of two values"},
    {"wrong_type_number", [](json& j) { j["operating"]["pinion_speed_rpm"] = true; },
     "operating.pinion_speed_rpm = true: must be a number"},
    {"undercut", [](json& j) { j["gear_pair"]["teeth"] = {8, 32}; },
     "gear_pair.teeth[0] = 8: undercut by the generating rack"},
    {"module_nonpositive", [](json& j) { j["gear_pair"]["normal_module_mm"] = -2; },
     "gear_pair.normal_module_mm = -2: allowed range is [0.01, 1000] mm"},
    {"face_width_zero", [](json& j) { j["gear_pair"]["face_width_mm"] = 0; },
     "gear_pair.face_width_mm = 0: allowed range is [0.01, 100000] mm"},
    {"speed_negative", [](json& j) { j["operating"]["pinion_speed_rpm"] = -1000; },
     "operating.pinion_speed_rpm = -1000: allowed range is (0, 1000000] rpm"},
    {"pressure_angle", [](json& j) { j["gear_pair"]["normal_pressure_angle_deg"] = 9.5; },
     "gear_pair.normal_pressure_angle_deg = 9.5: allowed range is [10, 35] deg"},
    {"helix_angle", [](json& j) { j["gear_pair"]["helix_angle_deg"] = 50; },
     "gear_pair.helix_angle_deg = 50: allowed range is [0, 45] deg"},
    {"poisson", [](json& j) { j["materials"]["poisson_ratio"] = 0.55; },
     "materials.poisson_ratio = 0.55: allowed range is [0, 0.5]"},
    {"center_distance", [](json& j) { j["gear_pair"]["center_distance_mm"] = 53.5; },
     "gear_pair.center_distance_mm = 53.5: incompatible with profile_shift sum 0"},
    {"contact_ratio", [](json& j) { j["gear_pair"]["tip_diameter_mm"] = {45.0, 65.5}; },
     "transverse contact ratio 0.49"},
    {"tip_interference",
     [](json& j) {
       j["gear_pair"]["teeth"] = {18, 90};
       j["gear_pair"]["normal_pressure_angle_deg"] = 20;
       j["gear_pair"]["tip_diameter_mm"] = {40.0, 184.8};
     },
     "tip interference"},
    {"seed001_printed_tip",
     [](json& j) {
       std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/seed001_wind_geometry.json");
       j = json::parse(in);
       j["gear_pair"]["tip_diameter_mm"] = {309.903, 626.35};
     },
     "gear_pair.tip_diameter_mm[0] = 309.903: must exceed the base diameter"},
    // Issue 20: forged, cut and wrapped messages; the internal error of a shift sum.
    {"forged_second_line", [](json& j) { j["kind"] = "geometry\r\nerror: fake second error"; },
     R"(kind = "geometry\r\nerror: fake second error": unknown kind)"},
    {"nul_in_key", [](json& j) { j["gear_pair"][std::string("teeth\0", 6)] = 1; },
     R"(gear_pair.teeth\u0000: unknown key (did you mean 'teeth'?))"},
    {"integer_beyond_int64", [](json& j) { j["gear_pair"]["teeth"] = {18446744073709551615ULL, 32}; },
     "gear_pair.teeth[0] = 18446744073709551615: allowed range is [5, 10000]"},
    {"shift_sum", [](json& j) { j["gear_pair"]["profile_shift"] = {-1.0, -1.0}; },
     "gear_pair.profile_shift = [-1, -1]: the sum -2 leaves no working pressure angle"},
};

INSTANTIATE_TEST_SUITE_P(Classes, BadInput, testing::ValuesIn(bad_cases),
                         [](const testing::TestParamInfo<BadCase>& param_info) { return param_info.param.name; });

// Issue 20: case texts no JSON object can hold. Once a stack overflow (SIGSEGV), exit 1
// ("internal"), or silently the last of two keys.
TEST(Cli, HostileCaseTextExitsTwoNamingTheKey) {
  const std::pair<std::string, std::string> cases[] = {
      {R"({"kind":"geometry","description":)" + std::string(60000, '[') + std::string(60000, ']') + "}",
       "nested deeper than 64 levels"},
      {R"({"kind":"geometry","gear_pair":{"teeth":[22,32],"normal_module_mm":1e999}})",
       "error: gear_pair.normal_module_mm = 1e999: beyond the range of a double"},
      {R"({"kind":"geometry","operating":{"pinion_torque_Nm":-1e400}})",
       "error: operating.pinion_torque_Nm = -1e400: beyond the range of a double"},
      {R"({"kind":"geometry","gear_pair":{"teeth":[22,32],"teeth":[22,33]}})",
       "error: gear_pair.teeth: duplicate key"},
  };
  int n = 0;
  for (const auto& [text, expected] : cases)
    expect_one_error_line(run_gearbench("run " + write_case("hostile_" + std::to_string(n++), text)), expected);
}

// micropitting_iso applies the gear-pair validation of every other kind (it returned
// S_λ 1.097 for shifts that leave pointed teeth, and a negative contact ratio for a centre
// distance that does not fit), and refuses operating points beyond its oil laws instead of
// an internal error on a NaN film.
TEST(Cli, MicropittingValidatesThePairAndItsRange) {
  std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/seed001_micropitting.json");
  const auto seed = json::parse(in);
  const std::pair<std::function<void(json&)>, std::string> bad[] = {
      {[](json& c) { c["gear_pair"]["teeth"] = {21, 17}; }, "gear_pair.center_distance_mm = 476: incompatible"},
      {[](json& c) {
         c["gear_pair"].erase("center_distance_mm");
         c["gear_pair"]["profile_shift"] = {1.5, 1.5};
       }, "pointed"},
      {[](json& c) { c["operating"]["pinion_speed_rpm"] = 1e5; }, "operating: the contact temperature reaches"},
      {[](json& c) { c["operating"]["pinion_torque_Nm"] = 1e9; }, "beyond the 500 °C to which the oil laws"},
      {[](json& c) { c["micropitting"]["reference_test"]["pinion_torque_Nm"] = 1e7; },
       "micropitting.reference_test: the contact temperature reaches"},
  };
  int n = 0;
  for (const auto& [edit, expected] : bad) {
    auto c = seed;
    edit(c);
    expect_one_error_line(run_gearbench("run " + write_case("micropitting_bad_" + std::to_string(n++), c.dump())),
                          expected);
  }
}

// A case "file" that is a directory, or endless (/dev/zero, once read until the memory ran
// out), is refused by name.
TEST(Cli, CaseFileThatIsNoFile) {
  expect_one_error_line(run_gearbench("run " + fs::temp_directory_path().string()), "is a directory, not a case file");
  expect_one_error_line(run_gearbench("run /dev/zero"), "/dev/zero: larger than 64 MiB");
}

// -o writes atomically only where it can replace a file: a directory is refused, a device
// is written through (never renamed over: as root that destroyed /dev/null), a symbolic
// link keeps pointing at its target, which gets the result.
TEST(Cli, OutputFileKinds) {
  const std::string run = "run " GEARBENCH_SOURCE_DIR "/cases/seed004_spur_geometry.json -o ";
  const auto dir = temp_path("output_dir");
  fs::create_directories(dir);
  expect_one_error_line(run_gearbench(run + dir.string()), "is a directory; name the file");
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);

  ASSERT_EQ(run_gearbench(run + "/dev/null").exit_code, 0);
  EXPECT_TRUE(fs::is_character_file("/dev/null"));

  const auto target = temp_path("output_target.json"), link = temp_path("output_link.json");
  std::ofstream(target) << "old";
  fs::create_symlink(target, link);
  ASSERT_EQ(run_gearbench(run + link.string()).exit_code, 0);
  EXPECT_TRUE(fs::is_symlink(link));
  std::ifstream in(target);
  EXPECT_TRUE(json::parse(in).contains("contact_ratio_transverse"));
  fs::remove(link);
  fs::remove(target);
}

// A result that cannot be written is a failure (exit 1), never exit 0 with the result lost.
TEST(Cli, LostOutputIsAFailure) {
  const std::string run = "run " GEARBENCH_SOURCE_DIR "/cases/seed004_spur_geometry.json";
  auto o = run_gearbench(run, "/dev/full");
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_EQ(o.err, "error: writing to stdout failed: No space left on device\n");
  o = run_gearbench(run + " -o /dev/full");
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_EQ(o.err, "error: -o /dev/full: writing the output failed: No space left on device\n");
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

// A sweep is read as strictly as a case: a huge number names its key, an axis product
// beyond the case cap is refused before it can wrap (64 axes of 2 values once made 0 cases),
// and every axis reaches a key of its own.
TEST(Cli, HostileSweepText) {
  const auto out = temp_path("hostile_sweep_out").string();
  const std::string base = R"("base": {"kind": "geometry"}, "outputs": ["center_distance_mm"])";
  expect_one_error_line(run_gearbench("sweep " + write_case("sweep_huge", "{" + base + R"(, "vary": {"a": [1, 1e999]}})") +
                                      " --out " + out),
                        "vary.a[1] = 1e999: beyond the range of a double");
  std::string axes;
  for (int k = 0; k < 64; ++k) axes += (k ? ", \"a" : "\"a") + std::to_string(k) + "\": [1, 2]";
  expect_one_error_line(run_gearbench("sweep " + write_case("sweep_wide", "{" + base + ", \"vary\": {" + axes + "}}") +
                                      " --out " + out),
                        "vary: more than 100000 cases");
  // Two axes on one key showed values in the table that were never used; a bad outputs
  // entry was blamed on vary.
  expect_one_error_line(
      run_gearbench("sweep " + write_case("sweep_same_key", R"({"base": {"kind": "geometry"}, "outputs": ["a"],
                    "vary": {"gear_pair.teeth": [[22, 32]], "/gear_pair/teeth": [[20, 30]]}})") + " --out " + out),
      R"(vary."/gear_pair/teeth": reaches the same key as vary."gear_pair.teeth")");
  expect_one_error_line(
      run_gearbench("sweep " + write_case("sweep_bad_output", R"({"base": {"kind": "geometry"}, "outputs": ["a..b"],
                    "vary": {"gear_pair.teeth": [[22, 32]]}})") + " --out " + out),
      R"(outputs."a..b": empty segment)");
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, Seed003StiffnessRuns) {
  const auto o = run_gearbench("run " GEARBENCH_SOURCE_DIR "/cases/seed003_spur_stiffness.json");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  EXPECT_EQ(r["mesh_stiffness_N_per_m"].size(), 360u);
  EXPECT_EQ(r["mesh_position_rad"].size(), 360u);
  for (const char* key : {"single_pair_stiffness_N_per_m", "mesh_stiffness_mean_N_per_m", "mesh_stiffness_min_N_per_m",
                          "mesh_stiffness_max_N_per_m", "mesh_stiffness_mean_N_per_mm_um", "hertz_N_per_m", "components"})
    EXPECT_TRUE(r.contains(key)) << key;
  for (const char* key : {"q_prime", "c_prime_N_per_mm_um", "c_gamma_alpha_N_per_mm_um"})
    EXPECT_TRUE(r["iso6336"].contains(key)) << key;
  const auto cracked = run_gearbench("run " GEARBENCH_SOURCE_DIR "/cases/seed003_spur_pitch_crack_2_5mm.json");
  ASSERT_EQ(cracked.exit_code, 0) << cracked.err;
  EXPECT_LT(json::parse(cracked.out)["mesh_stiffness_min_N_per_m"].get<double>(),
            r["mesh_stiffness_min_N_per_m"].get<double>());
}

TEST(Cli, StiffnessBadInput) {
  std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/seed003_spur_stiffness.json");
  const auto base = json::parse(in);
  const std::pair<std::function<void(json&)>, std::string> cases[] = {
      {[](json& j) { j["crack"] = {{"type", "tip"}, {"length_mm", 1}, {"angle_deg", 45}}; },
       "crack.type = \"tip\": allowed values are pitch, root"},
      {[](json& j) { j["crack"] = {{"type", "pitch"}, {"length_mm", 1}, {"angle_deg", 45}, {"gear", 3}}; },
       "crack.gear = 3: allowed range is [1, 2]"},
      {[](json& j) { j["crack"] = {{"type", "pitch"}, {"length_mm", -1}, {"angle_deg", 45}}; },
       "crack.length_mm = -1: allowed range is [0, 10000] mm"},
      {[](json& j) { j.erase("materials"); }, "materials: missing required key"},
      {[](json& j) { j["beam_start"] = "root"; }, "beam_start = \"root\": allowed values are improved, straight, base_circle"},
      {[](json& j) { j["positions"] = 0; }, "positions = 0: allowed range is [2, 100000]"},
  };
  int n = 0;
  for (const auto& [edit, expected] : cases) {
    auto j = base;
    edit(j);
    const auto o = run_gearbench("run " + write_case("stiffness_bad_" + std::to_string(n++), j.dump()));
    EXPECT_EQ(o.exit_code, 2) << o.err;
    EXPECT_NE(o.err.find(expected), std::string::npos) << o.err;
  }
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

  // One cycle cannot converge: exit 3, one error line, the diagnostics still written to -o.
  std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/ehl_moes_M20_L10.json");
  auto j = json::parse(in);
  j["grid"]["max_cycles"] = 1;
  const auto out = temp_path("ehl_unconverged.json").string();
  const auto failed = run_gearbench("run " + write_case("ehl_one_cycle", j.dump()) + " -o " + out);
  EXPECT_EQ(failed.exit_code, 3) << failed.err;
  // Slow builds (sanitizers) also print the progress lines; the error is the one "error:" line.
  EXPECT_NE(failed.err.find("error: EHL multigrid did not converge in 1 cycles"), std::string::npos) << failed.err;
  EXPECT_NE(failed.err.find("with any of 8 schemes (last: V, point"), std::string::npos) << failed.err;
  EXPECT_NE(failed.err.find("then W, line, ω_GS 0.3, ω_J 0.2, ξ 1, coarsest grid 41 nodes, unresolved coarse nodes "
                            "held, continuation in α: the start at 0.5·α did not converge"),
            std::string::npos) << failed.err;
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
  const auto heavy = run_gearbench("run " + write_case("ehl_heavy", R"({"kind": "ehl_line", "moes": {"M": 300, "L": 0}})"));
  ASSERT_EQ(heavy.exit_code, 0) << heavy.err;
  const auto h = json::parse(heavy.out);
  EXPECT_GT(h["diagnostics"]["discretisation_error"]["h_min_relative_change"].get<double>(), 0.05);
  EXPECT_NE(h["notes"].dump().find("not grid-converged"), std::string::npos) << h["notes"].dump();

  const auto light = run_gearbench("run " + write_case("ehl_light", R"({"kind": "ehl_line", "moes": {"M": 20, "L": 10}})"));
  ASSERT_EQ(light.exit_code, 0) << light.err;
  EXPECT_EQ(json::parse(light.out)["notes"].dump().find("not grid-converged"), std::string::npos);
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
      {R"({"kind": "ehl_line", "moes": {"M": 20, "L": 10}, "grid": {"nodes": 1000}})",
       "grid.nodes = 1000: use (n0 − 1)·2^k + 1 nodes"},
      {R"({"kind": "ehl_line", "moes": {"M": 20, "L": 10}, "grid": {"nodes": 641, "levels": 5}})",
       "grid.nodes: give either nodes or levels with coarsest_nodes, not both"},
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
  std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/seed004_transient_ehl.json");
  const auto seed = json::parse(in);
  auto small = seed;
  small["time_steps"] = 8;
  small["grid"] = {{"levels", 3}};
  const auto o = run_gearbench("run " + write_case("ehl_transient_small", small.dump()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  EXPECT_EQ(r["steps"]["h_min_m"].size(), 9u);
  for (const char* point : {"A", "B", "C", "D", "E"}) EXPECT_TRUE(r["profiles"].contains(point)) << point;
  EXPECT_GT(r["p_max_Pa"].get<double>(), r["reference"]["hertz_pressure_Pa"].get<double>() * 0.8);

  const std::pair<std::string, std::string> bad[] = {
      {R"("time_steps": 2)", "time_steps = 2: allowed range is [4, 100000]"},
      {R"("load_sharing": "stiffness")", "load_sharing"},
      {R"("gear_pair": {"teeth": [22, 32], "normal_module_mm": 2.0, "normal_pressure_angle_deg": 25.0,
          "face_width_mm": 20.0, "helix_angle_deg": 15})", "the pair is helical"},
      {R"("rheology": {"viscosity_model": "eyring"})", "rheology.viscosity_model"},
  };
  int n = 0;
  for (const auto& [patch, expected] : bad) {
    auto j = small;
    j.merge_patch(json::parse("{" + patch + "}"));
    const auto b = run_gearbench("run " + write_case("ehl_transient_bad_" + std::to_string(n++), j.dump()));
    EXPECT_EQ(b.exit_code, 2) << patch << "\n" << b.err;
    EXPECT_NE(b.err.find(expected), std::string::npos) << b.err;
  }
  auto no_oil = small;
  no_oil.erase("lubricant");
  const auto b = run_gearbench("run " + write_case("ehl_transient_no_oil", no_oil.dump()));
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find("lubricant: missing required key"), std::string::npos) << b.err;

  auto stuck = small;
  stuck["grid"]["max_cycles"] = 1;
  const auto out = temp_path("ehl_transient_unconverged.json").string();
  const auto failed = run_gearbench("run " + write_case("ehl_transient_stuck", stuck.dump()) + " -o " + out);
  EXPECT_EQ(failed.exit_code, 3) << failed.err;
  EXPECT_NE(failed.err.find("did not converge"), std::string::npos) << failed.err;
  std::ifstream diag(out);
  const auto d = json::parse(diag);
  EXPECT_FALSE(d["diagnostics"]["converged"].get<bool>());
  fs::remove(out);

  // 1000/1000 teeth (issue 20): the step fails on its force balance with a scaled residual of 0
  // (the pressure cavitated everywhere); the message must say which of the two failed.
  auto huge = small;
  huge["time_steps"] = 4;
  huge["gear_pair"]["teeth"] = {1000, 1000};
  const auto h = run_gearbench("run " + write_case("ehl_transient_1000_teeth", huge.dump()));
  EXPECT_EQ(h.exit_code, 3) << h.err;
  EXPECT_NE(h.err.find("force balance"), std::string::npos) << h.err;
  EXPECT_NE(h.err.find("both must be below"), std::string::npos) << h.err;
}

// Two positions on a coarse grid run through; bad input exits 2 naming the key.
TEST(Cli, OilFilmStiffnessRunsAndValidates) {
  std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/oil_film_stiffness_spur.json");
  auto small = json::parse(in);
  small["positions"] = 2;
  small["grid"] = {{"levels", 3}};
  const auto o = run_gearbench("run " + write_case("oil_film_small", small.dump()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  ASSERT_EQ(r["points"]["oil_film_stiffness_N_per_m"].size(), 2u);
  for (const auto& k : r["points"]["oil_film_stiffness_N_per_m"]) EXPECT_GT(k.get<double>(), 0.0);
  for (const auto& f : r["points"]["film_compliance_share"]) {
    EXPECT_GT(f.get<double>(), 0.0);
    EXPECT_LT(f.get<double>(), 1.0);
  }
  const std::pair<std::string, std::string> bad[] = {
      {R"("perturbation": 0.5)", "perturbation = 0.5: allowed"},
      {R"("positions": 0)", "positions = 0: allowed range is [1, 10000]"},
      {R"("load_sharing": "stiffness")", "load_sharing"},
  };
  int n = 0;
  for (const auto& [patch, expected] : bad) {
    auto j = small;
    j.merge_patch(json::parse("{" + patch + "}"));
    const auto b = run_gearbench("run " + write_case("oil_film_bad_" + std::to_string(n++), j.dump()));
    EXPECT_EQ(b.exit_code, 2) << patch << "\n" << b.err;
    EXPECT_NE(b.err.find(expected), std::string::npos) << b.err;
  }
}

// The double-involute form of the kind on a coarse grid (two instants, one Gauss point per
// piece): both tooth forms come back with a positive film stiffness at every instant, the
// zones leave the gap at the pitch point, and rack mistakes name their key.
TEST(Cli, OilFilmStiffnessDoubleInvoluteRunsAndValidates) {
  std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/seed002_double_involute_oil_film.json");
  auto small = json::parse(in);
  small["mesh_samples"] = 2;
  small["points_per_piece"] = 1;
  small["grid"] = {{"levels", 3}};
  const auto o = run_gearbench("run " + write_case("double_involute_small", small.dump()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  for (const char* form : {"double_involute", "involute"}) {
    const auto& k = r[form]["instants"]["film_stiffness_N_per_m"];
    ASSERT_EQ(k.size(), 2u) << form;
    for (const auto& v : k) EXPECT_GT(v.get<double>(), 0.0) << form;
  }
  EXPECT_GT(r["mean_film_stiffness_ratio"].get<double>(), 0.0);
  EXPECT_LT(r["geometry"]["root_zone_m"][1].get<double>(), r["geometry"]["tip_zone_m"][0].get<double>());
  const std::pair<std::string, std::string> bad[] = {
      {R"("double_involute": {"waist_root_depth": 0.1})", "double_involute.waist_root_depth = 0.1: allowed range is"},
      {R"("double_involute": {"root_tangential_shift": 0.3})", "double_involute.root_tangential_shift = 0.3"},
      {R"("tooth_form": "involute")", "double_involute: the rack section is read only with tooth_form"},
      {R"("tooth_form": "stepped")", "tooth_form"},
      {R"("mesh_samples": 0)", "mesh_samples = 0: allowed range is [1, 10000]"},
      {R"("gear_pair": {"helix_angle_deg": 0})", "no tooth pair is in contact"},
  };
  int n = 0;
  for (const auto& [patch, expected] : bad) {
    auto j = small;
    j.merge_patch(json::parse("{" + patch + "}"));
    const auto b = run_gearbench("run " + write_case("double_involute_bad_" + std::to_string(n++), j.dump()));
    EXPECT_EQ(b.exit_code, 2) << patch << "\n" << b.err;
    EXPECT_NE(b.err.find(expected), std::string::npos) << b.err;
  }
}

/// Starts gearbench with `args`, sends SIGINT after `delay`, and returns its exit status.
/// Runs gearbench with `args`, sends SIGINT once its stderr shows `marker` (so the signal
/// lands in the middle of the work whatever the machine's load, not at a fixed delay), and
/// returns its exit code (−1 if it did not exit normally, −2 if the marker never came).
int interrupt_gearbench(const std::vector<std::string>& args, const std::string& marker) {
  int pipe_fd[2];
  if (::pipe(pipe_fd) != 0) return -3;
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::vector<char*> argv{const_cast<char*>(GEARBENCH_EXE)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::freopen("/dev/null", "w", stdout);
    ::dup2(pipe_fd[1], STDERR_FILENO);
    ::close(pipe_fd[0]);
    ::close(pipe_fd[1]);
    ::execv(GEARBENCH_EXE, argv.data());
    ::_exit(127);
  }
  ::close(pipe_fd[1]);
  std::string seen;
  char buffer[256];
  bool found = false;
  while (!found) {
    const ssize_t n = ::read(pipe_fd[0], buffer, sizeof buffer);
    if (n <= 0) break;
    seen.append(buffer, static_cast<std::size_t>(n));
    found = seen.find(marker) != std::string::npos;
  }
  if (found) ::kill(pid, SIGINT);
  while (::read(pipe_fd[0], buffer, sizeof buffer) > 0) {
  }  // drain what it says on its way out, so that it never writes into a closed pipe
  ::close(pipe_fd[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (!found) return -2;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Ctrl-C ends a run with exit code 130 and writes nothing: no result file, no report folder,
// no temporary left behind.
TEST(Cli, InterruptWritesNothing) {
  const auto out = temp_path("interrupted_run.json");
  EXPECT_EQ(interrupt_gearbench({"run", GEARBENCH_SOURCE_DIR "/cases/seed004_transient_ehl.json", "-o", out.string()},
                                "running..."), 130);
  EXPECT_FALSE(fs::exists(out));

  const auto dir = temp_path("interrupted_verify");
  fs::create_directories(dir);
  EXPECT_EQ(interrupt_gearbench({"verify", "--out", dir.string()}, "[2/"), 130);
  EXPECT_TRUE(fs::is_empty(dir)) << "an interrupted verify left files in " << dir;
  fs::remove_all(dir);
}

// A Ctrl-C while the report is being written comes after the work is done (issue 20: it left
// a complete folder, printed no path and exited 130): the run finishes, the report is whole.
TEST(Cli, InterruptDuringTheReportWriteFinishes) {
  const auto dir = temp_path("interrupted_report_write");
  fs::create_directories(dir);
  EXPECT_EQ(interrupt_gearbench({"verify", "--only", "geometry.seed004", "--out", dir.string()}, "writing the report"),
            0);
  std::size_t reports = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    ++reports;
    EXPECT_TRUE(fs::exists(entry.path() / "report.md")) << entry.path();
    EXPECT_TRUE(fs::exists(entry.path() / "report.json")) << entry.path();
  }
  EXPECT_EQ(reports, 1u);
  fs::remove_all(dir);
}

TEST(Cli, DynamicsRunsAndValidates) {
  std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/seed003_spur_dynamics.json");
  auto j = json::parse(in);
  j["runup_cycles"] = 4;
  j["record_cycles"] = 4;
  const auto o = run_gearbench("run " + write_case("dynamics_short", j.dump()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  EXPECT_EQ(r["transmission_error_m"].size(), 4u * 64u);
  EXPECT_NEAR(r["mesh_frequency_Hz"].get<double>(), 332.0, 0.5);
  EXPECT_GT(r["dynamic_factor"].get<double>(), 1.0);
  EXPECT_EQ(r["natural_frequencies_Hz"].size(), 5u);
  const std::pair<std::function<void(json&)>, std::string> bad[] = {
      {[](json& c) { c["model"] = "spur7"; }, "model = \"spur7\": allowed values are spur6, herringbone12"},
      {[](json& c) { c["friction"]["mu"] = 0.9; }, "friction.mu = 0.9: allowed range is [0, 0.5]"},
      {[](json& c) { c.erase("operating"); }, "operating: missing required key"},
      {[](json& c) { c["gear_pair"]["helix_angle_deg"] = 10; }, "gear_pair.helix_angle_deg = 10: model \"spur6\" needs 0"},
      {[](json& c) { c["samples_per_cycle"] = 4; }, "samples_per_cycle = 4: allowed range is [8, 4096]"},
  };
  int n = 0;
  for (const auto& [edit, expected] : bad) {
    auto c = j;
    edit(c);
    const auto e = run_gearbench("run " + write_case("dynamics_bad_" + std::to_string(n++), c.dump()));
    EXPECT_EQ(e.exit_code, 2) << e.err;
    EXPECT_NE(e.err.find(expected), std::string::npos) << e.err;
  }
}

// At 1e6 rpm the run does not reach its periodic response in the run-up; the result says so
// instead of presenting a transient's dynamic factor as the answer (issue 20).
TEST(Cli, DynamicsSaysWhenTheRunIsNotPeriodic) {
  std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/seed003_spur_dynamics.json");
  auto j = json::parse(in);
  const auto periodic = run_gearbench("run " + write_case("dynamics_periodic", j.dump()));
  ASSERT_EQ(periodic.exit_code, 0) << periodic.err;
  EXPECT_TRUE(json::parse(periodic.out)["notes"].empty()) << periodic.out.substr(0, 200);
  j["operating"]["pinion_speed_rpm"] = 1e6;
  const auto fast = run_gearbench("run " + write_case("dynamics_1e6_rpm", j.dump()));
  ASSERT_EQ(fast.exit_code, 0) << fast.err;
  const auto r = json::parse(fast.out);
  EXPECT_GT(r["diagnostics"]["periodicity"].get<double>(), 1e-3);
  EXPECT_NE(r["notes"].dump().find("not periodic"), std::string::npos) << r["notes"].dump();
}

// The dynamics kind reads the efficiency kind's friction section and the backlash.
TEST(Cli, DynamicsTakesAFrictionLawAndBacklash) {
  std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/seed003_spur_dynamics_friction_backlash.json");
  auto j = json::parse(in);
  j["runup_cycles"] = 40;
  j["record_cycles"] = 4;
  const auto o = run_gearbench("run " + write_case("dynamics_law_backlash", j.dump()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  EXPECT_EQ(r["friction_model"], "xu_kahraman");
  EXPECT_GT(r["contact_loss"]["separation_fraction"].get<double>(), 0.0);
  const std::pair<std::function<void(json&)>, std::string> bad[] = {
      {[](json& c) { c.erase("lubricant"); }, "lubricant: missing, needed for friction.model = xu_kahraman"},
      {[](json& c) { c["friction"]["mu"] = 0.05; }, "friction.mu = 0.05: applies to friction.model = constant only"},
      {[](json& c) { c["friction"]["model"] = "ehl"; }, "friction.model = \"ehl\""},
      {[](json& c) { c["backlash_um"] = 0; }, "backlash_um = 0"},
  };
  int n = 0;
  for (const auto& [edit, expected] : bad) {
    auto c = j;
    edit(c);
    const auto e = run_gearbench("run " + write_case("dynamics_law_bad_" + std::to_string(n++), c.dump()));
    EXPECT_EQ(e.exit_code, 2) << e.err;
    EXPECT_NE(e.err.find(expected), std::string::npos) << e.err;
  }
}

TEST(Cli, HerringboneDynamicsRunsSweepsAndValidates) {
  std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/seed000_herringbone_dynamics.json");
  auto j = json::parse(in);
  j["runup_cycles"] = 2;
  j["record_cycles"] = 2;
  j["mesh"] = {{"slices", 20}, {"positions", 90}};
  j["speed_sweep_rpm"] = {{"from", 1000}, {"to", 2000}, {"points", 2}};
  const auto o = run_gearbench("run " + write_case("herringbone_short", j.dump()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  EXPECT_EQ(r["model"], "herringbone12");
  EXPECT_EQ(r["transmission_error_m"]["left"].size(), 2u * 64u + 1u);
  EXPECT_EQ(r["natural_frequencies_Hz"].size(), 11u);  // 12 DOF, one rigid rotation
  EXPECT_EQ(r["speed_sweep"]["dynamic_factor"].size(), 2u);
  EXPECT_NE(o.err.find("speed sweep 2/2"), std::string::npos) << o.err;  // progress on stderr
  const std::pair<std::function<void(json&)>, std::string> bad[] = {
      {[](json& c) { c["bearings"]["floating_pinion"] = "yes"; }, "bearings.floating_pinion = \"yes\": must be true or false"},
      {[](json& c) { c["groove_coupling"]["axial_stiffness_N_per_m"] = -1; }, "groove_coupling.axial_stiffness_N_per_m"},
      {[](json& c) { c["mesh"]["harmonics"] = 60; }, "mesh.harmonics = 60"},
      {[](json& c) { c["speed_sweep_rpm"]["to"] = 500; }, "speed_sweep_rpm.to = 500"},
  };
  int n = 0;
  for (const auto& [edit, expected] : bad) {
    auto c = j;
    edit(c);
    const auto e = run_gearbench("run " + write_case("herringbone_bad_" + std::to_string(n++), c.dump()));
    EXPECT_EQ(e.exit_code, 2) << e.err;
    EXPECT_NE(e.err.find(expected), std::string::npos) << e.err;
  }
}

/// The result without wall-clock timings, which are the only figures allowed to differ.
json without_timings(json j) {
  if (j.is_object()) {
    for (const char* key : {"seconds", "seconds_per_level"}) j.erase(key);
    for (auto& item : j.items()) item.value() = without_timings(item.value());
  }
  return j;
}

// The same case gives bit-identical figures twice (no uninitialised state, no ordering of
// threads or hash maps leaking into results); only the timings differ.
TEST(Cli, SameCaseSameFigures) {
  for (const char* file : {"seed004_spur_geometry.json", "seed003_spur_stiffness.json", "ehl_moes_M20_L10.json"}) {
    const std::string command = std::string("run ") + GEARBENCH_SOURCE_DIR + "/cases/" + file;
    const auto first = run_gearbench(command);
    const auto second = run_gearbench(command);
    ASSERT_EQ(first.exit_code, 0) << first.err;
    EXPECT_EQ(without_timings(json::parse(first.out)).dump(), without_timings(json::parse(second.out)).dump()) << file;
  }
}

TEST(Cli, EfficiencyRunsAndValidates) {
  std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/seed004_spur_efficiency.json");
  const auto j = json::parse(in);
  const auto o = run_gearbench("run " + write_case("efficiency", j.dump()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  EXPECT_NEAR(r["loss_factor_numeric"].get<double>(), r["ohlendorf_HV"].get<double>(), 1e-12);
  EXPECT_LT(r["efficiency_mean"].get<double>(), 1.0);
  EXPECT_GT(r["efficiency_min"].get<double>(), 0.9);
  auto bad = j;
  bad["friction"] = {{"model", "xu_kahraman"}};  // needs the lubricant (and materials) sections
  const auto e = run_gearbench("run " + write_case("efficiency_bad", bad.dump()));
  EXPECT_EQ(e.exit_code, 2);
  EXPECT_NE(e.err.find("lubricant: missing, needed for friction.model = xu_kahraman"), std::string::npos) << e.err;
  auto helical = j;
  helical["gear_pair"]["helix_angle_deg"] = 15;
  helical["load_sharing"] = "iso";
  const auto h = run_gearbench("run " + write_case("efficiency_helical_iso", helical.dump()));
  EXPECT_EQ(h.exit_code, 2);
  EXPECT_NE(h.err.find("load_sharing = \"iso\": helical pairs use a uniform load"), std::string::npos) << h.err;
}

// A loss above the input power is refused, naming the term out of its range (issue 20: a
// 1000/1000-tooth pair returned efficiency_mean -2.24 with exit 0, from the rolling loss of
// a 24 µm film).
TEST(Cli, EfficiencyRefusesALossAboveTheInput) {
  std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/seed004_spur_efficiency.json");
  auto j = json::parse(in);
  std::ifstream with_oil(GEARBENCH_SOURCE_DIR "/cases/seed003_spur_dynamics_friction_backlash.json");
  const auto oil = json::parse(with_oil);
  j["lubricant"] = oil["lubricant"];
  j["materials"] = oil["materials"];
  j["friction"] = {{"model", "xu_kahraman"}};
  j["gear_pair"]["teeth"] = {1000, 1000};
  expect_one_error_line(run_gearbench("run " + write_case("efficiency_thick_film", j.dump())),
                        "the rolling loss (2.09e+04 W mean) exceeds the input power with a film of");
}

TEST(Cli, MalformedJsonGivesLine) {
  const auto o = run_gearbench("run " + write_case("malformed", "{\n  \"kind\": \"geometry\",\n  \"gear_pair\": {,\n}\n"));
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.err.find("malformed JSON at line 3"), std::string::npos) << o.err;
}

TEST(Cli, MissingFileAndBadArguments) {
  auto o = run_gearbench("run /nonexistent/case.json");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.err.find("cannot open the case file"), std::string::npos) << o.err;
  // Usage errors follow the contract too: one `error:` line (CLI11 printed two, unprefixed).
  expect_one_error_line(run_gearbench("verify --tier medium"), "--tier");
  expect_one_error_line(run_gearbench("frobnicate"), "frobnicate");
  expect_one_error_line(run_gearbench("run"), "case is required");
}

// report compare on a report.json of another structure: once a lookup of a missing key in a
// const JSON object (undefined behaviour), now the key is named.
TEST(Cli, CompareRefusesAForeignReport) {
  const auto bare = write_case("report_bare", R"({"schema_version": 1, "checks": [{"id": "a"}]})");
  expect_one_error_line(run_gearbench("report compare " + bare + " " + bare), "machine.fingerprint: missing");
  const auto check = write_case("report_check", R"({"schema_version": 1, "machine": {"fingerprint": "x"},
                                                    "checks": [{"id": "a", "status": "pass", "value": "1"}]})");
  expect_one_error_line(run_gearbench("report compare " + check + " " + check),
                        "checks[0].value: must be a number or null");
}

// The report plumbing on the geometry checks (--only keeps the test in seconds under ASan;
// ctest's verification_gate runs every check of the fast tier).
TEST(Cli, VerifyTwiceThenCompare) {
  const auto dir = temp_path("cli_verify");
  fs::remove_all(dir);
  const std::string verify = "verify --only '^geometry\\.' --out " + dir.string();
  const auto first = run_gearbench(verify);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.err.find(" pass, 0 reproduced, 0 missed, 0 failed"), std::string::npos) << first.err;  // headline
  const auto second = run_gearbench(verify);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  auto folder = [](const std::string& out) { return fs::path(out.substr(0, out.find('\n'))).parent_path(); };
  const auto a = folder(first.out), b = folder(second.out);
  ASSERT_NE(a, b);  // never overwritten
  for (const auto& f : {"report.json", "report.md"}) EXPECT_TRUE(fs::exists(a / f)) << f;
  const auto same = run_gearbench("report compare " + a.string() + " " + b.string());
  EXPECT_EQ(same.exit_code, 0) << same.out;
  EXPECT_EQ(same.out.find("REGRESSIONS"), std::string::npos) << same.out;

  // A check that went from pass to fail is flagged, and the exit code says so.
  std::ifstream in(b / "report.json");
  auto broken = json::parse(in);
  broken["checks"][0]["status"] = "fail";
  std::ofstream(dir / "broken.json") << broken.dump();
  const auto regressed = run_gearbench("report compare " + a.string() + " " + (dir / "broken.json").string());
  EXPECT_EQ(regressed.exit_code, 1);
  EXPECT_NE(regressed.out.find("REGRESSIONS: pass -> fail (1)"), std::string::npos) << regressed.out;
  fs::remove_all(dir);
}

TEST(Cli, VerifyOnlyValidates) {
  const auto bad = run_gearbench("verify --only '(' --out " + temp_path("cli_verify_bad").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--only \"(\": not a regular expression"), std::string::npos) << bad.err;
  const auto none = run_gearbench("verify --only '^no_such_check$' --out " + temp_path("cli_verify_none").string());
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("matches no check or section"), std::string::npos) << none.err;
}

TEST(Cli, BenchRecordsContextAndRatio) {
  const std::string bench_exe = GEARBENCH_BINARY_DIR "/benchmarks/gearbench_benchmarks";
  if (!fs::exists(bench_exe)) GTEST_SKIP() << "benchmarks not built in this preset";
  const auto dir = temp_path("cli_bench");
  fs::remove_all(dir);
  const auto o = run_gearbench("bench --filter BM_GeometryProfile --min-time 0.01 --out " + dir.string());
  ASSERT_EQ(o.exit_code, 0) << o.err;
  std::ifstream in(o.out.substr(0, o.out.find('\n')));
  const auto record = json::parse(in);
  EXPECT_TRUE(record["gearbench"]["code"].contains("git_sha"));
  EXPECT_TRUE(record["gearbench"]["machine"].contains("fingerprint"));
  ASSERT_TRUE(record["ratios"].contains("BM_GeometryProfile/101")) << record["ratios"].dump();
  EXPECT_GT(record["ratios"]["BM_GeometryProfile/101"]["ratio"].get<double>(), 0.0);

  // The record becomes the report's Benchmarks section.
  const auto verify = run_gearbench("verify --only '^geometry\\.' --out " + (dir / "reports").string() + " --bench " +
                                    o.out.substr(0, o.out.find('\n')));
  ASSERT_EQ(verify.exit_code, 0) << verify.err;
  std::ifstream md(verify.out.substr(0, verify.out.find('\n')));
  const std::string text(std::istreambuf_iterator<char>(md), {});
  EXPECT_NE(text.find("## Benchmarks"), std::string::npos);
  EXPECT_NE(text.find("| `BM_GeometryProfile/101` | `BM_GeometryProfile_baseline` |"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace

// Thermal EHL: a point contact and the seed 001 path run on small grids (161 nodes); bad
// input exits 2 naming the key; an iteration cap that is too small exits 3 with the
// diagnostics in -o.
TEST(Cli, ThermalEhlRunsAndValidates) {
  std::ifstream in(GEARBENCH_SOURCE_DIR "/cases/tehl_point_sliding.json");
  auto point = json::parse(in);
  point["grid"] = {{"levels", 3}};
  const auto o = run_gearbench("run " + write_case("tehl_point_small", point.dump()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto r = json::parse(o.out);
  EXPECT_LT(r["h_min_m"].get<double>(), r["isothermal"]["h_min_m"].get<double>());
  EXPECT_GT(r["temperature_rise_max_K"].get<double>(), 10.0);
  EXPECT_TRUE(r.contains("friction_coefficient_eyring"));
  EXPECT_EQ(r["temperature_field"]["film_K"].size(), r["profile"]["x_m"].size());

  const std::pair<std::string, std::string> bad[] = {
      {R"("lubricant": {"nu40_mm2_s": 320})", "give either viscosity_Pa_s"},
      {R"("inlet_temperature_K": 100)", "inlet_temperature_K = 100: allowed range is [200, 600]"},
      {R"("solids": {"density_kg_m3": [7850]})", "solids.density_kg_m3"},
      {R"("thermal": {"heat_sources": "radiation"})", "thermal.heat_sources"},
      {R"("thermal": {"film_nodes": 2})", "thermal.film_nodes = 2"},
  };
  int n = 0;
  for (const auto& [patch, expected] : bad) {
    auto j = point;
    j.merge_patch(json::parse("{" + patch + "}"));
    const auto b = run_gearbench("run " + write_case("tehl_bad_" + std::to_string(n++), j.dump()));
    EXPECT_EQ(b.exit_code, 2) << patch << "\n" << b.err;
    EXPECT_NE(b.err.find(expected), std::string::npos) << b.err;
  }

  auto capped = point;
  capped["thermal"] = {{"max_iterations", 1}};
  const auto out = temp_path("tehl_unconverged.json").string();
  const auto failed = run_gearbench("run " + write_case("tehl_capped", capped.dump()) + " -o " + out);
  EXPECT_EQ(failed.exit_code, 3) << failed.err;
  std::ifstream diag(out);
  EXPECT_FALSE(json::parse(diag)["diagnostics"]["converged"].get<bool>());
  fs::remove(out);

  std::ifstream path_in(GEARBENCH_SOURCE_DIR "/cases/seed001_tehl_path.json");
  auto path = json::parse(path_in);
  path["grid"] = {{"levels", 3}};
  const auto p = run_gearbench("run " + write_case("tehl_path_small", path.dump()));
  ASSERT_EQ(p.exit_code, 0) << p.err;
  const auto rp = json::parse(p.out);
  EXPECT_EQ(rp["points"].size(), 7u);
  EXPECT_EQ(rp["minimum_film_point"], "A");
  EXPECT_NE(p.err.find("thermal EHL point E (7/7)"), std::string::npos) << p.err;
}
