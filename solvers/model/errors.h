#pragma once
// Typed errors of gearbench. Solvers never print or exit: they throw one of these, and
// the CLI turns it into a one-line `error: ...` and an exit code (2 input, 3 convergence).
#include <stdexcept>
#include <string>

namespace gearbench {

/// Bad input: the message names the key, the value and what is allowed. CLI exit code 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A solver that did not converge; the message says how far it got. CLI exit code 3.
/// `diagnostics` may carry the unconverged result as JSON text, for the CLI to write where
/// the user asked for output before it reports the failure.
class ConvergenceError : public std::runtime_error {
 public:
  explicit ConvergenceError(const std::string& message, std::string diagnostics_json = "")
      : std::runtime_error(message), diagnostics(std::move(diagnostics_json)) {}
  std::string diagnostics;
};

}  // namespace gearbench
