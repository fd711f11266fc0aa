#pragma once
// The viscosity index of ASTM D2270 / ISO 2909 (technically equivalent), and its inverse: the
// ν100 of an oil given by ν40 and VI (an ISO VG grade "with a stated viscosity index", issue
// 24). Kinematic viscosities in mm²/s.
#include <optional>
#include <utility>
#include <vector>

namespace gearbench::lubricant {

class ViscosityIndex {
 public:
  /// One row of D2270 Table 1: ν100 and the ν40 of the VI 0 (L) and VI 100 (H) oils of that ν100.
  struct Row {
    double nu100 = 0.0, L = 0.0, H = 0.0;
  };
  /// Table 1 (data/lubricants.json), ν100 strictly ascending from 2 mm²/s; std::invalid_argument otherwise.
  explicit ViscosityIndex(std::vector<Row> table_1);

  /// ν100 below which D2270 defines no viscosity index (1.2) [mm²/s].
  [[nodiscard]] double min_nu100() const { return table_.front().nu100; }
  /// L and H for ν100 ≥ min_nu100(): Table 1, linearly interpolated (5.1.1), its formulas
  /// above the last row (5.1.2).
  [[nodiscard]] std::pair<double, double> reference_viscosities(double nu100) const;
  /// VI (unrounded) of the oil of ν40 and ν100: procedure A where ν40 ≥ H (VI ≤ 100),
  /// procedure B below (VI ≥ 100); the two meet at ν40 = H.
  [[nodiscard]] double index(double nu40, double nu100) const;
  /// The VIs an oil of this ν40 can have: ν100 from min_nu100() up to ν40 (a viscosity that
  /// falls with temperature); empty when ν40 ≤ min_nu100(). index() rises with ν100 at fixed
  /// ν40 (checked over the table in verification/lubricant_test.cpp), so each VI in the range
  /// has one ν100.
  [[nodiscard]] std::optional<std::pair<double, double>> index_range(double nu40) const;
  /// ν100 of the oil of ν40 and VI, the inverse of index() (bisection to 1e-12 relative); empty
  /// when VI is outside index_range(ν40).
  [[nodiscard]] std::optional<double> nu100(double nu40, double vi) const;

 private:
  std::vector<Row> table_;
};

}  // namespace gearbench::lubricant
