#pragma once
// Case sections shared by the EHL kinds (their keys are the tables' of ehl/ehl_tables.h and the
// solvers' Options) and JSON output that never holds NaN (diagnostics of a failed solve may).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ehl/ehl_tables.h"
#include "ehl/line_contact_solver.h"
#include "model/case_reader.h"
#include "model/errors.h"
#include "model/json_reader.h"

namespace gearbench::app {

/// A gear-pair case's contact fluid and solids for EHL along the mesh (requires "operating",
/// "materials" and "lubricant"): E′ from "materials", η0, α and z from "lubricant"; the
/// optional "rheology" section (add_rheology_section) is read over it. Radius, load and speeds
/// are the mesh's; `kind` names the case kind in errors.
ehl::LineContactData gear_fluid(const model::GearCase& c, const std::string& kind);

/// The gear kinds' optional "rheology" section ({"viscosity_model", "density_model"}) into the
/// member `fluid` of a case.
template <class O>
void add_rheology_section(model::OptionTable<O>& t) {
  t.section("rheology", &O::fluid, ehl::rheology_table(),
            {.description = "pressure-viscosity and pressure-density laws of the film"});
}

/// The keys of a gear kind that solves EHL along the mesh, beside the gear case: the solver's
/// Options and the film's "rheology" over the case's fluid (gear_fluid).
template <class Options>
struct GearFluidCase {
  Options options;
  ehl::LineContactData fluid;

  static const model::OptionTable<GearFluidCase>& table() {
    static const auto table = [] {
      model::OptionTable<GearFluidCase> t;
      t.include(&GearFluidCase::options, Options::table());
      add_rheology_section(t);
      return t;
    }();
    return table;
  }
};

/// The options record of a solve: "options_given" and "options_used" in case keys.
template <class O>
void add_options_record(nlohmann::json& out, const model::OptionTable<O>& table, const O& given, const O& used) {
  out["options_given"] = table.to_json(given);
  out["options_used"] = table.to_json(used);
}

/// How a solve ended, written the same way by every kind at the top level of its result:
/// "converged" (bool), "message" (what stopped the solve, one sentence) and "summary" (the
/// Result's summary(), which the CLI prints on stderr). `Result` has converged, message and
/// summary() (model::SolveStatus and its summary; EhlResult alike).
template <class Result>
void add_solve_status(nlohmann::json& out, const Result& r) {
  out["converged"] = r.converged;
  out["message"] = r.message;
  out["summary"] = r.summary();
}

/// A solve that did not converge: ConvergenceError with its message and `out` as the
/// diagnostics (exit 3, the JSON still written to -o).
template <class Result>
void throw_unless_converged(const Result& r, const nlohmann::json& out) {
  if (!r.converged) throw ConvergenceError(r.message, out.dump(2));
}

/// Non-finite numbers become null.
nlohmann::json finite_or_null(double v);
nlohmann::json finite_vector(const std::vector<double>& v, double scale = 1.0);
/// A solve's work by part (ehl::EhlWork), keyed by the parts' names.
nlohmann::json work_by_part_json(const ehl::EhlWork& w);

/// Whether a Newtonian friction coefficient can be given: |μ| ≤ 1. A liquid film carries no
/// shear force above the normal load; a Newtonian traction beyond it (high slide-to-roll with a
/// piezoviscous oil: η·Δu/h at e^{αp}) is outside the Newtonian model, whose real limit is the
/// lubricant's limiting shear stress (Eyring τ0 of a few MPa, Yang & Wen 1990). Issue 20: the
/// mutation campaign got μ = 1.06e5 from `ehl_line` and −1.45 from `tehl_point`, with exit 0.
bool newtonian_friction_in_range(double mu);
/// The note of a friction coefficient withheld by newtonian_friction_in_range; `whose` names
/// the solution ("", "the isothermal solution's").
std::string withheld_friction_note(double mu, const std::string& whose);

}  // namespace gearbench::app
