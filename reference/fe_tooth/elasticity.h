#pragma once
// Two-dimensional linear elasticity by deal.II 9.4 (elasticity.cpp, in the deal.II plugin of
// fe_backend.h, is the only translation unit of gearbench that includes deal.II): Q2 (or Qp) elements, plane strain or plane stress, UMFPACK,
// Kelly-driven adaptive refinement until a probed displacement converges, deal.II's
// ConvergenceTable, optional VTU output. The header keeps deal.II out of its users.
#include <functional>
#include <string>
#include <vector>

#include "gear_mesh.h"

namespace gearbench::model {
template <class O>
class OptionTable;
}  // namespace gearbench::model

namespace gearbench::reference::fe {

struct ElasticMaterial {
  double youngs_modulus = 0.0;  ///< E [Pa]
  double poisson_ratio = 0.0;   ///< ν [-]
  bool plane_strain = true;     ///< else plane stress (λ* = 2λμ/(λ + 2μ))
};

/// A linear-elastic body under one distributed surface load, with one probed displacement.
struct ElasticProblem {
  QuadMesh mesh;
  ElasticMaterial material;
  /// Boundary faces (by midpoint) held fixed, u = 0.
  std::function<bool(const Vec2& midpoint)> clamped;
  /// Boundary faces (by midpoint and outward unit normal) that carry the load.
  std::function<bool(const Vec2& midpoint, const Vec2& normal)> loaded;
  /// Relative traction intensity at a point of a loaded face (≥ 0); the traction is
  /// intensity·load_direction, scaled so that its resultant is force_per_thickness.
  std::function<double(const Vec2& point)> intensity;
  Vec2 load_direction{};
  double force_per_thickness = 1.0;  ///< [N/m]
  /// Optional a-priori refinement: cells within `refine_radius` of `refine_centre` are
  /// refined until their diameter is below `refine_size` (resolves a narrow load patch).
  Vec2 refine_centre{};
  double refine_radius = 0.0, refine_size = 0.0;
  /// Optional: boundary faces (by midpoint) on a curved outline and the projection of a
  /// point onto it, so that refinement places new boundary vertices on the true curve.
  std::function<bool(const Vec2& midpoint)> on_outline;
  std::function<Vec2(const Vec2& point)> project;
  /// Optional factor on both Lamé constants by cell centre (1 where absent): a stiff region,
  /// e.g. a near-rigid gear body to separate the tooth's own compliance from the body's.
  std::function<double(const Vec2& cell_centre)> stiffness_factor;
  /// The result is u(probe)·probe_direction.
  Vec2 probe{}, probe_direction{};
  /// Converge on the load patch's work-conjugate displacement instead of the probe (a
  /// cracked body, where a probe near the slit sees one lip only).
  bool converge_on_load = false;
  /// Optional (spacing > 0): the last solve sampled on a grid of this spacing over the box
  /// [field_lower, field_upper]; points outside the body are skipped.
  Vec2 field_lower{}, field_upper{};
  double field_spacing = 0.0;
};

/// Displacement and von Mises stress at one point of the body.
struct FieldSample {
  Vec2 point{};
  Vec2 displacement{};  ///< [m]
  double von_mises = 0.0;  ///< [Pa]
};

struct ElasticOptions {
  int degree = 2;               ///< polynomial degree of the Lagrange elements
  int max_cycles = 8;           ///< solves (the first on the initial mesh)
  double refine_fraction = 0.3; ///< share of cells Kelly marks for refinement per cycle
  double tolerance = 0.005;     ///< converged: the last two relative changes are below it
  bool vtu = false;             ///< keep a VTU (displacement, von Mises) of the last mesh

  /// The keys of a case's "fe" section (fe_tooth_options.cpp, outside the plugin).
  static const model::OptionTable<ElasticOptions>& table();
  void validate() const;        ///< InputError naming the option
};

struct CycleRow {
  int cycle = 0;
  unsigned cells = 0;
  unsigned dofs = 0;
  double value = 0.0;   ///< probed displacement [m]
  double change = 0.0;  ///< relative change of the converged measure (0 for the first cycle)
  double rate = 0.0;    ///< observed order in h of the change (0 where undefined)
  /// Work-conjugate displacement of the load patch, f·u / resultant [m]: the mean
  /// displacement along load_direction weighted by the traction, local indentation included.
  double load_displacement = 0.0;
};

struct ElasticResult {
  double value = 0.0;            ///< probed displacement of the last cycle [m]
  bool converged = false;
  std::vector<CycleRow> cycles;
  double observed_rate = 0.0;    ///< of the last cycle (0 if undefined)
  std::string table;             ///< deal.II ConvergenceTable, text
  std::string vtu;               ///< when asked for
  std::vector<FieldSample> field;  ///< when field_spacing > 0
  double seconds = 0.0;
};

/// In the deal.II plugin (fe_backend.h): programs call it as fe_backend().solve_elastic, with
/// options they have validated (validate() and its table live outside the plugin, which links
/// nothing of ours).
ElasticResult solve_elastic(const ElasticProblem& problem, const ElasticOptions& options);

}  // namespace gearbench::reference::fe
