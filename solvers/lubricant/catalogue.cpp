#include "catalogue.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <stdexcept>

#include "model/errors.h"
#include "model/json_reader.h"
#include "rheology.h"
#include "viscosity_temperature.h"

namespace gearbench::lubricant {

extern const char* const catalogue_json;  // data/lubricants.json, generated into the build

namespace {

using nlohmann::json;

constexpr double T40 = celsius_zero + 40.0, T100 = celsius_zero + 100.0;
constexpr double T38 = celsius_zero + 38.0;
// ISO/TR 15144-1 (8): α_θ = α_38·[1 + 516·(1/T − 1/311)], T = θ + 273 (the TR's absolute
// temperature; the reference/closed_form port uses the same 273).
constexpr double iso_alpha_temperature_K = 516.0, iso_alpha_T38 = 311.0, iso_kelvin_offset = 273.0;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string display_base(BaseOil base) {
  switch (base) {
    case BaseOil::pao: return "PAO";
    case BaseOil::pag: return "PAG";
    case BaseOil::ester: return "ester";
    case BaseOil::mineral: break;
  }
  return "mineral";
}

constexpr BaseOil all_bases[] = {BaseOil::mineral, BaseOil::pao, BaseOil::ester, BaseOil::pag};

std::optional<Sourced> sourced(const json& entry, const char* key, const std::string& source) {
  if (!entry.contains(key)) return std::nullopt;
  const auto& v = entry.at(key);
  if (v.is_object()) return Sourced{v.at("value").get<double>(), v.at("source").get<std::string>()};
  return Sourced{v.get<double>(), source};
}

OilData read_oil(const json& e) {
  const std::string source = e.at("source").get<std::string>();
  OilData o;
  o.name = e.at("name").get<std::string>();
  if (e.contains("base")) o.base = parse_base_oil(e.at("base").get<std::string>(), "catalogue base of " + o.name);
  o.nu40 = sourced(e, "nu40_mm2_s", source);
  o.nu100 = sourced(e, "nu100_mm2_s", source);
  o.density_15C = sourced(e, "density_15C_kg_m3", source);
  o.thermal_conductivity = sourced(e, "thermal_conductivity_W_per_mK", source);
  o.specific_heat = sourced(e, "specific_heat_J_per_kgK", source);
  if (e.contains("at_temperature_C")) o.at_temperature = e.at("at_temperature_C").get<double>() + celsius_zero;
  o.viscosity = sourced(e, "viscosity_Pa_s", source);
  o.roelands_z = sourced(e, "roelands_z", source);
  o.pressure_viscosity = sourced(e, "pressure_viscosity_1_per_GPa", source);
  return o;
}

/// ASTM D2270 Table 1 from the catalogue's "viscosity_index_table_1" (rows ν100, L, H).
ViscosityIndex read_table_1(const json& data) {
  std::vector<ViscosityIndex::Row> rows;
  for (const auto& r : data.at("viscosity_index_table_1").at("rows"))
    rows.push_back({r.at(0).get<double>(), r.at(1).get<double>(), r.at(2).get<double>()});
  return ViscosityIndex(std::move(rows));
}

/// T [K] in degC as a message shows it (10 significant digits: no 39.85000000000002).
std::string celsius(double T) { return fmt::format("{:.10g}", T - celsius_zero); }

/// A temperature as the key that gave it names its unit ("..._K" in kelvin, else degC).
std::string shown_temperature(const std::string& key, double T) {
  return key.size() > 2 && key.compare(key.size() - 2, 2, "_K") == 0 ? fmt::format("{:.10g}", T) : celsius(T);
}

/// z from α and η (rheology.h), sourced from both.
std::optional<Sourced> derived_z(const std::optional<Sourced>& eta, const std::optional<Sourced>& alpha) {
  if (!eta || !alpha) return std::nullopt;
  return Sourced{roelands_z_from_alpha(eta->value, alpha->value * 1e-9), "roelands_z_from_alpha(" + alpha->source + ")"};
}

}  // namespace

BaseOil parse_base_oil(const std::string& name, const std::string& key) {
  for (const auto b : all_bases)
    if (lower(name) == base_oil_name(b)) return b;
  throw InputError(fmt::format("{} = {}: allowed values are mineral, pao, ester, pag", key, model::shown_value(name)));
}

std::string base_oil_name(BaseOil base) { return lower(display_base(base)); }

std::string grade_name(int grade, BaseOil base) { return fmt::format("ISO VG {} {}", grade, display_base(base)); }

const Catalogue& Catalogue::builtin() {
  static const Catalogue catalogue(model::parse_json(catalogue_json, "data/lubricants.json"));
  return catalogue;
}

Catalogue::Catalogue(const json& data) : sources_(data.at("sources")), viscosity_index_(read_table_1(data)) {
  const auto& limits = data.at("limits");
  const auto range = limits.at("temperature_C"), interval = limits.at("data_interval_C");
  temperature_range_ = {range[0].get<double>() + celsius_zero, range[1].get<double>() + celsius_zero};
  data_interval_ = {interval[0].get<double>() + celsius_zero, interval[1].get<double>() + celsius_zero};
  min_viscosity_ = limits.at("min_kinematic_viscosity_mm2_s").get<double>();
  single_point_tolerance_ = limits.at("single_point_tolerance_K").get<double>();
  for (const auto& [name, b] : data.at("base_oils").items()) {
    BaseData d;
    if (b.contains("alpha_38")) {
      const auto& a = b.at("alpha_38");
      const auto src = a.at("source").get<std::string>();
      d.alpha_coefficient = Sourced{a.at("coefficient_1_per_Pa").get<double>(), src};
      d.alpha_exponent = Sourced{a.at("exponent").get<double>(), src};
    }
    d.density_15C = sourced(b, "density_15C_kg_m3", "");
    d.specific_heat = sourced(b, "specific_heat_J_per_kgK", "");
    d.thermal_conductivity = sourced(b, "thermal_conductivity_W_per_mK", "");
    bases_[parse_base_oil(name, "catalogue base_oils")] = d;
  }
  grades_ = data.at("iso_vg_grades").get<std::vector<int>>();
  const auto& nu100 = data.at("grade_nu100_mm2_s");
  const auto source = nu100.at("source").get<std::string>();
  for (const auto base : all_bases)
    for (const auto& [grade, value] : nu100.at(base_oil_name(base)).items())
      grade_nu100_[base][std::stoi(grade)] = Sourced{value.get<double>(), source};
  for (const auto& e : data.at("oils")) oils_.push_back(read_oil(e));
}

std::vector<std::string> Catalogue::names() const {
  std::vector<std::string> names;
  for (const auto& o : oils_) names.push_back(o.name);
  for (const auto base : all_bases)
    for (const int g : grades_) names.push_back(grade_name(g, base));
  return names;
}

OilData Catalogue::find(const std::string& name, const std::string& key) const {
  for (const auto& o : oils_)
    if (lower(o.name) == lower(name)) return with_base_defaults(o);
  for (const auto base : all_bases)
    for (const int g : grades_)
      if (lower(grade_name(g, base)) == lower(name)) return grade(g, base, std::nullopt, key);
  std::string nearest;
  std::size_t best = std::string::npos;
  for (const auto& n : names())
    if (const auto d = model::edit_distance(lower(name), lower(n)); d < best) {
      best = d;
      nearest = n;
    }
  throw InputError(fmt::format("{} = {}: unknown oil (nearest known: '{}'); `gearbench lubricants` lists the catalogue",
                               key, model::shown_value(name), nearest));
}

void Catalogue::require_data(const OilData& oil, const std::string& key) {
  if (!oil.at_temperature && (!oil.nu40 || !oil.nu100))
    throw InputError(fmt::format("{} = {}: the catalogue has no sourced nu100 for this oil; give it as {{\"grade\", "
                                 "\"base\", \"nu100_mm2_s\"}} or {{\"grade\", \"base\", \"viscosity_index\"}}", key,
                                 model::shown_value(oil.name)));
}

double Catalogue::nu100_from_viscosity_index(double nu40, double vi, const std::string& key) const {
  if (const auto nu100 = viscosity_index_.nu100(nu40, vi)) return *nu100;
  const auto range = viscosity_index_.index_range(nu40);
  if (!range)
    throw InputError(fmt::format("{} = {}: ASTM D2270 / ISO 2909 define no viscosity index below nu100 = {} mm2/s, "
                                 "which an oil of nu40 = {} mm2/s cannot reach; give nu100_mm2_s", key,
                                 model::format_value(vi), model::format_value(viscosity_index_.min_nu100()),
                                 model::format_value(nu40)));
  throw InputError(fmt::format("{} = {}: allowed range for nu40 = {} mm2/s is [{:.1f}, {:.1f}] (nu100 from {} mm2/s, "
                               "where ASTM D2270 / ISO 2909 begin, up to nu40)", key, model::format_value(vi),
                               model::format_value(nu40), range->first, range->second,
                               model::format_value(viscosity_index_.min_nu100())));
}

OilData Catalogue::grade(int grade, BaseOil base, std::optional<double> nu100, const std::string& key) const {
  if (std::find(grades_.begin(), grades_.end(), grade) == grades_.end())
    throw InputError(fmt::format("{} = {}: not an ISO 3448 grade; allowed values are {}", key, grade,
                                 fmt::join(grades_, ", ")));
  OilData o;
  o.name = grade_name(grade, base);
  o.base = base;
  o.nu40 = Sourced{static_cast<double>(grade), "iso3448"};  // the grade's midpoint ν40
  if (nu100) {
    o.nu100 = Sourced{*nu100, "case"};
  } else if (const auto it = grade_nu100_.at(base).find(grade); it != grade_nu100_.at(base).end()) {
    o.nu100 = it->second;
  }
  return with_base_defaults(o);
}

OilData Catalogue::with_base_defaults(OilData o) const {
  if (!o.base || o.at_temperature) return o;
  const auto& b = bases_.at(*o.base);
  if (!o.density_15C) o.density_15C = b.density_15C;
  if (!o.specific_heat) o.specific_heat = b.specific_heat;
  if (!o.thermal_conductivity) o.thermal_conductivity = b.thermal_conductivity;
  return o;
}

std::optional<double> Catalogue::iso15144_pressure_viscosity(BaseOil base, double eta38, double T) const {
  const auto& b = bases_.at(base);
  if (!b.alpha_coefficient) return std::nullopt;
  const double alpha38 = b.alpha_coefficient->value * std::pow(eta38, b.alpha_exponent->value);  // (9)–(11)
  const double T_tr = T - celsius_zero + iso_kelvin_offset;
  return alpha38 * (1.0 + iso_alpha_temperature_K * (1.0 / T_tr - 1.0 / iso_alpha_T38));  // (8)
}

OilState Catalogue::at(const OilData& oil, double T, const std::string& key) const {
  OilState s;
  s.name = oil.name;
  s.temperature = T;
  s.base = oil.base;
  s.thermal_conductivity = oil.thermal_conductivity;
  s.specific_heat = oil.specific_heat;
  if (oil.at_temperature) {
    if (std::abs(T - *oil.at_temperature) > single_point_tolerance_)
      throw InputError(fmt::format("{} = {}: '{}' is given at {} degC only (its source has no viscosity-temperature "
                                   "data); use that temperature or give the oil's numbers", key, shown_temperature(key, T), oil.name,
                                   celsius(*oil.at_temperature)));
    s.viscosity = oil.viscosity;
    s.pressure_viscosity = oil.pressure_viscosity;
    s.roelands_z = oil.roelands_z ? oil.roelands_z : derived_z(s.viscosity, s.pressure_viscosity);
    return s;
  }
  add_two_point_state(oil, T, key, s);
  return s;
}

void Catalogue::add_two_point_state(const OilData& oil, double T, const std::string& key, OilState& s) const {
  if (!oil.nu40 || !oil.nu100)
    throw std::logic_error("Catalogue::at: '" + oil.name + "' has no nu40/nu100 (Catalogue::require_data first)");
  if (!(oil.nu100->value > 0.0 && oil.nu100->value < oil.nu40->value))
    throw InputError(fmt::format("{} = '{}': nu100_mm2_s = {} must be positive and below nu40 = {} mm2/s", key,
                                 oil.name, model::format_value(oil.nu100->value), model::format_value(oil.nu40->value)));
  const auto [lo, hi] = temperature_range_;
  if (!(T >= lo && T <= hi))
    throw InputError(fmt::format("{} = {}: allowed range is [{}, {}] degC (the catalogue's range for two-point oils)",
                                 key, shown_temperature(key, T), celsius(lo), celsius(hi)));
  if (T < data_interval_.first || T > data_interval_.second)
    s.warnings.push_back(fmt::format("viscosity extrapolated to {} degC beyond the data points {} and {} degC "
                                     "(ASTM D341 line)", celsius(T), celsius(data_interval_.first),
                                     celsius(data_interval_.second)));
  const WaltherLine line(T40, oil.nu40->value, T100, oil.nu100->value);
  const double nu = line.kinematic_viscosity_mm2_s(T);
  if (!(nu >= min_viscosity_))
    throw InputError(fmt::format("{} = {}: '{}' reaches {:.3g} mm2/s there, below the {} mm2/s of ASTM D341's "
                                 "two-constant form", key, shown_temperature(key, T), oil.name, nu, min_viscosity_));
  const std::string line_source = fmt::format("astm_d341({}, {})", oil.nu40->source, oil.nu100->source);
  s.nu40 = oil.nu40;
  s.nu100 = oil.nu100;
  if (oil.nu100->value >= viscosity_index_.min_nu100())
    s.viscosity_index = Sourced{viscosity_index_.index(oil.nu40->value, oil.nu100->value),
                                fmt::format("astm_d2270({}, {})", oil.nu40->source, oil.nu100->source)};
  s.density_15C = oil.density_15C;
  s.kinematic_viscosity = Sourced{nu, line_source};
  if (!oil.density_15C) return;
  const std::string rho_source = "iso15144(" + oil.density_15C->source + ")";
  s.density = Sourced{iso15144_density(oil.density_15C->value, T), rho_source};
  s.viscosity = Sourced{s.density->value * nu * 1e-6, line_source + " * " + rho_source};  // η = ρ·ν (16)
  if (oil.base) {
    const double eta38 = iso15144_density(oil.density_15C->value, T38) * line.kinematic_viscosity_mm2_s(T38) * 1e-6;
    if (const auto alpha = iso15144_pressure_viscosity(*oil.base, eta38, T))
      s.pressure_viscosity = Sourced{*alpha * 1e9, "iso15144(" + base_oil_name(*oil.base) + ")"};
  }
  s.roelands_z = derived_z(s.viscosity, s.pressure_viscosity);
}

}  // namespace gearbench::lubricant
