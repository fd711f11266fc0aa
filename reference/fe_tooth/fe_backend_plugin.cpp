// The entry point of libgearbench_fe_backend.so (fe_backend.h).
#include "fe_backend.h"

extern "C" const gearbench::reference::fe::FeBackend* gearbench_fe_backend() {
  using namespace gearbench::reference::fe;
  static const FeBackend backend{backend_layout(), &solve_elastic, &mesh_gear};
  return &backend;
}
