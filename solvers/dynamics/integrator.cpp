// The integrator methods' table, the options' validation, and the one factory: GSL odeiv2
// (gsl_integrator.cpp) for rk8pd, SUNDIALS (sundials_integrator.cpp) for the others.
#include <fmt/format.h>

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

#include "integrator.h"
#include "model/errors.h"

namespace gearbench::dynamics {

namespace {

constexpr std::array<IntegratorMethodName, 7> method_names{{
    {IntegratorMethod::rk8pd, "rk8pd", "GSL odeiv2 Prince–Dormand 8(9), 13 stages, standard step control", true},
    {IntegratorMethod::bdf, "bdf", "CVODE BDF, Newton iteration on a dense difference-quotient Jacobian", true},
    {IntegratorMethod::adams, "adams", "CVODE Adams–Moulton, fixed-point iteration", true},
    {IntegratorMethod::bogacki_shampine, "bogacki_shampine", "ARKODE ERK Bogacki–Shampine 3(2), 4 stages", true},
    {IntegratorMethod::dormand_prince, "dormand_prince", "ARKODE ERK Dormand–Prince 5(4), 7 stages", true},
    {IntegratorMethod::verner, "verner", "ARKODE ERK Verner 6(5), 8 stages", false},
    {IntegratorMethod::fehlberg, "fehlberg", "ARKODE ERK Fehlberg 8(7), 13 stages", false},
}};

}  // namespace

std::span<const IntegratorMethodName> integrator_methods() { return method_names; }

const char* integrator_key(IntegratorMethod method) {
  for (const auto& m : method_names)
    if (m.method == method) return m.key;
  throw std::logic_error("integrator_key: unknown method");
}

IntegratorMethod integrator_method(const std::string& key) {
  std::string allowed;
  for (const auto& m : method_names) {
    if (!m.offered) continue;
    if (key == m.key) return m.method;
    allowed += fmt::format("{}\"{}\"", allowed.empty() ? "" : ", ", m.key);
  }
  throw InputError(fmt::format("integrator.method = \"{}\": allowed values are {}", key, allowed));
}

void IntegratorOptions::validate() const {
  if (!(relative_tolerance >= 1e-14 && relative_tolerance <= 1e-2))
    throw InputError(fmt::format("integrator.rtol = {}: allowed range is [1e-14, 0.01]", relative_tolerance));
  if (!(absolute_tolerance >= 1e-20 && absolute_tolerance <= 1e-2))
    throw InputError(fmt::format("integrator.atol = {}: allowed range is [1e-20, 0.01]", absolute_tolerance));
  if (max_steps < 1) throw InputError(fmt::format("integrator.max_steps = {}: must be >= 1", max_steps));
}

const std::vector<double>& Integrator::advance_across_roots(double t_out, double stop, double tolerance,
                                                            long& events) {
  advance(t_out, stop);
  while (at_root_) {
    ++events;
    reset(t_, y_);
    if (t_ > t_out - tolerance) break;  // a root on the target: y is y(t_out)
    advance(t_out, stop);
  }
  return y_;
}

std::unique_ptr<Integrator> make_integrator(std::size_t size, Integrator::Rhs rhs, const IntegratorOptions& options) {
  if (options.method == IntegratorMethod::rk8pd) return make_gsl_integrator(size, std::move(rhs), options);
  return make_sundials_integrator(size, std::move(rhs), options);
}

}  // namespace gearbench::dynamics
