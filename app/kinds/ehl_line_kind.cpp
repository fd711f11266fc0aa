// Case kind "ehl_line": steady isothermal line-contact EHL by FAS multigrid, from
// dimensional contact data or from Moes' (M, L). Every key comes from a table (EhlLineCase,
// ehl/ehl_tables.h, EhlOptions::table()).
#include <cmath>
#include <fmt/format.h>

#include "ehl/ehl_tables.h"
#include "ehl/line_contact_solver.h"
#include "ehl_sections.h"
#include "kind_registry.h"
#include "lubricant/lubricant_section.h"
#include "model/errors.h"
#include "model/json_reader.h"

namespace gearbench::app {
namespace {

using nlohmann::json;

/// The keys of an ehl_line case: Moes' (M, L), or the dimensional contact and lubricant; the
/// grid.
struct EhlLineCase {
  std::optional<ehl::MoesPoint> moes;
  std::optional<ehl::ContactInput> contact;
  std::optional<ehl::LineContactData> lubricant;  ///< the lubricant's keys (contact left empty)
  ehl::EhlOptions grid;

  static const model::OptionTable<EhlLineCase>& table() {
    static const auto table = [] {
      model::OptionTable<EhlLineCase> t;
      t.section("moes", &EhlLineCase::moes, ehl::MoesPoint::table(),
                {.description = "Moes' dimensionless (M, L) instead of contact and lubricant (Barus viscosity, "
                                "incompressible)"});
      t.section("contact", &EhlLineCase::contact, ehl::ContactInput::table(),
                {.description = "the dimensional contact (required without moes)"});
      t.section("lubricant", &EhlLineCase::lubricant, ehl::line_lubricant_table(),
                {.description = "the lubricant (required without moes)"}, lubricant::named_or_explicit_schema);
      t.section("grid", &EhlLineCase::grid, ehl::EhlOptions::table(), {.description = "the EHL multigrid"});
      t.after_read([](model::ObjectReader& root, const EhlLineCase& c) {
        if (!c.moes && !c.contact) root.object("contact");  // missing required key
        if (!c.moes && !c.lubricant) root.object("lubricant");
      });
      return t;
    }();
    return table;
  }

