#pragma once
// How the normal load divides between the tooth pairs in contact. The ISO idealisation
// and equal sharing live here; the stiffness-based sharing of the energy method plugs in
// through the same interface.
#include <memory>
#include <string>

#include "gear_pair_geometry.h"

namespace gearbench::geometry {

class LoadSharing {
 public:
  virtual ~LoadSharing() = default;
  /// Share of the total normal load carried by the pair in contact at s [-].
  [[nodiscard]] virtual double share(const GearPairGeometry& g, double s) const = 0;
  [[nodiscard]] virtual std::string name() const = 0;
};

/// Load sharing factor X_Γ of ISO/TR 15144-1:2014 §6 (the ISO 6336 idealisation) for
/// gears without profile modification. Spur (ε_β = 0): 1/3 at A rising linearly to 2/3 at
/// B, 1 on B..D, 2/3 at D falling to 1/3 at E, so that the two pairs in double contact
/// sum to 1. Helical with ε_β ≥ 1: 1/ε_α along the whole path. For 0 < ε_β < 1
/// gearbench interpolates linearly in ε_β between the two (our choice; the standard's
/// own interpolation should replace it when checked against the text).
class IsoLoadSharing final : public LoadSharing {
 public:
  [[nodiscard]] double share(const GearPairGeometry& g, double s) const override;
  [[nodiscard]] std::string name() const override { return "iso"; }

 private:
  [[nodiscard]] static double spur_share(const GearPairGeometry& g, double s);
};

/// Equal sharing: each pair in contact carries 1/n of the load (half per pair in a
/// double-contact zone), the assumption of Ohlendorf's loss factor.
class EqualLoadSharing final : public LoadSharing {
 public:
  [[nodiscard]] double share(const GearPairGeometry& g, double s) const override;
  [[nodiscard]] std::string name() const override { return "equal"; }
};

/// "iso" or "equal"; InputError (naming `key`) otherwise.
std::unique_ptr<LoadSharing> make_load_sharing(const std::string& name, const std::string& key);

}  // namespace gearbench::geometry
