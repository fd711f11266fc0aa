#include "oil_film_stiffness.h"

#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <gsl/gsl_integration.h>
#include <limits>
#include <memory>
#include <stdexcept>

#include "geometry/load_sharing.h"
#include "model/errors.h"
#include "model/gsl_status.h"
#include "stiffness/pair_stiffness.h"

namespace gearbench::ehl {

namespace {

/// One steady EHL solve; ConvergenceError naming the position s if it does not converge.
EhlResult converged_solve(const LineContactData& d, const EhlOptions& grid, double s) {
  const LineContactProblem problem(d);
  auto r = LineContactSolver(problem, grid).try_solve();
  if (!r.converged)
    throw ConvergenceError(fmt::format(
        "oil-film stiffness: the EHL solve at s = {:.4f} mm (w = {:.4g} N/m, M = {:.3g}, L = {:.3g}) did not "
        "converge: {}", s * 1e3, d.load_per_length, d.moes_M(), d.moes_L(), r.message));
  return r;
}

/// The steady solves at the loads w(1 ± δ) of a nominal contact and the film stiffness
/// between them, k_oil = −Δw/Δh_c = −2δw/(h_c(w(1 + δ)) − h_c(w(1 − δ))) [N/m per metre of
/// face width], a central difference (error O(δ²)).
struct LoadStep {
  EhlResult plus, minus;
  double stiffness_per_length = 0.0;
};

/// An EHL film thins as the load rises in every regime (Moes' load exponents are all negative),
/// so a film that is not thinner at the higher load is a difference the two solves did not
/// resolve (their algebraic or discretisation errors differ by more than Δh_c): a
/// ConvergenceError naming the position and the films, never a negative stiffness (issue 20).
LoadStep solve_load_step(const LineContactData& nominal, const EhlOptions& grid, double delta, double s) {
  const double w = nominal.load_per_length;
  // Both solves on the nominal contact's nodes: the default domain and its mesh spacing move
  // with the load (X_in = −4.5 − 9.2/M with M ∝ w, and x = b·X with b ∝ √w), and their
  // discretisation errors with them, which a difference of 2δ·w takes for the film's response.
  // Measured (seventeenth session), the observed order of k_oil in δ = 16, 8, 4 % at the spur
  // case's mid-path: 2.29 with the domain moving, 1.97 on the nominal nodes; a pure power law
  // h ∝ w^−0.1 gives 2.01.
  const LineContactProblem at_nominal(nominal);
  const double x_in = at_nominal.x_in() * at_nominal.length_scale();
  const double x_out = at_nominal.x_out() * at_nominal.length_scale();
  const auto solve_at = [&](double load) {
    LineContactData d = nominal;
    d.load_per_length = load;
    EhlOptions o = grid;
    if (grid.x_in == 0.0 && grid.x_out == 0.0) {
      const double length = LineContactProblem(d).length_scale();
      o.x_in = x_in / length;
      o.x_out = x_out / length;
    }
    return converged_solve(d, o, s);
  };
  LoadStep step;
  step.plus = solve_at(w * (1.0 + delta));
  step.minus = solve_at(w * (1.0 - delta));
  const double h_plus = step.plus.h_central, h_minus = step.minus.h_central;
  if (!(h_plus < h_minus))
    throw ConvergenceError(fmt::format(
        "oil-film stiffness: at s = {:.4f} mm (M = {:.3g}, L = {:.3g}) the central film at the load w(1 + δ) = "
        "{:.4g} N/m, {:.6g} µm, is not thinner than at w(1 − δ) = {:.4g} N/m, {:.6g} µm: the two EHL solves do not "
        "resolve the film's response to a {:g} % load step (their discretisation errors, which differ between the "
        "two loads, are larger; a finer grid, grid.levels, makes them smaller)",
        s * 1e3, nominal.moes_M(), nominal.moes_L(), w * (1.0 + delta), h_plus * 1e6, w * (1.0 - delta),
        h_minus * 1e6, 100.0 * delta));
  step.stiffness_per_length = -2.0 * delta * w / (h_plus - h_minus);
  return step;
}

}  // namespace

EhlOptions OilFilmStiffnessOptions::default_grid() {
  EhlOptions o;
  // k_oil is a difference quotient of two films: on 641 nodes it was 0.5 % off its 1281-node
  // value at the spur case's mid-path, and its observed order in δ read 2.41 (the grid's error
  // moving with the load) against 2.12 on 1281 nodes and 2.01 for a pure power law h ∝ w^−0.1
  // (seventeenth session, with the inlet that grows with the film).
  o.nodes = 1281;
  o.stop = StopRule::residual;  // a difference of two solves: stopping at the error estimate is too coarse
  o.tolerance = 1e-9;  // Δh_c at δ = 2 % is ~0.3 % of h_c: the solves must be far tighter
  return o;
}

std::string OilFilmStiffnessResult::summary() const {
  return fmt::format("{} positions, {:.1f} work units, {:.2f} s", points.size(), work_units, seconds);
}

OilFilmStiffness::OilFilmStiffness(const geometry::GearPairGeometry& geometry,
                                   const std::array<model::Material, 2>& materials,
                                   const model::OperatingPoint& operating, const LineContactData& fluid,
                                   OilFilmStiffnessOptions options)
    : geometry_(geometry), materials_(materials), operating_(operating), fluid_(fluid), options_(std::move(options)) {
  options_.validate();
  if (geometry_.base_helix_angle() != 0.0)
    throw InputError("gear_pair.helix_angle_deg: oil_film_stiffness follows spur contacts; the pair is helical");
}

LineContactData OilFilmStiffness::contact_at(double s, double load_per_length) const {
  const auto k = geometry_.kinematics(s, operating_.pinion_speed);
  LineContactData d = fluid_;
  d.reduced_radius = k.reduced_radius;
  d.load_per_length = load_per_length;
  d.u1 = k.u1;
  d.u2 = k.u2;
  return d;
}

EhlResult OilFilmStiffness::solve_contact(const LineContactData& d, double s) const {
  return converged_solve(d, options_.grid, s);
}

OilFilmStiffnessResult OilFilmStiffness::solve() const {
  auto r = try_solve();
  if (!r.converged) throw ConvergenceError(r.message);
  return r;
}

OilFilmStiffnessResult OilFilmStiffness::try_solve() const {
  const auto start = std::chrono::steady_clock::now();
  const auto sharing = geometry::make_load_sharing(options_.load_sharing, "load_sharing");
  const stiffness::PairStiffness pair(geometry_, materials_, stiffness::ToothModel{},
                                      {geometry_.radii(0).root / 2.0, geometry_.radii(1).root / 2.0},
                                      std::nullopt, true);
  const double b = geometry_.pair().face_width;
  const double w_total = operating_.pinion_torque / geometry_.radii(0).base / b;
  const auto& path = geometry_.path();
  const double delta = options_.perturbation;

  OilFilmStiffnessResult out;
  out.face_width = b;
  for (int i = 0; i < options_.positions; ++i) try {
    // Cell centres: half a step inside A and E, where the pair still carries load (one
    // position is the middle of the path).
    const double t = (i + 0.5) / options_.positions;
    const double s = path.A + t * (path.E - path.A);
    const double w = sharing->share(geometry_, s) * w_total;
    const auto base = contact_at(s, w);
    const auto r0 = solve_contact(base, s);
    const auto step = solve_load_step(base, options_.grid, delta, s);
    const auto& rp = step.plus;
    const auto& rm = step.minus;

    OilFilmPoint p;
    p.position = s;
    p.load_per_length = w;
    p.reduced_radius = base.reduced_radius;
    p.entrainment = base.mean_speed();
    p.h_central = r0.h_central;
    p.h_min = r0.h_min;
    p.p_max = r0.p_max;
    p.stiffness_per_length = step.stiffness_per_length;
    p.stiffness = b * p.stiffness_per_length;
    p.pair_stiffness = pair.stiffness_per_width(s) * b;
    p.stiffness_with_film = 1.0 / (1.0 / p.pair_stiffness + 1.0 / p.stiffness);
    p.film_share = (1.0 / p.stiffness) / (1.0 / p.pair_stiffness + 1.0 / p.stiffness);
    p.moes_M = base.moes_M();
    p.moes_L = base.moes_L();
    p.film_load_exponent = std::log(rp.h_dpdx0 / rm.h_dpdx0) / std::log((1.0 + delta) / (1.0 - delta));
    p.cycles = r0.cycles + rp.cycles + rm.cycles;
    p.work_units = r0.work_units + rp.work_units + rm.work_units;
    out.work_units += p.work_units;
    out.points.push_back(p);
  } catch (const ConvergenceError& e) {
    out.fail(fmt::format("position {} of {}: {}", i + 1, options_.positions, e.what()));
    break;
  }
  if (out.message.empty())
    out.succeed(fmt::format("converged: the EHL solves at all {} positions met grid.tolerance = {:.1e} within "
                            "grid.max_cycles = {}", options_.positions, options_.grid.tolerance,
                            options_.grid.max_cycles));
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::string MeshPeriodOilFilmResult::summary() const {
  return fmt::format("{} instants over {:.4g} ms, mean film stiffness {:.4g} N/µm, {} EHL solves, {:.1f} work units, "
                     "{:.2f} s", instants.size(), period * 1e3, mean_film_stiffness * 1e-6, solves, work_units, seconds);
}

MeshPeriodOilFilm::MeshPeriodOilFilm(const geometry::DoubleInvolutePair& pair, const model::OperatingPoint& operating,
                                     const LineContactData& fluid, MeshPeriodOilFilmOptions options)
    : pair_(pair), operating_(operating), fluid_(fluid), options_(std::move(options)) {
  options_.validate();
}

MeshPeriodOilFilm::FilmPoint MeshPeriodOilFilm::film_at(double s, double load_per_length) const {
  const auto k = pair_.geometry().kinematics(s, operating_.pinion_speed);
  LineContactData d = fluid_;
  d.reduced_radius = k.reduced_radius_normal;
  d.u1 = k.u1;
  d.u2 = k.u2;
  d.load_per_length = load_per_length;
  const auto step = solve_load_step(d, options_.grid, options_.perturbation, s);
  // The mean of the two films is h_c(w) to O(δ²) (4e-4 of h_c at δ = 2 %), without a third solve.
  return {step.stiffness_per_length, 0.5 * (step.plus.h_central + step.minus.h_central),
          step.plus.work_units + step.minus.work_units};
}

MeshPeriodOilFilmResult MeshPeriodOilFilm::solve() const {
  auto r = try_solve();
  if (!r.converged) throw ConvergenceError(r.message);
  return r;
}

MeshPeriodOilFilmResult MeshPeriodOilFilm::try_solve() const {
  const auto start = std::chrono::steady_clock::now();
  const auto& g = pair_.geometry();
  const double beta_b = g.base_helix_angle();
  const double normal_force = operating_.pinion_torque / (g.radii(0).base * std::cos(beta_b));
  const double pb = g.base_pitch_transverse();
  model::gsl_use_status_codes();
  const std::unique_ptr<gsl_integration_glfixed_table, decltype(&gsl_integration_glfixed_table_free)> table(
      gsl_integration_glfixed_table_alloc(static_cast<std::size_t>(options_.points_per_piece)),
      &gsl_integration_glfixed_table_free);
  if (!table) throw std::runtime_error("GSL Gauss–Legendre table allocation failed");

  MeshPeriodOilFilmResult out;
  out.period = pair_.mesh_period(operating_.pinion_speed);
  for (int i = 0; i < options_.samples; ++i) try {
    MeshInstant m;
    m.travel = (i + 0.5) / options_.samples * pb;
    m.time = m.travel / (operating_.pinion_speed * g.radii(0).base);
    const auto pieces = pair_.contact_pieces(m.travel);
    for (const auto& p : pieces) m.contact_length += p.length;
    m.load_per_length = normal_force / m.contact_length;
    m.h_central_min = std::numeric_limits<double>::infinity();
    // The film at s, its central film, work and two solves counted into the instant.
    const auto film = [&](double s) {
      const auto f = film_at(s, m.load_per_length);
      m.h_central_min = std::min(m.h_central_min, f.h_central);
      m.work_units += f.work_units;
      out.solves += 2;
      return f;
    };
    int last_pair = 0;
    for (const auto& p : pieces) {
      double stiffness = 0.0;
      if (beta_b == 0.0) {
        stiffness = p.length * film(p.s_begin).stiffness_per_length;
      } else {
        for (std::size_t j = 0; j < table->n; ++j) {
          double s = 0.0, weight = 0.0;
          model::gsl_check(gsl_integration_glfixed_point(p.s_begin, p.s_end, j, &s, &weight, table.get()),
                           "Gauss–Legendre point");
          stiffness += weight * film(s).stiffness_per_length / std::sin(beta_b);
        }
      }
      m.film_stiffness += stiffness;
      if (p.pair != last_pair) ++m.pairs;
      last_pair = p.pair;
      if (p.pair != 2) continue;
      m.pair2_film_stiffness += stiffness;
      const double radius =
          g.kinematics(0.5 * (p.s_begin + p.s_end), operating_.pinion_speed).reduced_radius_normal;
      (p.zone == geometry::ToothZone::root ? m.pair2_root_length : m.pair2_tip_length) = p.length;
      (p.zone == geometry::ToothZone::root ? m.pair2_root_radius : m.pair2_tip_radius) = radius;
    }
    out.mean_film_stiffness += m.film_stiffness / options_.samples;
    out.work_units += m.work_units;
    out.instants.push_back(m);
  } catch (const ConvergenceError& e) {
    out.fail(fmt::format("instant {} of {}: {}", i + 1, options_.samples, e.what()));
    break;
  }
  if (out.message.empty())
    out.succeed(fmt::format("converged: the {} EHL solves at {} instants met grid.tolerance = {:.1e} within "
                            "grid.max_cycles = {}", out.solves, options_.samples, options_.grid.tolerance,
                            options_.grid.max_cycles));
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace gearbench::ehl
