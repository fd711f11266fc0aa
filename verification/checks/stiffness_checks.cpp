// Energy-method mesh stiffness against its references: the GSL quadrature of the same
// energy integrals (reference/quadrature, derived independently in Tian's pressure-angle
// parametrisation), ISO 6336-1 method B, the model's own continuity and crack behaviour,
// and the seed 003 reproduction.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "check_registry.h"
#include "closed_form/sainsot_foundation.h"
#include "quadrature/energy_quadrature.h"
#include "stiffness/mesh_stiffness.h"
#include "stiffness_pairs.h"

namespace gearbench::verification {
namespace {

using geometry::GearPairGeometry;
using stiffness::MeshStiffness;
using stiffness::MeshStiffnessOptions;

const char* section = "Energy-method mesh stiffness";
const char* seed_section = "Seed reproductions: mesh stiffness (seed 003)";
const char* solver = "stiffness";

struct StiffnessCase {
  model::GearPair pair;
  std::array<model::Material, 2> materials;
};

StiffnessCase load_case(const CheckContext& ctx, const std::string& file) {
  const auto c = ctx.gear_case(file);
  return {c.gear_pair, *c.materials};
}

StiffnessCase seed003(const CheckContext& ctx) { return load_case(ctx, "seed003_spur_stiffness.json"); }

stiffness::GearCrack pitch_crack(double length_mm) {
  return {{stiffness::Crack::Type::pitch, length_mm * 1e-3, 45.0 * M_PI / 180.0}, 0};
}

stiffness::GearCrack root_crack(double length_mm) {
  return {{stiffness::Crack::Type::root, length_mm * 1e-3, 45.0 * M_PI / 180.0}, 0};
}

// --- GSL quadrature agreement ------------------------------------------------------------

constexpr stiffness::ToothModel arc{stiffness::BeamStart::improved, stiffness::Fillet::circular_arc};
constexpr stiffness::ToothModel trochoid{stiffness::BeamStart::improved, stiffness::Fillet::trochoid};

reference::QuadBeamStart quad_start(stiffness::ToothModel m) {
  switch (m.start) {
    case stiffness::BeamStart::straight: return reference::QuadBeamStart::straight;
    case stiffness::BeamStart::base_circle: return reference::QuadBeamStart::base_circle;
    default:
      return m.fillet == stiffness::Fillet::trochoid ? reference::QuadBeamStart::trochoid
                                                     : reference::QuadBeamStart::circular_arc;
  }
}

/// Unshifted-wheel spur pairs beside seed 003 for the trochoid's agreement: R_f above R_b
/// (62/62), and a shifted pinion on ISO 53 profile D (h_fP 1.4, ρ_fP 0.39).
StiffnessCase z62_62(const CheckContext&) { return {spur_pair(62, 62, 2.0, 20.0), steel206}; }
StiffnessCase z19_48_profile_d(const CheckContext&) {
  model::GearPair g = spur_pair(19, 48, 3.2, 16.0, 0.3, 0.0);
  g.dedendum_coef = 1.4;
  g.root_radius_coef = 0.39;
  return {g, steel206};
}

/// Largest relative difference of bending, shear and axial compliance between production
/// and the GSL reference, over both gears and 41 positions along A..E.
CheckValue quadrature_agreement(const StiffnessCase& c, stiffness::ToothModel start,
                                const std::optional<stiffness::GearCrack>& crack) {
  const GearPairGeometry g(c.pair);
  const stiffness::PairStiffness production(g, c.materials, start,
                                            {0.5 * g.radii(0).root, 0.5 * g.radii(1).root}, crack, false);
  reference::QuadCrack qc;
  if (crack) {
    qc.type = crack->crack.type == stiffness::Crack::Type::pitch ? reference::QuadCrack::Type::pitch
                                                                 : reference::QuadCrack::Type::root;
    qc.length = crack->crack.length;
    qc.angle = crack->crack.angle;
  }
  double worst = 0.0;
  std::string where;
  const auto& p = g.path();
  for (int i = 0; i <= 40; ++i) {
    const double s = p.A + (p.E - p.A) * i / 40.0;
    const auto prod = production.compliance(s);
    for (int gear = 0; gear < 2; ++gear) {
      const bool cracked_gear = crack && crack->gear == gear;
      const auto ref = reference::energy_compliance_quadrature(
          c.pair, c.materials[static_cast<std::size_t>(gear)], gear, s, quad_start(start),
          cracked_gear ? qc : reference::QuadCrack{}, 1.0);
      const auto& t = prod.tooth[static_cast<std::size_t>(gear)];
      for (const auto& [name, a, b] : {std::tuple{"bending", t.bending, ref.bending},
                                       std::tuple{"shear", t.shear, ref.shear},
                                       std::tuple{"axial", t.axial, ref.axial}}) {
        const double rel = std::abs(a - b) / std::abs(b);
        if (rel > worst) {
          worst = rel;
          where = fmt::format("{} of gear {} at s = {:.4f} mm", name, gear + 1, s * 1e3);
        }
      }
    }
  }
  return {worst, 0.0, {{"worst", where}, {"positions", 41}}};
}

const std::string gsl_why =
    "GSL integrates at 1e-10 relative and production's panelled Gauss–Legendre rule is "
    "exact to ~1e-12 on smooth pieces; 1e-6 is the issue's bar and leaves room for the "
    "root-finding of the break points";

void register_quadrature_check(const std::string& tag, stiffness::ToothModel start,
                               std::optional<stiffness::GearCrack> crack,
                               StiffnessCase (*make)(const CheckContext&) = seed003) {
  Registry::instance().add(CheckSpec{
      .id = "stiffness.gsl." + tag, .section = section, .solver = solver,
      .reference = "GSL quadrature (Tian parametrisation)",
      .quantity = "max relative difference of k_b, k_s, k_a (both gears, 41 positions)",
      .unit = "-", .tolerance = {1e-6, 0}, .justification = gsl_why, .tier = Tier::fast,
      .run = [start, crack, make](const CheckContext& ctx) { return quadrature_agreement(make(ctx), start, crack); }});
}

// The fillet foundation and Hertz terms: the same closed forms, but on the reference's own
// beam start, load point and load angle (the geometry is what can go wrong).
void register_foundation_check(const std::string& tag, stiffness::ToothModel model,
                               StiffnessCase (*make)(const CheckContext&)) {
  Registry::instance().add(CheckSpec{
      .id = "stiffness.gsl.foundation." + tag, .section = section, .solver = solver,
      .reference = "Sainsot on the reference's tooth geometry",
      .quantity = "max relative difference of 1/k_f (both gears, 41 positions)", .unit = "-",
      .tolerance = {1e-9, 0},
      .justification = "one closed form on two independently derived geometries (Brent roots to 1e-14)",
      .tier = Tier::fast, .run = [model, make](const CheckContext& ctx) {
        const auto c = make(ctx);
        const GearPairGeometry g(c.pair);
        const std::array<double, 2> bore{0.5 * g.radii(0).root, 0.5 * g.radii(1).root};
        const stiffness::PairStiffness production(g, c.materials, model, bore, std::nullopt, true);
        double worst = 0.0;
        const auto& p = g.path();
        for (int i = 0; i <= 40; ++i) {
          const double s = p.A + (p.E - p.A) * i / 40.0;
          const auto prod = production.compliance(s);
          for (int gear = 0; gear < 2; ++gear) {
            const auto geometry = reference::load_geometry_quadrature(c.pair, gear, s, quad_start(model));
            const double ref = reference::sainsot_foundation_compliance(
                geometry, bore[static_cast<std::size_t>(gear)], c.materials[static_cast<std::size_t>(gear)].youngs_modulus,
                1.0);
            worst = std::max(worst, std::abs(prod.foundation[static_cast<std::size_t>(gear)] - ref) / std::abs(ref));
          }
        }
        return CheckValue{worst, 0.0};
      }});
}

const RegisterCheck hertz_agreement(CheckSpec{
    .id = "stiffness.gsl.hertz", .section = section, .solver = solver,
    .reference = "Hertz line contact (reference)", .quantity = "relative difference of 1/k_h",
    .unit = "-", .tolerance = {1e-14, 0}, .justification = "the same closed form: rounding only",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto c = seed003(ctx);
      const GearPairGeometry g(c.pair);
      const stiffness::PairStiffness production(g, c.materials, stiffness::ToothModel{},
                                                {0.5 * g.radii(0).root, 0.5 * g.radii(1).root}, std::nullopt, true);
      const double ref = reference::hertz_compliance_quadrature(c.materials[0], c.materials[1], 1.0);
      return CheckValue{std::abs(production.compliance(g.path().C).hertz - ref) / ref, 0.0};
    }});

const bool quadrature_checks = [] {
  register_quadrature_check("improved", arc, std::nullopt);
  register_quadrature_check("straight", {stiffness::BeamStart::straight}, std::nullopt);
  register_quadrature_check("base_circle", {stiffness::BeamStart::base_circle}, std::nullopt);
  for (double q : {1.0, 2.0, 2.5})
    register_quadrature_check(fmt::format("pitch_crack_{}mm", q), arc, pitch_crack(q));
  register_quadrature_check("root_crack_1mm", arc, root_crack(1.0));
  register_quadrature_check("trochoid", trochoid, std::nullopt);
  register_quadrature_check("trochoid.z62_62", trochoid, std::nullopt, z62_62);
  register_quadrature_check("trochoid.z19_48_x0.3_iso53_D", trochoid, std::nullopt, z19_48_profile_d);
  register_quadrature_check("trochoid.pitch_crack_2.5mm", trochoid, pitch_crack(2.5));
  register_quadrature_check("trochoid.root_crack_1mm", trochoid, root_crack(1.0));
  register_foundation_check("improved", arc, seed003);
  register_foundation_check("trochoid", trochoid, seed003);
  register_foundation_check("trochoid.z62_62", trochoid, z62_62);
  register_foundation_check("trochoid.z19_48_x0.3_iso53_D", trochoid, z19_48_profile_d);
  return true;
}();

// --- Model properties ---------------------------------------------------------------------

// Root circle crossing the base circle (z 41, α 20°): the dedendum is varied by ±1e-7
// relative around R_f = R_b. The compliance is Lipschitz in R_f with a sensitivity below
// ~10 per unit relative change, so a jump would show far above 1e-5. The circular-arc fillet
// switches branch there (arc below, involute from the root circle above); the generated
// fillet has no branch, and the check runs on the arc.
const RegisterCheck continuity(CheckSpec{
    .id = "stiffness.continuity_root_base", .section = section, .solver = solver,
    .reference = "the model itself (branch switch)",
    .quantity = "relative jump of the pair compliance at the pitch point across R_f = R_b",
    .unit = "-", .tolerance = {1e-5, 0},
    .justification = "a ±1e-7 relative step in R_f moves a continuous compliance by < 1e-6",
    .tier = Tier::fast, .run = [](const CheckContext&) {
      auto pair = spur_pair(41, 60, 2.0, 20.0);
      const double R = 0.5 * 41 * pair.normal_module;
      const double switch_coef = (R - R * std::cos(pair.normal_pressure_angle)) / pair.normal_module;
      auto compliance = [&](double coef) {
        pair.dedendum_coef = coef;
        const GearPairGeometry g(pair);
        const stiffness::PairStiffness k(g, steel206, arc,
                                         {0.5 * g.radii(0).root, 0.5 * g.radii(1).root}, std::nullopt, true);
        return k.compliance(g.path().C).total();
      };
      const double below = compliance(switch_coef * (1 - 1e-7));
      const double above = compliance(switch_coef * (1 + 1e-7));
      return CheckValue{std::abs(above - below) / below, 0.0, {{"dedendum_coef_at_switch", switch_coef}}};
    }});

/// Largest relative difference of the single-pair stiffness along A..E between a pitch
/// crack of `length_mm` and the healthy tooth (seed 003 pair).
double crack_change(const CheckContext& ctx, double length_mm) {
  const auto c = seed003(ctx);
  const GearPairGeometry g(c.pair);
  MeshStiffnessOptions healthy, cracked;
  cracked.crack = pitch_crack(length_mm);
  const auto a = MeshStiffness(g, c.materials, healthy).solve();
  const auto b = MeshStiffness(g, c.materials, cracked).solve();
  double worst = 0.0;
  for (std::size_t i = 0; i < a.single_pair_stiffness.size(); ++i)
    worst = std::max(worst, std::abs(a.single_pair_stiffness[i] - b.single_pair_stiffness[i]) / a.single_pair_stiffness[i]);
  return worst;
}

// Continuity at zero crack length. A crack of exactly 0 is no crack (the solver drops it), so
// the limit is probed with 1e-6 mm. Measured on the generated fillet: 7.5e-14 (1.5e-10 on the
// circular arc), while the 0.5 mm crack changes the stiffness by 1.9 %, whose linear share at
// 1e-6 mm would be 3.8e-8 (both in the diagnostics): the change vanishes faster than
// linearly. 1e-8 still fails a jump at q → 0 or any change of linear order.
const RegisterCheck crack_continuity(CheckSpec{
    .id = "stiffness.crack_length_continuity", .section = section, .solver = solver,
    .reference = "the healthy tooth",
    .quantity = "max relative difference of the single-pair stiffness, crack 1e-6 mm vs healthy",
    .unit = "-", .tolerance = {1e-8, 0},
    .justification = "measured 7.5e-14; the linear share of the 0.5 mm crack's 1.9 % change would be 3.8e-8, "
                     "so 1e-8 fails a jump or any change of linear order at q → 0",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const double half_mm = crack_change(ctx, 0.5);
      return CheckValue{crack_change(ctx, 1e-6), 0.0,
                        {{"change_at_0_5mm", half_mm}, {"linear_prediction_at_1e-6mm", half_mm * 1e-6 / 0.5}}};
    }});