  [[nodiscard]] ehl::LineContactData data() const {
    if (moes) return ehl::LineContactData::from_moes(moes->M, moes->L);
    auto d = *lubricant;
    contact->apply(d);
    return d;
  }
};

json result_json(const ehl::LineContactProblem& p, const ehl::EhlResult& r) {
  const auto& d = p.data();
  const double to_moes = 1.0 / d.moes_film_scale();
  return {
      {"kind", "ehl_line"},
      {"h_central_m", finite_or_null(r.h_central)},
      {"h_min_m", finite_or_null(r.h_min)},
      {"x_h_min_m", finite_or_null(r.x_h_min)},
      {"p_max_Pa", finite_or_null(r.p_max)},
      {"h_dpdx0_m", finite_or_null(r.h_dpdx0)},
      {"moes", {{"M", d.moes_M()}, {"L", d.moes_L()}, {"H_c", finite_or_null(r.h_central * to_moes)},
                {"H_min", finite_or_null(r.h_min * to_moes)}, {"H_dpdx0", finite_or_null(r.h_dpdx0 * to_moes)}}},
      {"hertz", {{"half_width_m", p.hertz_half_width()}, {"p_max_Pa", p.hertz_pressure()}}},
      {"friction_force_per_length_N_per_m", finite_or_null(r.friction_force)},
      {"friction_coefficient", finite_or_null(r.friction_coefficient)},
      {"rheology", {{"viscosity", d.viscosity_model == ehl::ViscosityModel::barus ? "barus" : "roelands"},
                    {"density", d.density_model == ehl::DensityModel::incompressible ? "incompressible" : "dowson_higginson"}}},
      {"profile", {{"x_m", finite_vector(r.X, p.length_scale())},
                   {"p_Pa", finite_vector(r.P, p.pressure_scale())},
                   {"h_m", finite_vector(r.H, p.film_scale())}}},
      {"diagnostics", {{"converged", r.converged}, {"message", r.message}, {"scheme", r.scheme},
                       {"stop_rule", r.stop_rule}, {"levels", r.levels}, {"cycles", r.cycles},
                       {"work_units", r.work_units}, {"work_units_at_error", finite_or_null(r.work_units_at_error)},
                       {"work_units_by_part", work_by_part_json(r.work_by_part)},
                       {"work_units_iterating", r.work_units_iterating},
                       {"convergence_factor", finite_or_null(r.convergence_factor)},
                       {"rule_factor", finite_or_null(r.rule_factor)},
                       {"seconds", r.seconds}, {"nodes", r.X.size()},
                       {"scaling", p.hertzian_scaling() ? "hertzian" : "rigid_isoviscous"},
                       {"residual_history", finite_vector(r.residual_history)},
                       {"force_balance_history", finite_vector(r.force_history)},
                       {"seconds_per_level", finite_vector(r.seconds_per_level)},
                       {"discretisation_error", {{"estimate", finite_or_null(r.error_estimate)},
                                                 {"order", 2},
                                                 {"h_min_relative_change", finite_or_null(r.h_min_change)},
                                                 {"p_max_relative_change", finite_or_null(r.p_max_change)}}},
                       {"full_multigrid", {{"nodes", r.fmg_nodes}, {"H_c", finite_vector(r.fmg_H_c)},
                                           {"H_min", finite_vector(r.fmg_H_min)},
                                           {"cycles_after", r.fmg_cycles}}}}},
  };
}


json run_ehl_line(const json& case_json) {
  model::ObjectReader root(case_json, "");
  root.string("kind");
  root.optional_string("description");
  if (root.has("moes") && (root.has("contact") || root.has("lubricant")))
    throw InputError("moes: give either \"moes\" or \"contact\" + \"lubricant\", not both");
  EhlLineCase k;
  EhlLineCase::table().read(root, k);
  root.finish();
  EhlLineCase::table().validate(k);
  const bool moes = k.moes.has_value();
  const auto data = k.data();
  const auto& options = k.grid;

  const ehl::LineContactProblem problem(data);
  ehl::refuse_grid_not_resolving_film(problem, options);
  const auto r = ehl::LineContactSolver(problem, options).try_solve();
  auto out = result_json(problem, r);
  add_solve_status(out, r);
  add_options_record(out, ehl::EhlOptions::table(), options, ehl::grid_used(options, r));
  json notes = json::array();
  if (moes)
    notes.push_back("Moes input: Barus viscosity and an incompressible lubricant (M and L fix neither p0 for "
                    "Roelands nor the pressure level)");
  notes.push_back("p_max is the Barus/Roelands pressure spike where there is one: it sharpens with every grid and "
                  "is not part of the stop rule or the error estimate");
  // The solver's own estimate against the error the user asked for (grid.target_error).
  if (!std::isfinite(r.error_estimate))
    notes.push_back("no discretisation-error estimate (a single grid, or no coarser level with a positive film)");
  else if (r.error_estimate > options.target_error)
    notes.push_back(fmt::format("the estimated discretisation error of H_c and H_min, {:.2g} %, is above the target "
                                "{:.2g} %: give more levels (grid.max_levels or grid.nodes)",
                                100.0 * r.error_estimate, 100.0 * options.target_error));
  if (!newtonian_friction_in_range(r.friction_coefficient)) {
    notes.push_back(withheld_friction_note(r.friction_coefficient, ""));
    out["friction_force_per_length_N_per_m"] = nullptr;
    out["friction_coefficient"] = nullptr;
  }
  if (!notes.empty()) out["notes"] = notes;
  throw_unless_converged(r, out);
  return out;
}

std::vector<json> ehl_line_schema() { return {EhlLineCase::table().schema()}; }

const RegisterKind ehl_line_kind({"ehl_line", "steady isothermal line-contact EHL (FAS multigrid)", run_ehl_line,
                                  ehl_line_schema});

}  // namespace
}  // namespace gearbench::app
