// Seed reproductions of the mesh efficiency (seed 004: spur efficiency over the mesh and its
// trends with torque, speed and pressure angle, and with the thermal friction law beside the
// limit that ties it to the isothermal one; seed 000: static herringbone efficiency),
// and the report's efficiency figures and tables.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "check_registry.h"
#include "closed_form/efficiency_closed_form.h"
#include "dynamics/spur6_dynamics.h"
#include "efficiency/dynamic_efficiency.h"
#include "efficiency/efficiency_sweep.h"
#include "efficiency/ehl_friction.h"
#include "efficiency/mesh_loss.h"
#include "lubricant/thermal_rheology.h"
#include "model/json_reader.h"

namespace gearbench::verification {
namespace {

using efficiency::EhlFriction;
using efficiency::MeshLoss;
using efficiency::MeshLossOptions;
using lubricant::FrictionModel;

const char* section = "Mesh loss and efficiency";
const char* seed_section = "Seed reproductions: efficiency";
const char* solver = "efficiency";
const char* seed004_file = "seed004_spur_efficiency_sweep.json";
const char* seed000_file = "seed000_herringbone_efficiency.json";

struct MediaCase {
  model::GearPair pair;
  model::OperatingPoint operating;
  efficiency::MeshLossMedia media;
};

MediaCase media_case(const CheckContext& ctx, const std::string& file) {
  const auto c = ctx.gear_case(file);
  return {c.gear_pair, *c.operating, {c.materials, c.lubricant}};
}

/// The options of the seed 004 case file: Xu–Kahraman friction, equal sharing (the seed's
/// "equal load on the tooth surfaces"), the default rolling-loss constant.
MeshLossOptions seed004_options() {
  MeshLossOptions o;
  o.friction_model = FrictionModel::xu_kahraman;
  return o;
}

/// Seed 000 case file: mixed friction with μ_BL 0.1, sliding loss only (seed 000 eq. 11).
MeshLossOptions seed000_options() {
  MeshLossOptions o;
  o.friction_model = FrictionModel::mixed;
  o.boundary_friction = 0.1;
  o.rolling_loss_constant = 0.0;
  o.positions = 100;
  return o;
}

efficiency::MeshLossResult seed004_base(const CheckContext& ctx) {
  const auto c = media_case(ctx, seed004_file);
  const geometry::GearPairGeometry g(c.pair);
  return MeshLoss(g, c.operating, seed004_options(), c.media).solve();
}

/// Seed 004 tables 2–4 about the base point (100 N·m, 1000 rpm, 25°).
std::vector<efficiency::SweepRow> seed004_sweeps(const CheckContext& ctx) {
  const auto c = media_case(ctx, seed004_file);
  efficiency::SweepSpec spec{{100, 125, 150, 175, 200}, {1000, 1250, 1500, 1750, 2000}, {20, 22.5, 25, 27.5, 30}};
  return efficiency::efficiency_sweep(c.pair, c.operating, seed004_options(), c.media, spec);
}

std::vector<efficiency::SweepRow> rows_of(const std::vector<efficiency::SweepRow>& rows, const std::string& parameter) {
  std::vector<efficiency::SweepRow> out;
  std::copy_if(rows.begin(), rows.end(), std::back_inserter(out), [&](const auto& r) { return r.parameter == parameter; });
  return out;
}

// --- Seed 004 -------------------------------------------------------------------------------

// The paper reads its efficiency curves (fig. 9a) to about 0.1 %.
const RegisterCheck seed004_min(CheckSpec{
    .id = "seed004.efficiency_min", .section = seed_section, .solver = solver, .reference = "seed 004 (93.8 %)",
    .quantity = "lowest instantaneous efficiency, 100 N·m, 1000 rpm, Xu–Kahraman friction", .unit = "%",
    .tolerance = {0.1, 0}, .justification = "the paper's curves read to ~0.1 %",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto r = seed004_base(ctx);
      return CheckValue{100.0 * r.efficiency_min, 93.8,
                        {{"friction_coefficient_mean", r.friction_coefficient_mean},
                         {"sliding_loss_mean_W", r.sliding_loss_mean}, {"rolling_loss_mean_W", r.rolling_loss_mean},
                         {"h_min_m", r.film_min}}};
    },
    .recorded = 97.9278, .recorded_tolerance = 1e-4});

const RegisterCheck seed004_max(CheckSpec{
    .id = "seed004.efficiency_max", .section = seed_section, .solver = solver, .reference = "seed 004 (99.8 %)",
    .quantity = "highest instantaneous efficiency, 100 N·m, 1000 rpm, Xu–Kahraman friction", .unit = "%",
    .tolerance = {0.1, 0}, .justification = "the paper's curves read to ~0.1 %",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      return CheckValue{100.0 * seed004_base(ctx).efficiency_max, 99.8};
    },
    .recorded = 99.9648, .recorded_tolerance = 1e-4});

