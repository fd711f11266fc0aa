#include "cantilever.h"

#include <cmath>

#include "fe_backend.h"
#include "model/errors.h"

namespace gearbench::reference::fe {

QuadMesh rectangle_mesh(double length, double height, int nx, int ny) {
  QuadMesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.vertices.push_back({length * i / nx, height * (j / double(ny) - 0.5)});
  auto id = [nx](int i, int j) { return static_cast<unsigned>(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) m.quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return m;
}

CantileverResult solve_cantilever(const Cantilever& c, const ElasticOptions& options) {
  if (!(c.length > 0 && c.height > 0 && c.cells_along > 0 && c.cells_across > 0))
    throw InputError("cantilever: length, height and cell counts must be positive");
  options.validate();  // before the options cross into the plugin
  const double L = c.length, H = c.height;
  ElasticProblem p;
  p.mesh = rectangle_mesh(L, H, c.cells_along, c.cells_across);
  p.material = c.material;
  const double eps = 1e-9 * L;
  p.clamped = [eps](const Vec2& m) { return m[0] < eps; };
  p.loaded = [L, eps](const Vec2& m, const Vec2&) { return m[0] > L - eps; };
  // Parabolic shear over the end section: the end load of the Timoshenko–Goodier solution.
  p.intensity = [H](const Vec2& x) { return std::max(0.0, 1.0 - 4.0 * x[1] * x[1] / (H * H)); };
  p.load_direction = {0.0, -1.0};
  p.force_per_thickness = c.force_per_thickness;
  p.probe = {L, 0.0};
  p.probe_direction = {0.0, -1.0};

  CantileverResult r;
  r.fe = fe_backend().solve_elastic(p, options);
  r.deflection = r.fe.value;
  const double E = c.material.youngs_modulus, nu = c.material.poisson_ratio;
  // Plane strain stiffens bending by 1/(1 − ν²) (E′ = E/(1 − ν²)); G is unchanged.
  const double E_eff = c.material.plane_strain ? E / (1 - nu * nu) : E;
  const double G = E / (2 * (1 + nu));
  // Cowper, J. Appl. Mech. 33 (1966) 335: κ = 10(1 + ν)/(12 + 11ν) for a rectangle.
  r.shear_coefficient = 10 * (1 + nu) / (12 + 11 * nu);
  const double I = H * H * H / 12.0;
  r.bending = c.force_per_thickness * L * L * L / (3 * E_eff * I);
  r.shear = c.force_per_thickness * L / (r.shear_coefficient * G * H);
  r.timoshenko = r.bending + r.shear;
  return r;
}

}  // namespace gearbench::reference::fe
