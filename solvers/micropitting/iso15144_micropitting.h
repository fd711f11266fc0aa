#pragma once
// ISO/TR 15144-1 method B: micropitting safety S_λ of a cylindrical gear pair from the local
// specific film thickness λ_GF,Y = h_Y/Ra at the contact points A, AB, B, C, D, DE, E.
//
// SOURCES AND HOW SURE THEY ARE (read before trusting a number; docs/iso15144.md has more)
// - The TR itself (ISO/TR 15144-1:2014, replacing :2010) was not available in this session.
//   Formula numbers "(n)" below are those of the 2014 edition as cited by a public port of the
//   method (a C# "MechanicalCalculatorWeb" Iso15144Micropitting, found with the search tool);
//   each coefficient was taken from that port and checked for dimensional and physical
//   consistency here (see the .cpp), which is not a confirmation at the source.
// - Seed 001 (its eqs. for ρ(T), the Ubbelohde–Walther law and S_λ = (h/Ra)/(1.4·h_ref/Ra_ref))
//   quotes the 2010 edition; where it and the port agree, both are cited.
// - Unconfirmed, flagged where used: the √cos β_b in p_H,Y (25), the buttressing factor (taken
//   from ISO/TR 13989-1 eqs. (49)–(56) as the port reproduces them), the 273 vs 273.15 K offset
//   of the Walther law, 288 vs 289 K in ρ(θ), and the material factor W_W of λ_GFP.
// Not implemented (InputError): ε_α ≥ 2, helical gears with 0 < ε_β < 1, profile-modified
// load sharing (the unmodified-profile clauses only; X_Ca may still be given).
//
// SI units in and out (m, Pa, K, m/s, m²/s); the TR's mixed units (mm, N/mm², °C, mPa·s, µm)
// live inside the .cpp only. reference/ rule: nothing from solvers/ but solvers/model.
#include <array>
#include <string>

#include "model/gear_pair.h"
#include "model/materials.h"
#include "model/option_table.h"