// Where the efficiency peaks, against the pitch point, both as fractions of the path A..E
// travelled by the pair that entered last: "highest near the pitch point".
const RegisterCheck seed004_peak(CheckSpec{
    .id = "seed004.efficiency_max_at_pitch_point", .section = seed_section, .solver = solver,
    .reference = "seed 004 (highest near the pitch point)",
    .quantity = "position of the highest efficiency minus the pitch point, fraction of A..E", .unit = "-",
    .tolerance = {0.02, 0},
    .justification = "0.02 of the path (0.03 of a mesh period, ε_α = 1.454) is finer than the paper's figure reads",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto rows = rows_of(seed004_sweeps(ctx), "torque_Nm");
      return CheckValue{rows.front().max_at - rows.front().pitch_at, 0.0,
                        {{"max_at", rows.front().max_at}, {"pitch_at", rows.front().pitch_at}}};
    }});

// "Lowest at engagement": the lowest efficiency lies in the double contact after the pair
// enters at A (path fraction 0 .. (B − A)/(E − A)).
const RegisterCheck seed004_low(CheckSpec{
    .id = "seed004.efficiency_min_at_engagement", .section = seed_section, .solver = solver,
    .reference = "seed 004 (lowest at engagement)",
    .quantity = "position of the lowest efficiency, fraction of A..E from the engagement at A", .unit = "-",
    .tolerance = {0.31, 0},
    .justification = "the engagement double-contact stretch A..B is (ε_α − 1)/ε_α = 0.312 of the path (ε_α = 1.454)",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto c = media_case(ctx, seed004_file);
      const geometry::GearPairGeometry g(c.pair);
      const double b_at = (g.path().B - g.path().A) / (g.path().E - g.path().A);
      const auto rows = rows_of(seed004_sweeps(ctx), "torque_Nm");
      return CheckValue{rows.front().min_at, 0.0, {{"B_at", b_at}}};
    }});

/// Signs of the seed's claims on tables 2–4 (figs. 9b–11b and the text): the mean efficiency
/// rises with torque and speed and falls with the pressure angle; the lowest and highest
/// efficiency both rise with torque; with speed the lowest rises and the highest falls
/// slightly; with the pressure angle both fall slightly; the sliding loss dominates (> 10×
/// the rolling loss). Each compares the ends of the sweep.
const RegisterCheck seed004_trends(CheckSpec{
    .id = "seed004.trends", .section = seed_section, .solver = solver,
    .reference = "seed 004 (10 claims on tables 2–4)",
    .quantity = "claims reproduced: mean/min/max efficiency trends with torque, speed, pressure angle; sliding dominant",
    .unit = "count", .tolerance = {0, 0}, .justification = "each claim is a sign (or an order of magnitude)",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto rows = seed004_sweeps(ctx);
      const auto change = [&](const char* p, double efficiency::SweepRow::*field) {
        const auto r = rows_of(rows, p);
        return r.back().*field - r.front().*field;
      };
      using R = efficiency::SweepRow;
      const auto base = rows_of(rows, "torque_Nm").front();
      const double dominance = base.sliding_loss_mean / base.rolling_loss_mean;
      nlohmann::json d = nlohmann::json::object();
      int met = 0;
      const auto claim = [&](const std::string& name, double value, bool rises) {
        d[name] = value;
        met += rises ? (value > 0) : (value < 0);
      };
      claim("d_eta_mean_torque_pct", 100 * change("torque_Nm", &R::efficiency_mean), true);
      claim("d_eta_mean_speed_pct", 100 * change("speed_rpm", &R::efficiency_mean), true);
      claim("d_eta_mean_angle_pct", 100 * change("pressure_angle_deg", &R::efficiency_mean), false);
      claim("d_eta_min_torque_pct", 100 * change("torque_Nm", &R::efficiency_min), true);
      claim("d_eta_max_torque_pct", 100 * change("torque_Nm", &R::efficiency_max), true);
      claim("d_eta_min_speed_pct", 100 * change("speed_rpm", &R::efficiency_min), true);
      claim("d_eta_max_speed_pct", 100 * change("speed_rpm", &R::efficiency_max), false);
      claim("d_eta_min_angle_pct", 100 * change("pressure_angle_deg", &R::efficiency_min), false);
      claim("d_eta_max_angle_pct", 100 * change("pressure_angle_deg", &R::efficiency_max), false);
      d["sliding_over_rolling"] = dominance;
      met += dominance > 10.0;
      return CheckValue{static_cast<double>(met), 10.0, d};
    },
    .recorded = 9.0, .recorded_tolerance = 0.0});

