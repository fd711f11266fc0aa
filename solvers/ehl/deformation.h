#pragma once
// Elastic deformation of a line contact on a uniform grid (Venner & Lubrecht 2000, ch. 3):
//   W_i = Σ_j K_{|i−j|}·P_j,   K_k = ∫ ln|X_i − X'| dX' over cell j of width h (P constant
//   per cell), i.e. K_k = (a + h/2)(ln|a + h/2| − 1) − (a − h/2)(ln|a − h/2| − 1), a = k·h.
// The film uses H = H0 + X²/2 − (D/π)·W. K is Toeplitz, so W is a linear convolution:
// evaluated by FFTW with zero padding to the first 7-smooth size ≥ 2n − 2 (Liu, Wang & Liu,
// Wear 243, 2000: DC-FFT), in O(n log n), or by the direct O(n²) sum that serves as its baseline.
#include <fftw3.h>

#include <memory>
#include <vector>

namespace gearbench::ehl {

class Deformation {
 public:
  /// Grid of `nodes` points with spacing h.
  Deformation(std::size_t nodes, double h);
  ~Deformation();
  Deformation(const Deformation&) = delete;
  Deformation& operator=(const Deformation&) = delete;

  /// W = K ∗ P by zero-padded FFT convolution.
  void apply(const std::vector<double>& P, std::vector<double>& W) const;
  /// W = K ∗ P by the direct sum (baseline and test reference).
  void apply_direct(const std::vector<double>& P, std::vector<double>& W) const;

  /// Kernel coefficient K_k for nodes k apart.
  [[nodiscard]] double kernel(std::size_t k) const { return kernel_[k]; }
  [[nodiscard]] std::size_t nodes() const { return n_; }

 private:
  std::size_t n_;
  std::size_t padded_;
  std::vector<double> kernel_;
  std::vector<double> kernel_hat_;  ///< the circulant's transform (real: c is even), over m
  // FFTW buffers (mutable: execution writes them) and the process's plans of this size
  // (deformation.cpp, plans_for: shared, destroyed at exit).
  double* real_buffer_ = nullptr;
  fftw_complex* complex_buffer_ = nullptr;
  fftw_plan forward_ = nullptr;
  fftw_plan backward_ = nullptr;
};

}  // namespace gearbench::ehl
