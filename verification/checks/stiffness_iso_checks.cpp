// The energy-method mesh stiffness against ISO 6336-1 method B (c′ and c_γα over a set of
// pairs, z 17…100, x −0.3…0.6) and beside its peer ROSS, each with the generated fillet (the
// default, which the checks use) and the circular arc side by side in the report.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "check_registry.h"
#include "closed_form/iso6336_stiffness.h"
#include "stiffness/mesh_stiffness.h"
#include "stiffness_pairs.h"

namespace gearbench::verification {
namespace {

using geometry::GearPairGeometry;
using stiffness::MeshStiffness;
using stiffness::MeshStiffnessOptions;

const char* section = "Energy-method mesh stiffness";
const char* solver = "stiffness";

// --- ISO 6336-1 method B ----------------------------------------------------------------

struct IsoPair {
  int z1, z2;
  double x1, x2;
};
// z 17…100 and x −0.3…0.6 wherever the pair is free of undercut and interference.
const IsoPair iso_pairs[] = {{17, 34, 0.3, 0.0},  {17, 34, 0.6, 0.0},  {25, 50, 0.0, 0.0},
                             {25, 50, 0.3, 0.0},  {25, 50, 0.6, 0.0},  {40, 80, 0.0, 0.0},
                             {40, 80, 0.3, 0.0},  {40, 80, 0.6, 0.0},  {60, 100, 0.0, 0.0},
                             {60, 100, 0.6, 0.0}, {100, 100, -0.3, -0.3}, {100, 100, 0.0, 0.0}};

model::GearPair iso_pair(const IsoPair& p) { return spur_pair(p.z1, p.z2, 2.0, 20.0, p.x1, p.x2); }

/// Mean of the single-pair curve over A..E per face width [N/(mm·µm)].
double mean_single_pair(const stiffness::MeshStiffnessResult& r, double face_width) {
  double sum = 0.0;
  for (double k : r.single_pair_stiffness) sum += k;
  return sum / static_cast<double>(r.single_pair_stiffness.size()) / (face_width * 1e3) * 1e-6;
}

double max_single_pair(const stiffness::MeshStiffnessResult& r, double face_width) {
  return *std::max_element(r.single_pair_stiffness.begin(), r.single_pair_stiffness.end()) /
         (face_width * 1e3) * 1e-6;
}

/// ISO 6336-1 defines c′ as the maximum stiffness of a single tooth pair per face width and
/// c_γα as the mean stiffness of the mesh; the energy method is compared quantity for
/// quantity. ISO method B is an empirical fit (C_M = 0.8 scales theory to measurement,
/// C_B corrects the rack), so ±20 % is the band for a theory-against-standard comparison.
void register_iso_check(const IsoPair& p, bool mesh) {
  Registry::instance().add(CheckSpec{
      .id = fmt::format("stiffness.iso6336.{}.z{}_{}_x{}_{}", mesh ? "c_gamma_alpha" : "c_prime",
                        p.z1, p.z2, p.x1, p.x2),
      .section = section, .solver = solver,
      .reference = mesh ? "ISO 6336-1 method B c_γα" : "ISO 6336-1 method B c′",
      .quantity = fmt::format("{} per face width, z {}/{}, x {}/{}",
                              mesh ? "mean mesh stiffness" : "max single-pair stiffness", p.z1,
                              p.z2, p.x1, p.x2),
      .unit = "N/(mm·µm)", .tolerance = {0, 0.2},
      .justification = "ISO method B is an empirical fit (C_M = 0.8 scales theory to "
                       "measurement): ±20 % is the band for theory against the standard",
      .tier = Tier::fast, .run = [p, mesh](const CheckContext&) {
        const auto pair = iso_pair(p);
        const GearPairGeometry g(pair);
        MeshStiffnessOptions o;
        o.positions = 60;
        const auto r = MeshStiffness(g, steel206, o).solve();
        const auto iso = reference::iso6336_stiffness(pair);
        if (mesh) return CheckValue{r.mean_per_face_width(), iso.c_gamma_alpha};
        return CheckValue{max_single_pair(r, pair.face_width), iso.c_prime,
                          {{"c_prime_theoretical", iso.c_prime_theoretical},
                           {"mean_single_pair", mean_single_pair(r, pair.face_width)}}};
      }});
}

const bool iso_checks = [] {
  for (const auto& p : iso_pairs) {
    register_iso_check(p, false);
    register_iso_check(p, true);
  }
  return true;
}();


/// Smallest and largest of a set of ratios, as "lo–hi".
struct Span {
  double lo = 1e300, hi = -1e300;
  void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
  [[nodiscard]] std::string text() const { return fmt::format("{:.2f}–{:.2f}", lo, hi); }
};

void add_iso_table(reports::Report& report) {
  std::string rows;
  Span max_ratio, mean_ratio, max_ratio_arc, mean_ratio_arc;
  for (const auto& p : iso_pairs) {
    const auto pair = iso_pair(p);
    const GearPairGeometry g(pair);
    MeshStiffnessOptions o, o_arc;
    o.positions = o_arc.positions = 60;
    o_arc.fillet = stiffness::Fillet::circular_arc;
    const auto r = MeshStiffness(g, steel206, o).solve();
    const auto a = MeshStiffness(g, steel206, o_arc).solve();
    const auto iso = reference::iso6336_stiffness(pair);
    max_ratio.add(max_single_pair(r, pair.face_width) / iso.c_prime);
    max_ratio_arc.add(max_single_pair(a, pair.face_width) / iso.c_prime);
    mean_ratio.add(r.mean_per_face_width() / iso.c_gamma_alpha);
    mean_ratio_arc.add(a.mean_per_face_width() / iso.c_gamma_alpha);
    rows += fmt::format("| {}/{} | {}/{} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} |\n",
                        p.z1, p.z2, p.x1, p.x2, max_single_pair(r, pair.face_width),
                        max_single_pair(a, pair.face_width), iso.c_prime, iso.c_prime_theoretical,
                        mean_single_pair(r, pair.face_width), r.mean_per_face_width(), a.mean_per_face_width(),
                        iso.c_gamma_alpha);
  }
  report.notes.push_back({section, fmt::format(
      "**Against ISO 6336-1 method B** (m 2 mm, α 20°, b 20 mm, steel, solid blanks), in "
      "N/(mm·µm), with the generated (trochoid) fillet, the default, beside the circular arc. ISO "
      "defines c′ as the maximum stiffness of one pair and c_γα as the mesh mean, and the checks "
      "compare those quantities (generated fillet). Single-pair maximum / c′: {} (arc {}); mesh "
      "mean / c_γα: {} (arc {}). The generated fillet stiffens the large-z teeth most, whose arc "
      "model started abruptly on the involute at the root circle. ISO's c′ carries "
      "the empirical C_M = 0.8; its theoretical c′_th = 1/q′ is listed for reference.\n\n"
      "| z | x | single-pair max | (arc) | ISO c′ | ISO c′_th | single-pair mean | mesh mean | (arc) | "
      "ISO c_γα |\n|---|---|---|---|---|---|---|---|---|---|\n{}",
      max_ratio.text(), max_ratio_arc.text(), mean_ratio.text(), mean_ratio_arc.text(), rows)});
}

/// ROSS (petrobras/ross 2.3.0, GearElementTVMS: the energy method on the generated trochoid
/// with Sainsot's foundation, θ_f from the rack) run by the author on the same inputs
/// (bore r_f/2, Hertz, 360 positions): a peer, not a reference. For 62/62 the issue gives
/// only the ratio (the circular arc 6.6 % below ROSS); its ROSS mean is inferred from it.
void add_ross_note(reports::Report& report) {
  const model::Material seed_steel{212e9, 0.289, 7850};
  auto mesh = [&](int z1, int z2, stiffness::Fillet fillet) {
    const GearPairGeometry g(spur_pair(z1, z2, 2.0, 20.0));
    MeshStiffnessOptions o;
    o.fillet = fillet;
    return MeshStiffness(g, {seed_steel, seed_steel}, o).solve();
  };
  const auto t = mesh(20, 25, stiffness::Fillet::trochoid), a = mesh(20, 25, stiffness::Fillet::circular_arc);
  const auto t62 = mesh(62, 62, stiffness::Fillet::trochoid), a62 = mesh(62, 62, stiffness::Fillet::circular_arc);
  const double ross_mean = 4.156e8, ross_min = 2.906e8, ross_max = 5.089e8;
  const double ross62 = a62.mean / (1.0 - 0.066);
  report.notes.push_back({section, fmt::format(
      "**Peer comparison with ROSS** (petrobras/ross 2.3.0, GearElementTVMS: energy method, generated "
      "trochoid, Sainsot foundation with θ_f from the rack; figures from issue 23, m 2, b 20 mm, E 212 GPa, "
      "ν 0.289, bore r_f/2, 360 positions). Not a pass/fail reference.\n\n"
      "| pair | | mean [1e8 N/m] | min | max |\n|---|---|---|---|---|\n"
      "| 20/25 | ROSS | {:.3f} | {:.3f} | {:.3f} |\n"
      "| 20/25 | gearbench, generated fillet | {:.3f} ({:+.1f} %) | {:.3f} ({:+.1f} %) | {:.3f} ({:+.1f} %) |\n"
      "| 20/25 | gearbench, circular arc | {:.3f} ({:+.1f} %) | {:.3f} ({:+.1f} %) | {:.3f} ({:+.1f} %) |\n"
      "| 62/62 | ROSS (inferred: arc 6.6 % below it) | {:.3f} | | |\n"
      "| 62/62 | gearbench, generated fillet | {:.3f} ({:+.1f} %) | {:.3f} | {:.3f} |\n"
      "| 62/62 | gearbench, circular arc | {:.3f} ({:+.1f} %) | {:.3f} | {:.3f} |\n",
      ross_mean * 1e-8, ross_min * 1e-8, ross_max * 1e-8,
      t.mean * 1e-8, 100 * (t.mean / ross_mean - 1), t.min * 1e-8, 100 * (t.min / ross_min - 1), t.max * 1e-8,
      100 * (t.max / ross_max - 1),
      a.mean * 1e-8, 100 * (a.mean / ross_mean - 1), a.min * 1e-8, 100 * (a.min / ross_min - 1), a.max * 1e-8,
      100 * (a.max / ross_max - 1),
      ross62 * 1e-8, t62.mean * 1e-8, 100 * (t62.mean / ross62 - 1), t62.min * 1e-8, t62.max * 1e-8,
      a62.mean * 1e-8, 100 * (a62.mean / ross62 - 1), a62.min * 1e-8, a62.max * 1e-8)});
}

const RegisterSection iso_section(SectionSpec{
    .id = "stiffness_iso6336", .tier = Tier::fast, .add = [](const CheckContext&, reports::Report& report) {
      add_iso_table(report);
      add_ross_note(report);
    }});

}  // namespace
}  // namespace gearbench::verification
