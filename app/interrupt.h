#pragma once
// Ctrl-C (SIGINT) and SIGTERM end gearbench at once: one line on stderr and exit code 130.
// Results reach disk only where the signal waits (a temporary file or folder, then a rename):
// inside a DeferInterrupts scope for a write the run goes on after (a benchmark record of a
// range), after hold_interrupts_to_the_end for a write that is the run's last step (run's
// result, verify's report, sweep's table). So an interrupted run never leaves a half-written
// result or report, never presents a partial one as complete, and exits 130 only with
// nothing written.
#include <csignal>

namespace gearbench::app {

/// Exit code of an interrupted run (128 + SIGINT, the shell's convention).
inline constexpr int exit_interrupted = 130;

void install_interrupt_handler();

/// Holds SIGINT and SIGTERM back for the rest of the run and never delivers them: for a run
/// whose last step commits its result (a report written and its path printed), so that a
/// Ctrl-C during that step cannot leave the result without its path, or end it with 130.
void hold_interrupts_to_the_end();

/// Holds SIGINT and SIGTERM back for its lifetime; a signal that arrived meanwhile ends the
/// program when the scope closes.
class DeferInterrupts {
 public:
  DeferInterrupts();
  ~DeferInterrupts();
  DeferInterrupts(const DeferInterrupts&) = delete;
  DeferInterrupts& operator=(const DeferInterrupts&) = delete;

 private:
  sigset_t previous_{};
};

}  // namespace gearbench::app
