#pragma once
// The convergence kit every check and test shares (issue 21): the observed order of a
// discretisation, Richardson extrapolation, and a table of a refinement study in the manner of
// deal.II's ConvergenceTable (value, change, observed order per row).
//
// For a quantity f_h = f + C·h^p + o(h^p) on grids refined by a ratio r:
//   p ≈ ln((f_1 − f_2)/(f_2 − f_3)) / ln r,   f ≈ f_3 + (f_3 − f_2)/(r^p − 1)
// (Roache, Verification and Validation in Computational Science and Engineering, 1998, §5.4).
// When the two changes have opposite signs the values are not in the asymptotic range and the
// order is undefined: observed_order returns NaN, which fails any check that compares it.
#include <string>
#include <vector>

namespace gearbench::verification {

/// Observed order from three values on grids refined by `ratio` (coarse → fine); NaN when the
/// changes alternate in sign or the finer change is zero.
[[nodiscard]] double observed_order(double coarse, double medium, double fine, double ratio = 2.0);
/// The observed order of the three finest values of a series on grids refined by `ratio`.
[[nodiscard]] double observed_order(const std::vector<double>& series, double ratio = 2.0);
/// Observed order from the errors of two runs whose step differs by `ratio`:
/// ln(e_coarse/e_fine)/ln r.
[[nodiscard]] double order_from_errors(double coarse_error, double fine_error, double ratio = 2.0);
/// Richardson extrapolation of the two finest values of a scheme of order p:
/// fine + (fine − medium)/(r^p − 1).
[[nodiscard]] double richardson(double medium, double fine, double order, double ratio = 2.0);
/// An answer's algebraic error over its grid's discretisation error: |answer − discrete|, the
/// answer against the grid's discrete solution, over |fine − richardson|, the Richardson estimate
/// from the discrete solution of the grid `ratio` times coarser (order p).
[[nodiscard]] double algebraic_error_share(double answer, double discrete, double coarser_discrete, double order,
                                           double ratio = 2.0);

/// A refinement study: one row per grid (coarse → fine), one column per quantity; each
/// quantity's change from the previous row and the observed order over the last three rows
/// are evaluated when printed.
class ConvergenceTable {
 public:
  /// `parameter` names the first column (e.g. "nodes"); `columns` the quantities.
  ConvergenceTable(std::string parameter, std::vector<std::string> columns);
  /// One grid: its parameter value and one value per column.
  void add_row(double parameter, const std::vector<double>& values);
  [[nodiscard]] const std::vector<double>& column(std::size_t k) const { return values_[k]; }
  /// A Markdown table: parameter, then value and change per column, then a last row with
  /// each column's observed order over the three finest rows (refinement `ratio`).
  [[nodiscard]] std::string markdown(double ratio = 2.0) const;

 private:
  std::string parameter_;
  std::vector<std::string> columns_;
  std::vector<double> parameters_;
  std::vector<std::vector<double>> values_;  ///< per column, per row
};

}  // namespace gearbench::verification
