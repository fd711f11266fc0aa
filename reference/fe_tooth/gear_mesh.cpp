#include "gear_mesh.h"

#include <gmsh.h>

#include <cmath>
#include <fmt/format.h>
#include <map>
#include <mutex>
#include <numbers>

#include "model/errors.h"

namespace gearbench::reference::fe {
namespace {

constexpr double pi = std::numbers::pi;

/// Spline control points per flank: the outline has ~400 samples per flank; every
/// `stride`-th one is passed to gmsh (its Catmull–Rom spline deviates from the dense
/// polyline by well under 1 µm at module 2 mm).
constexpr std::size_t stride = 4;

/// Indices of the flank samples handed to gmsh: every stride-th plus the last (tip corner).
std::vector<std::size_t> control_indices(const ToothOutline& t) {
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i + 1 < t.flank.size(); i += stride) idx.push_back(i);
  idx.push_back(t.flank.size() - 1);
  return idx;
}

/// The outer curve loop: for each tooth, lower flank root → tip, tip arc, upper flank
/// tip → root; the root point is shared with the next tooth. With a slit, tooth 0's upper
/// flank is split at the crack mouth (control points closer to it than a third of the
/// control spacing are dropped), whose gmsh point tag goes to `mouth`. Returns curve tags.
std::vector<int> add_outline(const ToothOutline& t, int centre, const std::optional<Slit>& slit, int& mouth) {
  namespace geo = gmsh::model::geo;
  const auto idx = control_indices(t);
  std::vector<int> curves;
  int first_root = -1, previous_root = -1;
  for (int k = 0; k < t.teeth; ++k) {
    const double turn = 2 * pi * k / t.teeth;
    auto point = [&](const Vec2& p) {
      const Vec2 q = rotate(p, turn);
      return geo::addPoint(q[0], q[1], 0.0);
    };
    std::vector<int> lower;
    for (std::size_t n = 0; n < idx.size(); ++n) {
      if (n == 0 && previous_root >= 0) {
        lower.push_back(previous_root);
        continue;
      }
      const auto& p = t.flank[idx[n]];
      lower.push_back(point({p[0], -p[1]}));
    }
    if (first_root < 0) first_root = lower.front();
    std::vector<std::vector<int>> upper(1);
    for (std::size_t n = idx.size(); n-- > 0;) {
      if (n == 0 && k == t.teeth - 1) {
        upper.back().push_back(first_root);
        continue;
      }
      const auto& p = t.flank[idx[n]];
      if (k == 0 && slit) {
        const auto& below = t.flank[n > 0 ? idx[n - 1] : 0];
        const double gap = std::hypot(p[0] - slit->mouth[0], p[1] - slit->mouth[1]);
        const double spacing = std::hypot(p[0] - below[0], p[1] - below[1]);
        if (mouth < 0 && idx[n] < slit->flank_index) {  // passed the mouth, going down
          mouth = point(slit->mouth);
          upper.back().push_back(mouth);
          upper.push_back({mouth});
        }
        if (gap < spacing / 3) continue;
      }
      upper.back().push_back(point(p));
    }
    curves.push_back(geo::addSpline(lower));
    curves.push_back(geo::addCircleArc(lower.back(), centre, upper.front().front()));
    for (const auto& part : upper) curves.push_back(geo::addSpline(part));
    previous_root = upper.back().back();
  }
  return curves;
}

std::vector<int> add_bore(double radius, int centre) {
  namespace geo = gmsh::model::geo;
  std::vector<int> pts, curves;
  for (int i = 0; i < 4; ++i)
    pts.push_back(geo::addPoint(radius * std::cos(pi / 2 * i), radius * std::sin(pi / 2 * i), 0.0));
  for (int i = 0; i < 4; ++i) curves.push_back(geo::addCircleArc(pts[i], centre, pts[(i + 1) % 4]));
  return curves;
}

/// Size field: near + growth·distance from the focus, capped at far. The subdivision into
/// quadrilaterals halves every edge, so gmsh is asked for twice the sizes.
void set_size_field(const GearMeshSizes& s) {
  const int field = gmsh::model::mesh::field::add("MathEval");
  gmsh::model::mesh::field::setString(
      field, "F",
      fmt::format("min({:.10g}, {:.10g} + {:.10g} * sqrt((x - {:.10g})^2 + (y - {:.10g})^2))", 2 * s.far,
                  2 * s.near, s.growth, s.focus[0], s.focus[1]));
  gmsh::model::mesh::field::setAsBackgroundMesh(field);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
}

/// Embeds the slit from the mouth (a point of the outline) to its tip and lets gmsh's
/// Plugin(Crack) duplicate the slit's nodes after meshing (gmsh reference manual, "Gmsh
/// plugins": Crack): `OpenBoundaryPhysicalGroup` is the mouth, so the crack opens there;
/// the tip stays shared. Returns the physical group tags {slit, mouth}.
std::array<int, 2> embed_slit(const Slit& slit, int mouth, int surface) {
  const int tip = gmsh::model::geo::addPoint(slit.tip[0], slit.tip[1], 0.0);
  const int line = gmsh::model::geo::addLine(mouth, tip);
  gmsh::model::geo::synchronize();
  gmsh::model::mesh::embed(1, {line}, 2, surface);
  return {gmsh::model::addPhysicalGroup(1, {line}), gmsh::model::addPhysicalGroup(0, {mouth})};
}

void open_slit(const std::array<int, 2>& groups) {
  gmsh::plugin::setNumber("Crack", "Dimension", 1);
  gmsh::plugin::setNumber("Crack", "PhysicalGroup", groups[0]);
  gmsh::plugin::setNumber("Crack", "OpenBoundaryPhysicalGroup", groups[1]);
  gmsh::plugin::setNumber("Crack", "NormalX", 0);
  gmsh::plugin::setNumber("Crack", "NormalY", 0);
  gmsh::plugin::setNumber("Crack", "NormalZ", 1);
  gmsh::plugin::run("Crack");
}

QuadMesh extract_quads() {
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, params;
  gmsh::model::mesh::getNodes(node_tags, coords, params);
  QuadMesh mesh;
  std::map<std::size_t, unsigned> index;
  for (std::size_t i = 0; i < node_tags.size(); ++i) {
    index[node_tags[i]] = static_cast<unsigned>(mesh.vertices.size());
    mesh.vertices.push_back({coords[3 * i], coords[3 * i + 1]});
  }
  std::vector<std::size_t> element_tags, element_nodes;
  gmsh::model::mesh::getElementsByType(3, element_tags, element_nodes);  // 3: 4-node quad
  for (std::size_t e = 0; e < element_tags.size(); ++e) {
    std::array<unsigned, 4> q{};
    for (std::size_t j = 0; j < 4; ++j) q[j] = index.at(element_nodes[4 * e + j]);
    mesh.quads.push_back(q);
  }
  return mesh;
}

}  // namespace

