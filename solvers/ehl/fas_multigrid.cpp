// The FAS multigrid of the line-contact EHL problem (fas_multigrid.h): the hierarchy of grids
// and the solve's entry; the parts of the iteration are in the files fas_multigrid_impl.h lists.
#include "fas_multigrid_impl.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

#include "model/errors.h"

namespace gearbench::ehl {

FasMultigrid::Impl::Impl(const LineContactProblem& problem, const EhlOptions& o, ContactState state)
    : problem_(problem), o_(o), state_(std::move(state)) {
  o_.validate();
  if (state_.load <= 0.0) state_.load = problem_.load();
  x_in_ = o_.domain_in(problem_);
  x_out_ = o_.domain_out(problem_);
  if (state_.has_fields() && o_.adaptive())
    throw std::invalid_argument("FasMultigrid: a contact state with fields needs a fixed grid (levels > 0)");
  if (o_.single_grid) {
    if (o_.nodes <= 0) throw std::invalid_argument("EhlOptions::single_grid needs the grid's nodes");
    coarsest_ = static_cast<std::size_t>(o_.nodes);
    add_level();
  } else {
    coarsest_ = coarsest_nodes();
    int levels = o_.adaptive() ? 1 : o_.levels;
    if (o_.nodes > 0) levels = levels_for_finest(static_cast<std::size_t>(o_.nodes));
    for (int k = 0; k < levels; ++k) add_level();
  }
  if (!state_.nearby.P.empty() && state_.nearby.P.size() != levels_.back()->n)
    throw std::invalid_argument("ContactState::nearby must hold the finest grid");
  inject_fields();
}

EhlResult FasMultigrid::Impl::solve(const std::optional<WarmStart>& warm) {
  const auto start = std::chrono::steady_clock::now();
  EhlResult r;
  r.scheme = o_.describe();
  bool unestimated = false;  // the error rule asked, but no level gave an estimate to stop at
  if (warm) {
    start_from(*warm);
    if (o_.stop == StopRule::discretisation_error && std::isfinite(warm->error_estimate))
      iterate_warm_start_to_error(r, *warm);
    else
      iterate_to_residual(r);
  } else if (o_.single_grid) {
    make_finest(*levels_.back());
    initial_guess(*levels_.back());
    iterate_to_residual(r);
  } else {
    // Under the error rule, converges every level to it; a level that misses it ends the solve.
    const bool every_level_met_its_rule = full_multigrid(r);
    unestimated = o_.stop == StopRule::discretisation_error && every_level_met_its_rule &&
                  !std::isfinite(r.error_estimate);
    if (failure_.empty() && (o_.stop == StopRule::residual || unestimated)) iterate_to_residual(r);
  }
  if (!failure_.empty()) reject(r, failure_);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const auto& l : levels_) r.seconds_per_level.push_back(l->seconds);
  r.levels = static_cast<int>(levels_.size());
  r.work_units = work_units();
  const double per_sweep = 1.0 / static_cast<double>(levels_.back()->n);
  r.work_by_part = node_sweeps_.scaled(per_sweep);
  r.work_units_iterating = iterating_sweeps_ * per_sweep;
  fill_figures(*levels_.back(), r);
  qualify_answer(r, unestimated);
  return r;
}

// A converged discrete solution whose film touches or crosses zero is not an answer: the
// surfaces would interpenetrate. It happens on fixed grids too coarse for a thin film, where
// the film's O(h²) discretisation error, a difference of O(1) terms, exceeds the film itself
// (thirty-third session, the map's points at L ≤ 2.5: M = 1000 on 641 nodes, M ≥ 500 on 513,
// M ≥ 200 on 257). The default grid, whose levels are added until the error estimate is below
// grid.target_error, resolves it. And a full-multigrid solve under the error rule that no level
// could estimate was stopped by the residual rule: its answer's accuracy is unknown, and the
// message says so ((1000, 0) on 1025 nodes ended 76 % below the converged film with nothing but
// an infinite estimate in the summary).
void FasMultigrid::Impl::qualify_answer(EhlResult& r, bool unestimated) const {
  if (!r.converged) return;
  const std::size_t nodes = levels_.back()->n;
  if (!(r.h_min > 0.0)) {
    reject(r, fmt::format("no film on this grid: the converged solution's minimum film is {:.3g} m (Moes' "
                          "estimate of the central film {:.3g} m); {} nodes do not resolve a film this thin: give "
                          "more nodes, or leave grid.nodes out for the grid chosen by grid.target_error",
                          r.h_min, problem_.isoviscous_film() * problem_.film_scale(), nodes));
  } else if (unestimated) {
    r.message += fmt::format("; no discretisation-error estimate on {} nodes (no coarser level with a positive "
                             "film to estimate it from), so the residual rule stopped it and the film's accuracy "
                             "is unknown: leave grid.nodes out for the grid chosen by grid.target_error",
                             nodes);
  }
}

std::vector<double> FasMultigrid::Impl::rho_h() {
  Level& fine = *levels_.back();
  update_film(fine);
  update_coefficients(fine);
  std::vector<double> out(fine.n);
  for (std::size_t i = 0; i < fine.n; ++i) out[i] = fine.rho[i] * std::max(fine.H[i], 0.0);
  return out;
}

