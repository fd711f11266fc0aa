#pragma once
// Sanity case of the finite-element reference: a rectangular plane "tooth" clamped at one
// end and loaded at the other by a parabolic shear traction, against Timoshenko beam
// theory (bending + shear).
#include "elasticity.h"

namespace gearbench::reference::fe {

struct Cantilever {
  double length = 10e-3;               ///< L [m]
  double height = 2e-3;                ///< H [m]
  ElasticMaterial material{210e9, 0.3, false};
  double force_per_thickness = 1e5;    ///< P [N/m]
  int cells_along = 10, cells_across = 2;  ///< initial mesh
};

struct CantileverResult {
  double deflection = 0.0;   ///< FE: downward displacement of the tip centroid [m]
  double bending = 0.0;      ///< P L³/(3 E′ I) [m]
  double shear = 0.0;        ///< P L/(κ G A) [m]
  double timoshenko = 0.0;   ///< bending + shear [m]
  double shear_coefficient = 0.0;  ///< κ (Cowper 1966)
  ElasticResult fe;
};

CantileverResult solve_cantilever(const Cantilever& c, const ElasticOptions& options);

/// Structured mesh of the rectangle [0, L] × [−H/2, H/2].
QuadMesh rectangle_mesh(double length, double height, int nx, int ny);

}  // namespace gearbench::reference::fe
