// Wall-clock timing for benchmark tables: the median of several runs, so one
// descheduled run does not move the figure.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace vivp::bench {

template <class F>
double MedianSeconds(F&& run, int repeats = 7) {
  std::vector<double> t;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    run();
    t.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
            .count());
  }
  std::nth_element(t.begin(), t.begin() + repeats / 2, t.end());
  return t[repeats / 2];
}

// Keeps the optimiser from discarding a computed value.
template <class T>
void DoNotOptimize(const T& value) {
  asm volatile("" : : "r,m"(value) : "memory");
}

}  // namespace vivp::bench
