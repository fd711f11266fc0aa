#pragma once
// Closed forms and a GSL quadrature for the mesh loss of a gear pair, from the model data
// alone (no solver code): Ohlendorf's loss factor, the AGMA 6011 estimate of seed 000, and
// the spur loss integral under Ohlendorf's load sharing.
#include "model/gear_pair.h"
#include "model/materials.h"

namespace gearbench::reference {

struct OhlendorfLossFactor {
  double H_V = 0.0;          ///< π(u + 1)/(z1·u·cos β_b)·(1 − ε_α + ε1² + ε2²)
  double eps_alpha = 0.0;    ///< ε_α
  double eps_1 = 0.0;        ///< pinion addendum contact ratio (C..E)/p_bt
  double eps_2 = 0.0;        ///< wheel addendum contact ratio (A..C)/p_bt
};

/// Ohlendorf (1958), as quoted by ISO/TR 14179-2 and Niemann & Winter II §21.8: the mean
/// sliding loss with constant μ is μ·H_V·P_in when the whole load sits on the single pair
/// and half on each pair in double contact.
OhlendorfLossFactor ohlendorf_loss_factor(const model::GearPair& pair);

/// Seed 000 eq. 13 (after ANSI/AGMA 6011): η = 1 − (22 − 0.8·α)·0.02·(z1 + z2)/(z1·z2),
/// α in degrees. Which pressure angle enters is not stated unambiguously by the seed.
double agma6011_efficiency(int z1, int z2, double pressure_angle_deg);

/// ISO/TR 14179-2:2001 (Schlenk) mean coefficient from the model data alone:
///   μ_mZ = 0.048·[(F_bt/b)/(v_ΣC·ρ_redC)]^0.2·η_oil^−0.05·Ra^0.25·X_L
/// with F_bt = T1/r_b1 over the whole face width [N/mm], v_ΣC = 2·v_t·sin α_wt (v_t the
/// pitch-line speed) [m/s], ρ_redC = T1C·T2C/(T1T2·cos β_b) [mm], η_oil [mPa·s], Ra the mean
/// of the flanks [µm]. With Ohlendorf's H_V the standard's mesh loss is P_VZP = μ_mZ·H_V·P_in.
double iso14179_mean_coefficient(const model::GearPair& pair, const model::OperatingPoint& operating,
                                 const model::Lubricant& lubricant, double lubricant_factor = 1.0);

/// Spur pair, constant μ, Ohlendorf's sharing: the mean sliding loss over μ·P_in from
///   (u + 1)/(u·r_b1·p_bt)·∫_A^E X(s)·|s − C| ds,   X = ½ on A..B and D..E, 1 on B..D,
/// integrated by GSL qagp with break points B, C, D to 1e-12 (|u1 − u2| = ω1(1 + 1/u)|s − C|).
double spur_loss_factor_quadrature(const model::GearPair& pair);

}  // namespace gearbench::reference
