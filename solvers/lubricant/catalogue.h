#pragma once
// The lubricant catalogue (data/lubricants.json, compiled in): ISO VG grades by base oil,
// reference oils of the seeds and of FEUP/FVA, and the base-oil data, every figure with its
// source; and the properties of an oil at a temperature:
//  - kinematic viscosity by ASTM D341 through ν40 and ν100 (WaltherLine); a grade's ν100 may
//    come from a stated viscosity index (ASTM D2270 / ISO 2909, viscosity_index.h),
//  - density by ISO/TR 15144-1 (20) from ρ15, dynamic viscosity η = ρ·ν,
//  - pressure–viscosity α by ISO/TR 15144-1 (8)–(11) per base oil (none for esters),
//  - Roelands z from α and η (rheology.h),
//  - specific heat and thermal conductivity where the catalogue has a sourced figure.
// A figure the catalogue has no source for stays empty: the caller must give it.
// Temperatures in K, SI values; catalogue keys name their units.
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "viscosity_index.h"

namespace gearbench::lubricant {

enum class BaseOil { mineral, pao, ester, pag };
/// "mineral", "pao", "ester", "pag" (InputError naming `key` otherwise).
BaseOil parse_base_oil(const std::string& name, const std::string& key);
std::string base_oil_name(BaseOil base);

/// A figure and the key of its source in the catalogue's "sources".
struct Sourced {
  double value = 0.0;
  std::string source;
};

/// One oil as the catalogue (or a case's grade specification) gives it: either two points
/// of its viscosity–temperature line (ν40, ν100) or fixed values at one temperature.
struct OilData {
  std::string name;
  std::optional<BaseOil> base;
  std::optional<Sourced> nu40, nu100;  ///< [mm²/s]
  std::optional<Sourced> density_15C;  ///< ρ15 [kg/m³]
  std::optional<Sourced> thermal_conductivity, specific_heat;  ///< [W/(m·K)], [J/(kg·K)]
  std::optional<double> at_temperature;  ///< [K]: an oil given at this temperature only
  /// η [Pa·s], α [1/GPa] (the case key's unit: a catalogue 24.8 stays 24.8), z
  std::optional<Sourced> viscosity, pressure_viscosity, roelands_z;
};

/// The properties of an oil at one temperature; empty where neither the catalogue nor a
/// formula gives them.
struct OilState {
  std::string name;
  double temperature = 0.0;                      ///< [K]
  std::optional<Sourced> nu40, nu100;            ///< [mm²/s]
  std::optional<Sourced> density_15C;            ///< [kg/m³]
  std::optional<Sourced> kinematic_viscosity;    ///< [mm²/s]
  std::optional<Sourced> density;                ///< ρ(T) [kg/m³]
  std::optional<Sourced> viscosity;              ///< η(T) [Pa·s]
  std::optional<Sourced> pressure_viscosity;     ///< α(T) [1/GPa]
  std::optional<Sourced> roelands_z;
  std::optional<Sourced> thermal_conductivity, specific_heat;
  std::optional<Sourced> viscosity_index;        ///< by ASTM D2270 from ν40, ν100 (none below 2 mm²/s at 100 °C)
  std::optional<BaseOil> base;
  std::vector<std::string> warnings;             ///< e.g. extrapolated beyond the data points
};

class Catalogue {
 public:
  /// The compiled-in data/lubricants.json.
  static const Catalogue& builtin();
  explicit Catalogue(const nlohmann::json& data);

  /// The oil of that name (case-insensitive: "ISO VG 320 mineral", "seed 001 PAO"); an
  /// InputError at `key` naming the nearest known name otherwise.
  [[nodiscard]] OilData find(const std::string& name, const std::string& key) const;
  /// An ISO VG grade of a base oil; ν100 from the catalogue unless given [mm²/s].
  [[nodiscard]] OilData grade(int grade, BaseOil base, std::optional<double> nu100, const std::string& key) const;
  /// ν100 [mm²/s] of an oil of ν40 with viscosity index `vi` (ASTM D2270 / ISO 2909);
  /// InputError at `key` (where VI came from) naming the VIs that ν40 allows.
  [[nodiscard]] double nu100_from_viscosity_index(double nu40, double vi, const std::string& key) const;
  /// InputError at `key` (the oil's name) when a two-point oil lacks ν100 (grades without a
  /// sourced one).
  static void require_data(const OilData& oil, const std::string& key);
  /// The properties at temperature T [K] of an oil that passed require_data; InputError at
  /// `key` (where T came from) outside the data's range.
  [[nodiscard]] OilState at(const OilData& oil, double T, const std::string& key) const;
  /// α(T) of ISO/TR 15144-1 from η at 38 °C; empty for a base without a formula.
  [[nodiscard]] std::optional<double> iso15144_pressure_viscosity(BaseOil base, double eta38, double T) const;

  [[nodiscard]] std::vector<std::string> names() const;
  [[nodiscard]] const std::vector<int>& grades() const { return grades_; }
  [[nodiscard]] const nlohmann::json& sources() const { return sources_; }
  /// ASTM D2270 / ISO 2909 with the catalogue's Table 1.
  [[nodiscard]] const ViscosityIndex& viscosity_index() const { return viscosity_index_; }

 private:
  struct BaseData {
    std::optional<Sourced> alpha_coefficient, alpha_exponent;  ///< α38 = a·η38^b
    std::optional<Sourced> density_15C, specific_heat, thermal_conductivity;
  };
  [[nodiscard]] OilData with_base_defaults(OilData oil) const;
  void add_two_point_state(const OilData& oil, double T, const std::string& key, OilState& s) const;

  nlohmann::json sources_;
  std::map<BaseOil, BaseData> bases_;
  std::vector<int> grades_;
  std::map<BaseOil, std::map<int, Sourced>> grade_nu100_;
  std::vector<OilData> oils_;
  ViscosityIndex viscosity_index_;
  std::pair<double, double> temperature_range_, data_interval_;  ///< [K]: resolvable, and the data points
  double min_viscosity_ = 2.0, single_point_tolerance_ = 0.01;
};

/// "ISO VG 320 mineral": the catalogue name of a grade.
std::string grade_name(int grade, BaseOil base);

}  // namespace gearbench::lubricant
