#include "analysis/interrupt.hpp"

#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>

namespace dartcheck::analysis {
namespace {

volatile std::sig_atomic_t flag = 0;
volatile std::sig_atomic_t first_second = 0;  // CLOCK_MONOTONIC seconds of the first signal
volatile std::sig_atomic_t count_second = 0;  // count_second_interrupt() was called

// say_on_early_interrupt's line: written before the handler that reads it
// can run (both signals are blocked while it is copied).
char note[1024];
volatile std::sig_atomic_t note_size = 0;

long monotonic_seconds() {
  timespec now{};
  ::clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe (POSIX)
  return static_cast<long>(now.tv_sec);
}

// write and _exit are async-signal-safe; no destructor or buffered output runs.
[[noreturn]] void exit_now() {
  constexpr char message[] = "interrupted (SIGINT or SIGTERM)\n";
  [[maybe_unused]] auto written = ::write(STDERR_FILENO, message, sizeof message - 1);
  if (note_size > 0) written = ::write(STDERR_FILENO, note, static_cast<std::size_t>(note_size));
  ::_exit(interrupted_exit);
}

// timeout(1) sends its signal to the command and then again to its process
// group, so one request can arrive twice within microseconds: a repeat ends
// the process only when it comes a full second or more after the first.
extern "C" void on_signal(int) {
  const long now = monotonic_seconds();
  if (flag == 0) {
    first_second = static_cast<std::sig_atomic_t>(now);
    flag = 1;
    ::alarm(grace_seconds);  // on_grace_over, unless interrupted() is asked first
    return;
  }
  if (now - first_second < 2) return;  // whole seconds: 2 means at least 1 s
  if (count_second != 0)
    flag = 2;
  else
    exit_now();
}

extern "C" void on_signal_exit(int) { exit_now(); }

// The run did not look at the flag within the grace period.
extern "C" void on_grace_over(int) {
  constexpr char message[] = "(ended 2 s after the signal, inside one rule, map or example: nothing more is written)\n";
  static_assert(grace_seconds == 2, "the message names the grace period");
  if (note_size == 0) {
    const std::size_t size = std::min(sizeof message - 1, sizeof note);
    std::copy_n(message, size, note);
    note_size = static_cast<std::sig_atomic_t>(size);
  }
  exit_now();
}

volatile std::sig_atomic_t seen = 0;  // interrupted() answered yes

// sigaction rather than std::signal: the handler stays installed and both
// signals are blocked while it runs, so SIGTERM cannot interleave with SIGINT.
void install(void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  action.sa_flags = SA_RESTART;
  ::sigaction(SIGINT, &action, nullptr);
  ::sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

void say_on_early_interrupt(std::string_view line) {
  sigset_t both, previous;
  sigemptyset(&both);
  sigaddset(&both, SIGINT);
  sigaddset(&both, SIGTERM);
  ::sigprocmask(SIG_BLOCK, &both, &previous);
  const std::size_t size = std::min(line.size(), sizeof note - 1);
  std::copy_n(line.data(), size, note);
  note[size] = '\n';
  note_size = static_cast<std::sig_atomic_t>(size + 1);
  ::sigprocmask(SIG_SETMASK, &previous, nullptr);
}

void exit_on_interrupt() { install(on_signal_exit); }

void catch_interrupts() {
  static const bool installed = [] {
    struct sigaction grace {};
    grace.sa_handler = on_grace_over;
    sigemptyset(&grace.sa_mask);
    sigaddset(&grace.sa_mask, SIGINT);
    sigaddset(&grace.sa_mask, SIGTERM);
    ::sigaction(SIGALRM, &grace, nullptr);
    install(on_signal);
    return true;
  }();
  (void)installed;
}

bool interrupted() {
  if (flag == 0) return false;
  if (seen == 0) {
    seen = 1;
    ::alarm(0);
  }
  return true;
}

void count_second_interrupt() { count_second = 1; }

bool interrupted_twice() { return flag == 2; }

}  // namespace dartcheck::analysis
