#pragma once
// Involute geometry and kinematics of an external cylindrical gear pair (spur, helical,
// herringbone = two helical halves of opposite hand), after ISO 21771:2007 and
// Niemann & Winter, Maschinenelemente II (1989), ch. 21. Transverse-plane quantities
// unless named otherwise. Positions along the line of action are distances s from T1,
// the tangent point of the pinion's base circle.
#include <array>
#include <string>
#include <vector>

#include "model/gear_pair.h"

namespace gearbench::geometry {

/// Per-gear radii [m].
struct GearRadii {
  double reference = 0.0;  ///< r = z·m_t/2
  double base = 0.0;       ///< r_b = r·cos α_t
  double tip = 0.0;        ///< r_a
  double root = 0.0;       ///< r_f = r − m_n(h_f* − x)
  double working = 0.0;    ///< r_w = r_b / cos α_wt
  double form = 0.0;       ///< r_Ff: lowest point of the rack-generated involute
};

/// Characteristic points of the path of contact, as distances from T1 [m].
struct PathOfContact {
  double T2 = 0.0;  ///< T1T2 = a·sin α_wt
  double A = 0.0;   ///< start of contact (wheel tip)
  double AB = 0.0;  ///< midpoint of A and B
  double B = 0.0;   ///< lowest point of single contact on the pinion
  double C = 0.0;   ///< pitch point
  double D = 0.0;   ///< highest point of single contact on the pinion
  double DE = 0.0;  ///< midpoint of D and E
  double E = 0.0;   ///< end of contact (pinion tip)
};

/// A stretch of the path of contact with a constant number of pairs in contact.
struct ContactZone {
  double begin = 0.0;  ///< [m from T1]
  double end = 0.0;
  int pairs = 0;
};

/// Curvature and kinematics of the contact at one position on the path.
struct ContactKinematics {
  double position = 0.0;          ///< s [m from T1]
  double pinion_radius = 0.0;     ///< radius of the contact point on the pinion [m]
  double rho1 = 0.0;              ///< pinion flank radius of curvature (transverse) [m]
  double rho2 = 0.0;              ///< wheel flank radius of curvature (transverse) [m]
  double reduced_radius = 0.0;    ///< R = ρ1ρ2/(ρ1+ρ2), transverse [m]
  double reduced_radius_normal = 0.0;  ///< R / cos β_b, normal section [m]
  double u1 = 0.0;                ///< pinion surface speed along the profile [m/s]
  double u2 = 0.0;                ///< wheel surface speed along the profile [m/s]
  double entrainment = 0.0;       ///< ū = (u1+u2)/2 [m/s]
  double sliding = 0.0;           ///< u_s = u1 − u2 [m/s]
  double slide_to_roll = 0.0;     ///< SRR = u_s/ū [-] (positive where the pinion is faster)
  double specific_sliding1 = 0.0; ///< (u1 − u2)/u1 [-]
  double specific_sliding2 = 0.0; ///< (u2 − u1)/u2 [-]
};

class GearPairGeometry {
 public:
  /// Computes all radii, angles and the path of contact; throws InputError (naming the
  /// case key) for undercut, tip interference, pointed teeth, a centre distance that the
  /// shifts do not allow, or a contact ratio below 1.
  explicit GearPairGeometry(const model::GearPair& pair);

  [[nodiscard]] const model::GearPair& pair() const { return pair_; }
  [[nodiscard]] const GearRadii& radii(int gear) const { return radii_.at(static_cast<std::size_t>(gear)); }
  [[nodiscard]] const PathOfContact& path() const { return path_; }

  [[nodiscard]] double transverse_module() const { return transverse_module_; }
  [[nodiscard]] double transverse_pressure_angle() const { return alpha_t_; }
  [[nodiscard]] double working_pressure_angle() const { return alpha_wt_; }
  [[nodiscard]] double base_helix_angle() const { return beta_b_; }
  [[nodiscard]] double center_distance() const { return center_distance_; }
  /// Centre distance at zero backlash for the given shifts (ISO 21771:2007).
  [[nodiscard]] double zero_backlash_center_distance() const { return zero_backlash_a_; }
  [[nodiscard]] double base_pitch_transverse() const { return base_pitch_; }
  [[nodiscard]] double gear_ratio() const;  ///< u = z2/z1

  /// ε_α = g_α / p_bt from the path of contact.
  [[nodiscard]] double contact_ratio_transverse() const;
  /// ε_β = b·tan β_b / p_bt from the base-plane contact lines (per helical half).
  [[nodiscard]] double contact_ratio_overlap() const;
  [[nodiscard]] double contact_ratio_total() const;

  /// Number of tooth pairs in contact when one pair is at s (transverse plane).
  [[nodiscard]] int pairs_in_contact(double s) const;
  /// Positions of the pairs in contact when one pair is at s (the pairs one base pitch
  /// apart on A..E, counted by integer offsets so that none is lost to rounding).
  [[nodiscard]] std::vector<double> positions_in_contact(double s) const;
  /// The path A..E split into zones of constant pair count (spur / transverse view).
  [[nodiscard]] std::vector<ContactZone> contact_zones() const;

  /// Radii of curvature, surface speeds and sliding at s for pinion speed ω1 [rad/s].
  [[nodiscard]] ContactKinematics kinematics(double s, double pinion_speed) const;

  /// Total length of the contact lines [m] at a mesh position, given as the transverse
  /// position s0 of one contact line on the front face (ISO 21771 §5.4; spur: b per
  /// pair). For a herringbone pair, both halves.
  [[nodiscard]] double contact_line_length(double s0) const;

  /// Warnings about the input that are not errors (e.g. backlash from the centre distance).
  [[nodiscard]] const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  void compute_pitch_geometry();
  void compute_center_distance();
  void compute_radii();
  void compute_path_of_contact();
  void check_feasibility() const;
  [[nodiscard]] double tip_tooth_thickness(int gear) const;
  [[nodiscard]] double contact_line_length_one_half(double s0) const;

  model::GearPair pair_;
  std::array<GearRadii, 2> radii_{};
  PathOfContact path_{};
  double transverse_module_ = 0.0;
  double alpha_t_ = 0.0;
  double alpha_wt_ = 0.0;
  double beta_b_ = 0.0;
  double center_distance_ = 0.0;
  double zero_backlash_a_ = 0.0;
  double base_pitch_ = 0.0;
  std::vector<std::string> warnings_;
};

}  // namespace gearbench::geometry
