#include "analysis/interrupt.hpp"

#include <csignal>

namespace dartcheck::analysis {
namespace {

volatile std::sig_atomic_t flag = 0;

extern "C" void on_signal(int sig) {
  flag = 1;
  std::signal(sig, SIG_DFL);  // the next one is not caught
}

}  // namespace

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