void FasMultigrid::Impl::add_level() {
  const std::size_t nodes = levels_.empty() ? coarsest_ : 2 * levels_.back()->n - 1;
  levels_.push_back(std::make_unique<Level>(nodes, x_in_, x_out_));
}

std::size_t FasMultigrid::Impl::nodes_resolving(double h_target) const {
  std::size_t intervals = 32;
  while ((x_out_ - x_in_) / static_cast<double>(intervals) > h_target && intervals < 1024) intervals *= 2;
  return intervals + 1;
}

std::size_t FasMultigrid::Impl::coarsest_nodes() const {
  if (o_.coarsest_nodes > 0) return static_cast<std::size_t>(o_.coarsest_nodes);
  // Half the pressure zone's width scale, the larger of b and ℓ, in X = x/ℓ: 0.5 in Hertzian
  // scaling (ℓ = b); in rigid scaling b ≈ 0.72·M·ℓ, so ℓ/2 up to M ≈ 1.4, b/2 above.
  const double zone = std::max(problem_.hertz_half_width() / problem_.length_scale(), 1.0);
  return nodes_resolving(std::min(coarsest_zone_spacing * zone, coarsest_film_spacing * std::sqrt(problem_.isoviscous_film())));
}

int FasMultigrid::Impl::levels_for_finest(std::size_t nodes) {
  std::size_t intervals = nodes - 1;
  int levels = 1;
  while (intervals % 2 == 0 && intervals / 2 >= coarsest_ - 1) {
    intervals /= 2;
    ++levels;
  }
  // A finest grid no finer than the sized coarsest is still given a coarser grid where the film
  // allows one: the direct Newton solve alone is not globally convergent (strict descent found
  // no step at M 2.15, L 28.3 on 161 nodes, residual 1e-3 for 60 cycles; with 81 nodes below it
  // 0.25 a cycle, fourteenth session).
  const std::size_t film_nodes =
      o_.coarsest_nodes > 0 ? coarsest_ : nodes_resolving(coarsest_film_spacing * std::sqrt(problem_.isoviscous_film()));
  if (levels == 1 && intervals % 2 == 0 && intervals / 2 >= film_nodes - 1) {
    intervals /= 2;
    ++levels;
  }
  coarsest_ = intervals + 1;
  if (coarsest_ > max_coarsest_nodes)
    throw InputError(fmt::format("grid.nodes = {}: allowed are (n0 − 1)·2^k + 1 nodes with a coarsest grid "
                                 "n0 ≤ {} (e.g. 2049, 4097, 5121)", nodes, max_coarsest_nodes));
  return levels;
}

void FasMultigrid::Impl::inject_fields() {
  Level& fine = *levels_.back();
  const auto check = [&](const std::vector<double>& v, const char* name) {
    if (!v.empty() && v.size() != fine.n)
      throw std::invalid_argument(fmt::format("ContactState::{} must hold the finest grid", name));
  };
  check(state_.rho_h_old, "rho_h_old");
  check(state_.flow_factor, "flow_factor");
  check(state_.wedge_factor, "wedge_factor");
  if (state_.time_step > 0.0 && state_.rho_h_old.empty())
    throw std::invalid_argument("ContactState::rho_h_old is needed with a time step");
  if (!state_.rho_h_old.empty()) fine.rho_h_old = state_.rho_h_old;
  if (!state_.flow_factor.empty()) fine.flow_factor = state_.flow_factor;
  if (!state_.wedge_factor.empty()) fine.wedge_factor = state_.wedge_factor;
  for (std::size_t k = levels_.size() - 1; k > 0; --k) {
    Level& f = *levels_[k];
    Level& c = *levels_[k - 1];
    if (!f.rho_h_old.empty()) c.rho_h_old.resize(c.n);
    for (std::size_t I = 0; I < c.n; ++I) {
      if (!f.rho_h_old.empty()) c.rho_h_old[I] = f.rho_h_old[2 * I];
      c.flow_factor[I] = f.flow_factor[2 * I];
      c.wedge_factor[I] = f.wedge_factor[2 * I];
    }
  }
}

std::size_t FasMultigrid::Impl::last_pressurised(const std::vector<double>& P) {
  std::size_t last = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P[i] > 0.0) last = i;
  return last;
}

std::size_t FasMultigrid::Impl::spike_index(const std::vector<double>& P) {
  const std::size_t last = last_pressurised(P);
  for (std::size_t i = last; i > 1; --i)
    if (P[i] >= P[i - 1] && P[i] >= P[i + 1]) return i;
  return last;
}

double FasMultigrid::Impl::relative(double a, double b) {
  if (a == b) return 0.0;
  return std::abs(a - b) / std::max(std::abs(b), 1e-300);
}

FasMultigrid::FasMultigrid(const LineContactProblem& problem, const EhlOptions& options, ContactState state)
    : impl_(std::make_unique<Impl>(problem, options, std::move(state))) {}

FasMultigrid::~FasMultigrid() = default;

EhlResult FasMultigrid::solve(const std::optional<WarmStart>& warm) { return impl_->solve(warm); }

std::vector<double> FasMultigrid::rho_h() { return impl_->rho_h(); }

}  // namespace gearbench::ehl
