#pragma once
// Thermal EHL next to ISO/TR 15144-1 method B (seed 001): the safety against micropitting
// S_λ = λ_GF,min/λ_GFP computed twice, once with the closed-form ISO films and once with the
// thermal EHL films of the same gear and of the oil's reference test (FZG C-GF at its failure
// load stage), as seed 001 does: S_λ = (h_min/Ra)/(1.4·h_ref/Ra_ref). Shared by the tehl_path
// kind and the verification checks.
#include <array>
#include <nlohmann/json.hpp>
#include <string>

#include "ehl/thermal_mesh_path.h"
#include "micropitting/iso15144_case.h"
#include "model/case_reader.h"

namespace gearbench::micropitting {

struct TehlMicropitting {
  micropitting::iso15144::Assessment iso;     ///< ISO films, λ and S_λ of gear and test
  ehl::ThermalPathPoint reference_point;   ///< thermal EHL of the test gear at A
  std::array<double, 7> lambda{};          ///< thermal EHL λ_GF,Y = h_min,Y/Ra, A … E
  double lambda_min = 0.0;
  std::string lambda_min_at;
  double lambda_GFT = 0.0;                 ///< h_ref/Ra_ref of the test gear (thermal EHL)
  double lambda_GFP = 0.0;                 ///< 1.4·W_W·λ_GFT
  double S_lambda = 0.0;                   ///< λ_min/λ_GFP
};

/// The ISO assessment of `m`, the thermal EHL reference film of its test gear at A (seed 001:
/// the test pair's minimum film is always at A; ISO's is too) with the gear case's lubricant
/// and solids at the test's oil temperature, and the thermal EHL S_λ of the solved `path`.
TehlMicropitting compare_with_iso(const ehl::ThermalPathResult& path, const model::ThermalPathCase& c,
                                  const MicropittingCase& m, const ehl::ThermalEhlOptions& options);

nlohmann::json micropitting_json(const TehlMicropitting& t);

}  // namespace gearbench::micropitting
