// Wall-clock timing for the benchmarks: best of several repeats on
// std::chrono::steady_clock. The machine is shared, so the minimum over
// repeats (not the mean) is the estimate of the undisturbed cost.
#pragma once

#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace bench {

struct TimingPolicy {
  double min_total_s = 0.05;  ///< keep repeating until this much time is spent...
  int min_repeats = 3;        ///< ...and at least this many repeats were made,
  double max_total_s = 0.6;   ///< unless this much time is spent already (one long run is enough)
};

/// Keeps a value alive so the optimiser cannot drop the computation behind it.
template <class T>
inline void do_not_optimize(const T& value) {
  asm volatile("" : : "r,m"(value) : "memory");
}

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

/// The fastest time of one pass summing sample(i) over i = 0 .. samples - 1 (the sum is
/// kept, so that no sample is optimised away).
template <class F>
double best_sum_seconds(int samples, F&& sample, const TimingPolicy& policy = {}) {
  return best_seconds(
      [&] {
        double sum = 0;
        for (int i = 0; i < samples; ++i) sum += sample(i);
        do_not_optimize(sum);
      },
      policy);
}

/// Each solver's sweep (`sweep(s)` appends its settings' measurements, each with its
/// `solver` and `seconds`, to `ms`), then `rounds - 1` more rounds over every measured
/// setting, each keeping the setting's fastest time (`again(m)`: its time once more, or
/// a negative number if it failed): the machine is shared, and a burst of load then
/// spoils one round of a setting, not all. `tick(what)` after each solver's part.
template <class Solver, class Measurement>
void measure_in_rounds(const std::vector<Solver>& solvers, std::vector<Measurement>& ms, int rounds,
                       const std::function<void(const Solver&)>& sweep,
                       const std::function<double(const Measurement&)>& again,
                       const std::function<void(const std::string&)>& tick) {
  for (const Solver& s : solvers) {
    sweep(s);
    tick(s.name);
  }
  for (int round = 1; round < rounds; ++round) {
    for (const Solver& s : solvers) {
      for (Measurement& m : ms) {
        if (m.solver != &s) continue;
        const double seconds = again(m);
        if (seconds >= 0.0) m.seconds = std::min(m.seconds, seconds);
      }
      tick(s.name + ", round " + std::to_string(round + 1));
    }
  }
}

}  // namespace bench
