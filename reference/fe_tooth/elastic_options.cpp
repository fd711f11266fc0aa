// ElasticOptions::validate, apart from elasticity.cpp: the solve runs in the deal.II plugin
// (fe_backend.h), and the callers outside it validate their options before they cross.
#include <string>

#include "elasticity.h"
#include "model/errors.h"

namespace gearbench::reference::fe {

void ElasticOptions::validate() const {
  if (degree < 1 || degree > 4) throw InputError("fe.degree = " + std::to_string(degree) + ": must be 1…4");
  if (max_cycles < 3 || max_cycles > 20)
    throw InputError("fe.max_cycles = " + std::to_string(max_cycles) + ": must be 3…20");
  if (!(refine_fraction > 0.0 && refine_fraction < 1.0))
    throw InputError("fe.refine_fraction = " + std::to_string(refine_fraction) + ": must lie in (0, 1)");
  if (!(tolerance > 0.0 && tolerance < 0.5))
    throw InputError("fe.tolerance = " + std::to_string(tolerance) + ": must lie in (0, 0.5)");
}

}  // namespace gearbench::reference::fe
