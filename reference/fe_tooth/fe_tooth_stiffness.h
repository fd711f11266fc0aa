#pragma once
// Finite-element tooth compliance of a spur pair (the independent reference for the
// energy method, docs/fe-tooth-model.md): each gear is meshed whole (every tooth, body to
// the bore, bore clamped); the normal force of a mesh position acts on the loaded tooth's
// flank along the line of action, spread over the Hertzian half-width; the tooth compliance
// is the displacement, along the line of action, of the point where the load line crosses
// the tooth centre line, per unit force. The pair adds the Hertz line-contact compliance.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "crack_slit.h"
#include "elasticity.h"
#include "model/gear_pair.h"
#include "model/materials.h"
#include "model/option_table.h"

namespace gearbench::reference::fe {

/// The keys of an fe_stiffness case beside the gear pair and materials (fe_tooth_options.cpp).
/// They are this reference's own, not the energy method's (reference/ reads no solver's
/// tables): the shared keys (crack, bore_diameter_mm) are named alike so one case serves both.
struct FeToothOptions {
  bool plane_stress = false;                         ///< else plane strain
  std::optional<std::array<double, 2>> bore_radius;  ///< [m]; default r_f/2 per gear
  double load_per_width = 1e5;        ///< normal force per face width [N/m] (Hertz width)
  double near_size_modules = 0.25;    ///< initial element size at the loaded tooth [m_n]
  double far_size_modules = 1.5;      ///< largest initial element size [m_n]
  int positions = 5;                  ///< solve(): equally spaced along A..E (one: the middle)
  ElasticOptions fe;                  ///< degree, cycles, Kelly fraction, tolerance
  bool vtu = false;                   ///< VTU of the first solve (gear 1, first position)
  /// Diagnostic: the body inside the root circle 1000× stiffer, so that the probe sees the
  /// tooth alone (the energy method's bending + shear + axial, without the foundation).
  bool rigid_body = false;
  /// A crack in one gear's loaded tooth, meshed as a slit (docs/fe-tooth-model.md, "Cracks").
  std::optional<ToothCrack> crack;

  static const model::OptionTable<FeToothOptions>& table();
  void validate() const { table().validate(*this); }  ///< InputError naming the key
};

/// One gear's tooth at one mesh position. A cracked tooth is solved twice, healthy and with
/// the slit: its compliance is the healthy probe compliance plus the slit's added
/// work-conjugate compliance (docs/fe-tooth-model.md, "Cracks").
struct ToothCompliance {
  double compliance = 0.0;       ///< [m/N] for the whole face width (probe on the load line)
  double crack_compliance = 0.0; ///< added by the slit, Δ(f·u)/F² [m/N] (0 if uncracked)
  double probe_compliance = 0.0; ///< the probe on the slit mesh itself [m/N] (diagnostic)
  double seconds = 0.0;          ///< all solves of this tooth
  /// Work-conjugate compliance of the loaded patch [m/N]: the tooth compliance plus the
  /// local indentation under the Hertzian pressure of half-width b (not added to Hertz).
  double contact_compliance = 0.0;
  double load_radius = 0.0;      ///< radius of the contact point [m]
  double hertz_half_width = 0.0; ///< [m]
  Vec2 load_point{}, probe{};    ///< tooth coordinates [m]
  bool cracked = false;          ///< this tooth carries the slit
  double probe_to_crack = 0.0;   ///< distance of the probe from the slit [m] (0 if uncracked)
  ElasticResult fe;              ///< the slit solve if cracked
};

struct FePosition {
  double path_position = 0.0;      ///< s from T1 [m]
  std::array<ToothCompliance, 2> tooth;
  double hertz_compliance = 0.0;   ///< [m/N]
  double pair_stiffness = 0.0;     ///< 1/(c1 + c2 + c_h) [N/m]
  /// 1/(Σ contact_compliance) [N/m]: the FE's own contact flattening instead of Hertz's
  /// constant — a bracket on the pair stiffness, not the energy method's definition.
  double pair_stiffness_fe_contact = 0.0;
};

struct FeToothResult {
  std::vector<FePosition> positions;
  ContactPath path;
  std::array<GearRadii, 2> radii;
  std::array<double, 2> bore_radius{};
  std::array<std::size_t, 2> initial_cells{};
  bool converged = true;           ///< every solve met the tolerance
  std::string message;             ///< which solves missed it, or that none did
  std::string vtu;
  double seconds = 0.0;
  /// The options as given and as used: the bore radii filled in where the case gave none.
  FeToothOptions options_given, options_used;

  /// One line: positions, elements, status, largest mesh, time.
  [[nodiscard]] std::string summary() const;
};

class FeToothStiffness {
 public:
  /// Generates both teeth and meshes both gears (once; every position reuses the meshes).
  FeToothStiffness(const model::GearPair& pair, const std::array<model::Material, 2>& materials,
                   FeToothOptions options);

  /// Compliance of gear `gear`'s tooth with the contact at path position s (from T1); with
  /// field_spacing > 0 [m] the solution is also sampled over the loaded tooth (fe.field).
  /// `healthy`: this tooth's uncracked result at s if already solved (a crack-length sweep),
  /// which spares the cracked tooth its healthy companion solve.
  [[nodiscard]] ToothCompliance tooth_compliance(int gear, double s, bool vtu = false, double field_spacing = 0.0,
                                                 const ToothCompliance* healthy = nullptr) const;
  /// Both teeth and the pair at s.
  [[nodiscard]] FePosition at(double s, bool vtu = false) const;
  /// The given positions (s from T1 [m]).
  [[nodiscard]] FeToothResult solve(const std::vector<double>& positions) const;
  /// options.positions equally spaced along A..E.
  [[nodiscard]] FeToothResult solve() const;

  [[nodiscard]] const ContactPath& path() const { return path_; }
  [[nodiscard]] const ToothOutline& tooth(int gear) const { return teeth_[static_cast<std::size_t>(gear)]; }
  /// The slit of the cracked gear's loaded tooth (tooth coordinates), if any.
  [[nodiscard]] const std::optional<Slit>& slit(int gear) const { return slits_[static_cast<std::size_t>(gear)]; }

 private:
  model::GearPair pair_;
  std::array<model::Material, 2> materials_;
  FeToothOptions options_;
  ContactPath path_;
  std::array<ToothOutline, 2> teeth_;
  std::array<double, 2> bore_{};
  std::array<QuadMesh, 2> meshes_;
  std::array<std::optional<Slit>, 2> slits_;
  std::array<QuadMesh, 2> slit_meshes_;  ///< the cracked gear's mesh with the slit

  [[nodiscard]] ToothCompliance solve_tooth(int gear, double s, bool vtu, double field_spacing, bool with_slit) const;
  std::array<std::vector<Vec2>, 2> outline_;  ///< dense outline of the loaded tooth ± 1
};

/// Hertz line-contact compliance of two elastic cylinders over face width L (Yang & Sun,
/// J. Mech. Trans. Autom. Des. 107 (1985) 411): 1/k_h = 2/(πL)·Σ (1 − ν²)/E.
double hertz_line_compliance(const model::Material& a, const model::Material& b, double face_width);

}  // namespace gearbench::reference::fe
