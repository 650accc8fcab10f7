// The sample times every integrated run shares, and a reference run's settings (compare.h).
#include "rigid/compare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rigid {

OdeOptions reference_options() {
  OdeOptions o;
  o.method = Method::kVern9;
  o.abs_tol = o.rel_tol = 1e-13;
  return o;
}

std::vector<double> uniform_times(double t0, double t1, std::size_t n) {
  if (n == 0) throw std::invalid_argument("uniform_times: need at least one time");
  std::vector<double> t(n, t0);
  for (std::size_t i = 1; i < n; ++i) {
    t[i] = t0 + (t1 - t0) * static_cast<double>(i) / static_cast<double>(n - 1);
  }
  if (n > 1) t.back() = t1;
  return t;
}

std::vector<double> sample_times(double t_end, double period, double step, double per_period,
                                 std::size_t max_samples) {
  const double spacing =
      std::max(period / per_period, t_end / static_cast<double>(max_samples - 1));
  if (!(step > 0.0)) {
    const double intervals = std::max(1.0, std::round(t_end / spacing));
    return uniform_times(0.0, t_end, static_cast<std::size_t>(intervals) + 1);
  }
  // every k-th step, and k large enough that the grid samples and t_end fit max_samples;
  // k is kept in a double (a step of 1e-24 s makes it 1e22, past any integer type) and
  // is a whole number, so n * step is still the product integrate_on_grid steps to
  const double k = std::max({1.0, std::round(spacing / step),
                             std::ceil(t_end / (step * static_cast<double>(max_samples - 1)))});
  // grid samples n * step short of t_end by more than roundoff, then t_end itself
  const double last = t_end * (1.0 - 8.0 * std::numeric_limits<double>::epsilon());
  std::vector<double> times;
  for (std::size_t i = 0; i < max_samples; ++i) {
    const double t = static_cast<double>(i) * k * step;
    if (!(t < last)) break;
    times.push_back(t);
  }
  times.push_back(t_end);
  return times;
}

}  // namespace rigid
