#pragma once
// The independent references' plain parameters from a production dynamics model, for the
// checks and the unit tests alike. The mesh excitation (pair stiffness; a half's k_m and
// friction arms) is the shared input, checked on its own; the equations are not shared.
#include "dynamics/herringbone12_dynamics.h"
#include "dynamics/spur6_dynamics.h"
#include "ode/herringbone12_rk4.h"
#include "ode/spur6_rk4.h"

namespace gearbench::verification {

/// `d` must outlive the result (its pair stiffness is called).
inline reference::Spur6Parameters spur6_reference(const dynamics::Spur6Dynamics& d) {
  const auto& p = d.parameters();
  reference::Spur6Parameters r{};
  r.m1 = p.m1;
  r.m2 = p.m2;
  r.I1 = p.I1;
  r.I2 = p.I2;
  r.rb1 = p.rb1;
  r.rb2 = p.rb2;
  r.k1 = r.k2 = p.k_bearing;
  r.c1 = r.c2 = p.c_bearing;
  r.T1 = p.T1;
  r.mu = p.mu;
  r.zeta_mesh = p.zeta_mesh;
  r.mean_mesh_stiffness = p.mean_mesh_stiffness;
  r.A = p.A;
  r.C = p.C;
  r.E = p.E;
  r.T1T2 = p.T1T2;
  r.pbt = p.pbt;
  r.contact_speed = p.contact_speed;
  r.pair_stiffness = [&d](double s) { return d.mesh_excitation().pair_stiffness(s); };
  r.backlash = p.backlash;
  return r;
}

/// `d` must outlive the result (its half mesh is called).
inline reference::Herringbone12Parameters herringbone_reference(const dynamics::Herringbone12Dynamics& d) {
  const auto& p = d.parameters();
  const auto& mesh = d.mesh();
  return {p.m_p, p.m_g, p.I_p, p.I_g, p.R_p, p.R_g, p.beta_b, p.k_radial, p.c_radial, p.k_axial_p, p.c_axial_p,
          p.k_axial_g, p.c_axial_g, p.k_groove, p.c_groove, p.k_twist, p.c_twist, p.T_p, p.T_g,
          p.mean_mesh_stiffness, p.mesh_damping, p.impact_force, p.impact_duration, p.period, p.clock_offset,
          [&mesh](double tau) {
            const auto m = mesh.at(tau, tau);
            return reference::HalfMeshValue{m.stiffness, m.chi_pinion, m.chi_wheel};
          }};
}

}  // namespace gearbench::verification
