#pragma once
// A tridiagonal system (sub, diag, sup)·x = rhs, set row by row and solved by the
// Thomas algorithm without pivoting (the film-temperature columns are diagonally dominant:
// conduction, upwind convection and the source slope all add to the diagonal). Its storage is
// kept from one solve to the next: a temperature sweep solves thousands of columns of the same
// size, and GSL's gsl_linalg_solve_tridiag, which this replaces, allocated two work arrays on
// every call. The arithmetic is GSL's (2.7, linalg/tridiag.c, solve_tridiag_nonsym) operation
// for operation, so the solutions are bitwise GSL's.
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
  /// The solution; throws std::runtime_error naming `what` on a zero pivot (GSL's EZERODIV).
  /// Valid until the next resize or solve.
  [[nodiscard]] const std::vector<double>& solve(std::string_view what);

 private:
  std::vector<double> sub_, diag_, sup_, rhs_;  ///< the system: sub_[r−1], sup_[r] couple rows r−1, r, r+1
  std::vector<double> pivot_, reduced_rhs_, x_;  ///< elimination's diagonal and right-hand side, the solution
};

}  // namespace gearbench::ehl
