// How a conserved quantity's error behaves over a run, in the two numbers that
// tell integrators apart: its largest deviation, and its secular drift, the
// trend of the signed error fitted by least squares and given per period. A
// symplectic method's error oscillates in a bounded band: its fitted trend is
// the band's width over the run's length and falls as the run grows. A
// non-symplectic method's error grows steadily: its trend per period stays put.
#pragma once

#include <vector>

namespace rigid {

/// The error of one invariant over a run.
struct InvariantError {
  double max_rel = 0.0;               ///< max |e(t)| over the samples
  double drift_per_period_rel = 0.0;  ///< least-squares slope of e(t) times the period
};

/// The error of an invariant sampled as signed relative errors `e` at times `t`
/// (equal sizes), its trend given per `period` (> 0). Fewer than two distinct
/// times have no trend (0).
InvariantError invariant_error(const std::vector<double>& t, const std::vector<double>& e,
                               double period);

}  // namespace rigid
