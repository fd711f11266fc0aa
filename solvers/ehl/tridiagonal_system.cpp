#include "tridiagonal_system.h"

#include <gsl/gsl_linalg.h>

#include "model/gsl_status.h"

namespace gearbench::ehl {

void TridiagonalSystem::resize(std::size_t n) {
  sub_.resize(n - 1);
  sup_.resize(n - 1);
  diag_.resize(n);
  rhs_.resize(n);
  x_.resize(n);
}

const std::vector<double>& TridiagonalSystem::solve(std::string_view what) {
  model::gsl_use_status_codes();
  gsl_vector_const_view d = gsl_vector_const_view_array(diag_.data(), diag_.size());
  gsl_vector_const_view e = gsl_vector_const_view_array(sup_.data(), sup_.size());
  gsl_vector_const_view f = gsl_vector_const_view_array(sub_.data(), sub_.size());
  gsl_vector_const_view b = gsl_vector_const_view_array(rhs_.data(), rhs_.size());
  gsl_vector_view x = gsl_vector_view_array(x_.data(), x_.size());
  model::gsl_check(gsl_linalg_solve_tridiag(&d.vector, &e.vector, &f.vector, &b.vector, &x.vector), what);
  return x_;
}

}  // namespace gearbench::ehl
