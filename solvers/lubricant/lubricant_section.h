#pragma once
// A case's lubricant section that names an oil — {"name": "ISO VG 320 mineral"} or {"grade":
// 320, "base": "mineral", "nu100_mm2_s": 23} or {"grade": 10, "base": "mineral",
// "viscosity_index": 95} (ν100 by ASTM D2270 / ISO 2909) — turned into the explicit keys the kind's reader
// takes, from the catalogue at the case's temperature (issue 24). Keys the section gives
// explicitly override the catalogue's; the echo says what was resolved and from where.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace gearbench::lubricant {

/// Which reader the section feeds (its keys and units).
enum class SectionForm {
  gear,              ///< model::read_lubricant: η, α, z and ρ at the temperature, ν40, ν100, k, c
  ehl_line,          ///< the ehl_line kind: η, α, z
  thermal,           ///< model::read_thermal_lubricant: ν40, ν100, ρ15, α at the inlet, k, c
  micropitting_oil,  ///< ISO/TR 15144-1 "oil": base, ν40, ν100, ρ15 (no temperature)
};

/// Where a case's temperature comes from: its key path (for messages) and value [K].
struct CaseTemperature {
  std::string key;
  double value = 0.0;
};

struct ResolvedSection {
  nlohmann::json section;  ///< the section with explicit numbers only
  nlohmann::json echo;     ///< name, temperature, values, their sources, explicit keys, warnings
};

/// True when the section names an oil ("name" or "grade").
bool names_oil(const nlohmann::json& section);

/// The schema of a section that may name an oil: either the explicit form (`explicit_schema`,
/// an object schema) or the naming keys with any explicit key beside them as an override.
nlohmann::json named_or_explicit_schema(nlohmann::json explicit_schema);

/// Resolves a section that names an oil. `path` is its key path ("lubricant"); `temperature`
/// the case's own (operating or inlet), if it has one — "temperature_C" in the section is the
/// alternative, not both. InputError (naming the key, the value and what is allowed) for an
/// unknown name or grade, a temperature outside the data, or a figure the form needs that
/// neither the catalogue nor the section gives.
ResolvedSection resolve_section(const nlohmann::json& section, const std::string& path, SectionForm form,
                                const std::optional<CaseTemperature>& temperature);

}  // namespace gearbench::lubricant
