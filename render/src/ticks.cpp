// Axis ticks: the 1-2-5 rule for linear axes and decades for log axes.
#include "rigid/render/ticks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rigid::render {

double nice_step(double range, int target_count) {
  if (!(range > 0) || !std::isfinite(range)) return 1.0;
  const double raw = range / std::max(1, target_count);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / mag;
  // Round the raw step to the nearest of 1, 2, 5, 10 on a log scale.
  const double nice = f < std::sqrt(2.0)    ? 1
                      : f < std::sqrt(10.0) ? 2
                      : f < std::sqrt(50.0) ? 5
                                            : 10;
  return nice * mag;
}

std::string format_tick(double v, int decimals) {
  std::string s = fmt::format("{:.{}f}", v, std::max(0, decimals));
  // "-0.0" reads as zero; otherwise use a true minus sign.
  if (s.front() == '-') {
    if (s.find_first_not_of("-0.") == std::string::npos)
      s.erase(0, 1);
    else
      s.replace(0, 1, "\u2212");
  }
  return s;
}

Ticks linear_ticks(double lo, double hi, int target_count) {
  if (!(hi > lo)) throw std::invalid_argument("linear_ticks: need lo < hi");
  Ticks t;
  t.lo = lo;
  t.hi = hi;
  const double step = nice_step(hi - lo, target_count);
  const double eps = step * 1e-9;
  const double first = std::ceil((lo - eps) / step);
  const double last = std::floor((hi + eps) / step);
  // Decimals: enough to show the step; large or tiny values get a common power of ten.
  const double mag = std::max(std::abs(lo), std::abs(hi));
  const int exp10 = (mag >= 1e5 || mag < 1e-3) ? static_cast<int>(std::floor(std::log10(mag))) : 0;
  const double unit = std::pow(10.0, exp10);
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step / unit) + 1e-9)));
  for (double k = first; k <= last; ++k) {
    const double v = k * step;
    t.values.push_back(v);
    std::string label = format_tick(v / unit, decimals);
    if (exp10 != 0 && std::abs(v) > eps) label += "\u00d710^{" + std::to_string(exp10) + "}";
    t.labels.push_back(label);
  }
  return t;
}

Ticks log_ticks(double lo, double hi, int max_count) {
  if (!(lo > 0) || !(hi > lo)) throw std::invalid_argument("log_ticks: need 0 < lo < hi");
  Ticks t;
  t.lo = lo;
  t.hi = hi;
  const int k0 = static_cast<int>(std::ceil(std::log10(lo) - 1e-9));
  const int k1 = static_cast<int>(std::floor(std::log10(hi) + 1e-9));
  // Every n-th decade so that at most max_count are labelled.
  const int n = std::max(1, (k1 - k0 + max_count) / std::max(1, max_count));
  for (int k = k0; k <= k1; ++k) {
    if ((k - k0) % n != 0) continue;
    t.values.push_back(std::pow(10.0, k));
    t.labels.push_back("10^{" + std::to_string(k) + "}");
  }
  // Minor ticks at 2..9 × 10^k when decades are shown one by one.
  if (n == 1)
    for (int k = k0 - 1; k <= k1; ++k)
      for (int m = 2; m <= 9; ++m) {
        const double v = m * std::pow(10.0, k);
        if (v >= lo && v <= hi) t.minor.push_back(v);
      }
  // Under two decades: 1, 2 and 5 times each power of ten, still a log axis's ticks
  // (the decade among them labelled as a decade), where two or more fall inside.
  if (t.values.size() < 2) {
    Ticks f;
    f.lo = lo;
    f.hi = hi;
    for (int k = k0 - 1; k <= k1; ++k)
      for (const int m : {1, 2, 5}) {
        const double v = m * std::pow(10.0, k);
        if (v < lo * (1 - 1e-9) || v > hi * (1 + 1e-9)) continue;
        f.values.push_back(v);
        f.labels.push_back((m == 1 ? "" : std::to_string(m) + "\u00d7") + "10^{" +
                           std::to_string(k) + "}");
      }
    if (f.values.size() >= 2 && static_cast<int>(f.values.size()) <= std::max(2, max_count))
      return f;
  }
  // Under one 1-2-5 step: linear ticks, so the axis is still readable.
  if (t.values.size() < 2) {
    Ticks lin = linear_ticks(lo, hi, 4);
    lin.minor.clear();
    return lin;
  }
  return t;
}

}  // namespace rigid::render
