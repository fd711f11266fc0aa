#include "elasticity.h"

#include <deal.II/base/convergence_table.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/vector_tools.h>

#include <chrono>
#include <cmath>
#include <sstream>


namespace gearbench::reference::fe {
namespace {

using namespace dealii;

constexpr types::boundary_id free_id = 0, clamped_id = 1, loaded_id = 2;
constexpr types::manifold_id outline_id = 1;

/// Straight between vertices, but every new boundary vertex is moved onto the true outline.
class OutlineManifold : public FlatManifold<2> {
 public:
  explicit OutlineManifold(std::function<Vec2(const Vec2&)> project) : project_(std::move(project)) {}
  [[nodiscard]] std::unique_ptr<Manifold<2>> clone() const override {
    return std::make_unique<OutlineManifold>(project_);
  }
  [[nodiscard]] Point<2> project_to_manifold(const ArrayView<const Point<2>>&,
                                             const Point<2>& candidate) const override {
    const Vec2 p = project_({candidate[0], candidate[1]});
    return {p[0], p[1]};
  }

 private:
  std::function<Vec2(const Vec2&)> project_;
};

/// Lamé constants; plane stress replaces λ by λ* = 2λμ/(λ + 2μ) (Timoshenko & Goodier,
/// Theory of Elasticity, 3rd ed. 1970, §19: the plane-strain solution with E, ν replaced).
struct Lame {
  double lambda, mu;
};
Lame lame(const ElasticMaterial& m) {
  const double E = m.youngs_modulus, nu = m.poisson_ratio;
  const double mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  return {m.plane_strain ? lambda : 2 * lambda * mu / (lambda + 2 * mu), mu};
}

Vec2 vec(const Point<2>& p) { return {p[0], p[1]}; }

void build_triangulation(const QuadMesh& mesh, Triangulation<2>& tria) {
  std::vector<Point<2>> vertices;
  vertices.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) vertices.emplace_back(v[0], v[1]);
  std::vector<CellData<2>> cells(mesh.quads.size());
  for (std::size_t i = 0; i < mesh.quads.size(); ++i) {
    const auto& q = mesh.quads[i];
    cells[i].vertices = {q[0], q[1], q[3], q[2]};  // counter-clockwise → deal.II's order
  }
  SubCellData sub;
  GridTools::delete_unused_vertices(vertices, cells, sub);
  GridTools::invert_all_negative_measure_cells(vertices, cells);
  GridTools::consistently_order_cells(cells);
  tria.create_triangulation(vertices, cells, sub);
}

/// Boundary and manifold ids of the coarse faces (children inherit them).
void mark_boundary(const ElasticProblem& p, Triangulation<2>& tria) {
  for (const auto& cell : tria.active_cell_iterators())
    for (const auto f : cell->face_indices()) {
      const auto face = cell->face(f);
      if (!face->at_boundary()) continue;
      const Vec2 mid = vec(face->center());
      const Tensor<1, 2> t = face->vertex(1) - face->vertex(0);
      Vec2 n{t[1] / t.norm(), -t[0] / t.norm()};
      const Tensor<1, 2> out = face->center() - cell->center();
      if (n[0] * out[0] + n[1] * out[1] < 0) n = {-n[0], -n[1]};
      face->set_boundary_id(p.clamped(mid) ? clamped_id : p.loaded(mid, n) ? loaded_id : free_id);
      if (p.on_outline && p.on_outline(mid)) face->set_manifold_id(outline_id);
    }
}

void refine_near_load(const ElasticProblem& p, Triangulation<2>& tria) {
  if (p.refine_radius <= 0.0) return;
  for (int level = 0; level < 16; ++level) {
    bool any = false;
    for (const auto& cell : tria.active_cell_iterators()) {
      const double d = std::hypot(cell->center()[0] - p.refine_centre[0], cell->center()[1] - p.refine_centre[1]);
      if (d < p.refine_radius + cell->diameter() && cell->diameter() > p.refine_size) {
        cell->set_refine_flag();
        any = true;
      }
    }
    if (!any) return;
    tria.execute_coarsening_and_refinement();
  }
}

struct LinearSystem {
  AffineConstraints<double> constraints;
  SparsityPattern pattern;
  SparseMatrix<double> matrix;
  Vector<double> rhs, solution;
};

void assemble_stiffness(const DoFHandler<2>& dof, const Lame& material, const ElasticProblem& p, LinearSystem& s) {
  const auto& fe = dof.get_fe();
  const QGauss<2> quadrature(fe.degree + 1);
  FEValues<2> v(fe, quadrature, update_gradients | update_JxW_values);
  const unsigned n = fe.n_dofs_per_cell();
  FullMatrix<double> k(n, n);
  std::vector<types::global_dof_index> dofs(n);
  Vector<double> zero(n);
  for (const auto& cell : dof.active_cell_iterators()) {
    v.reinit(cell);
    k = 0;
    const double factor = p.stiffness_factor ? p.stiffness_factor(vec(cell->center())) : 1.0;
    const Lame c{factor * material.lambda, factor * material.mu};
    for (const unsigned q : v.quadrature_point_indices())
      for (unsigned i = 0; i < n; ++i) {
        const unsigned ci = fe.system_to_component_index(i).first;
        for (unsigned j = 0; j < n; ++j) {
          const unsigned cj = fe.system_to_component_index(j).first;
          // Bilinear form of isotropic elasticity (deal.II step-8).
          k(i, j) += (v.shape_grad(i, q)[ci] * v.shape_grad(j, q)[cj] * c.lambda +
                      v.shape_grad(i, q)[cj] * v.shape_grad(j, q)[ci] * c.mu +
                      (ci == cj ? v.shape_grad(i, q) * v.shape_grad(j, q) * c.mu : 0.0)) *
                     v.JxW(q);
        }
      }
    cell->get_dof_indices(dofs);
    s.constraints.distribute_local_to_global(k, zero, dofs, s.matrix, s.rhs);
  }
}

/// Traction intensity·direction on the loaded faces, scaled to the given resultant.
void assemble_load(const DoFHandler<2>& dof, const ElasticProblem& p, LinearSystem& s) {
  const auto& fe = dof.get_fe();
  const QGauss<1> quadrature(fe.degree + 4);
  FEFaceValues<2> v(fe, quadrature, update_values | update_quadrature_points | update_JxW_values);
  auto for_loaded_faces = [&](auto&& body) {
    for (const auto& cell : dof.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == loaded_id) {
          v.reinit(cell, f);
          body(cell);
        }
  };
  double resultant = 0.0;
  for_loaded_faces([&](const auto&) {
    for (const unsigned q : v.quadrature_point_indices()) resultant += p.intensity(vec(v.quadrature_point(q))) * v.JxW(q);
  });
  if (!(resultant > 0.0)) throw std::runtime_error("fe: the load patch meets no loaded boundary face");
  const double scale = p.force_per_thickness / resultant;
  const unsigned n = fe.n_dofs_per_cell();
  Vector<double> local(n);
  std::vector<types::global_dof_index> dofs(n);
  for_loaded_faces([&](const auto& cell) {
    local = 0;
    for (const unsigned q : v.quadrature_point_indices()) {
      const double t = scale * p.intensity(vec(v.quadrature_point(q))) * v.JxW(q);
      for (unsigned i = 0; i < n; ++i)
        local(i) += t * p.load_direction[fe.system_to_component_index(i).first] * v.shape_value(i, q);
    }
    cell->get_dof_indices(dofs);
    s.constraints.distribute_local_to_global(local, dofs, s.rhs);
  });
}

void solve_system(const DoFHandler<2>& dof, const ElasticProblem& p, const Lame& c, LinearSystem& s) {
  s.constraints.clear();
  DoFTools::make_hanging_node_constraints(dof, s.constraints);
  VectorTools::interpolate_boundary_values(dof, clamped_id, Functions::ZeroFunction<2>(2), s.constraints);
  s.constraints.close();
  DynamicSparsityPattern dsp(dof.n_dofs());
  DoFTools::make_sparsity_pattern(dof, dsp, s.constraints, false);
  s.matrix.clear();
  s.pattern.copy_from(dsp);
  s.matrix.reinit(s.pattern);
  s.rhs.reinit(dof.n_dofs());
  s.solution.reinit(dof.n_dofs());
  assemble_stiffness(dof, c, p, s);
  assemble_load(dof, p, s);
  SparseDirectUMFPACK direct;
  direct.initialize(s.matrix);
  direct.vmult(s.solution, s.rhs);
  s.constraints.distribute(s.solution);
}

/// Von Mises stress from the displacement gradient; σ_zz = λ(ε_xx + ε_yy) in plane strain,
/// 0 in plane stress.
double von_mises(const Tensor<2, 2>& g, const Lame& c, bool plane_strain) {
  const double exx = g[0][0], eyy = g[1][1], exy = 0.5 * (g[0][1] + g[1][0]);
  const double tr = c.lambda * (exx + eyy);
  const double sxx = tr + 2 * c.mu * exx, syy = tr + 2 * c.mu * eyy, sxy = 2 * c.mu * exy;
  const double szz = plane_strain ? tr : 0.0;
  return std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
                   3 * sxy * sxy);
}

