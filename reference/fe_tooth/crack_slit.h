#pragma once
// A straight crack through the face width of the loaded tooth as a slit for the FE mesh
// (docs/fe-tooth-model.md, "Cracks"): derived here from the generated outline alone, with
// the geometry of seed 003 (Xu et al. 2022): the mouth on the loaded flank at the
// reference circle, the crack running into the tooth towards the root at angle ν to the
// tooth centre line, length q.
#include <optional>

#include "tooth_outline.h"

namespace gearbench::reference::fe {

/// Crack parameters as the case section "crack" gives them (type pitch only).
struct ToothCrack {
  int gear = 0;         ///< 0 pinion, 1 wheel
  double length = 0.0;  ///< q [m]
  double angle = 0.0;   ///< ν to the tooth centre line [rad]
  enum class Type { pitch } type = Type::pitch;  ///< the case key "type": the slit models the pitch crack only
};

/// The crack line in tooth coordinates (centre line on +x, loaded flank y > 0).
struct Slit {
  Vec2 mouth{};  ///< on the loaded flank at the reference circle
  Vec2 tip{};    ///< mouth − q·(cos ν, sin ν)
  /// Index of the first dense flank sample above the mouth (the outline is split there).
  std::size_t flank_index = 0;
};

/// The slit of `crack` in `tooth`. InputError (naming crack.length_mm / crack.angle_deg)
/// when the tip falls below the root circle or leaves less than 10 % of the local section
/// (a broken tooth, which a linear model cannot carry).
Slit pitch_crack_slit(const ToothOutline& tooth, const ToothCrack& crack);

/// Distance from p to the slit's segment [m].
double distance_to_slit(const Slit& slit, const Vec2& p);

}  // namespace gearbench::reference::fe
