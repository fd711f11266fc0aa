#pragma once
// What the dynamics models compute from a recorded time series: mean, rms and peak-to-peak,
// and the one-sided amplitude spectrum by FFTW.
#include <vector>

namespace gearbench::dynamics {

struct ResponseStats {
  double mean = 0, rms = 0, peak_to_peak = 0;
};

[[nodiscard]] ResponseStats statistics(const std::vector<double>& v);

/// One-sided amplitude spectrum of v − mean(v) sampled every dt (no window: records hold
/// whole periods): frequencies f [Hz] and amplitudes a (units of v).
void amplitude_spectrum(const std::vector<double>& v, double dt, std::vector<double>& f, std::vector<double>& a);

}  // namespace gearbench::dynamics