class VonMises : public DataPostprocessorScalar<2> {
 public:
  VonMises(Lame c, bool plane_strain)
      : DataPostprocessorScalar<2>("von_Mises", update_gradients), c_(c), plane_strain_(plane_strain) {}
  void evaluate_vector_field(const DataPostprocessorInputs::Vector<2>& in,
                             std::vector<Vector<double>>& out) const override {
    for (std::size_t q = 0; q < out.size(); ++q) {
      Tensor<2, 2> g;
      for (unsigned i = 0; i < 2; ++i) g[i] = in.solution_gradients[q][i];
      out[q](0) = von_mises(g, c_, plane_strain_);
    }
  }

 private:
  Lame c_;
  bool plane_strain_;
};

std::string write_vtu(const DoFHandler<2>& dof, const Vector<double>& u, const Lame& c, bool plane_strain) {
  const VonMises von_mises(c, plane_strain);
  DataOut<2> out;
  out.attach_dof_handler(dof);
  out.add_data_vector(u, std::vector<std::string>{"displacement", "displacement"}, DataOut<2>::type_dof_data,
                      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
                          2, DataComponentInterpretation::component_is_part_of_vector));
  out.add_data_vector(u, von_mises);
  out.build_patches(dof.get_fe().degree);
  std::ostringstream os;
  out.write_vtu(os);
  return os.str();
}

