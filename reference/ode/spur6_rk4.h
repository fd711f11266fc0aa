#pragma once
// Independent reference for the 6-DOF spur-pair dynamics: the equations of
// docs/dynamics-model.md coded from that page alone (nothing from solvers/, not even
// solvers/model) and integrated by the classical fixed-step Runge–Kutta method of order 4.
//
// The right-hand side is discontinuous where a pair enters (s = A) or leaves (s = E) the
// path of contact, and where a pair passes the pitch point C (the friction sign λ_j flips).
// As the page's section "Mesh" asks, spur6_rk4 steps exactly onto all of these times; it
// integrates every interval between two of them with the pair set of the interval's
// midpoint, so the right-hand side is smooth on each step and the method keeps order 4.
//
// With backlash (the page's section "Contact loss") the flanks push in one of three contact
// modes (working flanks, none, back flanks); the mode holds over every step, and a step in
// which it changes is cut where it changes, the point located by bisection of the step
// length (RK4's own event location, nothing from CVODE).
//
// SI units throughout; positions on the line of action are distances from T1.

#include <array>
#include <functional>
#include <optional>
#include <vector>

namespace gearbench::reference {

/// The plain parameters of the page's model (sections "Degrees of freedom and parameters",
/// "Mesh", "Friction").
struct Spur6Parameters {
  double m1, m2, I1, I2;          ///< masses [kg] and polar inertias [kg·m²]
  double rb1, rb2;                ///< base radii R_b1, R_b2 [m]
  double k1, k2, c1, c2;          ///< bearing stiffness [N/m] and damping [N·s/m], x and y
  double T1;                      ///< input torque [N·m]; the load T2 follows from the page's section "Loads"
  double mu;                      ///< friction coefficient μ
  double zeta_mesh;               ///< mesh damping ratio ζ_m
  double mean_mesh_stiffness;     ///< k̄ [N/m]
  double A, C, E, T1T2, pbt;      ///< path of contact from T1 [m]; base pitch p_bt [m]
  double contact_speed;           ///< u = ω1·R_b1 [m/s]
  std::function<double(double)> pair_stiffness;  ///< k_pair(s) [N/m] for A ≤ s ≤ E
  /// Backlash b [m] of the page's section "Contact loss"; 0: the linear mesh (contact is never lost).
  double backlash = 0.0;
  /// The page's Benedict–Kelley law (section "Friction laws") in place of the constant μ.
  struct BenedictKelley {
    double viscosity;     ///< η0 [Pa·s]
    double roughness_Ra;  ///< mean Ra of the flanks [m]
    double face_width;    ///< b [m]: the pair's load per length is F_j/b
  };
  std::optional<BenedictKelley> benedict_kelley;
};

/// μ of the page's Benedict–Kelley law at s [m from T1] under w [N/m] for these parameters
/// (nominal surface speeds u1 = ω1·s, u2 = ω2·(T1T2 − s)). Throws std::invalid_argument
/// without `benedict_kelley`.
double spur6_benedict_kelley(const Spur6Parameters& p, double s, double load_per_length);

/// q = [x1, y1, θ1, x2, y2, θ2] followed by q̇ (θ as deviations from the nominal rotation).
using Spur6State = std::array<double, 12>;

/// The page's initial state (section "Initial state"): static deflection δ0 = F̄/k̄ under
/// the quasi-static force F̄ of section "Loads", bearings deflected by ∓F̄/k_i, θ2 = 0, all
/// rates zero. Throws
/// std::invalid_argument for invalid parameters or non-positive bearing stiffness.
Spur6State spur6_static_state(const Spur6Parameters& p);

/// The page's section "Loads": the quasi-static mesh force F̄ = T1/(R_b1 + ā1) [N] and the
/// load torque T2 = F̄·(R_b2 + ā2) [N·m].
struct Spur6Loads {
  double force;
  double T2;
};
Spur6Loads spur6_loads(const Spur6Parameters& p);

/// dy/dt = [q̇, q̈] of the page's equations of motion at time t, with the pairs in contact at t
/// exactly as the page defines them (s_j = A + mod(u·t, p_bt) + j·p_bt ≤ E). Throws
/// std::invalid_argument for invalid parameters.
Spur6State spur6_derivative(const Spur6Parameters& p, double t, const Spur6State& y);
/// The same with the loads computed once by the caller.
Spur6State spur6_derivative(const Spur6Parameters& p, const Spur6Loads& loads, double t, const Spur6State& y);

/// One recorded state with the mesh quantities at that instant (page's pair set at t).
struct Spur6Sample {
  double t;
  Spur6State y;
  double mesh_force;          ///< F_m = Σ F_j [N]
  double friction_force;      ///< F_f = Σ μ·λ_j·F_j, on the wheel along y [N]
  double transmission_error;  ///< δ [m]
  int contact;                ///< +1 working flanks, 0 none, −1 back flanks
};

/// Classical RK4 from t = 0 to t_end with steps of at most dt (up to a relative 1e-9, so
/// an interval that is a whole number of steps in exact arithmetic is not split into one
/// more), stepping exactly onto every switch time (see the top of this file) and onto every
/// sample time. Samples are taken at t = k·sample_every ≤ t_end and at t_end. Throws
/// std::invalid_argument for invalid parameters, dt ≤ 0, sample_every ≤ 0 or t_end < 0.
std::vector<Spur6Sample> spur6_rk4(const Spur6Parameters& p, const Spur6State& y0,
                                   double t_end, double dt, double sample_every);

}  // namespace gearbench::reference
