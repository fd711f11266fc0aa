#include "quadrature/energy_quadrature.h"

#include <algorithm>
#include <functional>
#include <cmath>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_roots.h>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "closed_form/involute_closed_form.h"
#include "model/gsl_status.h"
#include "quadrature/trochoid_fillet.h"

namespace gearbench::reference {

namespace {

constexpr double quadrature_relative_error = 1e-10;
constexpr double root_tolerance = 1e-14;        // absolute, in the root's own unit (rad)
constexpr std::size_t quadrature_limit = 1000;  // subintervals per qagp call
constexpr double shear_factor = 1.2;            // spec, "Energies and compliances"


// ------------------------------------------------------------------ GSL wrappers

// Root of f on [lo, hi] (f(lo), f(hi) of opposite signs or zero) by Brent's method.
template <class Function>
double brent_root(Function f, double lo, double hi) {
  if (f(lo) == 0.0) return lo;
  if (f(hi) == 0.0) return hi;
  gsl_function gf{[](double t, void* p) { return (*static_cast<Function*>(p))(t); }, &f};
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  model::gsl_check(gsl_root_fsolver_set(solver.get(), &gf, lo, hi), "Brent bracket");
  for (int iteration = 0; iteration < 200; ++iteration) {
    model::gsl_check(gsl_root_fsolver_iterate(solver.get()), "Brent iteration");
    lo = gsl_root_fsolver_x_lower(solver.get());
    hi = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(lo, hi, root_tolerance, 0.0) == GSL_SUCCESS)
      return gsl_root_fsolver_root(solver.get());
  }
  throw std::runtime_error("GSL Brent: no convergence to 1e-14 in 200 iterations");
}

// ∫ f over [pts.front(), pts.back()] by gsl_integration_qagp, with the interior points as
// break points (pts sorted, strictly increasing).
template <class Function>
double integrate_with_breaks(Function& f, std::vector<double> pts) {
  gsl_function gf{[](double t, void* p) { return (*static_cast<Function*>(p))(t); }, &f};
  std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> work(
      gsl_integration_workspace_alloc(quadrature_limit), &gsl_integration_workspace_free);
  double result = 0.0, abserr = 0.0;
  model::gsl_check(
      gsl_integration_qagp(&gf, pts.data(), pts.size(), 0.0, quadrature_relative_error,
                           quadrature_limit, work.get(), &result, &abserr),
      "qagp");
  return result;
}

// ------------------------------------------------------------------ per-gear data

double involute_function(double alpha) { return std::tan(alpha) - alpha; }

// Spec, "Per-gear data".
struct Tooth {
  double z;              // number of teeth
  double R, Rb, Rf, Ra;  // reference, base, root and tip radii
  double alpha2;         // half tooth angle at the base circle
};

Tooth tooth_of(const model::GearPair& pair, int gear) {
  const double beta = pair.helix_angle;
  const double an = pair.normal_pressure_angle;
  const double mn = pair.normal_module;
  const double at = std::atan(std::tan(an) / std::cos(beta));
  const double z = pair.teeth[gear];
  const double x = pair.profile_shift[gear];
  Tooth t{};
  t.z = z;
  t.R = z * mn / std::cos(beta) / 2.0;
  t.Rb = t.R * std::cos(at);
  t.Rf = t.R - mn * (pair.dedendum_coef - x);
  t.Ra = pair.tip_diameter ? (*pair.tip_diameter)[gear] / 2.0 : t.R + mn * (pair.addendum_coef + x);
  t.alpha2 = M_PI / (2.0 * z) + 2.0 * x * std::tan(an) / z + involute_function(at);
  return t;
}

// ------------------------------------------------------------------ the involute flank

// Spec, "Tooth coordinates and the involute": x(α), h(α) and dx/dα = R_b(α + α_2)cos α.
double involute_x(const Tooth& t, double a) {
  return t.Rb * ((a + t.alpha2) * std::sin(a) + std::cos(a));
}
double involute_h(const Tooth& t, double a) {
  return t.Rb * ((a + t.alpha2) * std::cos(a) - std::sin(a));
}
double involute_dx(const Tooth& t, double a) { return t.Rb * (a + t.alpha2) * std::cos(a); }

// α at which the involute crosses the circle of radius r ≥ R_b: x² + h² = r². The bracket
// ends are the base circle (ψ = 0) and ψ = r/R_b, where the radius R_b√(1 + ψ²) exceeds r.
double involute_angle_at_radius(const Tooth& t, double r) {
  if (r < t.Rb) throw std::domain_error("the involute has no point below the base circle");
  const auto residual = [&](double a) {
    const double x = involute_x(t, a), h = involute_h(t, a);
    return x * x + h * h - r * r;
  };
  return brent_root(residual, -t.alpha2, r / t.Rb - t.alpha2);
}

// ------------------------------------------------------------------ the beam

// The beam from its start to the load is a chain of pieces, each in its own parameter u:
// straight (u = x), fillet (u = φ, the arc angle from B), trochoid (u = φ, the gear's roll
// angle while the rack generates it) and involute (u = α).
enum class PieceKind { straight, fillet, trochoid, involute };
struct Piece {
  PieceKind kind;
  double lo, hi;  // parameter range, lo < hi
};

struct Beam {
  Tooth tooth;
  double xB, hB;  // the base-circle point B
  double rho;     // fillet radius (spec, "improved" for R_f < R_b)
  double x0, h0;  // beam start
  std::vector<Piece> pieces;
  TrochoidFillet trochoid{};  // the generated fillet (trochoid start only)
};

// A section: its axial position, half thickness and |dx/du|.
struct Section {
  double x, h, jacobian;
};

Section section_at(const Beam& b, PieceKind kind, double u) {
  if (kind == PieceKind::straight) return {u, b.hB, 1.0};
  if (kind == PieceKind::fillet)  // x = x_B − ρ sin φ, h = h_B + ρ(1 − cos φ)
    return {b.xB - b.rho * std::sin(u), b.hB + b.rho * (1.0 - std::cos(u)), b.rho * std::cos(u)};
  if (kind == PieceKind::trochoid) {  // x falls as φ grows from the form to the root circle
    const TrochoidFillet::Point p = b.trochoid.at(u);
    return {p.x, p.h, -p.dx};
  }
  return {involute_x(b.tooth, u), involute_h(b.tooth, u), involute_dx(b.tooth, u)};
}

// Spec, "improved" for R_f < R_b: the arc centred at (x_B, h_B + ρ) joins B to the root
// circle, which it touches at φ_F with (sin φ_F, cos φ_F) = (x_B, h_B + ρ)/(R_f + ρ). The
// polar angle atan(h/x) grows along the arc; if it passes the tooth-space centre line, π/z,
// before φ_F (small z), the beam starts at that crossing (gearbench choice).
void add_fillet(Beam& b) {
  const Tooth& t = b.tooth;
  b.rho = (t.Rb * t.Rb - t.Rf * t.Rf) / (2.0 * (t.Rf - b.hB));
  const auto beyond_space_centre = [&](double phi) {
    const Section s = section_at(b, PieceKind::fillet, phi);
    return std::atan2(s.h, s.x) - M_PI / t.z;
  };
  double phi0 = std::atan2(b.xB, b.hB + b.rho);
  if (beyond_space_centre(phi0) > 0.0) {
    if (beyond_space_centre(0.0) >= 0.0)
      throw std::domain_error("the tooth is wider than its pitch at the base circle");
    phi0 = brent_root(beyond_space_centre, 0.0, phi0);
  }
  b.pieces.push_back({PieceKind::fillet, 0.0, phi0});
  const Section foot = section_at(b, PieceKind::fillet, phi0);
  b.x0 = foot.x;
  b.h0 = foot.h;
}

// Spec, "straight" for R_f < R_b: constant half thickness h_B from x_F = √(R_f² − h_B²) to B.
void add_straight_section(Beam& b) {
  b.x0 = std::sqrt(b.tooth.Rf * b.tooth.Rf - b.hB * b.hB);
  b.pieces.push_back({PieceKind::straight, b.x0, b.xB});
}

// Spec, "The generated fillet": from the root circle (φ_root) to the form circle (φ_form),
// where the involute takes over; returns the involute's α there.
double add_trochoid(Beam& b, const model::GearPair& pair, int gear) {
  b.trochoid = trochoid_fillet(pair, gear);
  b.pieces.push_back({PieceKind::trochoid, b.trochoid.phi_form, b.trochoid.phi_root});
  const TrochoidFillet::Point root = b.trochoid.at(b.trochoid.phi_root);
  const TrochoidFillet::Point form = b.trochoid.at(b.trochoid.phi_form);
  b.x0 = root.x;
  b.h0 = root.h;
  return involute_angle_at_radius(b.tooth, std::hypot(form.x, form.h));
}

// Spec, "Where the beam starts": the piece below the involute (if any), then the involute
// up to α_1.
Beam beam_of(const model::GearPair& pair, int gear, QuadBeamStart start, double alpha1) {
  const Tooth t = tooth_of(pair, gear);
  const double xB = t.Rb * std::cos(t.alpha2), hB = t.Rb * std::sin(t.alpha2);
  Beam b{t, xB, hB, 0.0, xB, hB, {}};  // base_circle: the beam starts at B
  double involute_start = -t.alpha2;
  if (start == QuadBeamStart::trochoid) {
    involute_start = add_trochoid(b, pair, gear);
  } else if (start != QuadBeamStart::base_circle) {
    if (t.Rf >= t.Rb) {  // the beam starts on the involute at the root circle
      involute_start = involute_angle_at_radius(t, t.Rf);
      b.x0 = involute_x(t, involute_start);
      b.h0 = involute_h(t, involute_start);
    } else if (t.Rf <= hB) {
      throw std::domain_error("root circle too small for the beam model");
    } else if (start == QuadBeamStart::circular_arc) {
      add_fillet(b);
    } else {
      add_straight_section(b);
    }
  }
  if (alpha1 < involute_start) throw std::domain_error("load point below the beam start");
  b.pieces.push_back({PieceKind::involute, involute_start, alpha1});
  return b;
}

// ------------------------------------------------------------------ the crack

// Spec, "Cracks": on sections x ≥ x_c the cracked side contributes min(h, h_c).
struct CrackLine {
  bool active = false;
  double xc = 0.0, hc = 0.0;
};

CrackLine crack_line(const Beam& b, const QuadCrack& crack, double alpha1) {
  if (!(crack.length >= 0.0)) throw std::invalid_argument("crack length must be >= 0");
  if (crack.type == QuadCrack::Type::none || crack.length == 0.0) return {};
  double xm = b.x0, hm = b.h0;  // root crack: mouth at the beam start
  if (crack.type == QuadCrack::Type::pitch) {
    const double alpha_g = involute_angle_at_radius(b.tooth, b.tooth.R);
    if (alpha1 <= alpha_g) return {};  // load below the mouth: no effect
    xm = involute_x(b.tooth, alpha_g);
    hm = involute_h(b.tooth, alpha_g);
  }
  return {true, xm - crack.length * std::cos(crack.angle),
          hm - crack.length * std::sin(crack.angle)};
}

double thickness(const Section& s, const CrackLine& c) {
  if (!c.active || s.x < c.xc) return 2.0 * s.h;
  return s.h + std::min(s.h, c.hc);
}

// ------------------------------------------------------------------ break points

// Parameters inside a piece where the integrand jumps (x = x_c) or kinks (h = h_c). On the
// involute x grows with α and h is unimodal (dh/dα = −R_b(α + α_2) sin α: rising for α < 0,
// falling after), so each monotone branch holds at most one crossing of h_c.
std::vector<double> crack_breaks_on_involute(const Tooth& t, const Piece& p, const CrackLine& c) {
  std::vector<double> breaks;
  if (involute_x(t, p.lo) < c.xc && c.xc < involute_x(t, p.hi))
    breaks.push_back(brent_root([&](double a) { return involute_x(t, a) - c.xc; }, p.lo, p.hi));
  const auto h_minus_hc = [&](double a) { return involute_h(t, a) - c.hc; };
  for (auto [lo, hi] : {std::pair{p.lo, std::min(0.0, p.hi)}, std::pair{std::max(0.0, p.lo), p.hi}})
    if (lo < hi && h_minus_hc(lo) * h_minus_hc(hi) < 0.0)
      breaks.push_back(brent_root(h_minus_hc, lo, hi));
  return breaks;
}

// On the fillet both crossings invert in closed form: sin φ = (x_B − x_c)/ρ and
// cos φ = 1 − (h_c − h_B)/ρ.
std::vector<double> crack_breaks_on_fillet(const Beam& b, const CrackLine& c) {
  std::vector<double> breaks;
  const double sin_phi = (b.xB - c.xc) / b.rho;
  if (sin_phi > 0.0 && sin_phi < 1.0) breaks.push_back(std::asin(sin_phi));
  const double cos_phi = 1.0 - (c.hc - b.hB) / b.rho;
  if (cos_phi > -1.0 && cos_phi < 1.0) breaks.push_back(std::acos(cos_phi));
  return breaks;
}

// The trochoid's x and h are smooth in φ with at most a few extrema: sign changes on 256
// steps bracket the crossings of x_c and h_c, Brent's method pins each down.
std::vector<double> crack_breaks_on_trochoid(const Beam& b, const Piece& p, const CrackLine& c) {
  std::vector<double> breaks;
  constexpr int steps = 256;
  for (const auto& f : {std::function<double(double)>([&](double u) { return b.trochoid.at(u).x - c.xc; }),
                        std::function<double(double)>([&](double u) { return b.trochoid.at(u).h - c.hc; })})
    for (int k = 0; k < steps; ++k) {
      const double lo = p.lo + (p.hi - p.lo) * k / steps, hi = p.lo + (p.hi - p.lo) * (k + 1) / steps;
      if (f(lo) * f(hi) < 0.0) breaks.push_back(brent_root(f, lo, hi));
    }
  return breaks;
}

// [lo, interior break points ..., hi] for gsl_integration_qagp.
std::vector<double> quadrature_points(const Beam& b, const Piece& p, const CrackLine& c) {
  std::vector<double> breaks;
  if (c.active) {
    switch (p.kind) {
      case PieceKind::straight:  // h is constant: no kink
        breaks = {c.xc};
        break;
      case PieceKind::fillet:
        breaks = crack_breaks_on_fillet(b, c);
        break;
      case PieceKind::trochoid:
        breaks = crack_breaks_on_trochoid(b, p, c);
        break;
      case PieceKind::involute:
        breaks = crack_breaks_on_involute(b.tooth, p, c);
        break;
    }
  }
  std::vector<double> pts{p.lo};
  std::sort(breaks.begin(), breaks.end());
  for (double u : breaks)
    if (u > pts.back() && u < p.hi) pts.push_back(u);
  pts.push_back(p.hi);
  return pts;
}

// ------------------------------------------------------------------ energies

// ∫ density(x, thickness) dx over the beam, piece by piece in each piece's own parameter.
template <class Density>
double integrate_beam(const Beam& b, const CrackLine& c, const Density& density) {
  bool cut_through = false;  // set instead of throwing through GSL's C frames
  double total = 0.0;
  for (const Piece& p : b.pieces) {
    auto integrand = [&](double u) {
      const Section s = section_at(b, p.kind, u);
      const double t = thickness(s, c);
      if (t <= 0.0) {
        cut_through = true;
        return 0.0;
      }
      return density(s.x, t) * s.jacobian;
    };
    total += integrate_with_breaks(integrand, quadrature_points(b, p, c));
  }
  if (cut_through) throw std::domain_error("the crack cuts a beam section through");
  return total;
}

// Roll angle of the contact on gear `gear` (spec, "The load").
double roll_angle(const model::GearPair& pair, const Tooth& t, int gear, double s) {
  if (gear == 0) return s / t.Rb;
  return (involute_closed_form(pair).line_of_action_length - s) / t.Rb;
}

void check_arguments(const model::GearPair& pair, const model::Material& m, int gear,
                     double face_width) {
  if (gear != 0 && gear != 1) throw std::invalid_argument("gear must be 0 (pinion) or 1 (wheel)");
  if (pair.teeth[gear] <= 0 || !(pair.normal_module > 0.0))
    throw std::invalid_argument("teeth and normal module must be positive");
  if (!(face_width > 0.0)) throw std::invalid_argument("face width must be positive");
  if (!(m.youngs_modulus > 0.0) || !(m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5))
    throw std::invalid_argument("need E > 0 and -1 < nu < 0.5");
}

}  // namespace