/// The solution on the grid of p.field_*: each cell takes the grid points inside its
/// bounding box that map into its reference square (MappingQ1's inverse), and evaluates
/// there by FEValues on those reference points.
std::vector<FieldSample> sample_field(const DoFHandler<2>& dof, const Vector<double>& u, const Lame& material,
                                      const ElasticProblem& p) {
  std::vector<FieldSample> out;
  const auto& fe = dof.get_fe();
  const MappingQ1<2> mapping;
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
  const double h = p.field_spacing;
  const auto lo = p.field_lower, hi = p.field_upper;
  for (const auto& cell : dof.active_cell_iterators()) {
    const auto box = cell->bounding_box();
    const double x0 = std::max(lo[0], box.lower_bound(0)), x1 = std::min(hi[0], box.upper_bound(0));
    const double y0 = std::max(lo[1], box.lower_bound(1)), y1 = std::min(hi[1], box.upper_bound(1));
    if (x0 > x1 || y0 > y1) continue;
    std::vector<Point<2>> real, unit;
    for (double y = lo[1] + h * std::ceil((y0 - lo[1]) / h); y <= y1; y += h)
      for (double x = lo[0] + h * std::ceil((x0 - lo[0]) / h); x <= x1; x += h) {
        try {
          const Point<2> r = mapping.transform_real_to_unit_cell(cell, Point<2>(x, y));
          // Half-open square: a point on a shared edge belongs to one cell only.
          if (r[0] >= 0 && r[0] < 1 && r[1] >= 0 && r[1] < 1) {
            real.emplace_back(x, y);
            unit.push_back(r);
          }
        } catch (const Mapping<2>::ExcTransformationFailed&) {
          continue;  // far outside this cell: not its point
        }
      }
    if (unit.empty()) continue;
    FEValues<2> v(mapping, fe, Quadrature<2>(unit), update_values | update_gradients);
    v.reinit(cell);
    cell->get_dof_indices(dofs);
    const double factor = p.stiffness_factor ? p.stiffness_factor(vec(cell->center())) : 1.0;
    for (unsigned q = 0; q < unit.size(); ++q) {
      FieldSample f{vec(real[q]), {0.0, 0.0}, 0.0};
      Tensor<2, 2> g;
      for (unsigned i = 0; i < dofs.size(); ++i) {
        const unsigned comp = fe.system_to_component_index(i).first;
        f.displacement[comp] += u(dofs[i]) * v.shape_value(i, q);
        g[comp] += u(dofs[i]) * v.shape_grad(i, q);
      }
      f.von_mises = von_mises(g, {factor * material.lambda, factor * material.mu}, p.material.plane_strain);
      out.push_back(f);
    }
  }
  return out;
}

