#pragma once
// The two-sided Mann–Whitney U test over benchmark repetitions, as Google Benchmark's
// tools/compare.py runs it (scipy.stats.mannwhitneyu with alternative='two-sided',
// method='auto', use_continuity=True).
#include <cstddef>
#include <vector>

namespace gearbench::reports {

struct UTestResult {
  double u1 = 0.0;          ///< U of the first sample: pairs (x, y) with x > y, ties count 1/2
  double u2 = 0.0;          ///< n1·n2 − u1
  double p_value = 1.0;     ///< two-sided
  bool exact = false;       ///< exact null distribution (small samples without ties)
  std::size_t n1 = 0, n2 = 0;
};

/// Fewer repetitions than this on either side: compare.py runs no test, nor do we.
constexpr std::size_t utest_min_repetitions = 2;
/// compare.py warns that results are unreliable below this many repetitions.
constexpr std::size_t utest_optimal_repetitions = 9;

/// How the p-value is computed; `automatic` is scipy's (and so compare.py's) choice.
enum class UTestMethod { automatic, exact, asymptotic };

/// U of the first sample from mid-ranks of the pooled samples (Mann & Whitney 1947;
/// scipy's "method 2": U1 = R1 − n1(n1+1)/2).
double u_statistic(const std::vector<double>& x, const std::vector<double>& y);

/// Two-sided test. `automatic`: exact (Gaussian binomial coefficients) when one sample has
/// at most 8 values and there are no ties, as scipy's method='auto'; otherwise the normal
/// approximation with tie and continuity correction. `exact` ignores ties, as scipy does.
/// Throws std::invalid_argument when a sample has fewer than utest_min_repetitions values.
UTestResult mann_whitney_u(const std::vector<double>& x, const std::vector<double>& y,
                           UTestMethod method = UTestMethod::automatic);

}  // namespace gearbench::reports
