#include "deformation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>

namespace gearbench::ehl {

namespace {
/// The forward and backward plans of one padded size.
struct Plans {
  fftw_plan forward = nullptr;
  fftw_plan backward = nullptr;
};

/// The process's plans by padded size; destroyed at exit (a static map alone would free its
/// nodes at exit and leave FFTW's plans unreachable: LeakSanitizer reports them).
struct PlanCache {
  std::mutex mutex;
  std::map<std::size_t, Plans> plans;
  PlanCache() = default;
  PlanCache(const PlanCache&) = delete;
  PlanCache& operator=(const PlanCache&) = delete;
  ~PlanCache() {
    for (auto& [size, p] : plans) {
      fftw_destroy_plan(p.forward);
      fftw_destroy_plan(p.backward);
    }
  }
};

/// FFTW's plans for a padded size, made once per process. Planning costs far more than a
/// transform (measured: 7.6 % of an isothermal 641-node solve's instructions, which builds one
/// Deformation per grid level; a thermal solve builds a multigrid per iteration). A plan runs on
/// any arrays of its size and alignment by new-array execution (fftw_execute_dft_r2c/c2r,
/// thread-safe), and fftw_alloc_* gives every buffer FFTW's SIMD alignment. The planner itself
/// is not thread-safe, hence the lock.
const Plans& plans_for(std::size_t padded) {
  static PlanCache cache;
  const std::lock_guard<std::mutex> lock(cache.mutex);
  if (const auto it = cache.plans.find(padded); it != cache.plans.end()) return it->second;
  double* real = fftw_alloc_real(padded);
  fftw_complex* spectrum = fftw_alloc_complex(padded / 2 + 1);
  if (!real || !spectrum) throw std::runtime_error("FFTW allocation failed");
  const int size = static_cast<int>(padded);
  Plans p{fftw_plan_dft_r2c_1d(size, real, spectrum, FFTW_ESTIMATE),
          fftw_plan_dft_c2r_1d(size, spectrum, real, FFTW_ESTIMATE)};
  fftw_free(real);
  fftw_free(spectrum);
  if (!p.forward || !p.backward) throw std::runtime_error("FFTW planning failed");
  return cache.plans.emplace(padded, p).first->second;
}

/// The smallest m ≥ `least` whose prime factors are 2, 3, 5 and 7, the sizes FFTW's codelets
/// transform fastest. The padding was 2n, which for the multigrid's n = 2^k + 1 is 2·(2^k + 1):
/// 514 = 2·257, 4098 = 2·3·683, 32770 = 2·5·29·113, sizes whose large prime factors FFTW
/// transforms by its generic or Rader codelets (one apply on 16385 nodes took 0.93 ms).
std::size_t smooth_size(std::size_t least) {
  for (std::size_t m = least;; ++m) {
    std::size_t r = m;
    for (const std::size_t p : {2, 3, 5, 7})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

double cell_integral(double a, double h) {
  auto f = [](double t) { return t == 0.0 ? 0.0 : t * (std::log(std::abs(t)) - 1.0); };
  return f(a + 0.5 * h) - f(a - 0.5 * h);
}
}  // namespace

// A circulant of any size m ≥ 2n − 2 holds the symmetric Toeplitz K exactly: the lags
// i − j ∈ [−(n−1), n−1] meet in one index only, m = 2n − 2 putting lags n − 1 and −(n − 1)
// both at index n − 1, where K_{n−1} serves both. For n = 2^k + 1 that is m = 2^(k+1).
Deformation::Deformation(std::size_t nodes, double h)
    : n_(nodes), padded_(smooth_size(std::max<std::size_t>(2 * nodes, 4) - 2)) {
  kernel_.resize(n_);
  for (std::size_t k = 0; k < n_; ++k) kernel_[k] = cell_integral(static_cast<double>(k) * h, h);

  real_buffer_ = fftw_alloc_real(padded_);
  complex_buffer_ = fftw_alloc_complex(padded_ / 2 + 1);
  if (!real_buffer_ || !complex_buffer_) throw std::runtime_error("FFTW allocation failed");
  const Plans& plans = plans_for(padded_);
  forward_ = plans.forward;
  backward_ = plans.backward;

  // Circulant embedding of the symmetric Toeplitz kernel: c = [K_0..K_{n−1}, 0…, K_{n−1}..K_1].
  for (std::size_t i = 0; i < padded_; ++i) real_buffer_[i] = 0.0;
  for (std::size_t k = 0; k < n_; ++k) real_buffer_[k] = kernel_[k];
  for (std::size_t k = 1; k < n_; ++k) real_buffer_[padded_ - k] = kernel_[k];
  fftw_execute_dft_r2c(forward_, real_buffer_, complex_buffer_);
  // c is real and even (c_k = c_{m−k}), so its transform is real: the imaginary parts are
  // rounding. FFTW's transforms are unnormalised; the 1/m of the inverse is taken here, once.
  kernel_hat_.resize(padded_ / 2 + 1);
  const double scale = 1.0 / static_cast<double>(padded_);
  for (std::size_t i = 0; i < kernel_hat_.size(); ++i) kernel_hat_[i] = complex_buffer_[i][0] * scale;
}

Deformation::~Deformation() {
  fftw_free(real_buffer_);
  fftw_free(complex_buffer_);
}

void Deformation::apply(const std::vector<double>& P, std::vector<double>& W) const {
  std::copy(P.begin(), P.begin() + static_cast<std::ptrdiff_t>(n_), real_buffer_);
  std::fill(real_buffer_ + n_, real_buffer_ + padded_, 0.0);
  fftw_execute_dft_r2c(forward_, real_buffer_, complex_buffer_);
  for (std::size_t i = 0; i < kernel_hat_.size(); ++i) {
    complex_buffer_[i][0] *= kernel_hat_[i];
    complex_buffer_[i][1] *= kernel_hat_[i];
  }
  fftw_execute_dft_c2r(backward_, complex_buffer_, real_buffer_);
  W.assign(real_buffer_, real_buffer_ + n_);
}

void Deformation::apply_direct(const std::vector<double>& P, std::vector<double>& W) const {
  W.assign(n_, 0.0);
  for (std::size_t i = 0; i < n_; ++i) {
    double sum = 0.0;
    for (std::size_t j = 0; j < n_; ++j) sum += kernel_[i > j ? i - j : j - i] * P[j];
    W[i] = sum;
  }
}

}  // namespace gearbench::ehl