// --- Seed 004 with the thermal friction law ---------------------------------------------
// The friction laws solved by EHL at every contact (efficiency/ehl_friction.h): "ehl_thermal"
// against the isothermal "ehl" law in their common limit, and seed 004's efficiency with the
// thermal law (the seed: friction "from the mean of a thermal EHL").

const char* thermal_file = "efficiency_seed004_ehl_thermal.json";

/// The seed 004 case of the thermal law with its options (ehl_thermal, equal sharing, 40 positions).
struct Seed004Thermal : MediaCase {
  MeshLossOptions options;
};

Seed004Thermal seed004_thermal(const CheckContext& ctx) {
  Seed004Thermal s{media_case(ctx, thermal_file), {}};
  const auto json = model::read_json_file(ctx.case_path(thermal_file));
  model::ObjectReader root(json, "");
  MeshLossOptions::table().read(root, s.options);
  if (s.options.friction_model != FrictionModel::ehl_thermal)
    throw std::runtime_error(std::string(thermal_file) + ": friction.model is not ehl_thermal");
  return s;
}

/// The case's efficiency with `law` (the "ehl" law with τ0 of the lubricant).
efficiency::MeshLossResult seed004_with(const CheckContext& ctx, FrictionModel law) {
  auto s = seed004_thermal(ctx);
  s.options.friction_model = law;
  if (law == FrictionModel::ehl) s.options.eyring_stress = s.media.lubricant->eyring_stress;
  const geometry::GearPairGeometry g(s.pair);
  return MeshLoss(g, s.operating, s.options, s.media).solve();
}

/// Seed 004 contacts at fractions of the path A..E (not the pitch point, where the sliding and
/// with it the Couette traction vanish and μ is a difference of small numbers), with the load
/// of equal sharing at the nominal torque.
std::vector<ehl::LineContactData> seed004_contacts(const Seed004Thermal& s) {
  const geometry::GearPairGeometry g(s.pair);
  const auto& p = g.path();
  auto fluid = ehl::LineContactData::from_gear_media(*s.media.materials, *s.media.lubricant);
  fluid.roelands_z = 0.0;  // z from η0 and α, as the thermal solver takes it
  std::vector<ehl::LineContactData> out;
  const double force = s.operating.pinion_torque / g.radii(0).base / s.pair.face_width;
  for (const double f : {0.05, 0.25, 0.5, 0.8}) {
    const double at = p.A + f * (p.E - p.A);
    const auto k = g.kinematics(at, s.operating.pinion_speed);
    auto d = fluid;
    d.load_per_length = (at < p.B || at > p.D ? 0.5 : 1.0) * force;
    d.reduced_radius = k.reduced_radius;
    d.u1 = k.u1;
    d.u2 = k.u2;
    out.push_back(d);
  }
  return out;
}

