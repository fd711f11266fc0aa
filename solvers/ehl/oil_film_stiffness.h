#pragma once
// Oil-film stiffness along the path of contact of a spur pair (seed 002): at each contact
// position the steady isothermal EHL line contact of that position (radius, surface speeds,
// the pair's share of the load) is solved at the load perturbed by ±δ, and
//   k_oil = −Δw / Δh_c   [N/m per metre of face width],  h_c the film at the Hertzian centre,
// a central difference (error O(δ²)). The film is a spring in series with the tooth pair:
//   1/k_with_film = 1/k_pair + 1/(b·k_oil),
// k_pair the energy-method pair stiffness (Hertz, bending, shear, axial, foundation).
#include <string>
#include <vector>

#include "geometry/double_involute.h"
#include "geometry/gear_pair_geometry.h"
#include "line_contact_solver.h"
#include "model/materials.h"
#include "model/solve_status.h"

namespace gearbench::ehl {

struct OilFilmStiffnessOptions {
  int positions = 21;                 ///< contact positions: centres of equal steps from A to E
  double perturbation = 0.02;         ///< δ: loads w(1 ± δ)
  std::string load_sharing = "equal";  ///< "equal" or "iso"
  EhlOptions grid = default_grid();

  static EhlOptions default_grid();
  /// The case keys of tooth_form "involute" beside the gear pair and the fluid (ehl_options.cpp).
  static const model::OptionTable<OilFilmStiffnessOptions>& table();
  void validate() const;              ///< InputError naming the key
};

struct OilFilmPoint {
  double position = 0.0;              ///< on the line of action, from T1 [m]
  double load_per_length = 0.0;       ///< w of this pair [N/m]
  double reduced_radius = 0.0;        ///< [m]
  double entrainment = 0.0;           ///< ū [m/s]
  double h_central = 0.0;             ///< at w [m]
  double h_min = 0.0;                 ///< at w [m]
  double p_max = 0.0;                 ///< at w [Pa]
  double stiffness_per_length = 0.0;  ///< k_oil [N/m²]
  double stiffness = 0.0;             ///< b·k_oil [N/m]
  double pair_stiffness = 0.0;        ///< energy method, this pair [N/m]
  double stiffness_with_film = 0.0;   ///< pair and film in series [N/m]
  double film_share = 0.0;            ///< the film's part of the compliance [-]
  double moes_M = 0.0, moes_L = 0.0;
  /// d ln h_dpdx0 / d ln w from the same solves (Moes' film; compared with his formula).
  double film_load_exponent = 0.0;
  int cycles = 0;                     ///< multigrid cycles of the three solves
  double work_units = 0.0;            ///< of the three solves, each in sweeps of its finest grid
};

/// converged and message: model::SolveStatus (the position whose EHL solves failed named).
struct OilFilmStiffnessResult : model::SolveStatus {
  std::vector<OilFilmPoint> points;
  double face_width = 0.0;
  double work_units = 0.0;            ///< of every solve (OilFilmPoint::work_units summed)
  double seconds = 0.0;
  [[nodiscard]] std::string summary() const;
};

class OilFilmStiffness {
 public:
  /// `fluid` supplies η0, α (or z), the rheology models and E′; radius, load and speeds come
  /// from the gears at each position.
  /// Keeps a reference to `geometry`, which must outlive this object.
  OilFilmStiffness(const geometry::GearPairGeometry& geometry, const std::array<model::Material, 2>& materials,
                   const model::OperatingPoint& operating, const LineContactData& fluid,
                   OilFilmStiffnessOptions options);
  /// Throws ConvergenceError naming the position whose EHL solve did not converge.
  [[nodiscard]] OilFilmStiffnessResult solve() const;
  /// The same, returning converged = false, the message and the positions solved before the
  /// failure instead of throwing.
  [[nodiscard]] OilFilmStiffnessResult try_solve() const;

 private:
  [[nodiscard]] LineContactData contact_at(double s, double load_per_length) const;
  [[nodiscard]] EhlResult solve_contact(const LineContactData& d, double s) const;

