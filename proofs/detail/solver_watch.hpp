// Interrupts a Z3 context when the caller asks to stop (Ctrl-C): prove's
// topological and embedding queries both run under one.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <thread>

#include <z3++.h>

namespace dartcheck::proofs {

// Interrupts the context's solver when the caller asks to stop: a thread
// polls `stop` while the rule is proved (Z3's interrupt is the one call
// that is safe from another thread).
class SolverWatch {
 public:
  SolverWatch(z3::context& ctx, const std::function<bool()>& stop) {
    if (!stop) return;
    thread_ = std::jthread([&ctx, stop, this](std::stop_token token) {
      while (!token.stop_requested()) {
        if (stop()) {
          fired_ = true;
          ctx.interrupt();
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    });
  }
  bool fired() const { return fired_; }

 private:
  std::atomic<bool> fired_ = false;
  std::jthread thread_;  // last: joined before fired_ goes
};

}  // namespace dartcheck::proofs
