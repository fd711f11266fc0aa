#pragma once
// The case keys of the EHL kinds that are not one solver's Options (issue 21): the dimensional
// "contact", the isothermal lubricant and rheology of a line contact, Moes' (M, L) and the
// double-involute rack. The solvers' own tables are their Options' table() (EhlOptions,
// TransientMeshOptions, OilFilmStiffnessOptions, MeshPeriodOilFilmOptions, ThermalEhlOptions);
// all are made in ehl_options.cpp.
#include <array>

#include "line_contact_problem.h"
#include "line_contact_solver.h"
#include "model/double_involute_rack.h"
#include "model/option_table.h"

namespace gearbench::ehl {

/// The "contact" section: R, w, [u1, u2], E' (SI, as the keys' units say).
struct ContactInput {
  double reduced_radius = 0.0;
  double load_per_length = 0.0;
  std::array<double, 2> surface_speeds{};
  double reduced_modulus = 0.0;

  static const model::OptionTable<ContactInput>& table();
  /// Sets the contact's radius, load, speeds and modulus in `d`.
  void apply(LineContactData& d) const;
};

/// The "moes" section of an ehl_line case.
struct MoesPoint {
  double M = 0.0, L = 0.0;
  static const model::OptionTable<MoesPoint>& table();
};

/// "viscosity_model", "density_model" (the gear kinds' "rheology" section, and keys of the
/// ehl_line lubricant).
const model::OptionTable<LineContactData>& rheology_table();
/// The ehl_line "lubricant": η0, α, Roelands z and the rheology keys.
const model::OptionTable<LineContactData>& line_lubricant_table();
/// The oil_film_stiffness kind's "double_involute" section.
const model::OptionTable<model::DoubleInvoluteRack>& double_involute_rack_table();

/// The options a solve ran with: those given, with the finest grid that target_error chose
/// where the grid was left to it.
EhlOptions grid_used(const EhlOptions& given, const EhlResult& r);

}  // namespace gearbench::ehl
