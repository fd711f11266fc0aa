// Anderson acceleration of a level's multigrid cycles (fas_multigrid_impl.h, CycleAcceleration).
#include "fas_multigrid_impl.h"

#include <algorithm>

namespace gearbench::ehl {
namespace {

/// The state a cycle maps: the level's pressure followed by H0.
std::vector<double> state_of(const std::vector<double>& P, double H0) {
  std::vector<double> x = P;
  x.push_back(H0);
  return x;
}

}  // namespace

std::unique_ptr<AndersonMixing> FasMultigrid::Impl::new_mixing() const {
  if (o_.acceleration_depth == 0 || o_.single_grid) return nullptr;
  return std::make_unique<AndersonMixing>(AndersonOptions{.depth = o_.acceleration_depth});
}

FasMultigrid::Impl::CycleAcceleration FasMultigrid::Impl::start_acceleration(const Level& l) const {
  return {new_mixing(), state_of(l.P, H0_)};
}

void FasMultigrid::Impl::accelerate(CycleAcceleration& a, Level& l, const EhlResult& r) {
  if (!a.mixing) return;
  const double image_residual = std::max(r.residual_history.back(), r.force_history.back());
  const std::vector<double> mixed = a.mixing->next(a.start, state_of(l.P, H0_));
  // The image, kept with its film to come back to.
  const std::vector<double> image_P = l.P, image_H = l.H;
  const double image_H0 = H0_;
  const auto image_film_of = l.film_of;
  set_state(l, mixed);
  // The mixed state's residual (its film and coefficients): counted as a sweep of the level.
  const double mixed_residual = std::max(scaled_residual(l), force_balance(l));
  node_sweeps_.acceleration += static_cast<double>(l.n);
  if (!(mixed_residual <= image_residual)) {
    // The next cycle's relaxation recomputes the coefficients; the film is the image's again.
    l.P = image_P;
    l.H = image_H;
    l.film_of = image_film_of;
    H0_ = image_H0;
    a.mixing = new_mixing();
  }
  a.start = state_of(l.P, H0_);
}

void FasMultigrid::Impl::set_state(Level& l, const std::vector<double>& x) {
  for (std::size_t i = 1; i + 1 < l.n; ++i) l.P[i] = l.cavitated_on_finer[i] ? 0.0 : std::max(0.0, x[i]);
  H0_ = x.back();
  l.film_of.valid = false;
}

void FasMultigrid::Impl::visit_coarse_twice(std::size_t k) {
  Level& coarse = *levels_[k];
  auto mixing = new_mixing();
  const std::vector<double> start = state_of(coarse.P, H0_);
  cycle(k, CycleType::W);
  const std::vector<double> first = state_of(coarse.P, H0_);
  cycle(k, CycleType::W);
  if (!mixing) return;
  (void)mixing->next(start, first);  // the plain step: the history's first difference
  set_state(coarse, mixing->next(first, state_of(coarse.P, H0_)));
}

}  // namespace gearbench::ehl
