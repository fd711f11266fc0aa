// Where the energy method's beam parts from the FE tooth alone (issue 23, docs/fe-tooth-model.md,
// "Where they part"). Two sets of figures:
//  1. The beam of the energy method (generated fillet) at the middle of A..E for the FE
//     comparison's gears: its bending : shear : axial shares, and the share of it that lies
//     between the FE's probe section x_Q and the load's x_1 (ToothCompliance::centre_line_point).
//  2. FE sub-models of the beam alone: a plane-stress cantilever clamped at x = 0 under a
//     parabolic end shear (reference/fe_tooth/cantilever.h), rectangular and linearly tapered
//     (half-angle of the taper given, the mesh's heights scaled), against the energy method's
//     beam integrals for the same shape: ∫ M²/(E I) dx + 1.2 ∫ V²/(G A) dx, by the midpoint rule
//     on 20000 intervals. FE converged to 1e-4 relative over two refinements.
// Build from a configured tree (Release), e.g.
//   g++ -std=c++20 -O2 -DNDEBUG -I<tree>/verification -I<tree>/solvers -I<tree>/reference
//       fe_beam_submodels.cpp <build>/solvers/libgearbench_solvers.a <build>/reference/libgearbench_fe_tooth.a
//       <build>/solvers/libgearbench_model.a -lgsl -lgslcblas -lfmt -ldl
// (the FE backend plugin is found at its build path).
#include <cmath>
#include <cstdio>

#include "fe_tooth/cantilever.h"
#include "fe_tooth/fe_backend.h"
#include "stiffness/pair_stiffness.h"
#include "support/test_support.h"

using namespace gearbench;

namespace {

void beam_shares(const model::GearPair& pair, const model::Material& steel, const char* name) {
  const geometry::GearPairGeometry g(pair);
  const stiffness::PairStiffness energy(g, {steel, steel}, {}, {0.5 * g.radii(0).root, 0.5 * g.radii(1).root},
                                        std::nullopt, true);
  const double s = 0.5 * (g.path().A + g.path().E);
  for (int gear = 0; gear < 2; ++gear) {
    const auto c = energy.compliance(s).tooth[static_cast<std::size_t>(gear)];
    const auto q = energy.tooth(gear).centre_line_point(energy.roll_angle(gear, s));
    const double beam = c.sum();
    std::printf("%s z %d: bending %.3f shear %.3f axial %.3f of the beam; above Q %.3f (shear %.3f)\n", name,
                pair.teeth[static_cast<std::size_t>(gear)], c.bending / beam, c.shear / beam, c.axial / beam,
                (beam - q.sum()) / beam, (c.shear - q.shear) / beam);
  }
}

void cantilever(double length_over_height, double taper_deg) {
  const double E = 210e9, nu = 0.3, G = E / (2 * (1 + nu)), P = 1e5;
  const double H0 = 2e-3, L = length_over_height * H0, H1 = H0 - 2 * L * std::tan(taper_deg * M_PI / 180);
  reference::fe::ElasticProblem p;
  p.mesh = reference::fe::rectangle_mesh(L, 1.0, std::max(4, static_cast<int>(8 * length_over_height)), 4);
  for (auto& v : p.mesh.vertices) v[1] *= H0 + (H1 - H0) * v[0] / L;
  p.material = {E, nu, false};
  const double eps = 1e-9 * L;
  p.clamped = [eps](const reference::fe::Vec2& m) { return m[0] < eps; };
  p.loaded = [L, eps](const reference::fe::Vec2& m, const reference::fe::Vec2&) { return m[0] > L - eps; };
  p.intensity = [H1](const reference::fe::Vec2& x) { return std::max(0.0, 1.0 - 4.0 * x[1] * x[1] / (H1 * H1)); };
  p.load_direction = {0.0, -1.0};
  p.force_per_thickness = P;
  p.probe = {L, 0.0};
  p.probe_direction = {0.0, -1.0};
  reference::fe::ElasticOptions o;
  o.max_cycles = 10;
  o.tolerance = 1e-4;
  const auto r = reference::fe::fe_backend().solve_elastic(p, o);
  double bending = 0, shear = 0;
  constexpr int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) * L / n, H = H0 + (H1 - H0) * x / L;
    bending += P * (L - x) * (L - x) * 12 / (E * H * H * H) * L / n;
    shear += 1.2 * P / (G * H) * L / n;
  }
  std::printf("L/H0 %.1f, taper %4.1f deg: FE / beam %.3f (shear %.2f of the beam; last FE change %.1g)\n",
              length_over_height, taper_deg, r.value / (bending + shear), shear / (bending + shear),
              r.cycles.back().change);
}

}  // namespace

int main() {
  using testing_support::spur_pair;
  const model::Material seed003_steel{212e9, 0.289, 7850}, iso_steel{206e9, 0.3, 7850};
  beam_shares(testing_support::seed003_pair(), seed003_steel, "seed 003");
  beam_shares(spur_pair(19, 48, 3.2, 20, 16), iso_steel, "19/48");
  beam_shares(spur_pair(62, 62, 2.0, 20, 20), iso_steel, "62/62");
  auto shifted = spur_pair(25, 50, 2.0, 20, 20);
  shifted.profile_shift = {0.3, 0.0};
  beam_shares(shifted, iso_steel, "25/50 x 0.3");
  beam_shares(spur_pair(40, 80, 2.0, 20, 20), iso_steel, "40/80");
  for (const double lh : {2.0, 1.0, 0.5})
    for (const double taper : {0.0, 10.0, 20.0, 30.0})
      if (2 * lh * std::tan(taper * M_PI / 180) < 0.9) cantilever(lh, taper);
}
