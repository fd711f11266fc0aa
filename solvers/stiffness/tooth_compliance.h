#pragma once
// Bending, shear and axial compliance of one tooth by the potential-energy method
// (docs/stiffness-model.md), integrated along the tooth's centre line x.
//
// The bending energy of a load at x_1 expands in moments of the section properties:
// with ξ = x − x_0, K = cos α_1·(x_1 − x_0) − sin α_1·h_1 and c = cos α_1,
//   1/k_b = ∫ (K − c·ξ)²/(E I) dξ = K²·J0 − 2Kc·J1 + c²·J2,   J_n = ∫ ξⁿ/(E I) dξ,
//   1/k_s = 1.2·cos²α_1·∫ dξ/(G A),  1/k_a = sin²α_1·∫ dξ/(E A).
// The J's are accumulated once per tooth over Gauss–Legendre panels, so a load position
// costs one partial panel.
#include <optional>
#include <vector>

#include "model/materials.h"
#include "tooth_profile.h"

namespace gearbench::stiffness {

/// A straight crack through the face width (docs/stiffness-model.md, "Cracks").
struct Crack {
  enum class Type { pitch, root };
  Type type = Type::pitch;
  double length = 0.0;  ///< q [m]
  double angle = 0.0;   ///< ν, to the centre line [rad]
};

/// Compliances 1/k of one tooth [m/N] for the whole face width of the slice.
struct ComplianceComponents {
  double bending = 0.0;
  double shear = 0.0;
  double axial = 0.0;
  [[nodiscard]] double sum() const { return bending + shear + axial; }
};

class ToothCompliance {
 public:
  ToothCompliance(ToothProfile profile, const model::Material& material, double face_width,
                  const std::optional<Crack>& crack);

  /// Compliances for a load at roll angle ψ on this tooth's flank, with the crack acting
  /// as its position decides (automatic), never (the uncracked teeth of the same gear), or
  /// as the caller decides for a whole time interval (a dynamics step that must not see the
  /// crack switch on inside it).
  enum class CrackMode { automatic, healthy, active, inactive };
  [[nodiscard]] ComplianceComponents at(double roll_angle, CrackMode mode = CrackMode::automatic) const;
  /// The healthy beam's displacement, along the load line, of the point Q where the load line
  /// crosses the centre line (x_Q = x_1 − h_1·tan α_1), per unit load: the same integrals
  /// over [x_0, x_Q] only. Below Q a unit force at Q on the load line has the load's moment,
  /// shear and normal force on every section, above it none (Castigliano). It is what the FE
  /// reference probes (docs/fe-tooth-model.md), so it compares with it like for like.
  [[nodiscard]] ComplianceComponents centre_line_point(double roll_angle) const;

  [[nodiscard]] const ToothProfile& profile() const { return profile_; }
  /// Crack tip half-thickness h_c (negative past the centre line), if cracked.
  [[nodiscard]] std::optional<double> crack_tip_thickness() const;

 private:
  struct Moments {
    double J0 = 0.0, J1 = 0.0, J2 = 0.0;  ///< ∫ ξⁿ/(E I) dξ
    double JA = 0.0;                       ///< ∫ dξ/A
  };
  /// Cumulative moments at panel ends over [x_0, x_tip] for one thickness law.
  struct Table {
    std::vector<double> ends;      ///< panel end points, ends[0] = x_0
    std::vector<Moments> cumulative;  ///< moments from x_0 to ends[k]
  };

  [[nodiscard]] double thickness(double x, bool cracked) const;
  [[nodiscard]] Moments panel_moments(double a, double b, bool cracked) const;
  [[nodiscard]] Table build_table(bool cracked) const;
  [[nodiscard]] Moments moments_to(const Table& table, double x1, bool cracked) const;
  [[nodiscard]] bool crack_active(double roll_angle) const;
  /// The three compliances of a load at `load`, integrated from x_0 to x_end.
  [[nodiscard]] ComplianceComponents components(const FlankPoint& load, double x_end, bool cracked) const;

  ToothProfile profile_;
  double E_ = 0.0, G_ = 0.0, width_ = 0.0;
  std::optional<Crack> crack_;
  double crack_tip_x_ = 0.0, crack_tip_h_ = 0.0;
  Table healthy_;
  Table cracked_;
};

}  // namespace gearbench::stiffness