// Monotone in crack length above the crack mouth, untouched below it.
const RegisterCheck crack_monotone(CheckSpec{
    .id = "stiffness.crack_monotone", .section = section, .solver = solver,
    .reference = "the model itself (crack ordering)",
    .quantity = "positions where k does not fall with crack length (0…2.5 mm) or changes below the mouth",
    .unit = "count", .tolerance = {0, 0},
    .justification = "a longer crack removes material: the order is exact, not approximate",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto c = seed003(ctx);
      const GearPairGeometry g(c.pair);
      const double mouth = g.radii(0).base * std::tan(g.transverse_pressure_angle());
      std::vector<std::vector<double>> curves;
      std::vector<double> positions;
      for (double q : {0.0, 0.5, 1.0, 1.5, 2.0, 2.5}) {
        MeshStiffnessOptions o;
        o.crack = pitch_crack(q);
        const auto r = MeshStiffness(g, c.materials, o).solve();
        curves.push_back(r.single_pair_stiffness);
        positions = r.path_position;
      }
      int violations = 0;
      for (std::size_t i = 0; i < positions.size(); ++i)
        for (std::size_t q = 1; q < curves.size(); ++q) {
          const bool above_mouth = positions[i] > mouth;
          if (above_mouth && !(curves[q][i] < curves[q - 1][i])) ++violations;
          if (!above_mouth && curves[q][i] != curves[0][i]) ++violations;
        }
      return CheckValue{static_cast<double>(violations), 0.0, {{"positions", positions.size()}}};
    }});

