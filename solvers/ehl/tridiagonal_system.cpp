#include "tridiagonal_system.h"

#include <fmt/format.h>
#include <stdexcept>

namespace gearbench::ehl {

void TridiagonalSystem::resize(std::size_t n) {
  sub_.resize(n - 1);
  sup_.resize(n - 1);
  diag_.resize(n);
  rhs_.resize(n);
}

const std::vector<double>& TridiagonalSystem::solve(std::string_view what) {
  const std::size_t n = diag_.size();
  pivot_.resize(n);
  reduced_rhs_.resize(n);
  x_.resize(n);
  // Both sweeps are chains of divisions, each step waiting for the last: the value carried
  // from one step to the next stays in a local (a register) rather than being read back from
  // the array it was just stored to, which put a store-to-load delay on every step.
  // Elimination of the subdiagonal, top down (GSL: alpha, z)...
  double pivot = diag_[0], reduced = rhs_[0];
  bool zero_pivot = pivot == 0.0;
  pivot_[0] = pivot;
  reduced_rhs_[0] = reduced;
  for (std::size_t i = 1; i < n; ++i) {
    const double t = sub_[i - 1] / pivot;
    pivot = diag_[i] - t * sup_[i - 1];
    reduced = rhs_[i] - t * reduced;
    pivot_[i] = pivot;
    reduced_rhs_[i] = reduced;
    zero_pivot = zero_pivot || pivot == 0.0;
  }
  if (zero_pivot) throw std::runtime_error(fmt::format("{}: zero pivot in the tridiagonal solve", what));
  // ... then back substitution.
  double x = reduced / pivot;
  x_[n - 1] = x;
  for (std::size_t i = n - 1; i-- > 0;) {
    x = (reduced_rhs_[i] - sup_[i] * x) / pivot_[i];
    x_[i] = x;
  }
  return x_;
}

}  // namespace gearbench::ehl
