#include "rigid/drift.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rigid {

InvariantError invariant_error(const std::vector<double>& t, const std::vector<double>& e,
                               double period) {
  if (t.size() != e.size()) throw std::invalid_argument("invariant_error: t and e differ in size");
  if (!(period > 0.0)) throw std::invalid_argument("invariant_error: the period must be positive");
  InvariantError out;
  const double n = static_cast<double>(t.size());
  double t_mean = 0.0, e_mean = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    out.max_rel = std::max(out.max_rel, std::abs(e[i]));
    t_mean += t[i] / n;
    e_mean += e[i] / n;
  }
  // The slope from centred sums (two passes: no cancellation of large t^2 sums).
  double stt = 0.0, ste = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    stt += (t[i] - t_mean) * (t[i] - t_mean);
    ste += (t[i] - t_mean) * (e[i] - e_mean);
  }
  if (stt > 0.0) out.drift_per_period_rel = ste / stt * period;
  return out;
}

}  // namespace rigid