// --- Helical slicing ------------------------------------------------------------------------

model::GearPair helical_seed003(const CheckContext& ctx) {
  auto pair = seed003(ctx).pair;
  pair.helix_angle = 15.0 * M_PI / 180.0;
  return pair;
}

// The sliced sum uses a cubic spline of the single-pair curve (1025 nodes on A..E); the
// curve is smooth on A..E, so the spline error scales as h⁴ and sits near 1e-10.
const RegisterCheck helical_spline(CheckSpec{
    .id = "stiffness.helical.spline_vs_direct", .section = section, .solver = solver,
    .reference = "direct evaluation of every slice",
    .quantity = "max relative difference of the sliced mesh stiffness (β 15°, 50 slices)",
    .unit = "-", .tolerance = {1e-7, 0},
    .justification = "natural cubic spline on 1025 nodes of a smooth curve: O(h⁴) ≈ 1e-10; "
                     "1e-7 leaves margin for the ends, where the natural end condition is O(h²)",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto pair = helical_seed003(ctx);
      const auto materials = seed003(ctx).materials;
      const GearPairGeometry g(pair);
      MeshStiffnessOptions o;
      o.positions = 24;
      const auto r = MeshStiffness(g, materials, o).solve();
      const stiffness::PairStiffness direct(g, materials, {o.beam_start, o.fillet},
                                            {0.5 * g.radii(0).root, 0.5 * g.radii(1).root}, std::nullopt, true);
      const double pb = g.base_pitch_transverse();
      const double w = pair.face_width / o.slices;
      const double shift = w * std::tan(g.base_helix_angle());
      double worst = 0.0;
      for (std::size_t i = 0; i < r.mesh_position.size(); ++i) {
        const double s0 = g.path().A + pb * static_cast<double>(i) / o.positions;
        double k = 0.0;
        for (int j = 0; j < o.slices; ++j) {
          const double sj = s0 - (j + 0.5) * shift;
          for (double s = sj - std::floor((sj - g.path().A) / pb) * pb; s <= g.path().E; s += pb)
            k += w * direct.stiffness_per_width(s);
        }
        worst = std::max(worst, std::abs(r.mesh_stiffness[i] - k) / k);
      }
      return CheckValue{worst, 0.0};
    }});

