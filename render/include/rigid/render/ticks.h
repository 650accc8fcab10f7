// Axis ticks: "nice" linear ticks by the 1-2-5 rule and log10 ticks at
// decades, with the labels a plot draws under them (in text.h markup).
#pragma once

#include <string>
#include <vector>

namespace rigid::render {

/// Tick positions and their labels for one axis; lo/hi is the axis range they were chosen for.
struct Ticks {
  std::vector<double> values;
  std::vector<std::string> labels;  ///< text.h markup, e.g. "0.5", "−2", "10^{-6}"
  std::vector<double> minor;        ///< minor tick positions (log axes: 2..9 × 10^k)
  double lo = 0, hi = 1;
};

/// The 1-2-5 step (1, 2 or 5 times a power of ten) giving about target_count intervals over range.
double nice_step(double range, int target_count);

/// Linear ticks at multiples of nice_step inside [lo, hi], labelled with just enough decimals.
Ticks linear_ticks(double lo, double hi, int target_count = 6);

/// Log10 ticks at decades 10^k inside [lo, hi] (lo > 0), labelled "10^{k}", thinned to at most
/// max_count; under two decades it falls back to linear 1-2-5 ticks.
Ticks log_ticks(double lo, double hi, int max_count = 8);

/// Formats v with `decimals` digits after the point, a true minus sign, and "−0" avoided.
std::string format_tick(double v, int decimals);

}  // namespace rigid::render
