#pragma once
// Anderson acceleration of a fixed-point iteration x = G(x): Walker & Ni, "Anderson acceleration
// for fixed-point iterations", SIAM J. Numer. Anal. 49(4) (2011) 1715–1735, their Algorithm AA
// with depth m and mixing β. With the residual f_k = G(x_k) − x_k and the differences
// ΔF = [f_{i+1} − f_i], ΔX = [x_{i+1} − x_i] of the last m_k ≤ m iterates,
//   γ = argmin ‖f_k − ΔF·γ‖₂,   x_{k+1} = x_k + β·f_k − (ΔX + β·ΔF)·γ,
// the least-squares problem solved by Householder QR (Eigen). On a linear map, without
// truncation, it is essentially GMRES (Walker & Ni's equivalence result; De Sterck, He &
// Krzysik, arXiv:2109.14181, for the windowed AA(m) as a Krylov method), so it converges where
// the relaxed iteration x + β·f diverges (an eigenvalue of G's Jacobian below 1 − 2/β).
// Safeguards (ours, the usual ones for AA):
//   - the condition of ΔF: the oldest differences are dropped while the diagonal of the QR
//     factor R spans more than `max_condition`, so nearly dependent differences cannot
//     amplify the noise of an inexactly evaluated G;
//   - restart: when ‖f_k‖ exceeds `restart_growth` times the smallest residual since the last
//     restart, the history is cleared and the step is the plain relaxed one, x + β·f.
#include <cstddef>
#include <deque>
#include <vector>

#include <Eigen/Dense>

namespace gearbench::ehl {

struct AndersonOptions {
  int depth = 5;                 ///< m: differences kept (at most as many as unknowns)
  double mixing = 1.0;           ///< β
  double max_condition = 1e8;    ///< bound on |R_00|/|R_kk| of ΔF's QR before the oldest column goes
  double restart_growth = 10.0;  ///< ‖f‖ above this × the smallest since the restart clears the history
};

class AndersonMixing {
 public:
  explicit AndersonMixing(AndersonOptions options = {});
  /// The next iterate from the current one `x` and its image `g` = G(x) (same size each call).
  [[nodiscard]] std::vector<double> next(const std::vector<double>& x, const std::vector<double>& g);
  /// Columns used by the last step (0: a plain relaxed step).
  [[nodiscard]] int columns_used() const { return columns_used_; }
  [[nodiscard]] int restarts() const { return restarts_; }

 private:
  AndersonOptions options_;
  std::deque<Eigen::VectorXd> dx_, df_;  ///< oldest first
  Eigen::VectorXd x_before_, f_before_;
  double smallest_residual_ = 0.0;
  int columns_used_ = 0, restarts_ = 0;
};

}  // namespace gearbench::ehl
