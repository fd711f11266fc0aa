// The integrator methods' table, the options' table, and the one factory: GSL odeiv2
// (gsl_integrator.cpp) for rk8pd, SUNDIALS (sundials_integrator.cpp) for the others.
#include <fmt/format.h>

#include <array>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

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

namespace {

model::OptionTable<IntegratorOptions> make_table() {
  model::OptionTable<IntegratorOptions> t;
  std::vector<std::pair<std::string, IntegratorMethod>> offered, study_only;
  std::string texts;
  for (const auto& m : method_names) {
    (m.offered ? offered : study_only).emplace_back(m.key, m.method);
    if (m.offered) texts += fmt::format("{}{} ({})", texts.empty() ? "" : "; ", m.key, m.description);
  }
  t.choice("method", &IntegratorOptions::method, offered,
           {.description = "time integrator (docs/dynamics-model.md, \"Integrators: work-precision\"): " + texts},
           study_only);
  // Below 1e-14 a tolerance asks for more than double precision resolves in a state of
  // rotations and micrometre deflections; above 1e-2 the response is not worth recording.
  t.number("rtol", &IntegratorOptions::relative_tolerance, model::Range::closed(1e-14, 1e-2),
           {.description = "relative tolerance of the local error"});
  t.number("atol", &IntegratorOptions::absolute_tolerance, model::Range::closed(1e-20, 1e-2),
           {.description = "absolute tolerance of the local error, alike for every state component (m, rad, m/s, "
                           "rad/s, J)"});
  t.integer("max_steps", &IntegratorOptions::max_steps, 1, 1000000000,
            {.description = "steps allowed between two output times (a sample, a restart or a break); more end the "
                            "run as not converged (exit 3)"});
  return t;
}

}  // namespace

const model::OptionTable<IntegratorOptions>& IntegratorOptions::table() {
  static const auto t = make_table();
  return t;
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