// Slicing is a midpoint rule across the face width. Averaged over a mesh cycle its error
// largely cancels: 50…400 slices differ by ~1e-5 relative and not monotonically, so no
// order is claimed (the diagnostics list the means); the check bounds the 200-slice mean
// against 400 slices.
const RegisterCheck helical_slices(CheckSpec{
    .id = "stiffness.helical.slice_convergence", .section = section, .solver = solver,
    .reference = "the same model on 400 slices",
    .quantity = "mean mesh stiffness on 200 slices (β 15°)", .unit = "N/(mm·µm)",
    .tolerance = {0, 1e-3},
    .justification = "the 200→400-slice change bounds the slicing error of the cycle mean",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto pair = helical_seed003(ctx);
      const auto materials = seed003(ctx).materials;
      const GearPairGeometry g(pair);
      std::vector<double> means;
      for (int slices : {50, 100, 200, 400}) {
        MeshStiffnessOptions o;
        o.positions = 90;
        o.slices = slices;
        means.push_back(MeshStiffness(g, materials, o).solve().mean_per_face_width());
      }
      return CheckValue{means[2], means[3], {{"means_50_100_200_400", means}}};
    }});

// --- Seed 003 reproduction ------------------------------------------------------------------

struct CrackDrops {
  double mesh = 0.0;   ///< max relative drop of the total mesh stiffness
  double shear = 0.0;  ///< max relative drop of the cracked tooth's shear stiffness
};