const RegisterCheck isothermal_limit(CheckSpec{
    .id = "efficiency.ehl_thermal.isothermal_newtonian_limit", .section = section, .solver = "efficiency.ehl_friction",
    .reference = "the \"ehl\" law's per-contact solve (isothermal FAS multigrid, traction of its film) with "
                 "τ0 = 1e12 MPa",
    .quantity = "largest relative difference of μ between the \"ehl_thermal\" per-contact solve with heat sources "
                "off and τ0 = 1e12 MPa and the \"ehl\" law's, at seed 004 contacts 0.05, 0.25, 0.5, 0.8 of A..E "
                "(the law's grid, 81 nodes)",
    .unit = "-", .tolerance = {1e-6, 0},
    .justification = "the exact common limit of the two laws: without heat T = T0, and with τ0 → ∞ the Ree–Eyring "
                     "film is Newtonian (η*/η − 1 ≈ −(τ/τ0)²/6 < 1e-8 for these stresses, ≤ 1e13 Pa), so both "
                     "solve the same isothermal Newtonian film on the same grid and integrate the same wall "
                     "stress η·Δu/h − (h/2)·dp/dx; what is left is the multigrid's residual tolerance (1e-8) "
                     "reached along two paths and the thermal iteration's h_min settled to 1e-3 between "
                     "iterations, whose factors are 1 here. The gap at τ0 = 5 MPa (an Eyring film against "
                     "Eyring traction post-processed on a Newtonian film) and with heat is recorded, not held",
    .tier = Tier::fast,
    .run = [](const CheckContext& ctx) {
      const auto s = seed004_thermal(ctx);
      const auto media = efficiency::thermal_friction_media(*s.media.materials, *s.media.lubricant,
                                                            s.operating.oil_temperature);
      auto options = EhlFriction::default_thermal_options();
      options.film.rheology = lubricant::ShearRheology::eyring;
      auto cold = options;
      cold.film.shear_heating = cold.film.compression = false;
      auto newtonian_oil = media.lubricant;
      newtonian_oil.eyring_stress = 1e18;
      const lubricant::ThermalRheology newtonian(newtonian_oil, media.inlet_temperature);
      const lubricant::ThermalRheology eyring(media.lubricant, media.inlet_temperature);
      const double tau0 = *media.lubricant.eyring_stress;
      double gap = 0.0;
      nlohmann::json rows = nlohmann::json::array();
      for (const auto& d : seed004_contacts(s)) {
        const double iso = EhlFriction::isothermal_coefficient(d, 1e18, options.grid);
        const double limit = EhlFriction::thermal_coefficient(d, newtonian, media.solids, cold);
        gap = std::max(gap, std::abs(limit / iso - 1.0));
        const double iso_eyring = EhlFriction::isothermal_coefficient(d, tau0, options.grid);
        const double cold_eyring = EhlFriction::thermal_coefficient(d, eyring, media.solids, cold);
        const double hot_eyring = EhlFriction::thermal_coefficient(d, eyring, media.solids, options);
        rows.push_back({{"w_N_per_m", d.load_per_length}, {"R_m", d.reduced_radius}, {"u_m_per_s", {d.u1, d.u2}},
                        {"newtonian_mu_ehl", iso}, {"newtonian_mu_ehl_thermal_heat_off", limit},
                        {"eyring_5MPa_mu_ehl", iso_eyring}, {"eyring_5MPa_mu_ehl_thermal_heat_off", cold_eyring},
                        {"eyring_5MPa_mu_ehl_thermal", hot_eyring}});
      }
      return CheckValue{gap, 0.0, {{"contacts", rows}}};
    }});

// The paper reads its efficiency curves (fig. 9a) to about 0.1 %, as seed004.efficiency_min.
CheckValue seed004_end(const CheckContext& ctx, bool lowest) {
  const auto t = seed004_with(ctx, FrictionModel::ehl_thermal);
  return CheckValue{100.0 * (lowest ? t.efficiency_min : t.efficiency_max), lowest ? 93.8 : 99.8,
                    {{"efficiency_mean_pct", 100.0 * t.efficiency_mean},
                     {"efficiency_min_pct", 100.0 * t.efficiency_min},
                     {"efficiency_max_pct", 100.0 * t.efficiency_max},
                     {"friction_coefficient_mean", t.friction_coefficient_mean},
                     {"sliding_loss_mean_W", t.sliding_loss_mean}, {"rolling_loss_mean_W", t.rolling_loss_mean}}};
}

