// The median wall time of `runs` calls of f, in milliseconds: what the
// side-by-side programs report (the machines are shared and noisy).
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace dartcheck::bench {

template <class F>
double median_ms(int runs, F f) {
  std::vector<double> t;
  for (int k = 0; k < runs; ++k) {
    const auto start = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

}  // namespace dartcheck::bench
