#pragma once
// A tridiagonal system (sub, diag, sup)·x = rhs, set row by row and solved by GSL
// (gsl_linalg_solve_tridiag: Thomas's elimination without pivoting; the film-temperature columns
// are diagonally dominant: conduction, upwind convection and the source slope all add to the
// diagonal). Its storage is kept from one solve to the next: a temperature sweep solves
// thousands of columns of the same size, and building the system's four vectors and the
// solution afresh for each was a tenth of the sweeps' instructions.
#include <cstddef>
#include <string_view>
#include <vector>

namespace gearbench::ehl {

class TridiagonalSystem {
 public:
  /// Sizes the system for n ≥ 1 unknowns (the storage is reused when n does not grow); every
  /// row is then set once (set_row) before the solve.
  void resize(std::size_t n);
  /// Row r: prev·x[r−1] + d·x[r] + next·x[r+1] = b; the coefficient of a neighbour outside the
  /// system (prev in row 0, next in the last row) is dropped. Inline: ~34 rows per column.
  void set_row(std::size_t r, double prev, double d, double next, double b) {
    if (r > 0) sub_[r - 1] = prev;
    diag_[r] = d;
    if (r + 1 < diag_.size()) sup_[r] = next;
    rhs_[r] = b;
  }
  /// The solution; a GSL error (a zero pivot: GSL_EZERODIV) throws, naming `what`. Valid until
  /// the next resize or solve.
  [[nodiscard]] const std::vector<double>& solve(std::string_view what);

 private:
  std::vector<double> sub_, diag_, sup_, rhs_;  ///< the system: sub_[r−1], sup_[r] couple rows r−1, r, r+1
  std::vector<double> x_;                       ///< the solution
};

}  // namespace gearbench::ehl
