#pragma once
// The part of the FE tooth reference that needs deal.II and gmsh — the elastic solve
// (elasticity.cpp) and the gear mesher (gear_mesh.cpp) — is built as a plugin,
// libgearbench_fe_backend.so, and loaded on first use. deal.II's stack (PETSc, Trilinos,
// OpenCASCADE, MPI: about 190 shared libraries) cost every start of a program that linked
// it 0.2 s and 150 MiB, and only this reference uses it. A plugin rather than a helper
// executable: this boundary takes callbacks (ElasticProblem's std::functions), which a
// process boundary cannot carry, and in one process every caller — the fe_stiffness kind,
// the FE checks of `gearbench verify` with their shared solves, sweeps, tests, benchmarks —
// stays as it was, with one CLI and so one contract.
#include <array>
#include <cstddef>
#include <optional>

#include "elasticity.h"
#include "gear_mesh.h"

namespace gearbench::reference::fe {

/// The sizes of the types that cross into the plugin: a plugin built from other sources (a
/// stale copy next to the executable) is refused instead of misread.
using BackendLayout = std::array<std::size_t, 7>;
constexpr BackendLayout backend_layout() {
  return {sizeof(ElasticProblem), sizeof(ElasticOptions), sizeof(ElasticResult), sizeof(QuadMesh),
          sizeof(ToothOutline),   sizeof(GearMeshSizes),  sizeof(Slit)};
}

struct FeBackend {
  BackendLayout layout{};  ///< backend_layout() as the plugin was compiled
  ElasticResult (*solve_elastic)(const ElasticProblem&, const ElasticOptions&) = nullptr;
  QuadMesh (*mesh_gear)(const ToothOutline&, double bore_radius, const GearMeshSizes&,
                        const std::optional<Slit>&) = nullptr;
};

/// The plugin's functions, loaded on the first call (thread-safe). PluginError when it is
/// not built, does not load, or comes from other sources.
const FeBackend& fe_backend();

}  // namespace gearbench::reference::fe

/// The plugin's entry point (fe_backend_plugin.cpp).
extern "C" const gearbench::reference::fe::FeBackend* gearbench_fe_backend();
