#include "anderson_mixing.h"

#include <algorithm>
#include <cmath>

#include "model/errors.h"

namespace gearbench::ehl {

AndersonMixing::AndersonMixing(AndersonOptions options) : options_(options) {
  if (options_.depth < 0) throw InputError("Anderson depth below 0");
  if (!(options_.mixing > 0.0 && options_.mixing <= 1.0)) throw InputError("Anderson mixing outside (0, 1]");
}

std::vector<double> AndersonMixing::next(const std::vector<double>& x_in, const std::vector<double>& g_in) {
  const auto size = static_cast<Eigen::Index>(x_in.size());
  const Eigen::Map<const Eigen::VectorXd> x(x_in.data(), size), g(g_in.data(), size);
  const Eigen::VectorXd f = g - x;
  const double beta = options_.mixing;
  const double residual = f.norm();

  if (x_before_.size() == size) {
    dx_.push_back(x - x_before_);
    df_.push_back(f - f_before_);
    if (static_cast<int>(dx_.size()) > options_.depth) {
      dx_.pop_front();
      df_.pop_front();
    }
  }
  if (dx_.empty() || residual > options_.restart_growth * smallest_residual_) {
    if (!dx_.empty()) ++restarts_;
    dx_.clear();
    df_.clear();
    smallest_residual_ = residual;
  }
  smallest_residual_ = std::min(smallest_residual_, residual);
  x_before_ = x;
  f_before_ = f;

  Eigen::VectorXd step = beta * f;
  while (!dx_.empty()) {
    const auto m = static_cast<Eigen::Index>(df_.size());
    if (m > size) {  // more differences than unknowns: the least squares is rank-deficient
      dx_.pop_front();
      df_.pop_front();
      continue;
    }
    Eigen::MatrixXd dF(size, m), dX(size, m);
    for (Eigen::Index c = 0; c < m; ++c) {
      dF.col(c) = df_[static_cast<std::size_t>(c)];
      dX.col(c) = dx_[static_cast<std::size_t>(c)];
    }
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(dF);
    const Eigen::VectorXd diagonal = qr.matrixQR().diagonal().cwiseAbs().head(m);
    if (!(diagonal.minCoeff() * options_.max_condition > diagonal.maxCoeff())) {  // also NaN
      dx_.pop_front();
      df_.pop_front();
      continue;
    }
    const Eigen::VectorXd gamma = qr.solve(f);
    step -= (dX + beta * dF) * gamma;
    break;
  }
  columns_used_ = static_cast<int>(dx_.size());
  std::vector<double> next(x_in.size());
  Eigen::Map<Eigen::VectorXd>(next.data(), size) = x + step;
  return next;
}

}  // namespace gearbench::ehl
