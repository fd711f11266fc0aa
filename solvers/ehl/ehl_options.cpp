// The keys of the EHL kinds (issue 21), one table each: the multigrid's "grid" section, the
// dimensional "contact" and the isothermal lubricant of a line contact, Moes' (M, L), the
// rheology choices, the double-involute rack and the options of the transient, oil-film and
// thermal solvers. The case readers (app/kinds/ehl_*, tehl_*), validate() and
// `gearbench schema` all come from them.
#include <fmt/format.h>

#include "ehl_tables.h"
#include "model/case_reader.h"
#include "model/errors.h"
#include "oil_film_stiffness.h"
#include "thermal_line_contact.h"
#include "transient_mesh_ehl.h"

namespace gearbench::ehl {
namespace {

using model::Range;

constexpr int max_nodes = (1 << 20) + 1;

/// The names of the multigrid cycles, for every key that chooses one.
std::vector<std::pair<std::string, CycleType>> cycle_choices() {
  return {{"V", CycleType::V}, {"W", CycleType::W}, {"F", CycleType::F}};
}

/// The relaxation settings of the multigrid: ranges the C++ API is held to; no case sets them.
model::OptionTable<EhlOptions> make_tuning_table() {
  model::OptionTable<EhlOptions> t;
  t.integer("pre_sweeps", &EhlOptions::pre_sweeps, 0, 20,
            {.description = "relaxations before the coarse-grid correction"});
  t.integer("post_sweeps", &EhlOptions::post_sweeps, 0, 20, {.description = "relaxations after it"});
  t.number("omega_gauss_seidel", &EhlOptions::omega_gauss_seidel, Range{0.0, 1.0, true, false},
           {.description = "under-relaxation of Gauss-Seidel changes"});
  t.number("omega_jacobi", &EhlOptions::omega_jacobi, Range{0.0, 1.0, true, false},
           {.description = "under-relaxation of the Jacobi line changes"});
  t.number("relaxation_switch", &EhlOptions::relaxation_switch, Range::closed(1.0, 1e3),
           {.description = "kappa: Gauss-Seidel where the Poiseuille diagonal exceeds kappa times the wedge term's"});
  t.integer("line_band", &EhlOptions::line_band, 1, 16, {.description = "half-bandwidth of a Jacobi line's Jacobian"});
  t.number("change_limit", &EhlOptions::change_limit, Range{0.0, 10.0, true, false},
           {.description = "largest |d ln eps| of one change of P"});
  t.number("spike_half_width", &EhlOptions::spike_half_width, Range{0.0, 1.0, true, false},
           {.description = "half-width of the window around the pressure spike solved by local Newton, in Hertzian "
                           "half-widths (at least 4 nodes); none without piezoviscosity, where there is no spike"});
  t.integer("free_boundary_sweeps", &EhlOptions::free_boundary_sweeps, 0, 20,
            {.description = "extra sweeps over the outlet window after each cycle"});
  t.integer("free_boundary_window", &EhlOptions::free_boundary_window, 1, 256,
            {.description = "pressurised nodes of the outlet window"});
  t.integer("acceleration_depth", &EhlOptions::acceleration_depth, 0, 10,
            {.description = "Anderson acceleration of the cycles on a level: states mixed into the next start (0: "
                            "plain cycles)"});
  t.rule([](const EhlOptions& o, const std::string& p) {
    if (o.pre_sweeps + o.post_sweeps < 1)
      throw InputError(fmt::format("{}pre_sweeps = {}, {}post_sweeps = {}: at least one relaxation per cycle", p,
                                   o.pre_sweeps, p, o.post_sweeps));
  });
  return t;
}

model::OptionTable<EhlOptions> make_grid_table() {
  model::OptionTable<EhlOptions> t;
  t.integer("nodes", &EhlOptions::nodes, 9, max_nodes,
            {.description = "nodes on the finest grid, (n0 - 1) 2^k + 1; not with levels; absent (and no levels): "
                            "levels are added until the error estimate is below target_error. ehl_line refuses a "
                            "grid too coarse for the film (spacing > 0.35 sqrt(film), naming the fewest nodes)",
             .unset = 0});
  t.integer("levels", &EhlOptions::levels, 1, 14,
            {.description = "grid levels from coarsest_nodes (which must be given); not with nodes", .unset = 0});
  t.integer("coarsest_nodes", &EhlOptions::coarsest_nodes, 9, 1025,
            {.description = "nodes on the coarsest grid; absent: sized by the film", .unset = 0});
  t.number("x_in", &EhlOptions::x_in, Range{-1e3, 0.0, false, true},
           {.description = "inlet end of the domain in the problem's length unit (given with x_out); absent: the "
                           "problem's own domain",
            .unset = 0.0});
  t.number("x_out", &EhlOptions::x_out, Range{0.0, 1e3, true, false},
           {.description = "outlet end of the domain (given with x_in)", .unset = 0.0});
  t.choice("cycle", &EhlOptions::cycle, cycle_choices(),
           {.description = "multigrid cycle: one (V) or two (W) coarse-grid visits per cycle, or an F-cycle"});
  t.integer("w_cycle_levels", &EhlOptions::w_cycle_levels, 1, 14,
            {.description = "levels above the coarsest grid on which a W-cycle visits the coarser grid twice (once "
                            "above them: O(N) a cycle)"});
  t.integer("max_cycles", &EhlOptions::max_cycles, 1, 100000,
            {.description = "cycles on the finest grid before the solve is reported unconverged"});
  t.integer("max_levels", &EhlOptions::max_levels, 2, 14, {.description = "cap on the levels target_error adds"});
  t.number("target_error", &EhlOptions::target_error, Range{0.0, 0.5, true, false},
           {.description = "estimated relative discretisation error of H_c and H_min the grid is refined to"});
  t.choice("stop", &EhlOptions::stop,
           std::vector<std::pair<std::string, StopRule>>{{"discretisation_error", StopRule::discretisation_error},
                                                         {"residual", StopRule::residual}},
           {.description = "accept the solve at a fraction of its discretisation-error estimate, or at a residual "
                           "tolerance (a tolerance given without stop asks for the residual rule)"});
  t.number("error_fraction", &EhlOptions::error_fraction, Range{0.0, 1.0, true, false},
           {.description = "discretisation-error rule: the algebraic error a cycle's change of H_c, H_min, H0 and "
                           "the pressurised film leaves below this fraction of the estimate"});
  t.number("tolerance", &EhlOptions::tolerance, Range{0.0, 1.0, true, true},
           {.description = "residual rule: scaled residual and force balance below it"});
  t.after_read([](model::ObjectReader& g, EhlOptions& o) {
    if (g.has("nodes") && g.has("levels"))
      throw InputError(g.key_path("nodes") + ": give either nodes or levels (with coarsest_nodes), not both");
    if (g.has("levels")) o.nodes = 0;  // over a holder's default grid of fixed nodes
    if (g.has("nodes")) o.levels = 0;
    if (g.has("tolerance") && !g.has("stop")) o.stop = StopRule::residual;
  });
  t.rule([](const EhlOptions& o, const std::string& p) {
    if (o.nodes != 0 && o.levels != 0)
      throw InputError(fmt::format("{}nodes = {}, {}levels = {}: give either nodes or levels, not both", p, o.nodes,
                                   p, o.levels));
    if (o.levels > 0 && o.coarsest_nodes == 0)
      throw InputError(fmt::format("{}levels = {}: needs {}coarsest_nodes in [9, 1025] (or give nodes instead)", p,
                                   o.levels, p));
    if ((o.x_in == 0.0) != (o.x_out == 0.0))
      throw InputError(fmt::format("{}x_in = {}, {}x_out = {}: give both or neither", p, model::format_value(o.x_in),
                                   p, model::format_value(o.x_out)));
    if (o.levels > 0 && o.finest_nodes() > max_nodes)
      throw InputError(fmt::format("{}levels = {}: at most {} nodes on the finest grid ({} from coarsest_nodes {})",
                                   p, o.levels, max_nodes, o.finest_nodes(), o.coarsest_nodes));
  });
  static const auto tuning = make_tuning_table();
  t.rule([](const EhlOptions& o, const std::string& p) { tuning.validate(o, p); });
  return t;
}

/// The rheology choices of an isothermal line contact.
model::OptionTable<LineContactData> make_rheology_table() {
  model::OptionTable<LineContactData> t;
  t.choice("viscosity_model", &LineContactData::viscosity_model,
           std::vector<std::pair<std::string, ViscosityModel>>{{"roelands", ViscosityModel::roelands},
                                                               {"barus", ViscosityModel::barus}},
           {.description = "pressure-viscosity law"});
  t.choice("density_model", &LineContactData::density_model,
           std::vector<std::pair<std::string, DensityModel>>{{"dowson_higginson", DensityModel::dowson_higginson},
                                                             {"incompressible", DensityModel::incompressible}},
           {.description = "pressure-density law"});
  return t;
}

model::OptionTable<ContactInput> make_contact_table() {
  model::OptionTable<ContactInput> t;
  t.number("reduced_radius_m", &ContactInput::reduced_radius, Range::positive(10.0),
           {.description = "reduced radius of curvature R", .unit = "m", .required = true});
  t.number("load_per_length_N_per_m", &ContactInput::load_per_length, Range::positive(1e10),
           {.description = "normal load per unit length w", .unit = "N/m", .required = true});
  t.number("surface_speeds_m_per_s", &ContactInput::surface_speeds, Range::closed(0.0, 1e3),
           {.description = "surface speeds [u1, u2] (their sum positive)", .unit = "m/s", .required = true});
  t.number("reduced_modulus_Pa", &ContactInput::reduced_modulus, Range::closed(1e6, 1e16),
           {.description = "reduced modulus E' = 2/((1 - nu1^2)/E1 + (1 - nu2^2)/E2)", .unit = "Pa", .required = true});
  t.rule([](const ContactInput& c, const std::string& p) {
    if (c.surface_speeds[0] + c.surface_speeds[1] <= 0.0)
      throw InputError(fmt::format("{}surface_speeds_m_per_s = [{}, {}]: the entrainment speed must be positive", p,
                                   model::format_value(c.surface_speeds[0]), model::format_value(c.surface_speeds[1])));
  });
  return t;
}

model::OptionTable<LineContactData> make_line_lubricant_table() {
  model::OptionTable<LineContactData> t;
  t.number("viscosity_Pa_s", &LineContactData::viscosity, Range::positive(1e4),
           {.description = "dynamic viscosity eta0", .unit = "Pa*s", .required = true});
  t.number("pressure_viscosity_1_per_GPa", &LineContactData::pressure_viscosity, Range::closed(0.0, 100.0),
           {.description = "pressure-viscosity coefficient alpha", .unit = "1/GPa", .scale = 1e-9, .required = true});
  t.number("roelands_z", &LineContactData::roelands_z, Range::positive(2.0),
           {.description = "Roelands pressure index z; absent: derived from alpha", .unset = 0.0});
  t.include([](auto& d) -> auto& { return d; }, rheology_table());
  return t;
}

model::OptionTable<MoesPoint> make_moes_table() {
  model::OptionTable<MoesPoint> t;
  t.number("M", &MoesPoint::M, Range::closed(1e-3, 1e4), {.description = "Moes load parameter M", .required = true});
  t.number("L", &MoesPoint::L, Range::closed(0.0, 100.0),
           {.description = "Moes material parameter L", .required = true});
  return t;
}

model::OptionTable<model::DoubleInvoluteRack> make_rack_table() {
  using R = model::DoubleInvoluteRack;
  model::OptionTable<R> t;
  t.number("tip_tangential_shift", &R::tip_tangential_shift, Range::closed(0.0, 0.5),
           {.description = "y_a*: the tip line moved towards the tooth centre, in m_n", .required = true});
  t.number("root_tangential_shift", &R::root_tangential_shift, Range::closed(0.0, 0.5),
           {.description = "y_d*: the root line moved away from the tooth centre, in m_n", .required = true});
  t.number("waist_tip_depth", &R::waist_tip_depth, Range::closed(0.0, 2.0),
           {.description = "l_a*: depth of the tip line's lower end below the datum line, in m_n", .required = true});
  t.number("waist_root_depth", &R::waist_root_depth, Range::closed(0.0, 2.0),
           {.description = "l_d*: depth of the root line's upper end below the datum line, in m_n", .required = true});
  return t;
}

/// The key every load-perturbing film-stiffness solve shares.
template <class O>
void add_perturbation(model::OptionTable<O>& t) {
  t.number("perturbation", &O::perturbation, Range{0.0, 0.2, true, false},
           {.description = "delta: the film stiffness is a central difference at loads w(1 +- delta)"});
}

template <class O>
void add_grid(model::OptionTable<O>& t) {
  t.section("grid", &O::grid, EhlOptions::table(), {.description = "the EHL multigrid"});
}

/// The solvers that follow a contact by a sequence of warm-started solves need a fixed grid.
template <class O>
void add_fixed_grid_rule(model::OptionTable<O>& t, std::string who) {
  t.rule([who](const O& o, const std::string& p) {
    if (o.grid.adaptive())
      throw InputError(fmt::format("{}grid.nodes: {} needs a fixed grid (grid.nodes or grid.levels)", p, who));
  });
}

model::OptionTable<TransientMeshOptions> make_transient_table() {
  model::OptionTable<TransientMeshOptions> t;
  t.integer("time_steps", &TransientMeshOptions::steps, 4, 100000, {.description = "time steps from A to E"});
  model::add_load_sharing(t, &TransientMeshOptions::load_sharing);
  add_grid(t);
  add_fixed_grid_rule(t, "ehl_transient");
  return t;
}

model::OptionTable<OilFilmStiffnessOptions> make_oil_film_table() {
  model::OptionTable<OilFilmStiffnessOptions> t;
  t.integer("positions", &OilFilmStiffnessOptions::positions, 1, 10000,
            {.description = "contact positions: centres of equal steps from A to E"});
  add_perturbation(t);
  model::add_load_sharing(t, &OilFilmStiffnessOptions::load_sharing);
  add_grid(t);
  return t;
}

model::OptionTable<MeshPeriodOilFilmOptions> make_mesh_period_table() {
  model::OptionTable<MeshPeriodOilFilmOptions> t;
  t.integer("mesh_samples", &MeshPeriodOilFilmOptions::samples, 1, 10000,
            {.description = "instants: centres of equal steps of one mesh period"});
  t.integer("points_per_piece", &MeshPeriodOilFilmOptions::points_per_piece, 1, 20,
            {.description = "Gauss-Legendre points along a helical contact-line piece"});
  add_perturbation(t);
  add_grid(t);
  return t;
}

/// Which heat sources the film's energy equation holds: a view of the two switches as one key.
enum class HeatSources { shear_and_compression, shear, compression, none };
constexpr bool heats_by_shear(HeatSources s) { return s == HeatSources::shear_and_compression || s == HeatSources::shear; }
constexpr bool heats_by_compression(HeatSources s) {
  return s == HeatSources::shear_and_compression || s == HeatSources::compression;
}
/// FilmTemperatureOptions' shear_heating and compression, read and written as one HeatSources.
template <class B>
struct HeatSourcesRef {
  B& shear;
  B& compression;
  bool operator==(HeatSources s) const { return shear == heats_by_shear(s) && compression == heats_by_compression(s); }
  const HeatSourcesRef& operator=(HeatSources s) const {
    shear = heats_by_shear(s);
    compression = heats_by_compression(s);
    return *this;
  }
};
template <class F>
HeatSourcesRef<std::conditional_t<std::is_const_v<F>, const bool, bool>> heat_sources(F& film) {
  return {film.shear_heating, film.compression};
}

/// The thermal iteration's settings the C++ API alone sets.
model::OptionTable<ThermalEhlOptions> make_thermal_tuning_table() {
  model::OptionTable<ThermalEhlOptions> t;
  t.integer("sweeps_per_iteration", &ThermalEhlOptions::sweeps_per_iteration, 1, 1000,
            {.description = "temperature sweeps between pressure solves"});
  t.integer("cycles_per_iteration", &ThermalEhlOptions::cycles_per_iteration, 1, 1000,
            {.description = "multigrid cycles per pressure solve"});
  t.choice("pressure_cycle", &ThermalEhlOptions::pressure_cycle, cycle_choices(),
           {.description = "multigrid cycle of the warm-started pressure solves inside the coupling"});
  t.number("film_tolerance", &ThermalEhlOptions::film_tolerance, Range{0.0, 0.1, true, true},
           {.description = "relative change of h_min between iterations"});
  t.number("factor_relaxation", &ThermalEhlOptions::factor_relaxation, Range{0.0, 1.0, true, false},
           {.description = "Anderson's mixing of the viscosity and density factors"});
  t.integer("anderson_depth", &ThermalEhlOptions::anderson_depth, 0, 50,
            {.description = "factor differences Anderson's acceleration keeps"});
  t.integer("nested_above_nodes", &ThermalEhlOptions::nested_above_nodes, 9, max_nodes,
            {.description = "grids of more nodes start from the converged solution of the grid half as fine"});
  return t;
}

model::OptionTable<ThermalEhlOptions> make_thermal_section_table() {
  model::OptionTable<ThermalEhlOptions> t;
  t.integer("film_nodes", [](auto& o) -> auto& { return o.film.film_nodes; }, 4, 200,
            {.description = "nodes across the film"});
  t.integer("solid_nodes", [](auto& o) -> auto& { return o.film.solid_nodes; }, 3, 200,
            {.description = "nodes into each solid, surface and depth included"});
  t.number("solid_depth_mm", [](auto& o) -> auto& { return o.film.depth; }, Range::positive(1e3),
           {.description = "depth below which the solids stay at the inlet temperature; absent: from the Hertz "
                           "half-width and the Peclet numbers",
            .unit = "mm", .scale = 1e-3, .unset = 0.0});
  t.choice("heat_sources", [](auto& o) { return heat_sources(o.film); },
           std::vector<std::pair<std::string, HeatSources>>{
               {"shear_and_compression", HeatSources::shear_and_compression},
               {"shear", HeatSources::shear},
               {"compression", HeatSources::compression},
               {"none", HeatSources::none}},
           {.description = "the film's heat sources: shear heating, compression heating"});
  t.integer("max_iterations", &ThermalEhlOptions::max_iterations, 1, 10000,
            {.description = "pressure-temperature iterations before the solve is reported unconverged"});
  t.number("temperature_tolerance", &ThermalEhlOptions::temperature_tolerance, Range{0.0, 10.0, true, true},
           {.description = "largest temperature change between iterations, relative to the film's largest rise "
                           "(at least 10 K)"});
  t.choice("stop", &ThermalEhlOptions::stop,
           std::vector<std::pair<std::string, CouplingStop>>{{"discretisation_error", CouplingStop::discretisation_error},
                                                             {"tolerance", CouplingStop::tolerance}},
           {.description = "stop the pressure-temperature iteration at grid.error_fraction of the estimated "
                           "discretisation error of h_min and the temperature rise (never tighter than the "
                           "tolerances), or at temperature_tolerance and film_tolerance"});
  static const auto tuning = make_thermal_tuning_table();
  t.rule([](const ThermalEhlOptions& o, const std::string& p) { tuning.validate(o, p); });
  return t;
}

model::OptionTable<ThermalEhlOptions> make_thermal_table() {
  model::OptionTable<ThermalEhlOptions> t;
  add_grid(t);
  t.choice("rheology", [](auto& o) -> auto& { return o.film.rheology; },
           std::vector<std::pair<std::string, lubricant::ShearRheology>>{
               {"newtonian", lubricant::ShearRheology::newtonian}, {"eyring", lubricant::ShearRheology::eyring}},
           {.description = "shear response of the film: Newtonian, or Ree-Eyring with tau0 from "
                           "lubricant.eyring_stress_MPa"});
  static const auto thermal = make_thermal_section_table();
  t.section("thermal", [](auto& o) -> auto& { return o; }, thermal,
            {.description = "the thermal solve: film and solid nodes, heat sources, iterations"});
  add_fixed_grid_rule(t, "the thermal solver");
  return t;
}

}  // namespace

const model::OptionTable<EhlOptions>& EhlOptions::table() { return model::built_once<make_grid_table>(); }

void EhlOptions::validate() const { table().validate(*this, "grid."); }

EhlOptions grid_used(const EhlOptions& given, const EhlResult& r) {
  EhlOptions used = given;
  if (given.adaptive() && !r.X.empty()) used.nodes = static_cast<int>(r.X.size());
  return used;
}

const model::OptionTable<LineContactData>& rheology_table() { return model::built_once<make_rheology_table>(); }
const model::OptionTable<ContactInput>& ContactInput::table() { return model::built_once<make_contact_table>(); }
void ContactInput::apply(LineContactData& d) const {
  d.reduced_radius = reduced_radius;
  d.load_per_length = load_per_length;
  d.u1 = surface_speeds[0];
  d.u2 = surface_speeds[1];
  d.reduced_modulus = reduced_modulus;
}
const model::OptionTable<LineContactData>& line_lubricant_table() {
  return model::built_once<make_line_lubricant_table>();
}
const model::OptionTable<MoesPoint>& MoesPoint::table() { return model::built_once<make_moes_table>(); }
const model::OptionTable<model::DoubleInvoluteRack>& double_involute_rack_table() {
  return model::built_once<make_rack_table>();
}

const model::OptionTable<TransientMeshOptions>& TransientMeshOptions::table() {
  return model::built_once<make_transient_table>();
}
void TransientMeshOptions::validate() const { table().validate(*this); }

const model::OptionTable<OilFilmStiffnessOptions>& OilFilmStiffnessOptions::table() {
  return model::built_once<make_oil_film_table>();
}
void OilFilmStiffnessOptions::validate() const { table().validate(*this); }

const model::OptionTable<MeshPeriodOilFilmOptions>& MeshPeriodOilFilmOptions::table() {
  return model::built_once<make_mesh_period_table>();
}
void MeshPeriodOilFilmOptions::validate() const { table().validate(*this); }

const model::OptionTable<ThermalEhlOptions>& ThermalEhlOptions::table() {
  return model::built_once<make_thermal_table>();
}
void ThermalEhlOptions::validate() const { table().validate(*this); }

}  // namespace gearbench::ehl
