#include "reynolds_stencil.h"

#include <algorithm>

namespace gearbench::ehl {

double ReynoldsCoefficients::jacobian(std::size_t i, std::size_t j) const {
  return film_response(film_derivative(i), i, j) + local_jacobian(i, j);
}

void ReynoldsCoefficients::jacobian_row(std::size_t i, std::size_t first, std::size_t last, double* out) const {
  const auto dL_dH = film_derivative(i);
  for (std::size_t j = first; j <= last; ++j) out[j - first] = film_response(dL_dH, i, j) + local_jacobian(i, j);
}

double ReynoldsCoefficients::film_response(const std::array<double, 3>& dL_dH, std::size_t i, std::size_t j) const {
  // Wedge and squeeze: −υ·Σ_m w_m ρ̄_{i−m} δH_{i−m}/h − ρ̄_i δH_i/ΔT with δH_k = −(D/π)K_|k−j| δP_j.
  double value = 0.0;
  for (std::size_t m = 0; m < 3 && m <= i; ++m)
    if (dL_dH[m] != 0.0) value -= film_factor * dL_dH[m] * deformation.kernel(i - m > j ? i - m - j : j - (i - m));
  return value;
}

std::array<double, 3> ReynoldsCoefficients::film_derivative(std::size_t i) const {
  const auto w = wedge_weights(i);
  std::array<double, 3> d{};
  for (std::size_t m = 0; m < 3 && m <= i; ++m) d[m] = -speed * w[m] * rho[i - m] / h;
  if (time_step > 0.0) d[0] -= rho[i] / time_step;
  return d;
}

double ReynoldsCoefficients::local_jacobian(std::size_t i, std::size_t j) const {
  double value = 0.0;
  if (rho_dP != nullptr && j <= i && i - j < 3) {
    // −υ·w_{i−j}·(dρ̄_j/dP)·H_j/h (and −(dρ̄_i/dP)·H_i/ΔT): the density of node j moves with P_j.
    const double own = (*rho_dP)[j] * std::max((*H)[j], 0.0);
    value -= speed * wedge_weights(i)[i - j] * own / h;
    if (time_step > 0.0 && j == i) value -= own / time_step;
  }
  // Poiseuille: (ε_{i−½}(P_{i−1} − P_i) + ε_{i+½}(P_{i+1} − P_i))/h².
  const double h2 = h * h;
  if (j == i) value -= (eps_face[i - 1] + eps_face[i]) / h2;
  if (j + 1 == i) value += eps_face[i - 1] / h2;
  if (j == i + 1) value += eps_face[i] / h2;
  if (eps_face_dP_left != nullptr) {
    // (∂ε_{i−½}/∂P_j)(P_{i−1} − P_i)/h² + (∂ε_{i+½}/∂P_j)(P_{i+1} − P_i)/h².
    const auto& p = *P;
    const auto& left = *eps_face_dP_left;
    const auto& right = *eps_face_dP_right;
    if (j + 1 == i) value += left[i - 1] * (p[i - 1] - p[i]) / h2;
    if (j == i) value += (right[i - 1] * (p[i - 1] - p[i]) + left[i] * (p[i + 1] - p[i])) / h2;
    if (j == i + 1) value += right[i] * (p[i + 1] - p[i]) / h2;
  }
  return value;
}

double ReynoldsCoefficients::h0_derivative(std::size_t i) const {
  const auto d = film_derivative(i);  // a uniform film shift reaches every film term alike
  return d[0] + d[1] + d[2];
}

}  // namespace gearbench::ehl