QuadMesh mesh_gear(const ToothOutline& tooth, double bore_radius, const GearMeshSizes& sizes,
                   const std::optional<Slit>& slit) {
  if (!(bore_radius > 0.0 && bore_radius < tooth.radii.root))
    throw InputError(fmt::format("bore_diameter_mm = {}: must lie in (0, {}) (the root diameter)",
                                 2e3 * bore_radius, 2e3 * tooth.radii.root));
  static std::mutex gmsh_mutex;
  const std::lock_guard lock(gmsh_mutex);
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.Verbosity", 0);
  gmsh::option::setNumber("General.NumThreads", 1);  // one surface: threads gain nothing, and
                                                      // a serial mesher is reproducible
  QuadMesh mesh;
  try {
    gmsh::model::add("gear");
    const int centre = gmsh::model::geo::addPoint(0.0, 0.0, 0.0);
    int mouth = -1;
    const int outer = gmsh::model::geo::addCurveLoop(add_outline(tooth, centre, slit, mouth));
    const int inner = gmsh::model::geo::addCurveLoop(add_bore(bore_radius, centre));
    const int surface = gmsh::model::geo::addPlaneSurface({outer, inner});
    gmsh::model::geo::synchronize();
    std::array<int, 2> groups{};
    if (slit) groups = embed_slit(*slit, mouth, surface);
    set_size_field(sizes);
    gmsh::option::setNumber("Mesh.Algorithm", 6);             // frontal-Delaunay
    // Triangles split into three quadrilaterals each (gmsh's subdivision): all quads without
    // the blossom recombination, which leaks memory in gmsh 4.8 (LeakSanitizer, 112 bytes).
    gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);
    gmsh::model::mesh::generate(2);
    if (slit) open_slit(groups);
    mesh = extract_quads();
  } catch (...) {
    gmsh::finalize();
    throw;
  }
  gmsh::finalize();
  if (mesh.quads.empty()) throw std::runtime_error("gmsh produced no quadrilaterals for the gear mesh");
  return mesh;
}

}  // namespace gearbench::reference::fe
