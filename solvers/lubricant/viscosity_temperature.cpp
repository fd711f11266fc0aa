#include "viscosity_temperature.h"

#include <cmath>

namespace gearbench::lubricant {

namespace {

double lglg(double nu_mm2_s) { return std::log10(std::log10(nu_mm2_s + walther_offset)); }
}  // namespace

WaltherLine::WaltherLine(double T1, double nu1_mm2_s, double T2, double nu2_mm2_s)
    : A_((lglg(nu1_mm2_s) - lglg(nu2_mm2_s)) / (std::log10(T1) - std::log10(T2))),
      B_(lglg(nu1_mm2_s) - A_ * std::log10(T1)) {}

double WaltherLine::kinematic_viscosity_mm2_s(double T) const {
  return std::pow(10.0, std::pow(10.0, A_ * std::log10(T) + B_)) - walther_offset;
}

double iso15144_density(double rho15, double T) {
  return rho15 - iso15144_density_slope * (T - (celsius_zero + 15.0));
}

}  // namespace gearbench::lubricant
