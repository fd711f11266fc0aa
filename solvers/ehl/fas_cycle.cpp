// The multigrid cycles: the FAS coarse problem (restriction), the coarse-grid correction, V/W
// cycles, full multigrid with its interpolation, and the warm start (Venner & Lubrecht 2000, ch. 6).
#include "fas_multigrid_impl.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gearbench::ehl {

void FasMultigrid::Impl::cycle(std::size_t k, CycleType type) {
  Level& fine = *levels_[k];
  if (k == 0) {
    if (o_.single_grid)
      relax_single_grid(fine);
    else
      solve_coarsest(fine, coarsest_steps_per_visit, coarsest_tolerance, coarsest_visit_reduction);
    return;
  }
  for (int s = 0; s < o_.pre_sweeps; ++s) relax(fine);
  Level& coarse = *levels_[k - 1];
  restrict_problem(fine, coarse);
  const std::vector<double> injected = coarse.P;
  if (k == 1) {
    // The coarsest grid is visited once, whatever the cycle: two visits there are two Newton
    // solves of the same problem in a row, and one, stopped at its merit's reduction, is enough
    // (W: the maps' medians 3–11 % lower, 0 failures on every map; twenty-eighth session).
    cycle(0, type);
  } else if (type == CycleType::W) {
    // Two visits up to w_cycle_levels above the coarsest grid, one above them: a full W-cycle
    // costs ν sweeps of the finest grid per level in one dimension, O(N log N) a cycle.
    if (k <= static_cast<std::size_t>(o_.w_cycle_levels))
      visit_coarse_twice(k - 1);
    else
      cycle(k - 1, CycleType::W);
  } else if (type == CycleType::F) {
    cycle(k - 1, CycleType::F);
    cycle(k - 1, CycleType::V);
  } else {
    cycle(k - 1, CycleType::V);
  }
  correct(coarse, injected, fine);
  for (int s = 0; s < o_.post_sweeps; ++s) relax(fine);
  const FilmBase before_spike{fine.P, fine.H};
  const NodeRange spike = relax_spike(fine);
  relax_free_boundary(fine, before_spike, spike);
}

void FasMultigrid::Impl::correct(const Level& coarse, const std::vector<double>& injected, Level& fine) const {
  std::vector<double> correction(fine.n, 0.0);
  for (std::size_t I = 0; I + 1 < coarse.n; ++I) {
    const double d0 = coarse.P[I] - injected[I];
    const double d1 = coarse.P[I + 1] - injected[I + 1];
    correction[2 * I] = d0;
    correction[2 * I + 1] = 0.5 * (d0 + d1);
  }
  // Where to correct is decided on the pressure before the correction.
  std::vector<char> corrected(fine.n, 0);
  for (std::size_t i = 1; i + 1 < fine.n; ++i)
    corrected[i] = fine.P[i - 1] > 0.0 && fine.P[i] > 0.0 && fine.P[i + 1] > 0.0;
  for (std::size_t i = 1; i + 1 < fine.n; ++i)
    if (corrected[i]) fine.P[i] = std::max(0.0, fine.P[i] + limit_change(fine, i, correction[i]));
}

void FasMultigrid::Impl::restrict_problem(Level& fine, Level& coarse) {
  update_film(fine);
  update_coefficients(fine);
  std::vector<double> r = residuals(fine);
  for (std::size_t i = 1; i + 1 < fine.n; ++i)
    if (fine.P[i] <= 0.0) r[i] = 0.0;
  for (std::size_t I = 0; I < coarse.n; ++I) {
    coarse.P[I] = fine.P[2 * I];
    coarse.cavitated_on_finer[I] = I > 0 && I + 1 < coarse.n && fine.P[2 * I] <= 0.0;
  }
  coarse.film_correction.clear();
  coarse.film_of.valid = false;
  update_film(coarse);
  coarse.film_correction.resize(coarse.n);
  for (std::size_t I = 0; I < coarse.n; ++I) {
    coarse.film_correction[I] = fine.H[2 * I] - coarse.H[I];
    coarse.H[I] = fine.H[2 * I];
  }
  coarse.film_of.valid = false;  // the injected film, equal to the corrected one up to rounding
  update_coefficients(coarse);
  std::fill(coarse.f.begin(), coarse.f.end(), 0.0);
  for (std::size_t I = 1; I + 1 < coarse.n; ++I)
    coarse.f[I] = operator_at(coarse, I) + 0.25 * (r[2 * I - 1] + 2.0 * r[2 * I] + r[2 * I + 1]);
  coarse.g = integral(coarse) + (fine.g - integral(fine));
  // Work: the fine residual and coefficients, the coarse film and coefficients count as a sweep
  // of the coarse grid, half a fine sweep. Timed against the fine relaxation sweeps of the same
  // solves, a restriction took 0.24–0.39 of one per fine node ((10, 0) on 16385 nodes, (10, 17.5)
  // on 4097, (20, 10) on 1025, (1, 17.5) on 2049, (200, 0) on 4097; twenty-second session) and
  // was not counted before; the coarse-grid correction (correct) took 0.02–0.04 and is not.
  node_sweeps_.restriction += static_cast<double>(coarse.n);
}

