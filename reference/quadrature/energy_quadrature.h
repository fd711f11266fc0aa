#pragma once
// Independent reference for the energy-method tooth model of docs/stiffness-model.md.
//
// The production solver integrates along the tooth axis x; this reference integrates each
// part of the beam in its own natural parameter instead: the involute in Tian's pressure
// angle α (dx = R_b(α + α_2)·cos α dα), the circular-arc fillet in its arc angle φ, the
// generated trochoid fillet in the gear's roll angle φ (trochoid_fillet.h) and the
// straight section in x. Every integral is GSL's adaptive gsl_integration_qagp with break
// points where the crack makes the integrand kink or jump, to a relative error of 1e-10;
// every root (the involute at a given radius, x or h) is GSL's Brent bracketing to 1e-14 rad.
#include <array>

#include "model/gear_pair.h"
#include "model/materials.h"

namespace gearbench::reference {

/// Where the cantilever beam starts (spec, "Where the beam starts"): `circular_arc` and
/// `trochoid` are the spec's `improved` beam with each of its two fillets.
enum class QuadBeamStart { base_circle, circular_arc, trochoid, straight };

/// A straight crack through the face width (spec, "Cracks").
struct QuadCrack {
  enum class Type { none, pitch, root } type = Type::none;
  double length = 0;  ///< q [m]
  double angle = 0;   ///< ν, between the crack and the tooth centre line [rad]
};

/// Tooth compliances 1/k [m/N] over the face width L (spec, "Energies and compliances").
struct QuadCompliance {
  double bending = 0, shear = 0, axial = 0;
};

/// The path of contact, computed here (positions from T1 along the line of action).
struct QuadContactPath {
  double line_of_action_length = 0;        ///< T1T2 = a·sin α_wt [m]
  double pitch_point = 0;                  ///< T1C [m]
  std::array<double, 2> tip_roll_angle{};  ///< ψ_a of pinion and wheel [rad]
  double start = 0;                        ///< A = T1T2 − R_b2·ψ_a2, the wheel's tip [m]
  double end = 0;                          ///< E = R_b1·ψ_a1, the pinion's tip [m]
};

/// Tooth compliance of gear `gear` (0 = pinion, 1 = wheel) when the pair is in contact at
/// distance s [m] from T1 along the line of action, for a slice of face width L [m].
/// Throws std::invalid_argument for bad arguments, std::domain_error when the load lies
/// outside the flank or the crack cuts a section through, std::runtime_error when GSL fails.
QuadCompliance energy_compliance_quadrature(const model::GearPair& pair,
                                            const model::Material& material, int gear, double s,
                                            QuadBeamStart start, const QuadCrack& crack,
                                            double face_width);

/// Hertz compliance 1/k_h = 2/(π L)·[(1 − ν1²)/E1 + (1 − ν2²)/E2] over the face width L,
/// which is Yang & Sun's k_h = π·E·L/(4(1 − ν²)) for equal materials (spec, "Contact").
double hertz_compliance_quadrature(const model::Material& m1, const model::Material& m2,
                                   double face_width);

/// Where the beam starts and where the load acts, for the fillet-foundation reference.
struct QuadLoadGeometry {
  double x0 = 0, h0 = 0;      ///< beam start (on the root circle, or where the fillets meet)
  double x1 = 0, h1 = 0;      ///< load point on the flank
  double alpha1 = 0;          ///< load angle α_1 [rad]
};
QuadLoadGeometry load_geometry_quadrature(const model::GearPair& pair, int gear, double s,
                                          QuadBeamStart start);

/// T1T2, T1C (from reference/closed_form) and the tip roll limits, found as the involute's
/// crossing of the tip circle by Brent's method.
QuadContactPath contact_path_quadrature(const model::GearPair& pair);

}  // namespace gearbench::reference
