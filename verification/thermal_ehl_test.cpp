// Thermal EHL (issue #4), unit tier: the temperature-dependent rheology against its defining
// formulas, the film temperature solver's isothermal limit, and the heat balance of one
// sliding contact on a small grid. The physics checks (trends, grid convergence, Gupta's
// band, seed 001) are in verification/checks/tehl_checks.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ehl/film_temperature.h"
#include "ehl/thermal_line_contact.h"
#include "ehl/traction.h"
#include "lubricant/rheology.h"
#include "lubricant/thermal_rheology.h"
#include "model/errors.h"
#include "support/thermal_fixtures.h"

namespace gearbench::ehl {
namespace {

constexpr double T0 = 313.15;  // inlet temperature [K]

model::ThermalLubricant roelands_oil() { return testing_support::mineral_oil(); }

model::ThermalLubricant walther_oil() {
  auto d = roelands_oil();
  d.viscosity = 0.0;
  d.temperature_viscosity = 0.0;
  d.nu40 = 320e-6;
  d.nu100 = 24e-6;
  return d;
}

model::ThermalSolids steel() { return testing_support::steel_solids(); }

LineContactData contact(double u1, double u2) {
  auto c = testing_support::sliding_contact(0.0);
  c.u1 = u1;
  c.u2 = u2;
  return c;
}

ThermalEhlOptions small_grid() {
  ThermalEhlOptions o;
  o.grid.nodes = 161;  // the unit tier also runs under ASan
  return o;
}

/// The mineral oil with a Ree–Eyring stress of 5 MPa, and its film's options on `nodes`.
model::ThermalLubricant eyring_oil() {
  auto d = roelands_oil();
  d.eyring_stress = 5e6;
  return d;
}
ThermalEhlOptions eyring_film(int nodes) {
  ThermalEhlOptions o;
  o.grid.nodes = nodes;
  o.film.rheology = lubricant::ShearRheology::eyring;
  return o;
}

// Ubbelohde–Walther through its two defining points, to rounding (the law is fitted to them).
TEST(ThermalRheology, WaltherPassesThroughNu40AndNu100) {
  const lubricant::ThermalRheology r(walther_oil(), T0);
  EXPECT_NEAR(r.walther_kinematic_viscosity(313.15) / 320e-6, 1.0, 1e-12);
  EXPECT_NEAR(r.walther_kinematic_viscosity(373.15) / 24e-6, 1.0, 1e-12);
  // η(0, T0) = ρ(T0)·ν(T0) with the ISO density law ρ15 − 0.7·(T − 15 °C).
  const double rho = 870.0 - 0.7 * (313.15 - 288.15);
  EXPECT_NEAR(r.inlet_viscosity(), rho * 320e-6, 1e-12);
}

// At the inlet temperature both forms reduce to the isothermal Roelands law of the solver,
// so the thermal factors are exactly 1 in an isothermal film.
TEST(ThermalRheology, ReducesToIsothermalRoelandsAtInletTemperature) {
  for (const auto& data : {roelands_oil(), walther_oil()}) {
    const lubricant::ThermalRheology r(data, T0);
    for (double p : {0.0, 0.3e9, 1.0e9, 2.0e9}) {
      const double isothermal = lubricant::roelands_viscosity(r.inlet_viscosity(), r.roelands_z(), p);
      EXPECT_NEAR(r.viscosity(p, T0) / isothermal, 1.0, 1e-13) << p;
      EXPECT_NEAR(r.density(p, T0) / r.density(0.0, T0),
                  lubricant::dowson_higginson_density_ratio(p), 1e-14);
    }
  }
}

// The Roelands temperature term: d ln η/dT at p = 0 equals −β (S0 is defined so).
TEST(ThermalRheology, RoelandsTemperatureSlopeIsBeta) {
  const lubricant::ThermalRheology r(roelands_oil(), T0);
  const double T = 313.15, dT = 1e-4;
  const double slope = (std::log(r.viscosity(0.0, T + dT)) - std::log(r.viscosity(0.0, T - dT))) / (2 * dT);
  EXPECT_NEAR(slope, -0.03, 1e-8);
  EXPECT_LT(r.viscosity(1e9, 353.15), r.viscosity(1e9, 313.15));
  EXPECT_NEAR(r.thermal_expansion(0.0, T), -0.7 / (870.0 - 0.7 * 25.0), 1e-15);
}

// The temperature sweeps take η at a column's cached pressure factor and ∂ln η/∂T
// analytically: the same η as viscosity(p, T), and the slope a central difference gives.
TEST(ThermalRheology, AtPressureMatchesViscosityAndItsTemperatureSlope) {
  for (const auto& data : {roelands_oil(), walther_oil()}) {
    const lubricant::ThermalRheology r(data, T0);
    for (double p : {0.0, 2e8, 1e9})
      for (double T : {T0, T0 + 30.0, T0 + 150.0}) {
        const auto at_p = r.at_pressure(p);
        double slope = 0.0;
        EXPECT_EQ(at_p.viscosity(T, &slope), r.viscosity(p, T));
        const double dT = 1e-3;
        const double fd = (std::log(r.viscosity(p, T + dT)) - std::log(r.viscosity(p, T - dT))) / (2.0 * dT);
        EXPECT_NEAR(slope, fd, 1e-6 * std::abs(fd)) << "p " << p << " T " << T;
      }
  }
}

TEST(ThermalRheology, RejectsUnphysicalData) {
  auto d = walther_oil();
  d.nu100 = 400e-6;
  EXPECT_THROW((lubricant::ThermalRheology{d, T0}), InputError);
  d = roelands_oil();
  d.thermal_conductivity = 0.0;
  EXPECT_THROW((lubricant::ThermalRheology{d, T0}), InputError);
  // Below the Roelands pole (138 K) plus a margin.
  EXPECT_THROW((lubricant::ThermalRheology{roelands_oil(), 150.0}), InputError);
}

// Heat sources off: the energy equation has T = T0 as its exact solution, the film integrals
// (Simpson, exact for the quadratic ζ-profiles of a uniform film) give factors of exactly 1,
// and the thermal solution equals the isothermal one to the multigrid tolerance (1e-8 on the
// scaled residual; 1e-6 relative on the figures leaves room for the re-solve from a warm start).
TEST(ThermalLineContact, WithoutHeatSourcesEqualsIsothermal) {
  const lubricant::ThermalRheology rheology(roelands_oil(), T0);
  auto o = small_grid();
  o.film.shear_heating = false;
  o.film.compression = false;
  const auto r = ThermalLineContact(contact(2.5, 1.5), rheology, steel(), o).solve();
  EXPECT_LT(std::abs(r.temperature_rise_max), 1e-9);
  EXPECT_NEAR(r.h_min / r.isothermal_h_min, 1.0, 1e-6);
  EXPECT_NEAR(r.p_max / r.isothermal_p_max, 1.0, 1e-6);
  EXPECT_NEAR(r.friction_coefficient / r.isothermal_friction_coefficient, 1.0, 1e-6);
}

// Energy balance of a sliding contact (SRR 0.5): heat generated in the film = heat carried
// out by the film and both solids + heat lost through the depth d. First-order upwinding in
// x and the non-conservative convection form make the discrete balance inexact by O(Δx):
// measured 0.4 % at 161–641 nodes; 2 % leaves room without hiding a missing term (the
// smallest term, the film outflow, is 0.7 % of the total).
TEST(ThermalLineContact, HeatBalanceCloses) {
  const lubricant::ThermalRheology rheology(roelands_oil(), T0);
  const auto r = ThermalLineContact(contact(2.5, 1.5), rheology, steel(), small_grid()).solve();
  ASSERT_GT(r.heat.generated(), 0.0);
  EXPECT_NEAR(r.heat.removed() / r.heat.generated(), 1.0, 0.02);
  EXPECT_GT(r.temperature_rise_max, 10.0);
  EXPECT_LT(r.h_min, r.isothermal_h_min);
}

// Nested iteration (issue 26) changes the start, not the solution: the sliding contact's Eyring
// film on 161 nodes (the unit tier also runs under ASan), nested on 81 and from the isothermal
// start, both stopped at the tolerances. Each stop
// leaves h_min within about 3e-5 of the fixed point (film_tolerance 1e-5 on the estimated
// remaining error, whose known miss on the Eyring roller is 2.6e-5: docs/thermal-ehl-model.md),
// so the two agree within 1e-4; measured 1e-6.
TEST(ThermalLineContact, NestedStartReachesTheSameSolution) {
  const lubricant::ThermalRheology rheology(eyring_oil(), T0);
  ThermalEhlOptions o = eyring_film(161);
  o.stop = CouplingStop::tolerance;
  o.nested_above_nodes = 81;
  const auto nested = ThermalLineContact(contact(2.5, 1.5), rheology, steel(), o).solve();
  o.nested_above_nodes = 161;
  const auto cold = ThermalLineContact(contact(2.5, 1.5), rheology, steel(), o).solve();
  EXPECT_GT(nested.coarse_grid_iterations, 0);
  EXPECT_EQ(cold.coarse_grid_iterations, 0);
  EXPECT_NEAR(nested.h_min / cold.h_min, 1.0, 1e-4);
  EXPECT_NEAR(nested.h_central / cold.h_central, 1.0, 1e-4);
  EXPECT_NEAR(nested.friction_coefficient / cold.friction_coefficient, 1.0, 1e-4);
  // The work of every pressure solve, on both grids, part by part: the parts add up to
  // work_units, the 81-node grid's isothermal start is among them, and there is more than the
  // last solve's work.
  for (const auto* r : {&nested, &cold}) {
    EXPECT_NEAR(r->work_by_part.total(), r->work_units, 1e-12 * r->work_units);
    EXPECT_GT(r->work_by_part.start, 0.0);
    EXPECT_GT(r->work_by_part.relaxation, r->pressure.work_by_part.relaxation);
  }
}

// The discretisation-error stop (issue 26: the coupling stops on the multigrid's rule) ends
// the iteration once h_min is within a tenth of its own discretisation error, estimated from
// the nested grid half as fine: on the Eyring sliding contact (321 nodes nested on 161) its
// h_min agrees with the tolerance rule's (1e-5) within the tolerance it used, and it takes
// fewer iterations. Measured: estimate 0.47 %, tolerance used 4.7e-4, h_min 1.8e-5 apart,
// 11 against 20 iterations.
TEST(ThermalLineContact, StopsAtATenthOfItsDiscretisationError) {
  const lubricant::ThermalRheology rheology(eyring_oil(), T0);
  ThermalEhlOptions o = eyring_film(321);
  const auto rule = ThermalLineContact(contact(2.5, 1.5), rheology, steel(), o).solve();
  o.stop = CouplingStop::tolerance;
  const auto tight = ThermalLineContact(contact(2.5, 1.5), rheology, steel(), o).solve();
  ASSERT_TRUE(rule.h_min_error_estimate.has_value());
  EXPECT_FALSE(tight.h_min_error_estimate.has_value());
  EXPECT_GT(*rule.h_min_error_estimate, 1e-4);  // a 321-node film is not within 0.01 %
  EXPECT_DOUBLE_EQ(rule.film_tolerance_used, o.grid.error_fraction * *rule.h_min_error_estimate);
  EXPECT_DOUBLE_EQ(tight.film_tolerance_used, o.film_tolerance);
  EXPECT_NEAR(rule.h_min / tight.h_min, 1.0, rule.film_tolerance_used);
  EXPECT_LT(rule.iterations, tight.iterations);
}

// The coupling settles to a tolerance far below the default's: the Newtonian sliding contact
// (cases/tehl_point_sliding.json) to 1e-6 of its 70 K rise, its pressure solves to a residual of
// 1e-11. Until the film's cross-film convection took continuous weights (the exponential
// scheme, film_temperature.cpp), an inlet backflow node sitting at the hybrid scheme's switch
// toggled by 5e-4 K with period 3, and this solve stopped unconverged at its 60 iterations
// (measured: 24 now, on 641 nodes 42).
TEST(ThermalLineContact, SettlesFarBelowTheDefaultTolerance) {
  const lubricant::ThermalRheology rheology(roelands_oil(), T0);
  ThermalEhlOptions o;
  o.grid.nodes = 321;
  o.grid.stop = StopRule::residual;
  o.grid.tolerance = 1e-11;
  o.stop = CouplingStop::tolerance;
  o.temperature_tolerance = 1e-6;
  o.film_tolerance = 1e-8;
  const auto r = ThermalLineContact(contact(2.5, 1.5), rheology, steel(), o).try_solve();
  EXPECT_TRUE(r.converged) << r.message;
  EXPECT_LE(r.temperature_change_history.back(), 1e-6 * std::max(10.0, r.temperature_rise_max));
}

// A pressure solve that cannot converge (one cycle to a residual of 1e-14) is a status of
// try_solve, not an exception, from the isothermal start onward; solve() turns it into a
// ConvergenceError that says so.
TEST(ThermalLineContact, UnconvergedStartIsAStatus) {
  const lubricant::ThermalRheology rheology(roelands_oil(), T0);
  auto o = small_grid();
  o.grid.max_cycles = 1;
  o.grid.tolerance = 1e-14;
  const ThermalLineContact contact_solver(contact(2.5, 1.5), rheology, steel(), o);
  ThermalEhlResult r;
  ASSERT_NO_THROW(r = contact_solver.try_solve());
  EXPECT_FALSE(r.converged);
  EXPECT_FALSE(r.pressure.converged);
  EXPECT_EQ(r.iterations, 0);
  try {
    (void)contact_solver.solve();
    ADD_FAILURE() << "no ConvergenceError";
  } catch (const ConvergenceError& e) {
    EXPECT_NE(std::string(e.what()).find("pressure solve NOT converged"), std::string::npos) << e.what();
  }
}

TEST(ThermalLineContact, RejectsBadOptions) {
  const lubricant::ThermalRheology rheology(roelands_oil(), T0);
  auto o = small_grid();
  o.film.film_nodes = 2;
  EXPECT_THROW(ThermalLineContact(contact(2.0, 2.0), rheology, steel(), o).solve(), InputError);
  o = small_grid();
  o.factor_relaxation = 0.0;
  EXPECT_THROW(ThermalLineContact(contact(2.0, 2.0), rheology, steel(), o), InputError);
  o = small_grid();
  o.anderson_depth = -1;
  EXPECT_THROW(ThermalLineContact(contact(2.0, 2.0), rheology, steel(), o), InputError);
  EXPECT_THROW(ThermalLineContact(contact(-1.0, 2.0), rheology, steel(), small_grid()).solve(), InputError);
}

// A Ree–Eyring film (τ0 = 5 MPa) in the same sliding contact: its energy balance closes as the
// Newtonian one does (same discretisation, 2 %), and the stress limit lowers both the traction
// and the heating below the Newtonian film's; rheology "eyring" without an Eyring stress is
// an input error.
TEST(ThermalLineContact, EyringFilmLimitsTractionAndHeating) {
  const lubricant::ThermalRheology rheology(eyring_oil(), T0);
  const auto newtonian = ThermalLineContact(contact(2.5, 1.5), rheology, steel(), small_grid()).solve();
  const auto o = eyring_film(161);
  const auto eyring = ThermalLineContact(contact(2.5, 1.5), rheology, steel(), o).solve();
  EXPECT_EQ(eyring.rheology, lubricant::ShearRheology::eyring);
  EXPECT_NEAR(eyring.heat.removed() / eyring.heat.generated(), 1.0, 0.02);
  EXPECT_LT(std::abs(eyring.friction_coefficient), std::abs(newtonian.friction_coefficient));
  EXPECT_LT(eyring.temperature_rise_max, newtonian.temperature_rise_max);
  EXPECT_GT(eyring.temperature_rise_max, 1.0);
  EXPECT_FALSE(eyring.friction_coefficient_eyring.has_value());  // no post-processing of an Eyring film
  const lubricant::ThermalRheology no_stress(roelands_oil(), T0);
  EXPECT_THROW(ThermalLineContact(contact(2.5, 1.5), no_stress, steel(), o).solve(), InputError);
}

// A column at the outlet spike of a near-rolling Eyring film (0.9 GPa, 0.4 µm, |h·∂p/∂x| 20τ0)
// thins steeply with the gradient, so a temperature sweep takes the gradient that carries the
// pressure solve's Poiseuille flux (ρ/η)·h³·∂p/∂x/12: here a solve whose coefficient is e² of
// the column's at its own gradient, i.e. a flux the column carries only at a steeper gradient.
// Where the column barely thins (a gentle gradient, or a Newtonian film) the pressure's own
// gradient stays.
TEST(FilmTemperature, SteeplyThinningColumnTakesTheGradientThatCarriesTheFlux) {
  const lubricant::ThermalRheology rheology(eyring_oil(), T0);
  std::vector<double> x(5);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = (static_cast<double>(i) - 2.0) * 1e-6;
  FilmTemperatureOptions o;
  o.rheology = lubricant::ShearRheology::eyring;
  const FilmTemperature field(x, 1.0, 1.0, 1e-4, rheology, steel(), o);
  const double p = 0.9e9, h = 0.4e-6, g = -20.0 * 5e6 / h;
  const double own = field.column_flow(2, p, g, h).rho_over_eta_e();
  const double poiseuille = std::exp(2.0) * own;
  const double carried = field.flux_carrying_gradient(2, p, g, h, poiseuille);
  EXPECT_LT(carried, g);  // same sign, steeper
  EXPECT_NEAR(field.column_flow(2, p, carried, h).rho_over_eta_e() * carried / (poiseuille * g), 1.0, 1e-9);
  // A gentle gradient (h·|∂p/∂x| below τ0) and a Newtonian film keep the pressure's own.
  EXPECT_EQ(field.flux_carrying_gradient(2, p, -0.5 * 5e6 / h, h, poiseuille), -0.5 * 5e6 / h);
  FilmTemperatureOptions newtonian;
  const FilmTemperature film(x, 1.0, 1.0, 1e-4, rheology, steel(), newtonian);
  EXPECT_EQ(film.flux_carrying_gradient(2, p, g, h, poiseuille), g);
}

// Eyring traction from a solved film: τ0 → ∞ gives back the solver's Newtonian traction
// (the same integrand, asinh(x) = x + O(x³): 1e-9 relative at τ0 = 1e15 Pa); a finite τ0
// lowers it, the more the smaller τ0 (asinh is concave and odd).
TEST(EyringTraction, ReducesToNewtonianAndFallsWithTheStress) {
  auto d = contact(2.5, 1.5);
  d.viscosity = 0.05;
  d.pressure_viscosity = 20e-9;
  const LineContactProblem problem(d);
  EhlOptions o;
  o.nodes = 161;
  const auto r = LineContactSolver(problem, o).solve();
  EXPECT_NEAR(eyring_traction(problem, r, 1e15).coefficient / r.friction_coefficient, 1.0, 1e-9);
  const double mu10 = std::abs(eyring_traction(problem, r, 10e6).coefficient);
  const double mu5 = std::abs(eyring_traction(problem, r, 5e6).coefficient);
  EXPECT_LT(mu5, mu10);
  EXPECT_LT(mu10, std::abs(r.friction_coefficient));
  EXPECT_GT(mu5, 0.0);
}

}  // namespace
}  // namespace gearbench::ehl