CheckSpec seed004_thermal_end(bool lowest) {
  const std::string end = lowest ? "lowest" : "highest";
  return {.id = std::string("seed004.ehl_thermal.efficiency_") + (lowest ? "min" : "max"), .section = seed_section,
          .solver = solver, .reference = lowest ? "seed 004 (93.8 %)" : "seed 004 (99.8 %)",
          .quantity = end + " instantaneous efficiency, 100 N·m, 1000 rpm, friction from the thermal Ree–Eyring EHL "
                            "at every contact (cases/efficiency_seed004_ehl_thermal.json)",
          .unit = "%", .tolerance = {0.1, 0}, .justification = "the paper's curves read to ~0.1 %",
          .tier = Tier::fast, .run = [lowest](const CheckContext& ctx) { return seed004_end(ctx, lowest); },
          .recorded = lowest ? 98.5254 : 99.9566, .recorded_tolerance = 1e-3};
}

const RegisterCheck seed004_thermal_min(seed004_thermal_end(true));
const RegisterCheck seed004_thermal_max(seed004_thermal_end(false));

// --- Seed 000 -------------------------------------------------------------------------------

const RegisterCheck seed000_static(CheckSpec{
    .id = "seed000.static_efficiency", .section = seed_section, .solver = solver, .reference = "seed 000 (99.1 %)",
    .quantity = "mean static efficiency, herringbone, mixed friction, sliding loss only", .unit = "%",
    .tolerance = {0.05, 0}, .justification = "the paper prints one decimal (±0.05 %)",
    .tier = Tier::fast, .run = [](const CheckContext& ctx) {
      const auto c = media_case(ctx, seed000_file);
      const geometry::GearPairGeometry g(c.pair);
      const auto r = MeshLoss(g, c.operating, seed000_options(), c.media).solve();
      return CheckValue{100.0 * r.efficiency_mean, 99.1,
                        {{"friction_coefficient_mean", r.friction_coefficient_mean},
                         {"loss_factor_numeric", r.loss_factor_numeric},
                         {"ohlendorf_HV", reference::ohlendorf_loss_factor(c.pair).H_V}}};
    },
    .recorded = 99.1162, .recorded_tolerance = 1e-4});

// --- Report ---------------------------------------------------------------------------------

std::string law_table(const CheckContext& ctx, std::vector<reports::Series>& curves) {
  const auto c = media_case(ctx, seed004_file);
  const geometry::GearPairGeometry g(c.pair);
  std::string rows;
  for (const auto law : {FrictionModel::xu_kahraman, FrictionModel::benedict_kelley, FrictionModel::iso14179,
                         FrictionModel::mixed}) {
    auto o = seed004_options();
    o.friction_model = law;
    const auto r = MeshLoss(g, c.operating, o, c.media).solve();
    curves.push_back({lubricant::friction_model_name(law), scaled(r.mesh_position, 180.0 / M_PI), scaled(r.efficiency, 100.0)});
    rows += fmt::format("| {} | {:.4f} | {:.3f} | {:.3f} | {:.3f} | {:.1f} | {:.1f} |\n", lubricant::friction_model_name(law),
                        r.friction_coefficient_mean, 100 * r.efficiency_min, 100 * r.efficiency_mean,
                        100 * r.efficiency_max, r.sliding_loss_mean, r.rolling_loss_mean);
  }
  return rows;
}

void add_sweep_figures(const CheckContext& ctx, reports::Report& report) {
  const auto rows = seed004_sweeps(ctx);
  for (const auto& [parameter, label] : {std::pair{"torque_Nm", "input torque [N·m]"},
                                         std::pair{"speed_rpm", "pinion speed [rpm]"},
                                         std::pair{"pressure_angle_deg", "pressure angle [deg]"}}) {
    std::vector<double> x, lo, mean, hi;
    for (const auto& r : rows_of(rows, parameter)) {
      x.push_back(r.value);
      lo.push_back(100 * r.efficiency_min);
      mean.push_back(100 * r.efficiency_mean);
      hi.push_back(100 * r.efficiency_max);
    }
    report.figures.push_back({std::string("efficiency_seed004_sweep_") + parameter, seed_section,
                              std::string("Seed 004 sweep (Xu–Kahraman friction): efficiency against ") + label,
                              label, "η [%]", {{"min", x, lo}, {"mean", x, mean}, {"max", x, hi}}});
  }
}

