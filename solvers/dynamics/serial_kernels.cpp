#include "serial_kernels.h"

#include <algorithm>
#include <cmath>

namespace gearbench::dynamics {

namespace {

// The semantics of each kernel are those of the SUNDIALS 6.4 N_Vector API (z may alias x or y).
double* data(N_Vector v) { return NV_DATA_S(v); }
sunindextype length(N_Vector v) { return NV_LENGTH_S(v); }

void linear_sum(realtype a, N_Vector x, realtype b, N_Vector y, N_Vector z) {  // z = a·x + b·y
  const double *xd = data(x), *yd = data(y);
  double* zd = data(z);
  for (sunindextype i = 0; i < length(z); ++i) zd[i] = a * xd[i] + b * yd[i];
}

void constant(realtype c, N_Vector z) { std::fill_n(data(z), length(z), c); }

void product(N_Vector x, N_Vector y, N_Vector z) {  // z = x·y componentwise
  const double *xd = data(x), *yd = data(y);
  double* zd = data(z);
  for (sunindextype i = 0; i < length(z); ++i) zd[i] = xd[i] * yd[i];
}

void scale(realtype c, N_Vector x, N_Vector z) {
  const double* xd = data(x);
  double* zd = data(z);
  for (sunindextype i = 0; i < length(z); ++i) zd[i] = c * xd[i];
}

void absolute(N_Vector x, N_Vector z) {
  const double* xd = data(x);
  double* zd = data(z);
  for (sunindextype i = 0; i < length(z); ++i) zd[i] = std::abs(xd[i]);
}

void inverse(N_Vector x, N_Vector z) {
  const double* xd = data(x);
  double* zd = data(z);
  for (sunindextype i = 0; i < length(z); ++i) zd[i] = 1.0 / xd[i];
}

void add_constant(N_Vector x, realtype b, N_Vector z) {
  const double* xd = data(x);
  double* zd = data(z);
  for (sunindextype i = 0; i < length(z); ++i) zd[i] = xd[i] + b;
}

realtype max_norm(N_Vector x) {
  double m = 0.0;
  for (sunindextype i = 0; i < length(x); ++i) m = std::max(m, std::abs(data(x)[i]));
  return m;
}

realtype weighted_square_sum(N_Vector x, N_Vector w) {  // Σ (x_i·w_i)²
  const double *xd = data(x), *wd = data(w);
  double s = 0.0;
  for (sunindextype i = 0; i < length(x); ++i) s += (xd[i] * wd[i]) * (xd[i] * wd[i]);
  return s;
}

realtype wrms_norm(N_Vector x, N_Vector w) {
  return std::sqrt(weighted_square_sum(x, w) / static_cast<double>(length(x)));
}

// z = Σ_j c_j·X_j; z may be X_0 (the packages update a vector in place this way).
int linear_combination(int n, realtype* c, N_Vector* X, N_Vector z) {
  double* zd = data(z);
  const sunindextype size = length(z);
  if (X[0] == z) {
    for (sunindextype i = 0; i < size; ++i) zd[i] *= c[0];
  } else {
    const double* x0 = data(X[0]);
    for (sunindextype i = 0; i < size; ++i) zd[i] = c[0] * x0[i];
  }
  for (int j = 1; j < n; ++j) {
    const double* xj = data(X[j]);
    for (sunindextype i = 0; i < size; ++i) zd[i] += c[j] * xj[i];
  }
  return 0;
}

// Z_j = a_j·x + Y_j.
int scale_add_multi(int n, realtype* a, N_Vector x, N_Vector* Y, N_Vector* Z) {
  const double* xd = data(x);
  for (int j = 0; j < n; ++j) {
    const double* yd = data(Y[j]);
    double* zd = data(Z[j]);
    for (sunindextype i = 0; i < length(x); ++i) zd[i] = a[j] * xd[i] + yd[i];
  }
  return 0;
}

}  // namespace

void install_serial_kernels(N_Vector v) {
  auto& ops = *v->ops;
  ops.nvlinearsum = linear_sum;
  ops.nvconst = constant;
  ops.nvprod = product;
  ops.nvscale = scale;
  ops.nvabs = absolute;
  ops.nvinv = inverse;
  ops.nvaddconst = add_constant;
  ops.nvmaxnorm = max_norm;
  ops.nvwrmsnorm = wrms_norm;
  ops.nvwsqrsumlocal = weighted_square_sum;
  ops.nvlinearcombination = linear_combination;
  ops.nvscaleaddmulti = scale_add_multi;
}

}  // namespace gearbench::dynamics
