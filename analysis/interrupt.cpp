#include "analysis/interrupt.hpp"

#include <unistd.h>

#include <csignal>

namespace dartcheck::analysis {
namespace {

volatile std::sig_atomic_t flag = 0;

extern "C" void on_signal(int sig) {
  flag = 1;
  std::signal(sig, SIG_DFL);  // the next one is not caught
}

// Commands with nothing to keep: say so and end now (write and _exit are
// async-signal-safe; no destructor or buffered output runs).
extern "C" void on_signal_exit(int) {
  constexpr char message[] = "interrupted (SIGINT or SIGTERM)\n";
  [[maybe_unused]] const auto written = ::write(STDERR_FILENO, message, sizeof message - 1);
  ::_exit(interrupted_exit);
}

}  // namespace

void exit_on_interrupt() {
  std::signal(SIGINT, on_signal_exit);
  std::signal(SIGTERM, on_signal_exit);
}

void catch_interrupts() {
  static const bool installed = [] {
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    return true;
  }();
  (void)installed;
}

bool interrupted() { return flag != 0; }

}  // namespace dartcheck::analysis
