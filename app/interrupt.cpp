#include "interrupt.h"

#include <unistd.h>

namespace gearbench::app {
namespace {

/// Async-signal-safe: write(2) and _exit(2) only.
extern "C" void on_interrupt(int) {
  constexpr char message[] = "\ngearbench: interrupted; nothing further is written\n";
  [[maybe_unused]] const auto written = ::write(STDERR_FILENO, message, sizeof message - 1);
  ::_exit(exit_interrupted);
}

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

}  // namespace

void install_interrupt_handler() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void hold_interrupts_to_the_end() {
  const sigset_t set = interrupt_signals();
  sigprocmask(SIG_BLOCK, &set, nullptr);
}

DeferInterrupts::DeferInterrupts() {
  const sigset_t set = interrupt_signals();
  sigprocmask(SIG_BLOCK, &set, &previous_);
}

DeferInterrupts::~DeferInterrupts() { sigprocmask(SIG_SETMASK, &previous_, nullptr); }

}  // namespace gearbench::app