bool FasMultigrid::Impl::grid_complete(const EhlResult& r, std::size_t levels) const {
  return !o_.adaptive() || (levels >= 3 && r.error_estimate <= o_.target_error) ||
         static_cast<int>(levels) >= o_.max_levels;
}

bool FasMultigrid::Impl::full_multigrid(EhlResult& r) {
  start_on_coarsest();
  record_fmg_level(r, 0);
  for (std::size_t k = 1; failure_.empty(); ++k) {
    if (k == levels_.size()) {
      if (grid_complete(r, k)) break;
      add_level();
    }
    interpolate_solution(*levels_[k - 1], *levels_[k]);
    make_finest(*levels_[k]);
    update_film(*levels_[k]);
    node_sweeps_.interpolation += static_cast<double>(levels_[k]->n);
    // The cubic interpolation of a resolved spike overshoots (eighth session); the cycle's first
    // relaxation brings the film outside the spike's window up to date.
    (void)relax_spike(*levels_[k]);
    const Watched start = watched(*levels_[k]);
    cycle(k);
    record_fmg_level(r, k);
    // A level whose film is still negative (heavy loads on coarse grids: no estimate) is not
    // the end: finer levels may resolve it (tenth session, (1000, 0) positive from 2049 nodes).
    // The first level with a film has no estimate either, but it is the next level's reference:
    // below the finest it is converged to a tenth of its change from the filmless level over
    // 2^p − 1 (≥ 33 %), about what its full-multigrid cycle is off.
    const bool finest = k + 1 == levels_.size() && grid_complete(r, k + 1);
    const bool first_with_film = r.fmg_H_min.size() - first_level_with_film(r) == 1;
    if (!std::isfinite(r.error_estimate) && (finest || !first_with_film)) continue;
    const bool error_rule = o_.stop == StopRule::discretisation_error;
    // Under the residual rule the finest grid is iterate_to_residual's; the levels below it are
    // converged to their discretisation error as under the error rule, so that the finest grid
    // starts from full multigrid's answer. With one cycle a level, (10, 25) on 16385 nodes with
    // a 33-node coarsest grid started at a scaled residual of 4.6e-3 and did not reach 1e-8 in 60
    // cycles; from converged levels it took 15 (twenty-eighth session).
    if (!error_rule && finest) continue;
    // Under the error rule every level is converged before the next: the estimate is then a
    // difference of discrete solutions. One cycle per level leaves algebraic errors larger than
    // the discretisation error in places (Martin's limit: H_min 0.504 after one cycle on 129
    // nodes against 0.458 converged; the estimate on 513 nodes read 0.14 % for a 0.43 % error,
    // eleventh session). A level below the finest whose full-multigrid cycle already meets the
    // rule is converged enough for the estimate; the finest, whose figures are the answer, is
    // accepted on a cycle's own change (twenty-third session: accepted on its full-multigrid
    // cycle at the residual's factor, the finest grid's H_min was up to 1.7 × the bound off its
    // discrete solution at 5 of the default map's 71 points).
    // The full-multigrid cycle's change from the interpolated start is the level's difference
    // from the coarser one, not an algebraic error: over the film it is largest at the spike,
    // whose film no coarser grid resolves. Its acceptance reads the figures' change, as the
    // estimate does; with the film's, (10, 0) on 16385 nodes under W(2,1) on five levels, whose
    // factor of 0.02–0.05 had accepted levels 513 … 8193 on that cycle, accepted none
    // (thirty-sixth session). The levels' own cycles read the film's (change_of).
    const Watched end = watched(*levels_[k]);
    const double fmg_change = change_of(end, start);
    if (finest || !fmg_cycle_reaches_error(r, k, figures_change(end, start)))
      iterate_to_error(r, k, fmg_change, last_change_estimate(r));
    // A level below the finest that misses its error is the residual iteration's start all the
    // same (iterate_to_residual decides the outcome); under the error rule the solve ends there.
    if (!r.converged && error_rule) return false;
  }
  return true;
}

void FasMultigrid::Impl::interpolate_solution(const Level& coarse, Level& fine) {
  for (std::size_t I = 0; I < coarse.n; ++I) fine.P[2 * I] = coarse.P[I];
  for (std::size_t I = 0; I + 1 < coarse.n; ++I) {
    const double value =
        I >= 1 && I + 2 < coarse.n
            ? (-coarse.P[I - 1] + 9.0 * coarse.P[I] + 9.0 * coarse.P[I + 1] - coarse.P[I + 2]) / 16.0
            : 0.5 * (coarse.P[I] + coarse.P[I + 1]);
    fine.P[2 * I + 1] = std::max(0.0, value);
  }
}

void FasMultigrid::Impl::start_from(const WarmStart& warm) {
  Level& fine = *levels_.back();
  if (warm.P.size() != fine.n) throw std::invalid_argument("WarmStart::P must hold the finest grid");
  fine.P = warm.P;
  H0_ = warm.H0;
  make_finest(fine);
  update_film(fine);
}

}  // namespace gearbench::ehl
