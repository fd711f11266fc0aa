#pragma once
// Closed-form film thickness at a contact point of the mesh, for the specific film
// thickness λ of the mixed friction law and for the rolling loss.
#include <array>

#include "model/materials.h"

namespace gearbench::efficiency {

/// E′ = 2/((1 − ν1²)/E1 + (1 − ν2²)/E2) [Pa] (Dowson & Higginson's reduced modulus).
double reduced_modulus(const std::array<model::Material, 2>& materials);

/// Maximum Hertz pressure of a line contact, p_h = √(w·E′/(2πR)) [Pa] (Johnson, Contact
/// Mechanics, 1985, §4.3, with E′ as above).
double hertz_line_pressure(double load_per_length, double reduced_radius, double reduced_modulus);

/// Dowson–Higginson minimum film of an isothermal line contact (Dowson & Higginson,
/// Elasto-hydrodynamic Lubrication, 1977; REFERENCE-FACTS):
///   h_min = 2.65·R·U^0.70·G^0.54·W^−0.13,  U = η0·ū/(E′R),  G = α·E′,  W = w/(E′R),
/// ū = (u1 + u2)/2, w the load per unit length [N/m]. Returns metres.
double dowson_higginson_min_film(double load_per_length, double reduced_radius, double entrainment,
                                 double viscosity, double pressure_viscosity, double reduced_modulus);

}  // namespace gearbench::efficiency
