#include "tridiagonal_system.h"

#include <fmt/format.h>
#include <stdexcept>

namespace gearbench::ehl {

void TridiagonalSystem::reset(std::size_t n) {
  sub_.assign(n - 1, 0.0);
  sup_.assign(n - 1, 0.0);
  diag_.assign(n, 0.0);
  rhs_.assign(n, 0.0);
}

const std::vector<double>& TridiagonalSystem::solve(std::string_view what) {
  const std::size_t n = diag_.size();
  pivot_.resize(n);
  reduced_rhs_.resize(n);
  x_.resize(n);
  // Elimination of the subdiagonal, top down (GSL: alpha, z)...
  bool zero_pivot = diag_[0] == 0.0;
  pivot_[0] = diag_[0];
  reduced_rhs_[0] = rhs_[0];
  for (std::size_t i = 1; i < n; ++i) {
    const double t = sub_[i - 1] / pivot_[i - 1];
    pivot_[i] = diag_[i] - t * sup_[i - 1];
    reduced_rhs_[i] = rhs_[i] - t * reduced_rhs_[i - 1];
    zero_pivot = zero_pivot || pivot_[i] == 0.0;
  }
  if (zero_pivot) throw std::runtime_error(fmt::format("{}: zero pivot in the tridiagonal solve", what));
  // ... then back substitution.
  x_[n - 1] = reduced_rhs_[n - 1] / pivot_[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) x_[i] = (reduced_rhs_[i] - sup_[i] * x_[i + 1]) / pivot_[i];
  return x_;
}

}  // namespace gearbench::ehl
