#pragma once
// The fixed-step machinery the independent dynamics references share: the classical RK4
// step, equal steps over an interval between right-hand-side switches (optionally with a
// state-dependent mode located by bisection), and the sorted set of switch and sample
// times the integration steps onto.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace gearbench::reference::ode {

/// Breakpoints closer than this fraction of dt are merged, and an interval is cut into
/// ceil(length/dt − this) steps: round-off must neither create slivers nor add a step.
inline constexpr double relative_slack = 1e-9;

/// One classical fourth-order Runge–Kutta step of y' = f(t, y) (State: a fixed-size array).
template <class State, class Rhs>
void rk4_step(const Rhs& f, double t, double h, State& y) {
  const auto advanced = [&y](double step, const State& dy) {
    State r;
    for (std::size_t i = 0; i < y.size(); ++i) r[i] = y[i] + step * dy[i];
    return r;
  };
  const State d1 = f(t, y);
  const State d2 = f(t + h / 2, advanced(h / 2, d1));
  const State d3 = f(t + h / 2, advanced(h / 2, d2));
  const State d4 = f(t + h, advanced(h, d3));
  for (std::size_t i = 0; i < y.size(); ++i) y[i] += h / 6 * (d1[i] + 2 * d2[i] + 2 * d3[i] + d4[i]);
}

/// From a to b in equal RK4 steps of at most dt.
template <class State, class Rhs>
void integrate_interval(const Rhs& f, double a, double b, double dt, State& y) {
  const auto steps = static_cast<std::size_t>(std::max(1.0, std::ceil((b - a) / dt - relative_slack)));
  const double h = (b - a) / static_cast<double>(steps);
  for (std::size_t i = 0; i < steps; ++i) rk4_step(f, a + static_cast<double>(i) * h, h, y);
}

/// From a to b in RK4 steps of at most dt under a discrete mode that holds over each step
/// (f(mode, t, y)). Where mode_of(y) at the end of a step differs from `mode`, the step is
/// cut: its length is bisected down to relative_slack·dt to the first point where the mode
/// has changed, the state taken there, the mode switched and the rest of the interval
/// integrated in equal steps again. Returns the number of switches.
template <class State, class Rhs, class ModeOf>
int integrate_interval_with_modes(const Rhs& f, const ModeOf& mode_of, int& mode, double a, double b, double dt,
                                  State& y) {
  int switches = 0;
  double t = a;
  while (b - t > relative_slack * dt) {
    const auto steps = static_cast<std::size_t>(std::max(1.0, std::ceil((b - t) / dt - relative_slack)));
    const double h = (b - t) / static_cast<double>(steps);
    const auto step = [&](double length) {
      State z = y;
      rk4_step([&](double time, const State& state) { return f(mode, time, state); }, t, length, z);
      return z;
    };
    bool switched = false;
    for (std::size_t i = 0; i < steps && !switched; ++i) {
      const State next = step(h);
      if (mode_of(next) == mode) {
        y = next;
        t = (i + 1 == steps) ? b : t + h;
        continue;
      }
      double lo = 0.0, hi = h;  // the mode holds at lo, has changed at hi
      while (hi - lo > relative_slack * dt) {
        const double mid = 0.5 * (lo + hi);
        (mode_of(step(mid)) == mode ? lo : hi) = mid;
      }
      y = step(hi);
      t += hi;
      mode = mode_of(y);
      ++switches;
      switched = true;
    }
  }
  return switches;
}

struct Breakpoint {
  double t;
  bool sample;
};

/// 0, every switch time and every k·sample_every at least the slack inside (0, t_end), and
/// t_end, sorted; points closer than the slack are merged, keeping a sample time exactly.
inline std::vector<Breakpoint> breakpoints(const std::vector<double>& switches, double t_end, double dt,
                                           double sample_every) {
  const double slack = relative_slack * dt;
  std::vector<Breakpoint> inner;
  for (const double t : switches)
    if (t > slack && t < t_end - slack) inner.push_back({t, false});
  for (double k = 1; k * sample_every < t_end - slack; ++k) inner.push_back({k * sample_every, true});
  std::sort(inner.begin(), inner.end(), [](const Breakpoint& l, const Breakpoint& r) { return l.t < r.t; });
  std::vector<Breakpoint> points{{0.0, true}};
  for (const Breakpoint& b : inner) {
    if (b.t - points.back().t >= slack)
      points.push_back(b);
    else if (b.sample && !points.back().sample)
      points.back() = b;
  }
  points.push_back({t_end, true});
  return points;
}

}  // namespace gearbench::reference::ode
