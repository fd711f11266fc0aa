#pragma once
// What the dynamics models compute from a recorded time series: mean, rms and peak-to-peak,
// and the one-sided amplitude spectrum by FFTW.
#include <vector>

namespace gearbench::dynamics {

struct ResponseStats {
  double mean = 0, rms = 0, peak_to_peak = 0;
};

/// Work over the recorded window [J]: the balance of docs/dynamics-model.md
/// ΔE = W_in − W_out − D_damping − D_friction + W_parametric + W_impact.
struct EnergyBalance {
  double input = 0, output = 0, damping = 0, friction = 0, parametric = 0, impact = 0, energy_change = 0;
  double residual = 0;  ///< relative_residual(): (ΔE − right-hand side) over the dissipation

  /// (ΔE − right-hand side) / (D_damping + D_friction). Where nothing is dissipated (no
  /// damping and no friction, or a load so small that the dissipation underflows) it is taken
  /// over the largest of the other terms, and it is 0 where every term is 0: the balance then
  /// holds trivially (issue 20: a torque of 5e-324 N·m once made it 0/0 and exit 1).
  [[nodiscard]] double relative_residual() const;
};

[[nodiscard]] ResponseStats statistics(const std::vector<double>& v);

/// One-sided amplitude spectrum of v − mean(v) sampled every dt (no window: records hold
/// whole periods): frequencies f [Hz] and amplitudes a (units of v).
void amplitude_spectrum(const std::vector<double>& v, double dt, std::vector<double>& f, std::vector<double>& a);

}  // namespace gearbench::dynamics
