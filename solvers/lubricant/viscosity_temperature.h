#pragma once
// A lubricant's viscosity and density against temperature at ambient pressure: the laws the
// thermal EHL rheology and the lubricant catalogue share. Temperatures in K.
namespace gearbench::lubricant {

inline constexpr double celsius_zero = 273.15;  ///< [K]
/// −dρ/dT of ISO/TR 15144-1 (20) [kg/(m³·K)].
inline constexpr double iso15144_density_slope = 0.7;
inline constexpr double walther_offset = 0.7;  ///< [mm²/s], the 0.7 in lg lg(ν + 0.7) (ASTM D341)

/// ASTM D341 (Ubbelohde–Walther) through two points:
///   lg lg(ν + 0.7) = A·lg T + B,  ν in mm²/s, T in K
/// (ISO/TR 15144-1 (17)–(19) and seed 001 eq. 1.3 quote the same law). The two-constant form
/// holds for ν ≥ 2 mm²/s; below, D341 adds correction terms that are not implemented.
class WaltherLine {
 public:
  /// The line through (T1, ν1) and (T2, ν2), ν in mm²/s; T1 ≠ T2.
  WaltherLine(double T1, double nu1_mm2_s, double T2, double nu2_mm2_s);
  [[nodiscard]] double kinematic_viscosity_mm2_s(double T) const;
  [[nodiscard]] double slope() const { return A_; }  ///< A (negative: ν falls with T)

 private:
  double A_ = 0.0, B_ = 0.0;
};

/// ISO/TR 15144-1 (20), seed 001 eq. 1.3: ρ(T) = ρ15 − 0.7·(T − 15 °C) [kg/m³].
double iso15144_density(double rho15, double T);

}  // namespace gearbench::lubricant
