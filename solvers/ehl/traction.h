#pragma once
// Traction of a solved isothermal line contact with an Eyring limiting-shear fluid (Eyring
// 1936; as used for EHL traction by Johnson & Tevaarwerk, Proc. R. Soc. A 356 (1977) 215,
// and Evans & Johnson, Proc. IMechE C 200 (1986) 313): the film and pressure come from the
// Newtonian solution (the inlet, which sets the film, is Newtonian), and in the contact the
// shear stress follows τ = τ0·asinh(τ_N/τ0) of the Newtonian stress
// τ_N = η(p)·(u2 − u1)/h − (h/2)·dp/dx on surface 1. τ0 → ∞ gives back the Newtonian traction.
#include "fas_multigrid.h"

namespace gearbench::ehl {

struct Traction {
  double force_per_length = 0.0;  ///< ∫τ dx on surface 1 [N/m]
  double coefficient = 0.0;       ///< force / w
};

/// Eyring traction of the solution `r` of `problem`, with the Eyring stress τ0 [Pa] > 0;
/// only where the film is pressurised (the cavitated film carries no full-film shear).
Traction eyring_traction(const LineContactProblem& problem, const EhlResult& r, double eyring_stress);

}  // namespace gearbench::ehl