namespace gearbench::micropitting::iso15144 {

/// Base oil, selecting the pressure–viscosity formula (9)–(11) of the TR.
enum class OilBase { mineral, polyalphaolefin, polyglycol };
/// Lubrication method, selecting X_S of the bulk temperature (84).
enum class LubricationMethod { dip, spray, submerged };

struct Oil {
  double nu40 = 0.0;    ///< kinematic viscosity at 40 °C [m²/s]
  double nu100 = 0.0;   ///< kinematic viscosity at 100 °C [m²/s]
  double rho15 = 0.0;   ///< density at 15 °C [kg/m³]
  OilBase base = OilBase::mineral;
  double lubricant_factor = 1.0;  ///< X_L of the friction coefficient (86)
};

/// Thermal data of one gear body: B_M = √(λ_M·ρ_M·c_M) (82)–(83).
struct Solid {
  double conductivity = 0.0;   ///< λ_M [W/(m·K)]
  double density = 0.0;        ///< ρ_M [kg/m³]
  double specific_heat = 0.0;  ///< c_M [J/(kg·K)]
};

/// One gear pair at one operating point, everything method B needs.
struct Inputs {
  model::GearPair pair;
  std::array<model::Material, 2> materials{};  ///< E, ν per gear
  std::array<Solid, 2> solids{};
  double pinion_speed = 0.0;    ///< ω1 [rad/s]
  double pinion_torque = 0.0;   ///< T1 [N·m]
  double K_A = 1.0, K_v = 1.0, K_Halpha = 1.0, K_Hbeta = 1.0;
  std::array<double, 2> roughness_Ra{};  ///< Ra per flank [m]
  double oil_temperature = 0.0;          ///< θ_oil [K]
  Oil oil;
  LubricationMethod method = LubricationMethod::dip;
  double tip_relief_factor = 1.0;  ///< X_Ca of (84); 1 for unmodified profiles
  int accuracy_grade = 7;          ///< Q of the spur load sharing (46)–(48); ≤ 7 counts as 7
  bool buttressing = true;         ///< X_but at A and E of helical gears
  std::string operating_section = "operating";  ///< where speed, torque, Ra, θ_oil were read
  /// The keys of the "micropitting" section that these inputs hold (K factors, lubrication,
  /// X_Ca, accuracy grade, buttressing, oil), as a case gives them (iso15144_case.cpp).
  static const model::OptionTable<Inputs>& table();
  /// Throws InputError naming the case key (as in the "micropitting" section), the value and
  /// the allowed range: the table's ranges, then what the method needs of the other sections.
  void validate() const;
};

/// Figures at one contact point Y.
struct PointResult {
  std::string name;            ///< A, AB, B, C, D, DE, E
  double position = 0.0;       ///< distance from T1 along the line of action [m]
  double rho1 = 0.0, rho2 = 0.0;  ///< transverse radii of curvature [m]
  double rho_n = 0.0;          ///< normal relative radius ρ_n,Y [m]
  double buttressing = 1.0;    ///< X_but,Y
  double load_share = 0.0;     ///< X_Y
  double p_dyn = 0.0;          ///< local Hertzian pressure with K factors [Pa]
  double v_r1 = 0.0, v_r2 = 0.0;  ///< tangential speeds [m/s]
  double v_sum = 0.0;          ///< v_Σ,Y [m/s]
  double v_g = 0.0;            ///< sliding speed |v_r1 − v_r2| [m/s]
  double flash_temperature = 0.0;    ///< θ_fl,Y [K]
  double contact_temperature = 0.0;  ///< θ_B,Y [K]
  double nu_B = 0.0, rho_B = 0.0, eta_B = 0.0, alpha_B = 0.0;  ///< oil at θ_B,Y (SI)
  double sliding_parameter = 0.0;    ///< S_GF,Y
  double U = 0.0, W = 0.0;           ///< speed and load parameters U_Y, W_Y
  double h = 0.0;                    ///< film thickness h_Y [m]
  double lambda = 0.0;               ///< λ_GF,Y = h_Y/Ra
};

struct Result {
  double transverse_pressure_angle = 0.0, working_pressure_angle = 0.0;  ///< [rad]
  double base_helix_angle = 0.0;                                         ///< [rad]
  double center_distance = 0.0;                                          ///< [m]
  double contact_ratio_transverse = 0.0, contact_ratio_overlap = 0.0;
  std::array<double, 2> addendum_contact_ratio{};  ///< ε1, ε2
  double reduced_modulus = 0.0;   ///< E_r [Pa]
  double Ra = 0.0;                ///< 0.5(Ra1 + Ra2) [m]
  double tangential_force = 0.0;  ///< F_t at the reference circle [N]
  double power = 0.0;             ///< [W]
  double helical_load_factor = 1.0;  ///< K_Bγ
  double roughness_factor = 0.0;     ///< X_R
  double eta_oil = 0.0;              ///< at θ_oil [Pa·s]
  double friction_coefficient = 0.0; ///< μ_m
  double loss_factor = 0.0;          ///< H_V
  double bulk_temperature = 0.0;     ///< θ_M [K]
  double nu_M = 0.0, rho_M = 0.0, eta_M = 0.0;  ///< oil at θ_M (SI)
  double alpha_38 = 0.0, alpha_M = 0.0;         ///< pressure–viscosity coefficients [1/Pa]
  double materials_parameter = 0.0;             ///< G_M
  std::array<double, 2> thermal_contact_coefficient{};  ///< B_M1, B_M2 [W·s^½/(m²·K)]
  std::array<PointResult, 7> points;
  double lambda_min = 0.0;
  std::string lambda_min_at;
};

/// Method B at the seven points. Throws InputError (validate() and the unsupported ranges).
Result evaluate(const Inputs& in);

/// The safety against micropitting of a gear, its reference test evaluated by the same method.
struct Assessment {
  Result gear;
  Result reference_test;
  double lambda_GFT = 0.0;  ///< λ_GF,min of the test gear at its failure load stage
  double lambda_GFP = 0.0;  ///< permissible specific film thickness
  double S_lambda = 0.0;    ///< λ_GF,min/λ_GFP
};

/// λ_GFP = 1.4·W_W·λ_GFT (the 1.4 as in seed 001's S_λ, quoting TR:2010; W_W, the material
/// factor of the 2014 edition, is unconfirmed: 1 keeps the 2010 form).
double permissible_lambda(double lambda_GFT, double material_factor = 1.0);
/// λ_GFT from `test`, λ_GFP, and S_λ of `gear`.
Assessment assess(const Inputs& gear, const Inputs& test, double material_factor = 1.0);

// ---- The single formulas, exposed for the unit tests -----------------------------------

/// Ubbelohde–Walther: lg lg(ν + 0.7) = A·lg T + B through (313 K, ν40) and (373 K, ν100),
/// ν in mm²/s, T = θ + 273 (17)–(19). Returns m²/s; T in K.
double kinematic_viscosity(const Oil& oil, double temperature);
/// ρ(θ) = ρ15·[1 − 0.7·(θ − 15 °C)/ρ15] with ρ in kg/m³ (20); T in K.
double density(const Oil& oil, double temperature);
/// η = ν·ρ [Pa·s] (16).
double dynamic_viscosity(const Oil& oil, double temperature);
/// α_38 by base oil (9)–(11) [1/Pa].
double pressure_viscosity_38(const Oil& oil);
/// α_θ = α_38·[1 + 516·(1/T − 1/311)] (8), (28) [1/Pa]; T in K.
double pressure_viscosity(const Oil& oil, double temperature);
/// B_M = √(λ·ρ·c) (82).
double thermal_contact_coefficient(const Solid& s);
/// K_Bγ of the friction coefficient (88)–(90).
double helical_load_factor(double total_contact_ratio);
/// X_S of the bulk temperature (84).
double lubrication_method_factor(LubricationMethod m);
/// X_Y of a spur pair with unmodified profiles (46)–(48); s and the path points from T1.
double load_sharing_spur(double s, double A, double B, double D, double E, int accuracy_grade);
/// θ_fl = (√π/2)·μ·p·|v_g|·√(8ρ_n·p/E_r)/(B_M1√v_r1 + B_M2√v_r2) (80), SI.
double flash_temperature(double mu, double p_dyn, double v_g, double v_r1, double v_r2,
                         double rho_n, double reduced_modulus, double B_M1, double B_M2);
/// h = 1600·ρ_n·G^0.6·U^0.7·W^−0.13·S_GF^0.22 with h in µm, ρ_n in mm (4); here in metres.
double film_thickness(double rho_n, double G, double U, double W, double S_GF);

}  // namespace gearbench::micropitting::iso15144
