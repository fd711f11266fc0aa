#pragma once
// Independent reference for the 12-DOF herringbone dynamics: the equations of
// docs/dynamics-model.md ("12-DOF herringbone model") coded from that page alone (nothing
// from solvers/) and integrated by the classical fixed-step Runge–Kutta method of order 4,
// stepping exactly onto the start and end of every mesh-in impact pulse (where the
// right-hand side has a kink) and onto every sample time.
//
// The mesh excitation of a half (k_m, χ_p, χ_g as functions of the half's clock) is an
// input, as the pair stiffness is for the spur reference: it comes from the stiffness
// solver, which is checked on its own.
#include <array>
#include <functional>
#include <vector>

namespace gearbench::reference {

/// The mesh of one half at one instant of its clock: k_m [N/m] and the friction arms
/// χ_p, χ_g [m] (μ included).
struct HalfMeshValue {
  double k, chi_p, chi_g;
};

struct Herringbone12Parameters {
  double m_p, m_g, I_p, I_g;          ///< one half's blanks [kg, kg·m²]
  double R_p, R_g, beta_b;            ///< base radii [m], base helix angle [rad]
  double k_radial, c_radial;          ///< every half's radial bearings
  double k_axial_p, c_axial_p, k_axial_g, c_axial_g;  ///< axial bearings (pinion: 0 when floating)
  double k_groove, c_groove;          ///< axial coupling of the halves
  double k_twist, c_twist;            ///< torsional coupling of the halves
  double T_p, T_g;                    ///< torques per half [N·m]
  double mean_mesh_stiffness;         ///< k̄ per half [N/m]
  double mesh_damping;                ///< c_m at k̄ [N·s/m]; a half's damping is c_m·k_m/k̄
  double impact_force, impact_duration;  ///< half-sine pulse per mesh cycle and half (0: none)
  double period;                      ///< mesh cycle [s]
  std::array<double, 2> clock_offset; ///< half h's clock is t + clock_offset[h]
  std::function<HalfMeshValue(double)> mesh;  ///< of a half's clock, both halves alike
};

/// q (12) as [y_p, z_p, θ_p, y_g, z_g, θ_g] of the left half, then of the right, followed by q̇.
using Herringbone12State = std::array<double, 24>;

struct Herringbone12Sample {
  double t;
  std::array<double, 2> delta;  ///< δ_h [m]
  std::array<double, 2> force;  ///< F_nh [N]
};

/// dy/dt of the page's equations at t (a pulse acts while its half's clock is within
/// [n·T, n·T + duration)). Throws std::invalid_argument for invalid parameters.
Herringbone12State herringbone12_derivative(const Herringbone12Parameters& p, double t,
                                            const Herringbone12State& y);

/// RK4 from t = 0 to t_end in steps of at most dt, stepping onto every pulse's start and
/// end and onto the samples t = k·sample_every (and t_end). Throws std::invalid_argument for
/// invalid parameters, dt ≤ 0, sample_every ≤ 0 or t_end < 0.
std::vector<Herringbone12Sample> herringbone12_rk4(const Herringbone12Parameters& p, const Herringbone12State& y0,
                                                   double t_end, double dt, double sample_every);

}  // namespace gearbench::reference
