#include "viscosity_index.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gearbench::lubricant {

namespace {
// ASTM D2270 5.1.2: L and H above Table 1 (ν100 = Y > 70 mm²/s), mm²/s.
double L_above_table(double Y) { return (0.8353 * Y + 14.67) * Y - 216.0; }
double H_above_table(double Y) { return (0.1684 * Y + 11.85) * Y - 97.0; }
// ASTM D2270 6.1.3: VI = (10^N − 1)/0.00715 + 100.
constexpr double procedure_b_factor = 0.00715;
}  // namespace

ViscosityIndex::ViscosityIndex(std::vector<Row> table_1) : table_(std::move(table_1)) {
  if (table_.size() < 2) throw std::invalid_argument("ViscosityIndex: Table 1 needs at least two rows");
  for (std::size_t i = 1; i < table_.size(); ++i)
    if (!(table_[i].nu100 > table_[i - 1].nu100))
      throw std::invalid_argument("ViscosityIndex: Table 1 rows must ascend in nu100");
}

std::pair<double, double> ViscosityIndex::reference_viscosities(double nu100) const {
  if (nu100 > table_.back().nu100) return {L_above_table(nu100), H_above_table(nu100)};
  const auto hi = std::max(table_.begin() + 1, std::lower_bound(table_.begin(), table_.end(), nu100,
                                                               [](const Row& r, double y) { return r.nu100 < y; }));
  const auto lo = hi - 1;
  const double t = (nu100 - lo->nu100) / (hi->nu100 - lo->nu100);
  return {lo->L + t * (hi->L - lo->L), lo->H + t * (hi->H - lo->H)};
}

double ViscosityIndex::index(double nu40, double nu100) const {
  const auto [L, H] = reference_viscosities(nu100);
  if (nu40 >= H) return 100.0 * (L - nu40) / (L - H);                    // procedure A (5.1.3)
  const double N = (std::log10(H) - std::log10(nu40)) / std::log10(nu100);  // procedure B (6.1.3)
  return (std::pow(10.0, N) - 1.0) / procedure_b_factor + 100.0;
}

std::optional<std::pair<double, double>> ViscosityIndex::index_range(double nu40) const {
  if (!(nu40 > min_nu100())) return std::nullopt;
  return std::pair{index(nu40, min_nu100()), index(nu40, nu40)};
}

std::optional<double> ViscosityIndex::nu100(double nu40, double vi) const {
  const auto range = index_range(nu40);
  if (!range || !(vi >= range->first && vi <= range->second)) return std::nullopt;
  double lo = min_nu100(), hi = nu40;  // index(nu40, lo) ≤ vi ≤ index(nu40, hi)
  while (hi - lo > 1e-12 * hi) {
    const double mid = 0.5 * (lo + hi);
    (index(nu40, mid) < vi ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace gearbench::lubricant