/// Seed 003's own tooth model: the circular-arc fillet (its eq. 1, as gearbench reads it).
MeshStiffnessOptions seed003_options(std::optional<stiffness::GearCrack> crack) {
  MeshStiffnessOptions o;
  o.fillet = stiffness::Fillet::circular_arc;
  o.crack = crack;
  return o;
}

CrackDrops crack_drops(const CheckContext& ctx, double length_mm) {
  const auto c = seed003(ctx);
  const GearPairGeometry g(c.pair);
  const auto healthy = seed003_options(std::nullopt), cracked = seed003_options(pitch_crack(length_mm));
  const auto h = MeshStiffness(g, c.materials, healthy).solve();
  const auto k = MeshStiffness(g, c.materials, cracked).solve();
  CrackDrops d;
  for (std::size_t i = 0; i < k.mesh_stiffness.size(); ++i)
    d.mesh = std::max(d.mesh, 1.0 - k.mesh_stiffness[i] / k.healthy_mesh_stiffness[i]);
  for (std::size_t i = 0; i < k.shear[0].size(); ++i)
    d.shear = std::max(d.shear, 1.0 - k.shear[0][i] / h.shear[0][i]);
  return d;
}

const RegisterCheck seed003_mesh_drop(CheckSpec{
    .id = "seed003.mesh_stiffness_drop_2_5mm", .section = seed_section, .solver = solver,
    .reference = "seed 003 (14.3 %)",
    .quantity = "max drop of the total mesh stiffness, 2.5 mm pitch crack at 45°", .unit = "%",
    .tolerance = {1.0, 0}, .justification = "one percentage point: the paper reads its curves to 0.1 %, "
    "but our tooth model's free choices (fillet, foundation) move the figure by more",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) { return CheckValue{100 * crack_drops(ctx, 2.5).mesh, 14.3}; },
    .recorded = 32.1, .recorded_tolerance = 0.01});

const RegisterCheck seed003_shear_drop(CheckSpec{
    .id = "seed003.shear_stiffness_drop_2_5mm", .section = seed_section, .solver = solver,
    .reference = "seed 003 (49 %)",
    .quantity = "max drop of the cracked tooth's shear stiffness, 2.5 mm crack", .unit = "%",
    .tolerance = {1.0, 0}, .justification = "one percentage point (the paper prints 49 %)",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) { return CheckValue{100 * crack_drops(ctx, 2.5).shear, 49.0}; },
    .recorded = 55.0, .recorded_tolerance = 0.01});

// --- Figures and notes ----------------------------------------------------------------------

