#pragma once
// Steady thermal EHL at the characteristic points A, AB, B, C, D, DE, E of the path of
// contact of a gear pair (seed 001): each point is a quasi-static line contact with the local
// normal radius of curvature, the local surface speeds and the local load.
//   w_Y = K_A·K_v·K_Hα·K_Hβ · X_Y · T1/(r_b1·b)   [N/m of contact line],
// with the load share X_Y of ISO/TR 15144-1 ("iso", gears without profile modification: for
// helical gears with ε_β ≥ 1, X_Y = 1/ε_α, so that w_Y is the transverse force spread over
// the total contact-line length b·ε_α/cos β_b, in the normal plane) or equal sharing. The
// radius is the normal-section R/cos β_b; the speeds are the transverse surface speeds along
// the profile (as ISO/TR 15144-1 and DIN 3990 use them).
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "geometry/gear_pair_geometry.h"
#include "model/materials.h"
#include "thermal_line_contact.h"

namespace gearbench::ehl {

struct ThermalPathPoint {
  std::string name;                 ///< "A", "AB", "B", "C", "D", "DE", "E"
  double position = 0.0;            ///< from T1 along the line of action [m]
  LineContactData contact;          ///< radius, load, speeds at the point
  double load_share = 0.0;          ///< X_Y
  double hertz_pressure = 0.0;      ///< p_H,Y [Pa]
  double slide_to_roll = 0.0;       ///< (u1 − u2)/ū
  ThermalEhlResult result;
};

/// converged and message: model::SolveStatus (the point that did not converge named).
struct ThermalPathResult : model::SolveStatus {
  std::vector<ThermalPathPoint> points;  ///< all seven, or those up to and including a failed one
  double seconds = 0.0;
  int minimum_film_point = 0;       ///< index of the smallest h_min
  [[nodiscard]] std::string summary() const;
};

class ThermalMeshPath {
 public:
  /// Keeps references to `geometry` and `rheology`, which must outlive this object.
  ThermalMeshPath(const geometry::GearPairGeometry& geometry, const model::OperatingPoint& operating,
                  const std::array<model::Material, 2>& materials, const lubricant::ThermalRheology& rheology,
                  const model::ThermalSolids& solids, model::LoadFactors factors, std::string load_sharing,
                  ThermalEhlOptions options);
  /// The contact at each point, without solving (for the ISO comparison and the report).
  [[nodiscard]] std::vector<ThermalPathPoint> contacts() const;
  /// Solves one named point ("A", …, "E"); InputError for an unknown name.
  [[nodiscard]] ThermalPathPoint solve_point(const std::string& name) const;
  /// Solves every point; throws ConvergenceError naming the point that failed. `progress`
  /// gets one line per solved point.
  [[nodiscard]] ThermalPathResult run(const std::function<void(const std::string&)>& progress = {}) const;
  /// The same, returning converged = false, the message naming the point, and the points up to
  /// and including it instead of throwing.
  [[nodiscard]] ThermalPathResult try_run(const std::function<void(const std::string&)>& progress = {}) const;

 private:
  const geometry::GearPairGeometry& geometry_;
  model::OperatingPoint operating_;
  std::array<model::Material, 2> materials_;
  const lubricant::ThermalRheology& rheology_;
  model::ThermalSolids solids_;
  model::LoadFactors factors_;
  std::string load_sharing_;
  ThermalEhlOptions options_;

  void solve(ThermalPathPoint& pt) const;
  /// Solves `pt`; "" when it converged, else the sentence naming it and what did not converge.
  [[nodiscard]] std::string attempt(ThermalPathPoint& pt) const;
};

}  // namespace gearbench::ehl
