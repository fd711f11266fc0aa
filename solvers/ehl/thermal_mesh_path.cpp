#include "thermal_mesh_path.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "geometry/load_sharing.h"
#include "model/errors.h"

namespace gearbench::ehl {

ThermalMeshPath::ThermalMeshPath(const geometry::GearPairGeometry& geometry, const model::OperatingPoint& operating,
                                 const std::array<model::Material, 2>& materials,
                                 const lubricant::ThermalRheology& rheology, const model::ThermalSolids& solids,
                                 model::LoadFactors factors, std::string load_sharing, ThermalEhlOptions options)
    : geometry_(geometry), operating_(operating), materials_(materials), rheology_(rheology), solids_(solids),
      factors_(factors), load_sharing_(std::move(load_sharing)), options_(std::move(options)) {
  options_.validate();
  geometry::make_load_sharing(load_sharing_, "load_sharing");  // validates the name
}

std::vector<ThermalPathPoint> ThermalMeshPath::contacts() const {
  const auto sharing = geometry::make_load_sharing(load_sharing_, "load_sharing");
  const auto& path = geometry_.path();
  // A and E are the ends of contact, where the ISO share is still 1/3 (spur): taken a hair
  // inside so that the pair in question carries its load.
  const double inset = 1e-9 * (path.E - path.A);
  const std::vector<std::pair<std::string, double>> named{
      {"A", path.A + inset}, {"AB", path.AB}, {"B", path.B}, {"C", path.C},
      {"D", path.D},         {"DE", path.DE}, {"E", path.E - inset}};
  const double full_load = factors_.product() * operating_.pinion_torque / geometry_.radii(0).base /
                           geometry_.pair().face_width;
  const double E_reduced = model::reduced_modulus(materials_);
  std::vector<ThermalPathPoint> points;
  for (const auto& [name, s] : named) {
    const auto k = geometry_.kinematics(s, operating_.pinion_speed);
    ThermalPathPoint pt;
    pt.name = name;
    pt.position = s;
    pt.load_share = sharing->share(geometry_, s);
    pt.contact.reduced_radius = k.reduced_radius_normal;
    pt.contact.load_per_length = pt.load_share * full_load;
    pt.contact.u1 = k.u1;
    pt.contact.u2 = k.u2;
    pt.contact.reduced_modulus = E_reduced;
    pt.hertz_pressure = std::sqrt(pt.contact.load_per_length * E_reduced /
                                  (2.0 * std::numbers::pi * pt.contact.reduced_radius));
    pt.slide_to_roll = k.slide_to_roll;
    points.push_back(std::move(pt));
  }
  return points;
}

std::string ThermalMeshPath::attempt(ThermalPathPoint& pt) const {
  const ThermalLineContact contact(pt.contact, rheology_, solids_, options_);
  const auto& d = contact.isothermal_data();
  const std::string where = fmt::format(
      "point {} of the path (R {:.4g} m, w {:.4g} N/m, u [{:.4g}, {:.4g}] m/s, p_H {:.4g} GPa, Moes M {:.4g}, "
      "L {:.4g})", pt.name, d.reduced_radius, d.load_per_length, d.u1, d.u2, pt.hertz_pressure * 1e-9,
      d.moes_M(), d.moes_L());
  try {
    pt.result = contact.try_solve();
  } catch (const ConvergenceError& e) {
    pt.result.fail(e.what());
    return fmt::format("{}: {}", where, e.what());
  }
  if (!pt.result.converged)
    return fmt::format("thermal EHL at {} did not converge: {}", where, pt.result.message);
  return {};
}

void ThermalMeshPath::solve(ThermalPathPoint& pt) const {
  if (auto failure = attempt(pt); !failure.empty()) throw ConvergenceError(failure);
}

std::string ThermalPathResult::summary() const {
  int iterations = 0;
  for (const auto& pt : points) iterations += pt.result.iterations;
  const auto& thinnest = points.empty() ? ThermalPathPoint{} : points[static_cast<std::size_t>(minimum_film_point)];
  return fmt::format("{} points, {} thermal iterations, {:.2f} s; smallest h_min {:.4e} m at {}{}", points.size(),
                     iterations, seconds, thinnest.result.h_min, thinnest.name,
                     converged ? "" : fmt::format(" (point {} did not converge)", points.back().name));
}

ThermalPathPoint ThermalMeshPath::solve_point(const std::string& name) const {
  auto points = contacts();
  const auto it = std::find_if(points.begin(), points.end(), [&](const auto& p) { return p.name == name; });
  if (it == points.end())
    throw InputError(fmt::format("point \"{}\": allowed are A, AB, B, C, D, DE, E", name));
  solve(*it);
  return std::move(*it);
}

ThermalPathResult ThermalMeshPath::run(const std::function<void(const std::string&)>& progress) const {
  auto out = try_run(progress);
  if (!out.converged) throw ConvergenceError(out.message);
  return out;
}

ThermalPathResult ThermalMeshPath::try_run(const std::function<void(const std::string&)>& progress) const {
  const auto start = std::chrono::steady_clock::now();
  ThermalPathResult out;
  out.points = contacts();
  for (auto& pt : out.points) {
    if (auto failure = attempt(pt); !failure.empty()) {
      out.points.resize(static_cast<std::size_t>(&pt - out.points.data()) + 1);  // up to the failed point
      out.fail(std::move(failure));
      break;
    }
    if (progress)
      progress(fmt::format("thermal EHL point {} ({}/{}): h_min {:.4f} µm, film temperature rise {:.2f} K, {} "
                           "iterations, {:.2f} s", pt.name, &pt - out.points.data() + 1, out.points.size(),
                           pt.result.h_min * 1e6, pt.result.temperature_rise_max, pt.result.iterations,
                           pt.result.seconds));
  }
  if (out.message.empty())
    out.succeed(fmt::format("converged: the thermal EHL at all {} points of the path (A, AB, B, C, D, DE, E) "
                            "converged", out.points.size()));
  for (std::size_t i = 1; i < out.points.size(); ++i)
    if (out.points[i].result.h_min < out.points[static_cast<std::size_t>(out.minimum_film_point)].result.h_min)
      out.minimum_film_point = static_cast<int>(i);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace gearbench::ehl
