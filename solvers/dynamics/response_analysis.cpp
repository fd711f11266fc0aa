#include "response_analysis.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>

namespace gearbench::dynamics {

ResponseStats statistics(const std::vector<double>& v) {
  ResponseStats s;
  const double n = static_cast<double>(v.size());
  s.mean = std::accumulate(v.begin(), v.end(), 0.0) / n;
  double sq = 0.0;
  for (double x : v) sq += x * x;
  s.rms = std::sqrt(sq / n);
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  s.peak_to_peak = *hi - *lo;
  return s;
}

void amplitude_spectrum(const std::vector<double>& v, double dt, std::vector<double>& f, std::vector<double>& a) {
  const int n = static_cast<int>(v.size());
  std::vector<double> in(v);
  const double mean = std::accumulate(in.begin(), in.end(), 0.0) / n;
  for (auto& x : in) x -= mean;
  std::vector<std::complex<double>> out(static_cast<std::size_t>(n / 2 + 1));
  fftw_plan plan = fftw_plan_dft_r2c_1d(n, in.data(), reinterpret_cast<fftw_complex*>(out.data()), FFTW_ESTIMATE);
  fftw_execute(plan);
  fftw_destroy_plan(plan);
  f.resize(out.size());
  a.resize(out.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    f[k] = static_cast<double>(k) / (n * dt);
    const bool unpaired = k == 0 || 2 * static_cast<int>(k) == n;  // DC and Nyquist have no mirror
    a[k] = (unpaired ? 1.0 : 2.0) * std::abs(out[k]) / n;
  }
}

double EnergyBalance::relative_residual() const {
  const double imbalance = energy_change - (input - output - damping - friction + parametric + impact);
  double scale = damping + friction;
  if (!(scale > 0.0))
    scale = std::max({std::abs(input), std::abs(output), std::abs(parametric), std::abs(impact), std::abs(energy_change)});
  if (!(scale > 0.0)) return 0.0;  // every term is zero, and so is the imbalance
  return imbalance / scale;
}

}  // namespace gearbench::dynamics
