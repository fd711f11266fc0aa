#include "traction.h"

#include <cmath>

namespace gearbench::ehl {

Traction eyring_traction(const LineContactProblem& problem, const EhlResult& r, double eyring_stress) {
  const auto& d = problem.data();
  const double hs = problem.film_scale(), ls = problem.length_scale(), ps = problem.pressure_scale();
  const double dX = r.X[1] - r.X[0];
  Traction t;
  for (std::size_t i = 1; i + 1 < r.X.size(); ++i) {
    if (r.P[i] <= 0.0 || r.H[i] <= 0.0) continue;
    const double h = r.H[i] * hs;
    const double dpdx = (r.P[i + 1] - r.P[i - 1]) / (2.0 * dX) * ps / ls;
    const double eta = d.viscosity * problem.viscosity(r.P[i]);
    const double newtonian = eta * (d.u2 - d.u1) / h - 0.5 * h * dpdx;
    t.force_per_length += eyring_stress * std::asinh(newtonian / eyring_stress) * dX * ls;
  }
  t.coefficient = t.force_per_length / d.load_per_length;
  return t;
}

}  // namespace gearbench::ehl
