#include "oil_film_stiffness.h"

#include <chrono>
#include <cmath>
#include <fmt/format.h>

#include "geometry/load_sharing.h"
#include "model/errors.h"
#include "stiffness/pair_stiffness.h"

namespace gearbench::ehl {

EhlOptions OilFilmStiffnessOptions::default_grid() {
  EhlOptions o;
  o.levels = 5;        // 641 nodes
  o.tolerance = 1e-9;  // Δh_c at δ = 2 % is ~0.3 % of h_c: the solves must be far tighter
  return o;
}

void OilFilmStiffnessOptions::validate() const {
  if (positions < 1 || positions > 10000)
    throw InputError(fmt::format("positions = {}: allowed range is [1, 10000]", positions));
  if (!(perturbation > 0.0 && perturbation <= 0.2))
    throw InputError(fmt::format("perturbation = {}: allowed range is (0, 0.2]", perturbation));
  if (load_sharing != "equal" && load_sharing != "iso")
    throw InputError(fmt::format("load_sharing = \"{}\": allowed values are \"equal\", \"iso\"", load_sharing));
  grid.validate();
}

std::string OilFilmStiffnessResult::summary() const {
  return fmt::format("{} positions, {:.2f} s", points.size(), seconds);
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
  const LineContactProblem problem(d);
  auto r = LineContactSolver(problem, options_.grid).try_solve();
  if (!r.converged)
    throw ConvergenceError(fmt::format(
        "oil-film stiffness: the EHL solve at s = {:.4f} mm (w = {:.4g} N/m, M = {:.3g}, L = {:.3g}) did not "
        "converge in {} cycles", s * 1e3, d.load_per_length, d.moes_M(), d.moes_L(), r.cycles));
  return r;
}

OilFilmStiffnessResult OilFilmStiffness::solve() const {
  const auto start = std::chrono::steady_clock::now();
  const auto sharing = geometry::make_load_sharing(options_.load_sharing, "load_sharing");
  const stiffness::PairStiffness pair(geometry_, materials_, stiffness::BeamStart::improved,
                                      {geometry_.radii(0).root / 2.0, geometry_.radii(1).root / 2.0},
                                      std::nullopt, true);
  const double b = geometry_.pair().face_width;
  const double w_total = operating_.pinion_torque / geometry_.radii(0).base / b;
  const auto& path = geometry_.path();
  const double delta = options_.perturbation;

  OilFilmStiffnessResult out;
  out.face_width = b;
  for (int i = 0; i < options_.positions; ++i) {
    // Cell centres: half a step inside A and E, where the pair still carries load (one
    // position is the middle of the path).
    const double t = (i + 0.5) / options_.positions;
    const double s = path.A + t * (path.E - path.A);
    const double w = sharing->share(geometry_, s) * w_total;
    const auto base = contact_at(s, w);
    const auto r0 = solve_contact(base, s);
    const auto rp = solve_contact(contact_at(s, w * (1.0 + delta)), s);
    const auto rm = solve_contact(contact_at(s, w * (1.0 - delta)), s);

    OilFilmPoint p;
    p.position = s;
    p.load_per_length = w;
    p.reduced_radius = base.reduced_radius;
    p.entrainment = base.mean_speed();
    p.h_central = r0.h_central;
    p.h_min = r0.h_min;
    p.p_max = r0.p_max;
    p.stiffness_per_length = -2.0 * delta * w / (rp.h_central - rm.h_central);
    p.stiffness = b * p.stiffness_per_length;
    p.pair_stiffness = pair.stiffness_per_width(s) * b;
    p.stiffness_with_film = 1.0 / (1.0 / p.pair_stiffness + 1.0 / p.stiffness);
    p.film_share = (1.0 / p.stiffness) / (1.0 / p.pair_stiffness + 1.0 / p.stiffness);
    p.moes_M = base.moes_M();
    p.moes_L = base.moes_L();
    p.film_load_exponent = std::log(rp.h_dpdx0 / rm.h_dpdx0) / std::log((1.0 + delta) / (1.0 - delta));
    p.cycles = r0.cycles + rp.cycles + rm.cycles;
    out.points.push_back(p);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace gearbench::ehl