// ------------------------------------------------------------------ public functions

QuadCompliance energy_compliance_quadrature(const model::GearPair& pair,
                                            const model::Material& material, int gear, double s,
                                            QuadBeamStart start, const QuadCrack& crack,
                                            double face_width) {
  model::gsl_use_status_codes();
  check_arguments(pair, material, gear, face_width);
  const Tooth tooth = tooth_of(pair, gear);
  const double psi = roll_angle(pair, tooth, gear, s);
  const double psi_tip = involute_angle_at_radius(tooth, tooth.Ra) + tooth.alpha2;
  if (psi > psi_tip * (1.0 + 1e-9)) throw std::domain_error("load point above the tip");

  // Spec, "The load": α_1 = ψ − α_2, load point (x_1, h_1), F_b = F cos α_1, F_a = F sin α_1.
  const double alpha1 = psi - tooth.alpha2;
  const Beam beam = beam_of(pair, gear, start, alpha1);
  const CrackLine crack_at_load = crack_line(beam, crack, alpha1);
  const double x1 = involute_x(tooth, alpha1), h1 = involute_h(tooth, alpha1);
  if (thickness({x1, h1, 0.0}, crack_at_load) <= 0.0)
    throw std::domain_error("the crack cuts the loaded section through");
  const double c = std::cos(alpha1), sn = std::sin(alpha1);

  // Spec, "Energies and compliances": I = t³L/12, A = tL, G = E/(2(1 + ν)).
  const double E = material.youngs_modulus, L = face_width;
  const double G = E / (2.0 * (1.0 + material.poisson_ratio));
  const auto bending = [&](double x, double t) {
    const double arm = c * (x1 - x) - sn * h1;  // M(x)/F, seed 003 eq. 2
    return arm * arm / (E * t * t * t * L / 12.0);
  };
  const auto shear = [&](double, double t) { return shear_factor * c * c / (G * t * L); };
  const auto axial = [&](double, double t) { return sn * sn / (E * t * L); };
  return {integrate_beam(beam, crack_at_load, bending), integrate_beam(beam, crack_at_load, shear),
          integrate_beam(beam, crack_at_load, axial)};
}

