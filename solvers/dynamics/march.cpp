#include "march.h"

#include <algorithm>
#include <cmath>

namespace gearbench::dynamics {

MarchOutcome march(const DynamicsModel& model, const IntegratorOptions& options, const MarchPlan& plan,
                   std::vector<double> y, const Recorder& record) {
  double t_mid = 0.0;
  const auto integrator = make_integrator(
      model.state_size(), [&](double t, const double* state, double* dydt) { model.derivative(t, t_mid, state, dydt); },
      options);
  if (const int count = model.contact_function_count(); count > 0)
    integrator->set_roots(count, [&model](double, const double* state, double* g) { model.contact_functions(state, g); });

  MarchOutcome out;
  std::vector<double> breaks = model.break_times(0.0, plan.t_end);
  breaks.push_back(plan.t_end);
  // Sample times within this of a break are taken at the break: the integrators refuse an
  // output time within their own rounding of the current time.
  const double tiny = 1e-9 * plan.sample_interval;
  std::size_t next = 0;
  double a = 0.0;
  for (std::size_t i = 0; i < breaks.size(); ++i) {
    const double b = breaks[i];
    t_mid = 0.5 * (a + b);
    integrator->reset(a, y);
    double reached = a;
    // To `target` in calls of at most plan.longest_call, restarting at every contact root.
    auto advance_to = [&](double target) {
      while (target > reached + plan.longest_call)
        y = integrator->advance_across_roots(reached += plan.longest_call, b, tiny, out.contact_events);
      y = integrator->advance_across_roots(target, b, tiny, out.contact_events);
      reached = target;
    };
    for (; next < plan.samples; ++next) {
      const double ts = plan.t_record + static_cast<double>(next) * plan.sample_interval;
      if (ts > b + tiny) break;
      if (ts > reached + tiny) advance_to(std::min(ts, b));
      if (next == 0) {
        out.y_record = y;
        out.energy_record = model.energy(ts, t_mid, y.data());
      }
      record(ts, t_mid, y);
    }
    if (b > reached + tiny) advance_to(b);
    // The stiffness jumps at b: the energy with the next interval's pairs minus this one's.
    if (i + 1 < breaks.size() && b > plan.t_record - tiny)
      out.jumps += model.energy(b, 0.5 * (b + breaks[i + 1]), y.data()) - model.energy(b, t_mid, y.data());
    a = b;
  }
  out.y_end = y;
  out.t_mid_end = t_mid;
  out.energy_end = model.energy(plan.t_end, t_mid, y.data());
  out.steps = integrator->steps();
  out.rhs_evaluations = integrator->rhs_evaluations();
  return out;
}

double periodicity(std::span<const double> v, std::size_t period) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  double drift = 0.0;
  for (std::size_t i = v.size() - period; i < v.size(); ++i) drift = std::max(drift, std::abs(v[i] - v[i - period]));
  return drift / std::max(*hi - *lo, 1e-300);
}

}  // namespace gearbench::dynamics
