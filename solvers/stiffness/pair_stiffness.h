#pragma once
// Stiffness of one tooth pair in contact at a position on the line of action: Hertz in
// series with each tooth's bending, shear, axial and fillet-foundation compliance
// (seed 003 eq. 5). Everything is per unit face width; a slice of width w has w·k.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "foundation.h"
#include "geometry/gear_pair_geometry.h"
#include "geometry/load_sharing.h"
#include "tooth_compliance.h"

namespace gearbench::stiffness {

/// A crack on one gear (0 = pinion, 1 = wheel).
struct GearCrack {
  Crack crack;
  int gear = 0;
};

/// Compliances per unit face width [m²/N... i.e. (m/N)·m] of one pair at one position.
struct PairCompliance {
  std::array<ComplianceComponents, 2> tooth{};  ///< bending, shear, axial per gear
  std::array<double, 2> foundation{};           ///< Sainsot fillet foundation per gear
  double hertz = 0.0;
  [[nodiscard]] double total() const;
};

class PairStiffness {
 public:
  /// Keeps a reference to `geometry`, which must outlive this object.
  PairStiffness(const geometry::GearPairGeometry& geometry, const std::array<model::Material, 2>& materials,
                ToothModel tooth_model, const std::array<double, 2>& bore_radii,
                const std::optional<GearCrack>& crack, bool with_foundation);

  /// Compliances per unit width with the pair in contact at s (m from T1); `healthy`
  /// evaluates a pair of uncracked teeth even when one gear carries a crack.
  [[nodiscard]] PairCompliance compliance(double s, bool healthy = false) const;
  /// The same with the crack's state imposed on the cracked tooth.
  [[nodiscard]] PairCompliance compliance(double s, ToothCompliance::CrackMode mode) const;
  /// Pair stiffness per unit face width [N/m²] at s; 0 outside A..E.
  [[nodiscard]] double stiffness_per_width(double s, bool healthy = false) const;
  [[nodiscard]] double stiffness_per_width(double s, ToothCompliance::CrackMode mode) const;
  [[nodiscard]] bool cracked() const { return cracked_; }

  [[nodiscard]] const geometry::GearPairGeometry& geometry() const { return geometry_; }
  [[nodiscard]] const std::vector<std::string>& warnings() const { return warnings_; }
  [[nodiscard]] const ToothCompliance& tooth(int gear) const { return teeth_.at(static_cast<std::size_t>(gear)); }
  /// Roll angle of gear `gear`'s flank with the pair in contact at s.
  [[nodiscard]] double roll_angle(int gear, double s) const;

 private:

  const geometry::GearPairGeometry& geometry_;
  std::vector<ToothCompliance> teeth_;
  std::array<FoundationParameters, 2> foundation_{};
  double hertz_per_width_ = 0.0;
  bool with_foundation_ = true;
  bool cracked_ = false;
  std::vector<std::string> warnings_;
};

/// Load sharing in proportion to the pair stiffnesses in contact (spur, transverse plane,
/// all teeth healthy): the geometry's load-sharing hook filled by the energy method.
class StiffnessLoadSharing final : public geometry::LoadSharing {
 public:
  /// Keeps a reference to `pair`, which must outlive this object.
  explicit StiffnessLoadSharing(const PairStiffness& pair) : pair_(pair) {}
  [[nodiscard]] double share(const geometry::GearPairGeometry& g, double s) const override;
  [[nodiscard]] std::string name() const override { return "stiffness"; }

 private:
  const PairStiffness& pair_;
};

}  // namespace gearbench::stiffness