void add_seed003_figures(const CheckContext& ctx, reports::Report& report) {
  const auto c = seed003(ctx);
  const GearPairGeometry g(c.pair);
  const double to_deg = 180.0 / M_PI;
  std::vector<reports::Series> mesh, bending, shear;
  for (double q : {0.0, 1.0, 2.0, 2.5}) {
    const auto r = MeshStiffness(g, c.materials, seed003_options(pitch_crack(q))).solve();
    const std::string label = q == 0.0 ? "healthy" : fmt::format("{} mm crack", q);
    mesh.push_back({label, scaled(r.mesh_position, to_deg), scaled(r.mesh_stiffness, 1e-8)});
    const auto roll = scaled(r.path_position, 1.0 / g.radii(0).base * to_deg);
    bending.push_back({label, roll, scaled(r.bending[0], 1e-8)});
    shear.push_back({label, roll, scaled(r.shear[0], 1e-8)});
  }
  {
    const auto r = MeshStiffness(g, c.materials, MeshStiffnessOptions{}).solve();
    const auto roll = scaled(r.path_position, 1.0 / g.radii(0).base * to_deg);
    const std::vector<double> hertz(roll.size(), r.hertz * 1e-8);
    report.figures.push_back({"stiffness_seed003_components", section,
                              "Seed 003 pair, healthy: stiffness components along A..E (log scale)",
                              "pinion roll angle [deg]", "k [1e8 N/m]",
                              {{"bending, pinion", roll, scaled(r.bending[0], 1e-8)},
                               {"shear, pinion", roll, scaled(r.shear[0], 1e-8)},
                               {"axial, pinion", roll, scaled(r.axial[0], 1e-8)},
                               {"foundation, pinion", roll, scaled(r.foundation[0], 1e-8)},
                               {"Hertz", roll, hertz},
                               {"single pair", roll, scaled(r.single_pair_stiffness, 1e-8)}},
                              true});
  }
  report.figures.push_back({"stiffness_seed003_mesh", seed_section,
                            "Seed 003: mesh stiffness over the cracked tooth's engagement (45° pitch crack)",
                            "pinion rotation from A [deg]", "k [1e8 N/m]", mesh});
  report.figures.push_back({"stiffness_seed003_bending", seed_section,
                            "Seed 003: bending stiffness of the cracked pinion tooth",
                            "pinion roll angle [deg]", "k_b [1e8 N/m]", bending});
  report.figures.push_back({"stiffness_seed003_shear", seed_section,
                            "Seed 003: shear stiffness of the cracked pinion tooth",
                            "pinion roll angle [deg]", "k_s [1e8 N/m]", shear});

  std::string rows;
  for (double q : {1.0, 2.0, 2.5}) {
    const auto d = crack_drops(ctx, q);
    rows += fmt::format("| {} | {:.1f} | {:.1f} |\n", q, 100 * d.mesh, 100 * d.shear);
  }
  report.notes.push_back({seed_section, fmt::format(
      "Crack at the pitch circle of the pinion, 45°, through the face; improved tooth model "
      "(docs/stiffness-model.md) with seed 003's circular-arc fillet and the Sainsot foundation.\n\n"
      "| crack [mm] | max drop of mesh stiffness [%] | max drop of shear stiffness [%] |\n"
      "|---|---|---|\n{}\n"
      "The paper reports 14.3 % and 49 % at 2.5 mm. Both are missed, in opposite directions, "
      "and the gap is understood in part. At 2.5 mm the crack passes the centre line "
      "(h_c = −0.20 mm). Seed eq. (10) then writes the section as (h_x − h_c)·L: read with "
      "h_c signed, that thickens the section. With that literal reading the drops become "
      "19.8 % (mesh) and 38.9 % (shear), which brackets the paper's pair. gearbench keeps the "
      "physical ligament h_x + h_c. The paper's fillet arc (eq. 1) is garbled in print: "
      "gearbench's arc choice, the foundation term and the u_f convention all shift the "
      "healthy stiffness, and with it the relative drop. Seed figure 3 cannot be digitised "
      "from the text, so the remaining share of the gap cannot be assigned.", rows)});
}

const RegisterSection stiffness_section(SectionSpec{
    .id = "stiffness", .tier = Tier::fast, .add = [](const CheckContext& ctx, reports::Report& report) {
      add_seed003_figures(ctx, report);
    }});

}  // namespace
}  // namespace gearbench::verification
