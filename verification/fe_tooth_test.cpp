// The deal.II finite-element tooth reference (reference/fe_tooth): the cantilever sanity
// case against Timoshenko beam theory, the generated tooth geometry against the involute's
// closed form, and the tooth compliance's convergence and load-patch independence on one
// position (seconds; the comparison with the energy method is in checks/fe_stiffness_checks).
#include <gtest/gtest.h>

#include <cmath>

#include "fe_tooth/cantilever.h"
#include "fe_tooth/fe_backend.h"
#include "fe_tooth/fe_tooth_stiffness.h"
#include "model/errors.h"

namespace gearbench::reference::fe {
namespace {

const model::Material steel{212e9, 0.289, 7850};

model::GearPair seed003_pair() {
  model::GearPair g;
  g.teeth = {20, 25};
  g.normal_module = 2e-3;
  g.normal_pressure_angle = 20.0 * M_PI / 180.0;
  g.face_width = 20e-3;
  return g;
}

CantileverResult converged_cantilever(bool plane_strain) {
  Cantilever c;
  c.material.plane_strain = plane_strain;
  ElasticOptions o;
  o.max_cycles = 10;
  o.tolerance = 1e-5;
  return solve_cantilever(c, o);
}

// Tolerance: the shear term (3 % of the deflection at L/H = 5). The fully clamped 2D end
// restrains warping, which Timoshenko's beam does not; that end effect is a fraction of the
// shear term, and the FE is converged to 1e-5, so agreement within the shear term is the
// bar. A wrong Lamé constant or plane-stress switch misses it by 9 % or more.
TEST(FeCantilever, PlaneStressMatchesTimoshenkoBeam) {
  const auto r = converged_cantilever(false);
  std::printf("%splane stress: FE/Timoshenko %.5f, shear share %.4f, rate %.2f, %.2f s\n", r.fe.table.c_str(),
              r.deflection / r.timoshenko, r.shear / r.timoshenko, r.fe.observed_rate, r.fe.seconds);
  EXPECT_TRUE(r.fe.converged);
  EXPECT_NEAR(r.deflection / r.timoshenko, 1.0, r.shear / r.timoshenko);
}

// Plane strain: the beam's bending modulus becomes E/(1 − ν²); same tolerance and reason.
TEST(FeCantilever, PlaneStrainMatchesTimoshenkoBeam) {
  const auto r = converged_cantilever(true);
  std::printf("plane strain: FE/Timoshenko %.5f\n", r.deflection / r.timoshenko);
  EXPECT_TRUE(r.fe.converged);
  EXPECT_NEAR(r.deflection / r.timoshenko, 1.0, r.shear / r.timoshenko);
}

// The generated flank above the form circle is the envelope of the straight rack flank,
// an involute: its polar angle must follow the tooth-thickness closed form (ISO 21771)
// θ(r) = π/(2z) + 2x tan α/z + inv α − inv α_r, cos α_r = r_b/r. Tolerance 1e-9 rad: the
// envelope is exact, so only rounding remains. (The tip corner, interpolated between two
// samples, is off by ~1e-6 rad, 20 nm at the tip, and is left out.)
TEST(FeToothGeometry, InvoluteFollowsThicknessClosedForm) {
  auto pair = seed003_pair();
  pair.profile_shift = {0.3, -0.2};
  for (int gear = 0; gear < 2; ++gear) {
    const auto t = generate_tooth(pair, gear);
    const double z = pair.teeth[static_cast<std::size_t>(gear)], x = pair.profile_shift[static_cast<std::size_t>(gear)];
    const double a = pair.normal_pressure_angle;
    auto inv = [](double v) { return std::tan(v) - v; };
    double worst = 0.0;
    for (std::size_t i = t.involute_start; i + 1 < t.flank.size(); ++i) {
      const double r = std::hypot(t.flank[i][0], t.flank[i][1]);
      const double expected = M_PI / (2 * z) + 2 * x * std::tan(a) / z + inv(a) - inv(std::acos(t.radii.base / r));
      worst = std::max(worst, std::abs(std::atan2(t.flank[i][1], t.flank[i][0]) - expected));
    }
    EXPECT_LT(worst, 1e-9) << "gear " << gear + 1;
    // The profile starts on the root circle at the tooth-space centre line.
    EXPECT_NEAR(std::hypot(t.flank[0][0], t.flank[0][1]), t.radii.root, 1e-12);
    EXPECT_NEAR(std::atan2(t.flank[0][1], t.flank[0][0]), M_PI / z, 1e-12);
  }
}

TEST(FeToothGeometry, RejectsWhatItDoesNotModel) {
  auto helical = seed003_pair();
  helical.helix_angle = 0.2;
  EXPECT_THROW(generate_tooth(helical, 0), InputError);
  auto undercut = seed003_pair();
  undercut.teeth = {12, 25};
  EXPECT_THROW(generate_tooth(undercut, 0), InputError);
}

// The options are validated from their table before anything is meshed or crosses into the
// deal.II plugin (which validates nothing itself): the key, the value and the range.
TEST(FeToothOptions, ValidateNamesKeyValueAndRange) {
  const auto error = [](auto edit) {
    FeToothOptions o;
    edit(o);
    try {
      const FeToothStiffness model(seed003_pair(), {steel, steel}, o);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error([](auto& o) { o.fe.degree = 0; }), "fe.degree = 0: allowed range is [1, 4]");
  EXPECT_EQ(error([](auto& o) { o.fe.tolerance = 0.0; }), "fe.tolerance = 0: allowed range is (0, 0.5)");
  EXPECT_EQ(error([](auto& o) { o.far_size_modules = 0.2; }),
            "mesh.far_size_modules = 0.2: must be at least mesh.near_size_modules = 0.25");
  EXPECT_EQ(error([](auto& o) { o.crack = ToothCrack{2, 1e-3, 0.5}; }), "crack.gear = 3: allowed range is [1, 2]");
  EXPECT_EQ(error([](auto& o) { o.bore_radius = std::array<double, 2>{0.005, -0.001}; }),
            "bore_diameter_mm[1] = -2: allowed range is (0, 10000000] mm");
  Cantilever c;
  ElasticOptions bad;
  bad.max_cycles = 30;
  EXPECT_THROW((void)solve_cantilever(c, bad), InputError);
}

// One position (the pitch point, pinion): the compliance converges to the bar
// (< 0.5 % over each of the last two refinements), the probe lies inside the tooth, and
// doubling the load (which widens the Hertz patch by √2) moves the compliance by less than
// the convergence tolerance: the probe on the centre line sees the load's resultant only
// (Saint-Venant), so the FE tooth compliance contains no local contact flattening.
TEST(FeToothCompliance, ConvergesAndIgnoresTheLoadPatch) {
  const auto pair = seed003_pair();
  FeToothOptions o;
  o.plane_stress = true;
  const FeToothStiffness model(pair, {steel, steel}, o);
  const double pitch_point = model.tooth(0).radii.base * std::tan(20.0 * M_PI / 180.0);
  const auto c = model.tooth_compliance(0, pitch_point);
  std::printf("%scompliance %.6e m/N, rate %.2f, %.2f s\n", c.fe.table.c_str(), c.compliance, c.fe.observed_rate,
              c.fe.seconds);
  ASSERT_TRUE(c.fe.converged);
  EXPECT_LT(c.fe.cycles.back().change, 0.005);
  EXPECT_GT(c.probe[0], model.tooth(0).radii.root);
  EXPECT_LT(c.probe[0], c.load_point[0]);

  o.load_per_width *= 2;
  const FeToothStiffness doubled(pair, {steel, steel}, o);
  const auto c2 = doubled.tooth_compliance(0, pitch_point);
  EXPECT_NEAR(c2.compliance / c.compliance, 1.0, 0.005);
}

// Seed 003's 2.5 mm pitch crack at 45° meshed as a slit: the mouth lies on the flank at
// the reference circle, the tip q further at ν to the centre line, and gmsh's Plugin(Crack)
// leaves duplicated nodes along it — every slit node but the tip appears twice (tolerance
// 1e-12 m: the copies are the same coordinates). Without the plugin the count is zero.
TEST(FeToothCrack, SlitHasDuplicatedNodes) {
  const auto pair = seed003_pair();
  const auto tooth = generate_tooth(pair, 0);
  const Slit slit = pitch_crack_slit(tooth, ToothCrack{0, 2.5e-3, M_PI / 4});
  EXPECT_NEAR(std::hypot(slit.mouth[0], slit.mouth[1]), tooth.radii.pitch, 1e-9);
  EXPECT_NEAR(std::hypot(slit.tip[0] - slit.mouth[0], slit.tip[1] - slit.mouth[1]), 2.5e-3, 1e-12);
  EXPECT_LT(slit.tip[1], 0.0);  // case 3 of seed 003: past the centre line
  GearMeshSizes sizes;
  sizes.near = 0.5e-3;
  sizes.far = 3e-3;
  sizes.growth = 0.2;
  sizes.focus = {0.5 * (tooth.radii.root + tooth.radii.tip), 0.0};
  const auto mesh = fe_backend().mesh_gear(tooth, 0.5 * tooth.radii.root, sizes, slit);
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& q : mesh.quads)
    for (const auto v : q) used[v] = 1;
  int on_slit = 0, duplicated = 0;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!used[i] || distance_to_slit(slit, mesh.vertices[i]) > 1e-12) continue;
    ++on_slit;
    for (std::size_t j = 0; j < mesh.vertices.size(); ++j)
      if (j != i && used[j] && std::hypot(mesh.vertices[j][0] - mesh.vertices[i][0],
                                          mesh.vertices[j][1] - mesh.vertices[i][1]) < 1e-12) {
        ++duplicated;
        break;
      }
  }
  std::printf("slit: %d nodes on it, %d of them duplicated\n", on_slit, duplicated);
  EXPECT_GE(on_slit, 5);
  EXPECT_EQ(duplicated, on_slit - 1);  // all but the tip
}

// A crack that leaves less than 10 % of the section is a broken tooth: InputError.
TEST(FeToothCrack, RejectsABrokenTooth) {
  const auto tooth = generate_tooth(seed003_pair(), 0);
  EXPECT_THROW(pitch_crack_slit(tooth, ToothCrack{0, 4e-3, M_PI / 4}), InputError);
}

}  // namespace
}  // namespace gearbench::reference::fe
