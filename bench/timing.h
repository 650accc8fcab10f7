// Wall-clock timing for the benchmarks: best of several repeats on
// std::chrono::steady_clock. The machine is shared, so the minimum over
// repeats (not the mean) is the estimate of the undisturbed cost.
#pragma once

#include <algorithm>
#include <chrono>
#include <limits>

namespace bench {

struct TimingPolicy {
  double min_total_s = 0.05;  ///< keep repeating until this much time is spent...
  int min_repeats = 3;        ///< ...and at least this many repeats were made,
  double max_total_s = 0.6;   ///< unless this much time is spent already (one long run is enough)
};

/// Runs f() repeatedly and returns the fastest single run in seconds.
template <class F>
double best_seconds(F&& f, const TimingPolicy& policy = {}) {
  using clock = std::chrono::steady_clock;
  double best = std::numeric_limits<double>::infinity(), total = 0.0;
  for (int rep = 1;; ++rep) {
    const auto t0 = clock::now();
    f();
    const double s = std::chrono::duration<double>(clock::now() - t0).count();
    best = std::min(best, s);
    total += s;
    if (total >= policy.max_total_s) break;
    if (rep >= policy.min_repeats && total >= policy.min_total_s) break;
  }
  return best;
}

/// Keeps a value alive so the optimiser cannot drop the computation behind it.
template <class T>
inline void do_not_optimize(const T& value) {
  asm volatile("" : : "r,m"(value) : "memory");
}

}  // namespace bench