/// Observed order in h of the change between cycles: with N dofs ~ h^−2 in 2D,
/// p = 2·log(Δ_{k−1}/Δ_k)/log(N_k/N_{k−1}) — deal.II's reduction_rate_log2 with dim 2.
double observed_rate(const CycleRow& previous, const CycleRow& current) {
  if (previous.change <= 0.0 || current.change <= 0.0 || current.dofs <= previous.dofs) return 0.0;
  return 2.0 * std::log(previous.change / current.change) /
         std::log(static_cast<double>(current.dofs) / previous.dofs);
}

}  // namespace

ElasticResult solve_elastic(const ElasticProblem& p, const ElasticOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  Triangulation<2> tria;
  build_triangulation(p.mesh, tria);
  std::unique_ptr<OutlineManifold> outline;
  if (p.on_outline && p.project) {
    outline = std::make_unique<OutlineManifold>(p.project);
    tria.set_manifold(outline_id, *outline);
  }
  mark_boundary(p, tria);
  refine_near_load(p, tria);

  const Lame c = lame(p.material);
  const FESystem<2> fe(FE_Q<2>(static_cast<unsigned>(o.degree)), 2);
  DoFHandler<2> dof(tria);
  LinearSystem s;
  ElasticResult r;
  ConvergenceTable table;
  for (int cycle = 0; cycle < o.max_cycles; ++cycle) {
    if (cycle > 0) {
      Vector<float> error(tria.n_active_cells());
      KellyErrorEstimator<2>::estimate(dof, QGauss<1>(fe.degree + 1), std::map<types::boundary_id, const Function<2>*>(),
                                       s.solution, error);
      GridRefinement::refine_and_coarsen_fixed_number(tria, error, o.refine_fraction, 0.0);
      tria.execute_coarsening_and_refinement();
    }
    dof.distribute_dofs(fe);
    solve_system(dof, p, c, s);
    Vector<double> u(2);
    VectorTools::point_value(dof, s.solution, Point<2>(p.probe[0], p.probe[1]), u);
    CycleRow row{cycle, tria.n_active_cells(), static_cast<unsigned>(dof.n_dofs()),
                 u(0) * p.probe_direction[0] + u(1) * p.probe_direction[1]};
    // f·u is the work of the load; constrained rows of f are condensed onto their masters
    // and u satisfies the constraints, so the condensed product equals the full one.
    row.load_displacement = (s.rhs * s.solution) / p.force_per_thickness;
    const auto measure = [&p](const CycleRow& cr) { return p.converge_on_load ? cr.load_displacement : cr.value; };
    if (!r.cycles.empty()) {
      row.change = std::abs(measure(row) - measure(r.cycles.back())) / std::abs(measure(row));
      row.rate = observed_rate(r.cycles.back(), row);
      table.add_value("cycle", cycle);
      table.add_value("cells", row.cells);
      table.add_value("dofs", row.dofs);
      table.add_value("value", measure(row));
      table.add_value("change", row.change);
    }
    r.cycles.push_back(row);
    const auto n = r.cycles.size();
    if (n >= 3 && r.cycles[n - 1].change < o.tolerance && r.cycles[n - 2].change < o.tolerance) {
      r.converged = true;
      break;
    }
  }
  table.set_scientific("value", true);
  table.set_precision("value", 8);
  table.set_scientific("change", true);
  table.evaluate_convergence_rates("change", "dofs", ConvergenceTable::reduction_rate_log2, 2);
  std::ostringstream text;
  table.write_text(text);
  r.table = text.str();
  r.value = r.cycles.back().value;
  r.observed_rate = r.cycles.back().rate;
  if (o.vtu) r.vtu = write_vtu(dof, s.solution, c, p.material.plane_strain);
  if (p.field_spacing > 0.0) r.field = sample_field(dof, s.solution, c, p);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  dof.clear();
  return r;
}

}  // namespace gearbench::reference::fe
