// A lab's motion drawn from an integrator (poinsot, tennis_racquet, top_nutation):
// one run of the chosen method from the start through every time an animation will
// ask for, its states kept with those of the lab's own run, and any other time
// integrated on from the nearest earlier kept state. Each frame is then what one run
// from t = 0 gives there, never a step of another run, and the same t gives the same
// state in any order (nothing mutable).
//
// One failure rule for every run it makes, the lab's own run's (report_run): any
// failure of the integrator (a broken rule, more steps or evaluations than the
// budget) is an InputError naming the input that governs the step, "--step" for a
// fixed-step method and "--tolerance" for an adaptive one; so is a run whose states
// are no longer finite, or whose conserved quantities ran away (refuse_runaway over
// the invariants the lab holds its own run to): a run of other samples that lost them
// would draw a body no longer the same. The three caches this replaces each had a rule
// of their own: poinsot's was this one but for the divergence; tennis_racquet's named
// the input only for the run ahead (a step between frames threw core's error unnamed)
// and refused no run-away; top_nutation's named it only for a broken rule (a run past
// its budget threw unnamed) and refused no run-away either.
#pragma once

#include <cmath>
#include <cstddef>
#include <exception>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/figures.h"
#include "common/inputs.h"
#include "common/integrated_run.h"
#include "rigid/compare.h"
#include "rigid/rotation.h"

namespace rigid::lab {

/// `times` from the start as one run samples them: sorted, without repeats or negative
/// times, beginning with 0.
std::vector<double> times_from_start(std::vector<double> times);

/// Refuses (an InputError naming `input`) a run that diverged: a state not finite.
[[noreturn]] void refuse_divergence(const std::string& input);

/// Refuses (std::invalid_argument) t, a time before the motion's start, t = 0.
[[noreturn]] void refuse_before_start(double t);

/// `motion`, but at each time a lab's own run sampled, that sample's state, as the lab's
/// CSV writes it (a closed form evaluated by another route differs by an ulp or two).
template <class Sample>
BodyMotion keeping_samples(BodyMotion motion, const std::vector<Sample>& samples) {
  auto kept = std::make_shared<std::map<double, BodyState>>();
  for (const Sample& s : samples) kept->emplace(s.t, BodyState{attitude(s.x), omega_body(s.x)});
  return [motion = std::move(motion), kept](double t) {
    const auto found = kept->find(t);
    return found != kept->end() ? found->second : motion(t);
  };
}

/// The integrated motion of `Problem` (compare.h), sampled ahead.
template <class Problem>
class IntegratedMotion {
 public:
  using State = typename Problem::State;
  using Sample = typename Run<Problem>::Sample;

  /// The motion from x0 at t = 0 by `options`: the lab's own run's `run_samples` kept,
  /// then one run through `sample_times` (times_from_start; none for fewer than two),
  /// whose states take the place of the lab's run's at a time both sampled. A run is
  /// held to its first `runaway_invariants` invariants (at least the energy), as the
  /// lab's own run is (ExactErrorWords::runaway_invariants).
  IntegratedMotion(Problem problem, const State& x0, const OdeOptions& options,
                   std::size_t runaway_invariants, const std::vector<Sample>& run_samples,
                   const std::vector<double>& sample_times)
      : problem_(std::move(problem)),
        options_(options),
        input_(step_input(options)),
        runaway_invariants_(runaway_invariants) {
    keep(run_samples);
    if (sample_times.empty()) return;
    times_ = times_from_start(sample_times);
    if (times_.size() >= 2) keep(integrate_from(x0, times_).samples);
  }

  /// The state at t >= 0: a kept one, or integrated on from the nearest earlier kept
  /// one (one sample spacing's work). Throws std::invalid_argument for t < 0, and an
  /// InputError (the failure rule above) for a run that fails.
  State state(double t) const {
    const auto after = states_.upper_bound(t);
    if (after == states_.begin()) refuse_before_start(t);
    const auto& [t0, x0] = *std::prev(after);
    if (t0 == t) return x0;
    return integrate_from(x0, {t0, t}).samples.back().x;
  }

  /// The times sampled ahead, times_from_start of the sample times given (none if none).
  const std::vector<double>& sampled_times() const { return times_; }

 private:
  void keep(const std::vector<Sample>& samples) {
    for (const Sample& s : samples) states_[s.t] = s.x;
  }

  Run<Problem> integrate_from(const State& x0, const std::vector<double>& times) const {
    Run<Problem> run;
    try {
      run = integrate(problem_, x0, times, options_);
    } catch (const std::exception& e) {
      throw InputError(input_, e.what());
    }
    // A sample that is not finite has no finite invariants to judge either.
    for (const Sample& s : run.samples) {
      for (const double v : s.x) {
        if (!std::isfinite(v)) refuse_divergence(input_);
      }
    }
    refuse_runaway(input_,
                   runaway_drift({run.max_invariant_error.begin(), run.max_invariant_error.end()},
                                 runaway_invariants_));
    return run;
  }

  Problem problem_;
  OdeOptions options_;
  std::string input_;  ///< the input a failure names
  std::size_t runaway_invariants_;
  std::map<double, State> states_;  ///< the states kept, by time
  std::vector<double> times_;       ///< the times sampled ahead
};

}  // namespace rigid::lab
