// The flow across one thermal-EHL film column (solvers/ehl/column_flow.h), unit tier: the
// Ree–Eyring law against its defining formula, the Eyring column against the closed form of
// a uniform Couette film, the column's own consistency (no slip, linear stress) with pressure
// flow and a viscosity that varies across the film, and the Newtonian limit τ0 → ∞.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ehl/column_flow.h"
#include "lubricant/rheology.h"

namespace gearbench::ehl {
namespace {

std::vector<double> nodes(int n) {
  std::vector<double> z(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) z[static_cast<std::size_t>(j)] = static_cast<double>(j) / (n - 1);
  return z;
}

/// A hot mid-film: the viscosity falls by a factor 50 from the walls to the middle.
std::vector<double> hot_core(const std::vector<double>& z, double wall) {
  std::vector<double> eta;
  for (double s : z) eta.push_back(wall * std::exp(-4.0 * std::log(50.0) * s * (1.0 - s)));
  return eta;
}

// τ = τ0·asinh(η·γ̇/τ0) inverts γ̇ = (τ0/η)·sinh(τ/τ0), to rounding; the equivalent viscosity
// is τ/γ̇, η itself at τ = 0, and falls with the stress.
TEST(EyringLaw, InvertsTheSinhLawAndThins) {
  const double eta = 200.0, tau0 = 5e6;
  for (double tau : {-3e7, -1e5, 1e3, 2e6, 4e7}) {
    const double rate = lubricant::eyring_shear_rate(tau, eta, tau0);
    EXPECT_NEAR(tau0 * std::asinh(eta * rate / tau0) / tau, 1.0, 1e-13);
    EXPECT_NEAR(lubricant::eyring_equivalent_viscosity(tau, eta, tau0) * rate / tau, 1.0, 1e-13);
  }
  EXPECT_EQ(lubricant::eyring_equivalent_viscosity(0.0, eta, tau0), eta);
  EXPECT_LT(lubricant::eyring_equivalent_viscosity(4e7, eta, tau0), lubricant::eyring_equivalent_viscosity(2e6, eta, tau0));
}

// Uniform viscosity, no pressure gradient: the stress is uniform and equals the closed form
// τ0·asinh(η(U_b − U_a)/(h τ0)); the velocity is linear between the walls.
TEST(ColumnFlow, EyringCouetteFilmMatchesTheClosedForm) {
  const auto z = nodes(10);
  const double eta = 5e3, tau0 = 5e6, h = 5e-7, Ua = 2.5, Ub = 1.5;
  const auto c = column_flow(z, std::vector<double>(z.size(), eta), std::vector<double>(z.size(), 870.0), Ua, Ub, 0.0,
                             h, tau0);
  const double exact = tau0 * std::asinh(eta * (Ub - Ua) / (h * tau0));
  for (std::size_t j = 0; j < z.size(); ++j) {
    EXPECT_NEAR(c.stress[j] / exact, 1.0, 1e-12) << j;
    EXPECT_NEAR(c.u[j], Ua + (Ub - Ua) * z[j], 1e-12) << j;
  }
  EXPECT_LT(std::abs(exact), eta * std::abs(Ub - Ua) / h);  // shear thinning
}

// Pressure flow and a hot core: the stress is linear across the film, τ_a + p_x·h·ζ (momentum),
// the velocity meets both walls (no slip), and each node obeys the Eyring law.
TEST(ColumnFlow, EyringColumnIsConsistent) {
  const auto z = nodes(10);
  const auto eta = hot_core(z, 1e4);
  const double tau0 = 5e6, h = 6e-7, dpdx = -4e13, Ua = 3.0, Ub = 1.0;
  const auto c = column_flow(z, eta, std::vector<double>(z.size(), 870.0), Ua, Ub, dpdx, h, tau0);
  EXPECT_NEAR(c.u.front(), Ua, 1e-12);
  EXPECT_NEAR(c.u.back(), Ub, 1e-9);
  const double scale = std::abs(c.stress.front()) + std::abs(dpdx * h);
  for (std::size_t j = 0; j < z.size(); ++j) {
    EXPECT_NEAR(c.stress[j], c.stress.front() + dpdx * h * z[j], 1e-9 * scale) << j;
    EXPECT_NEAR(c.shear_rate[j] / lubricant::eyring_shear_rate(c.stress[j], eta[j], tau0), 1.0, 1e-9) << j;
  }
  EXPECT_NEAR(eyring_wall_stress(z, eta, Ub - Ua, dpdx, h, tau0) / c.stress.front(), 1.0, 1e-12);
}

// τ0 → ∞: the Eyring column tends to the Newtonian one as the model says, η*/η − 1 ≈ −s²/6
// with s = τ/τ0, so the wall-stress difference falls 100-fold per decade of τ0 (held to
// 100 ± 5 %: the next term is O(s⁴)), and at τ0 = 1e14 Pa (s ≈ 3e-4 for these 3e10 Pa Newtonian
// stresses) every figure agrees to 1e-7.
TEST(ColumnFlow, EyringTendsToNewtonian) {
  const auto z = nodes(10);
  const auto eta = hot_core(z, 1e4);
  const std::vector<double> rho(z.size(), 870.0);
  const auto newtonian = column_flow(z, eta, rho, 3.0, 1.0, -4e13, 6e-7, std::nullopt);
  auto wall_gap = [&](double tau0) {
    return std::abs(column_flow(z, eta, rho, 3.0, 1.0, -4e13, 6e-7, tau0).stress.front() / newtonian.stress.front() - 1.0);
  };
  EXPECT_NEAR(wall_gap(1e12) / wall_gap(1e13), 100.0, 5.0);
  const auto eyring = column_flow(z, eta, rho, 3.0, 1.0, -4e13, 6e-7, 1e14);
  EXPECT_NEAR(eyring.rho_over_eta_e() / newtonian.rho_over_eta_e(), 1.0, 1e-7);
  EXPECT_NEAR(eyring.rho_star(3.0, 1.0) / newtonian.rho_star(3.0, 1.0), 1.0, 1e-7);
  for (std::size_t j = 0; j < z.size(); ++j) {
    EXPECT_NEAR(eyring.stress[j] / newtonian.stress.front(), newtonian.stress[j] / newtonian.stress.front(), 1e-7);
    EXPECT_NEAR(eyring.u[j], newtonian.u[j], 1e-7 * 3.0);
    EXPECT_EQ(newtonian.stress[j], newtonian.eta_star[j] * newtonian.shear_rate[j]);
  }
}

// Shear thinning raises the Poiseuille coefficient (ρ/η)_e of a sliding column: the film
// conducts pressure flow through a thinned, less viscous oil.
TEST(ColumnFlow, EyringThinsThePoiseuilleCoefficient) {
  const auto z = nodes(10);
  const auto eta = hot_core(z, 1e4);
  const std::vector<double> rho(z.size(), 870.0);
  const auto newtonian = column_flow(z, eta, rho, 3.0, 1.0, -4e13, 6e-7, std::nullopt);
  const auto eyring = column_flow(z, eta, rho, 3.0, 1.0, -4e13, 6e-7, 5e6);
  EXPECT_GT(eyring.rho_over_eta_e(), 10.0 * newtonian.rho_over_eta_e());
  EXPECT_LT(std::abs(eyring.stress.front()), std::abs(newtonian.stress.front()));
}

}  // namespace
}  // namespace gearbench::ehl