/// Dynamic efficiency (seed 000 §2.2) from the 6-DOF spur dynamics of the seed 003 pair
/// (constant μ = 0.06 as seed 003): η_D(t) over four mesh periods against the static curve.
std::string add_dynamic_figure(const CheckContext& ctx, reports::Report& report) {
  const auto c = ctx.gear_case("seed003_spur_dynamics.json");
  const geometry::GearPairGeometry g(c.gear_pair);
  dynamics::Spur6Options so;
  so.record_cycles = 4;
  const auto dyn = dynamics::Spur6Dynamics(g, *c.materials, *c.operating, so).solve();
  MeshLossOptions o;
  o.friction_coefficient = 0.06;
  const auto r = efficiency::dynamic_efficiency(g, *c.operating, o, {}, dyn.time, {dyn.mesh_force}, dyn.mesh_frequency);
  std::vector<double> t_ms = scaled(dyn.time, 1e3), static_curve;
  efficiency::DynamicEfficiencyOptions once;
  const auto s = efficiency::dynamic_efficiency(g, *c.operating, o, {}, dyn.time,
                                                {std::vector<double>(dyn.time.size(), dyn.static_mesh_force)},
                                                dyn.mesh_frequency, once);
  report.figures.push_back({"efficiency_dynamic_seed003", section,
                            "Dynamic mesh efficiency η_D(t) from the 6-DOF spur dynamics (seed 003 pair, μ = 0.06)",
                            "time [ms]", "η [%]",
                            {{"dynamic", t_ms, scaled(r.efficiency, 100.0)}, {"static", t_ms, scaled(s.efficiency, 100.0)}}});
  return fmt::format("Dynamic efficiency of the seed 003 pair (6-DOF spur dynamics, 50 N·m, 996 rpm, μ = 0.06): "
                     "mean η_D {:.4f} % against the static {:.4f} % on the same phase grid (dynamic factor {:.3f}). "
                     "With a constant μ the loss is linear in the load, so the dynamic mean moves only through the "
                     "correlation of the force with the sliding speed over the mesh period.",
                     100 * r.mean, 100 * r.static_mean, dyn.dynamic_factor);
}

