#include "mann_whitney.h"

#include <algorithm>
#include <cmath>
#include <gsl/gsl_cdf.h>
#include <numeric>
#include <stdexcept>

namespace gearbench::reports {

namespace {

struct PooledRanks {
  std::vector<double> rank;  ///< mid-rank of each pooled value, x first then y
  double tie_term = 0.0;     ///< Σ (t³ − t) over groups of t tied values
};

PooledRanks mid_ranks(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> pooled(x);
  pooled.insert(pooled.end(), y.begin(), y.end());
  std::vector<std::size_t> order(pooled.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return pooled[a] < pooled[b]; });
  PooledRanks out{std::vector<double>(pooled.size()), 0.0};
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && pooled[order[j + 1]] == pooled[order[i]]) ++j;
    const double mid = 0.5 * static_cast<double>(i + j) + 1.0;  // ranks i+1..j+1
    for (std::size_t k = i; k <= j; ++k) out.rank[order[k]] = mid;
    const double t = static_cast<double>(j - i + 1);
    out.tie_term += t * t * t - t;
    i = j + 1;
  }
  return out;
}

/// Number of arrangements of m x's and n y's with each U = 0..mn: the coefficients of the
/// Gaussian binomial coefficient [m+n choose m]_q = Π_{i=1..m} (1 − q^{n+i}) / (1 − q^i)
/// (Andrews, The Theory of Partitions, 1976, thm 3.1; the U distribution is the
/// partition count of Mann & Whitney 1947, eq. 2). Exact in doubles while C(m+n, m) < 2^53.
std::vector<double> u_counts(std::size_t m, std::size_t n) {
  const std::size_t top = m * n;
  std::vector<double> c(top + 1, 0.0);
  c[0] = 1.0;
  for (std::size_t i = 1; i <= m; ++i) {
    // multiply by (1 − q^{n+i}), then divide by (1 − q^i); degrees above mn vanish.
    for (std::size_t k = top; k >= n + i && k <= top; --k) c[k] -= c[k - n - i];
    for (std::size_t k = i; k <= top; ++k) c[k] += c[k - i];
  }
  return c;
}

double binomial(std::size_t n, std::size_t k) {
  double b = 1.0;
  for (std::size_t i = 1; i <= k; ++i) b = b * static_cast<double>(n - k + i) / static_cast<double>(i);
  return b;
}

/// P(U ≥ u) under the null hypothesis, exactly.
double exact_survival(double u, std::size_t n1, std::size_t n2) {
  const auto counts = u_counts(std::min(n1, n2), std::max(n1, n2));
  const auto from = static_cast<std::size_t>(std::ceil(u));
  double tail = 0.0;
  for (std::size_t k = from; k < counts.size(); ++k) tail += counts[k];
  return tail / binomial(n1 + n2, std::min(n1, n2));
}

/// U1 = R1 − n1(n1+1)/2 with R1 the rank sum of the first n1 pooled values.
double u_from_ranks(const PooledRanks& ranks, std::size_t n1) {
  const double r1 = std::accumulate(ranks.rank.begin(), ranks.rank.begin() + static_cast<long>(n1), 0.0);
  const double n = static_cast<double>(n1);
  return r1 - n * (n + 1.0) / 2.0;
}

}  // namespace

double u_statistic(const std::vector<double>& x, const std::vector<double>& y) {
  return u_from_ranks(mid_ranks(x, y), x.size());
}

UTestResult mann_whitney_u(const std::vector<double>& x, const std::vector<double>& y, UTestMethod method) {
  if (x.size() < utest_min_repetitions || y.size() < utest_min_repetitions)
    throw std::invalid_argument("Mann-Whitney U test needs at least 2 values in each sample");
  UTestResult r;
  r.n1 = x.size();
  r.n2 = y.size();
  const auto ranks = mid_ranks(x, y);
  const double n1 = static_cast<double>(r.n1), n2 = static_cast<double>(r.n2), n = n1 + n2;
  r.u1 = u_from_ranks(ranks, r.n1);
  r.u2 = n1 * n2 - r.u1;
  const double u = std::max(r.u1, r.u2);  // two-sided: twice the upper tail of the larger U
  // scipy's _mwu_choose_method: exact when a sample has ≤ 8 values and nothing is tied.
  // Counts are exact in doubles below 2^53 ≈ 9.0e15 arrangements.
  const bool representable = binomial(r.n1 + r.n2, std::min(r.n1, r.n2)) < 9.0e15;
  r.exact = method == UTestMethod::exact ? representable
            : method == UTestMethod::asymptotic
                ? false
                : std::min(r.n1, r.n2) <= 8 && ranks.tie_term == 0.0 && representable;
  double p;
  if (r.exact) {
    p = 2.0 * exact_survival(u, r.n1, r.n2);
  } else {
    // Normal approximation: mean n1·n2/2, variance n1·n2/12·((n+1) − Σ(t³−t)/(n(n−1)))
    // (tie-corrected, Lehmann 1975, Nonparametrics, eq. 1.55), continuity correction 1/2.
    const double sd = std::sqrt(n1 * n2 / 12.0 * ((n + 1.0) - ranks.tie_term / (n * (n - 1.0))));
    p = sd > 0.0 ? 2.0 * gsl_cdf_ugaussian_Q((u - n1 * n2 / 2.0 - 0.5) / sd) : 1.0;
  }
  r.p_value = std::clamp(p, 0.0, 1.0);
  return r;
}

}  // namespace gearbench::reports