  const geometry::GearPairGeometry& geometry_;
  std::array<model::Material, 2> materials_;
  model::OperatingPoint operating_;
  LineContactData fluid_;
  OilFilmStiffnessOptions options_;
};

/// Oil-film stiffness over one mesh period of a double-involute pair (seed 002), or of the
/// ordinary involute pair with the same data (a DoubleInvolutePair with a zero step). At each
/// instant the normal force F_bn = T1/(r_b1·cos β_b) spreads uniformly over the total contact-
/// line length L(t), w = F_bn/L(t) (spur: equal sharing between the pairs in contact); every
/// contact point carries the EHL line contact of its position (normal-section reduced
/// radius, surface speeds) under w, and its film stiffness per length k_oil = −Δw/Δh_c is the
/// central difference of two solves at w(1 ± δ). A pair's film stiffness is ∫ k_oil dl along its
/// contact line (spur: b·k_oil; helical: Gauss–Legendre along each piece, dl = ds/sin β_b),
/// the mesh's the sum over the pairs (films of different pairs act in parallel).
struct MeshPeriodOilFilmOptions {
  int samples = 12;             ///< instants: centres of equal steps of one mesh period
  int points_per_piece = 3;     ///< Gauss–Legendre points along a helical contact-line piece
  double perturbation = 0.02;   ///< δ: loads w(1 ± δ)
  EhlOptions grid = OilFilmStiffnessOptions::default_grid();
  /// The case keys of tooth_form "double_involute" beside the rack (ehl_options.cpp).
  static const model::OptionTable<MeshPeriodOilFilmOptions>& table();
  void validate() const;        ///< InputError naming the key
};

struct MeshInstant {
  double time = 0.0;                  ///< from the start of the period [s]
  double travel = 0.0;                ///< τ = ω1·r_b1·t [m]
  double contact_length = 0.0;        ///< L(t), all pairs [m]
  double load_per_length = 0.0;       ///< w = F_bn/L(t) [N/m]
  double film_stiffness = 0.0;        ///< all pairs [N/m]
  double pair2_root_length = 0.0;     ///< L_G2(t) [m]
  double pair2_tip_length = 0.0;      ///< L_D2(t) [m]
  double pair2_film_stiffness = 0.0;  ///< the seed's second pair [N/m]
  /// Normal-section reduced radius at the middle of the second pair's piece in each zone
  /// (the seed's "equivalent radius"; 0 where the pair has no piece in the zone) [m].
  double pair2_root_radius = 0.0, pair2_tip_radius = 0.0;
  double h_central_min = 0.0;         ///< thinnest central film of the instant (mean of the ± solves) [m]
  int pairs = 0;                      ///< pairs in contact
  double work_units = 0.0;            ///< of the instant's solves, each in sweeps of its finest grid
};

/// converged and message: model::SolveStatus (the instant and position whose EHL solves failed named).
struct MeshPeriodOilFilmResult : model::SolveStatus {
  std::vector<MeshInstant> instants;
  double period = 0.0;                ///< [s]
  double mean_film_stiffness = 0.0;   ///< over the instants [N/m]
  int solves = 0;
  double work_units = 0.0;            ///< of every solve (MeshInstant::work_units summed)
  double seconds = 0.0;
  [[nodiscard]] std::string summary() const;
};

class MeshPeriodOilFilm {
 public:
  /// `fluid` supplies η0, α (or z), the rheology models and E′.
  /// Keeps a reference to `pair`, which must outlive this object.
  MeshPeriodOilFilm(const geometry::DoubleInvolutePair& pair, const model::OperatingPoint& operating,
                    const LineContactData& fluid, MeshPeriodOilFilmOptions options);
  /// Throws ConvergenceError naming the position whose EHL solve did not converge.
  [[nodiscard]] MeshPeriodOilFilmResult solve() const;
  /// The same, returning converged = false, the message and the instants solved before the
  /// failure instead of throwing.
  [[nodiscard]] MeshPeriodOilFilmResult try_solve() const;

 private:
  struct FilmPoint {
    double stiffness_per_length = 0.0;  ///< [N/m²]
    double h_central = 0.0;             ///< [m]
    double work_units = 0.0;            ///< of its two solves
  };
  [[nodiscard]] FilmPoint film_at(double s, double load_per_length) const;

  const geometry::DoubleInvolutePair& pair_;
  model::OperatingPoint operating_;
  LineContactData fluid_;
  MeshPeriodOilFilmOptions options_;
};

}  // namespace gearbench::ehl
