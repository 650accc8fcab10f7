// The mean of a smooth periodic function over one period by the trapezoidal rule,
// which converges geometrically on such a function (the herpolhode's turning rate,
// a top's phi_dot over its nutation phase).
#pragma once

#include <cmath>

namespace rigid {

/// The mean of f over [0, period), f smooth and `period`-periodic: the trapezoidal rule
/// from 256 samples, doubled (each time adding the midpoints) until two doublings in a
/// row agree to `rel_tol`, with at least 1024 samples so that a narrow peak missed alike
/// by two coarse sums cannot pass for convergence; at most 2^22 samples.
template <class F>
double periodic_mean(F f, double period, double rel_tol = 1e-13) {
  constexpr int kFirst = 256, kLeast = 1024, kMost = 1 << 22;
  double sum = 0.0;
  for (int k = 0; k < kFirst; ++k) sum += f(period * k / kFirst);
  double mean = sum / kFirst;
  int agreed = 0;
  for (int n = kFirst; n < kMost && agreed < 2; n *= 2) {
    for (int k = 0; k < n; ++k) sum += f(period * (k + 0.5) / n);
    const double refined = sum / (2 * n);
    const bool close = std::abs(refined - mean) <= rel_tol * std::abs(refined);
    agreed = close && 2 * n >= kLeast ? agreed + 1 : 0;
    mean = refined;
  }
  return mean;
}

}  // namespace rigid
