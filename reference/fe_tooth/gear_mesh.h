#pragma once
// Unstructured quadrilateral mesh of a whole spur gear (every tooth, the body down to the
// bore) from the generated outline, by the gmsh API (gmsh 4.8, a deal.II dependency).
// The mesh is graded: fine at `focus` (the loaded tooth), coarser with distance from it.
#include <array>
#include <vector>

#include <optional>

#include "crack_slit.h"
#include "tooth_outline.h"

namespace gearbench::reference::fe {

/// Vertices and quadrilaterals, each quad's vertices counter-clockwise.
struct QuadMesh {
  std::vector<Vec2> vertices;
  std::vector<std::array<unsigned, 4>> quads;
};

struct GearMeshSizes {
  double near = 0.0;    ///< element size at the focus [m]
  double far = 0.0;     ///< largest element size [m]
  double growth = 0.3;  ///< size increase per unit distance from the focus [-]
  Vec2 focus{};
};

/// Meshes the gear of `tooth` (tooth 0 centred on +x) with a bore of radius bore_radius.
/// With a slit, tooth 0 carries it as a crack: the slit is embedded in the mesh and gmsh's
/// Plugin(Crack) duplicates its nodes (all but the tip), open at the mouth on the flank.
/// gmsh is a process-wide singleton: calls are serialised internally. In the deal.II plugin
/// (fe_backend.h): programs call it as fe_backend().mesh_gear.
QuadMesh mesh_gear(const ToothOutline& tooth, double bore_radius, const GearMeshSizes& sizes,
                   const std::optional<Slit>& slit = std::nullopt);

}  // namespace gearbench::reference::fe