const RegisterSection efficiency_section(SectionSpec{
    .id = "efficiency", .tier = Tier::fast, .add = [](const CheckContext& ctx, reports::Report& report) {
      std::string closed;
      for (const auto& [label, file] : {std::pair{"seed 004 spur", "seed004_spur_geometry.json"},
                                        std::pair{"seed 001 helical", "seed001_wind_geometry.json"},
                                        std::pair{"seed 000 herringbone", "seed000_herringbone_geometry.json"}}) {
        const auto c = ctx.gear_case(file);
        const geometry::GearPairGeometry g(c.gear_pair);
        const auto r = MeshLoss(g, *c.operating, MeshLossOptions{}).solve();
        const auto hv = reference::ohlendorf_loss_factor(c.gear_pair);
        closed += fmt::format("| {} | {:.5f} | {:.5f} | {:+.2f} % | {:.3f} |\n", label, r.loss_factor_numeric, hv.H_V,
                              100.0 * (r.loss_factor_numeric / hv.H_V - 1.0), 100.0 * r.efficiency_mean);
      }
      report.notes.push_back({section, fmt::format(
          "Closed-form comparison, constant μ = 0.05, equal sharing. H_VL is the numeric loss factor (mean "
          "sliding loss over μ·P_in); for spur gears it equals Ohlendorf's H_V, the same integral. For helical "
          "and herringbone gears the load per unit contact-line length is uniform, and the two differ (+19–20 % "
          "here; REFERENCE-FACTS quotes 15–18 % from a public audit of other pairs).\n\n"
          "| pair | H_VL (numeric) | H_V (Ohlendorf) | difference | mean η [%] |\n|---|---|---|---|---|\n{}", closed)});

      std::vector<reports::Series> curves;
      const auto laws = law_table(ctx, curves);
      report.figures.push_back({"efficiency_seed004_laws", seed_section,
                                "Seed 004 (fig. 9a equivalent): instantaneous efficiency over one mesh period, 100 N·m, 1000 rpm",
                                "pinion rotation from engagement [deg]", "η [%]", curves});
      add_sweep_figures(ctx, report);
      report.notes.push_back({section, add_dynamic_figure(ctx, report)});
      const auto c0 = media_case(ctx, seed000_file);
      const geometry::GearPairGeometry g0(c0.pair);
      const auto r0 = MeshLoss(g0, c0.operating, seed000_options(), c0.media).solve();
      report.figures.push_back({"efficiency_seed000_static", seed_section,
                                "Seed 000 (fig. 4 equivalent): static efficiency of the herringbone pair over one mesh period",
                                "pinion rotation [deg]", "η [%]",
                                {{"mixed friction", scaled(r0.mesh_position, 180.0 / M_PI), scaled(r0.efficiency, 100.0)}}});
      report.notes.push_back({seed_section, fmt::format(
          "**Seed 004.** Friction by the Xu–Kahraman regression (itself a fit to thermal non-Newtonian EHL, the "
          "nearest to the seed's thermal-EHL mean; its S is the flanks' mean rms roughness, √(π/2)·Ra), equal "
          "sharing, Dowson–Higginson film, rolling loss of eq. 9 with C_r = 6.2e8 Pa. Not printed by the seed "
          "and assumed: ν 0.3, Ra 0.4 µm. By law at 100 N·m, "
          "1000 rpm:\n\n| law | mean μ | η min [%] | η mean [%] | η max [%] | sliding [W] | rolling [W] |\n"
          "|---|---|---|---|---|---|---|\n{}\n"
          "The shape is reproduced: lowest efficiency in the engagement double contact, highest at the pitch "
          "point, sliding loss dominant; efficiency rises with torque (the rolling loss barely depends on load) "
          "and with speed (μ falls with entrainment speed), and the maximum falls slightly with speed, as "
          "the paper says. The level is not: the paper's minimum of 93.8 % needs a loss of 6.2 % of the input "
          "power at engagement, a friction coefficient near 0.2 with its equal-load assumption, far above any "
          "lubricated law here (μ 0.05–0.09). Its eq. 10 gives P in kW (T·n/9550) while eqs. 8–9 carry 10⁻³ "
          "factors whose units are not stated; a unit slip there would explain a loss several times ours. The "
          "mean efficiency rises with the pressure angle here (shorter path of contact, less sliding) where the "
          "paper finds it falls; its figure 11 shows both extremes falling slightly, which ours do (9 of the "
          "paper's 10 trend claims hold, see seed004.trends).\n\n"
          "**Seed 000.** Mixed friction (eq. 8) with the Xu–Kahraman full-film coefficient, μ_BL = 0.1, "
          "Zhou–Hoeprich fluid share from λ = h_min/σ; sliding loss only, as eq. 11; uniform load per unit "
          "contact-line length. Assumed: E 206 GPa, α 22/GPa, Ra 0.4 µm. Static mean {:.3f} % against 99.1 %; "
          "mean μ {:.4f}; H_VL {:.4f} against Ohlendorf's {:.4f}. The agreement rests on the assumed roughness, "
          "which the seed does not print: Ra 0.2 / 0.4 / 0.8 µm give 99.35 / 99.12 / 98.34 %, and taking the "
          "regression's S as the mean Ra instead of the mean rms roughness gives 99.19 %. It shows the model "
          "lands in the seed's range, not that it is validated. The seed's dynamic mean (98.8 %) needs the "
          "herringbone dynamics; efficiency::dynamic_efficiency takes any mesh-force series (tested with the "
          "6-DOF spur model).",
          laws, 100 * r0.efficiency_mean, r0.friction_coefficient_mean, r0.loss_factor_numeric,
          reference::ohlendorf_loss_factor(c0.pair).H_V)});
      report.notes.push_back({seed_section, fmt::format(
          "Seed 000 eq. 13 gives {:.2f} % with the normal pressure angle 18.334° and {:.2f} % "
          "with the printed transverse 20°. The paper's 98.9 % lies between the two, and "
          "neither rounds to it: (22 − 0.8α) = 6.74 would need α ≈ 19.1°.",
          100.0 * reference::agma6011_efficiency(17, 44, 18.334317), 100.0 * reference::agma6011_efficiency(17, 44, 20.0))});
    }});

}  // namespace
}  // namespace gearbench::verification
