#include "convergence.h"

#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <stdexcept>

namespace gearbench::verification {

double observed_order(double coarse, double medium, double fine, double ratio) {
  const double quotient = (coarse - medium) / (medium - fine);
  if (!(quotient > 0.0) || !std::isfinite(quotient)) return std::numeric_limits<double>::quiet_NaN();
  return std::log(quotient) / std::log(ratio);
}

double observed_order(const std::vector<double>& series, double ratio) {
  const std::size_t n = series.size();
  if (n < 3) throw std::invalid_argument("observed_order: a series of at least three grids is needed");
  return observed_order(series[n - 3], series[n - 2], series[n - 1], ratio);
}

double order_from_errors(double coarse_error, double fine_error, double ratio) {
  return std::log(coarse_error / fine_error) / std::log(ratio);
}

double richardson(double medium, double fine, double order, double ratio) {
  return fine + (fine - medium) / (std::pow(ratio, order) - 1.0);
}

double algebraic_error_share(double answer, double discrete, double coarser_discrete, double order, double ratio) {
  return std::abs(answer - discrete) / std::abs(richardson(coarser_discrete, discrete, order, ratio) - discrete);
}

ConvergenceTable::ConvergenceTable(std::string parameter, std::vector<std::string> columns)
    : parameter_(std::move(parameter)), columns_(std::move(columns)), values_(columns_.size()) {}

void ConvergenceTable::add_row(double parameter, const std::vector<double>& values) {
  if (values.size() != columns_.size())
    throw std::invalid_argument(fmt::format("ConvergenceTable: {} values for {} columns", values.size(), columns_.size()));
  parameters_.push_back(parameter);
  for (std::size_t k = 0; k < values.size(); ++k) values_[k].push_back(values[k]);
}

std::string ConvergenceTable::markdown(double ratio) const {
  std::string head = "| " + parameter_ + " |", rule = "|---|";
  for (const auto& c : columns_) {
    head += fmt::format(" {} | change |", c);
    rule += "---|---|";
  }
  std::string text = head + "\n" + rule + "\n";
  for (std::size_t i = 0; i < parameters_.size(); ++i) {
    text += fmt::format("| {:g} |", parameters_[i]);
    for (const auto& v : values_)
      text += i == 0 ? fmt::format(" {:.6g} | — |", v[i]) : fmt::format(" {:.6g} | {:.3g} |", v[i], v[i] - v[i - 1]);
    text += "\n";
  }
  if (parameters_.size() >= 3) {
    text += "| observed order |";
    for (const auto& v : values_) text += fmt::format(" {:.3g} | |", observed_order(v, ratio));
    text += "\n";
  }
  return text;
}

}  // namespace gearbench::verification
