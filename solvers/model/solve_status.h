#pragma once
// How a solve ended, the same for every solver's Result (issue 21; Ceres' Summary
// termination_type/message, Eigen's info()): whether it converged and one sentence saying what
// stopped it (converged, or which step, point or iteration did not, naming it). A Result
// derives from SolveStatus and adds its own brief summary().
#include <string>
#include <utility>

namespace gearbench::model {

struct SolveStatus {
  bool converged = false;
  std::string message;  ///< what stopped the solve, in a sentence

  /// The solve converged; `why` says so in a sentence.
  void succeed(std::string why) {
    converged = true;
    message = std::move(why);
  }
  /// The solve did not converge; `why` names what did not.
  void fail(std::string why) {
    converged = false;
    message = std::move(why);
  }
};

}  // namespace gearbench::model