QuadLoadGeometry load_geometry_quadrature(const model::GearPair& pair, int gear, double s,
                                          QuadBeamStart start) {
  model::gsl_use_status_codes();
  const Tooth tooth = tooth_of(pair, gear);
  const double alpha1 = roll_angle(pair, tooth, gear, s) - tooth.alpha2;
  const Beam beam = beam_of(pair, gear, start, alpha1);
  return {beam.x0, beam.h0, involute_x(tooth, alpha1), involute_h(tooth, alpha1), alpha1};
}

double hertz_compliance_quadrature(const model::Material& m1, const model::Material& m2,
                                   double face_width) {
  if (!(face_width > 0.0) || !(m1.youngs_modulus > 0.0) || !(m2.youngs_modulus > 0.0))
    throw std::invalid_argument("face width and Young's moduli must be positive");
  const auto softness = [](const model::Material& m) {
    return (1.0 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
  };
  return 2.0 / (M_PI * face_width) * (softness(m1) + softness(m2));
}

QuadContactPath contact_path_quadrature(const model::GearPair& pair) {
  model::gsl_use_status_codes();
  const InvoluteClosedForm closed = involute_closed_form(pair);
  QuadContactPath path;
  path.line_of_action_length = closed.line_of_action_length;
  path.pitch_point = closed.pitch_point_from_T1;
  const std::array<Tooth, 2> teeth{tooth_of(pair, 0), tooth_of(pair, 1)};
  for (int gear : {0, 1})
    path.tip_roll_angle[gear] =
        involute_angle_at_radius(teeth[gear], teeth[gear].Ra) + teeth[gear].alpha2;
  path.end = teeth[0].Rb * path.tip_roll_angle[0];
  path.start = path.line_of_action_length - teeth[1].Rb * path.tip_roll_angle[1];
  return path;
}

}  // namespace gearbench::reference
