// The integrated motion every lab that plays an integrator shares
// (labs/common/integrated_motion.h): its states are one run's from t = 0, the same
// in any order of asking, and every failure is an InputError naming the input that
// governs the step.
#include "common/integrated_motion.h"

#include <catch2/catch.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "rigid/free_body_integrate.h"

using rigid::FreeBodyProblem;
using rigid::Method;
using rigid::OdeOptions;
using rigid::RotationState;
using rigid::lab::InputError;
using Motion = rigid::lab::IntegratedMotion<FreeBodyProblem>;

namespace {

const FreeBodyProblem kBody(rigid::PrincipalMoments{1.0, 2.0, 3.0});
const RotationState kStart = rigid::make_state({1.0, 0.1, 1.0}, Eigen::Quaterniond::Identity());
// The free body's lab holds a run to T and |L|.
constexpr std::size_t kRunawayInvariants = 2;

OdeOptions options_of(Method method, double step = 0.01) {
  OdeOptions o;
  o.method = method;
  o.step = step;
  o.abs_tol = o.rel_tol = 1e-10;
  return o;
}

// The input an InputError thrown by `make` names, and its rule.
template <class Make>
std::pair<std::string, std::string> refusal(Make&& make) {
  try {
    make();
  } catch (const InputError& e) {
    return {e.input, e.rule};
  }
  FAIL("no InputError");
  return {};
}

}  // namespace

TEST_CASE("integrated motion: the times ahead run from 0, sorted, once each") {
  CHECK(rigid::lab::times_from_start({0.5, -1.0, 0.25, 0.5, 0.0}) ==
        std::vector<double>{0.0, 0.25, 0.5});
  CHECK(rigid::lab::times_from_start({2.0}) == std::vector<double>{0.0, 2.0});
}

TEST_CASE("integrated motion: its states are one run's from t = 0, in any order of asking") {
  for (const Method m : {Method::kRk4, Method::kDopri5, Method::kSplitting4}) {
    INFO(rigid::method_name(m));
    const OdeOptions o = options_of(m);
    const std::vector<double> frames{0.0, 0.7, 1.3, 2.0};
    const Motion motion(kBody, kStart, o, kRunawayInvariants, {}, {1.3, 0.7, 2.0, 0.7});
    CHECK(motion.sampled_times() == frames);
    // at a frame: the one run's state there, bit for bit
    const auto run = rigid::integrate(kBody, kStart, frames, o);
    for (std::size_t k = 0; k < frames.size(); ++k) {
      CHECK(motion.state(frames[k]) == run.samples[k].x);
    }
    // between frames: integrated on from the frame before, whichever was asked first
    const RotationState later = motion.state(1.9);
    const RotationState between = motion.state(1.0);
    CHECK(between == rigid::integrate(kBody, run.samples[1].x, {0.7, 1.0}, o).samples.back().x);
    CHECK(motion.state(1.9) == later);
    CHECK(later == rigid::integrate(kBody, run.samples[2].x, {1.3, 1.9}, o).samples.back().x);
  }
}

TEST_CASE("integrated motion: the lab's own run is kept, the run ahead takes its place") {
  const OdeOptions o = options_of(Method::kRk4);
  const auto own = rigid::integrate(kBody, kStart, {0.0, 0.5, 1.0}, o);
  // with nothing sampled ahead, the lab's run's states
  const Motion alone(kBody, kStart, o, kRunawayInvariants, own.samples, {});
  CHECK(alone.sampled_times().empty());
  CHECK(alone.state(0.5) == own.samples[1].x);
  // a run ahead through 0.5 replaces its state there (the same run: the same state)
  const Motion both(kBody, kStart, o, kRunawayInvariants, own.samples, {0.5, 0.75});
  CHECK(both.state(0.5) == own.samples[1].x);
  CHECK(both.state(1.0) == own.samples[2].x);
  CHECK(both.state(0.75) == rigid::integrate(kBody, kStart, {0.0, 0.5, 0.75}, o).samples[2].x);
}

TEST_CASE("integrated motion: every failure names the input that governs the step") {
  // A run past its step budget: ahead, and between frames (where a cache once let core's
  // error through unnamed).
  OdeOptions fixed = options_of(Method::kRk4);
  fixed.max_steps = 1000;
  const auto [input, rule] = refusal([&] { Motion(kBody, kStart, fixed, 2, {}, {0.0, 20.0}); });
  CHECK(input == "--step");
  CHECK_THAT(rule, Catch::Contains("needs more than 1000 steps"));
  const Motion short_run(kBody, kStart, fixed, kRunawayInvariants, {}, {0.0, 5.0});
  CHECK(refusal([&] { short_run.state(30.0); }).first == "--step");
  OdeOptions adaptive = options_of(Method::kDopri5);
  adaptive.max_steps = 5;
  const auto [adaptive_input, adaptive_rule] = refusal([&] {
    Motion(kBody, kStart, adaptive, 2, {}, {0.0, 20.0});
  });
  CHECK(adaptive_input == "--tolerance");
  CHECK_THAT(adaptive_rule, Catch::Contains("needs more than 5 steps"));
  // A run that kept going but lost T and |L| (rk4 three times past its stable step grows
  // T by 1e131 in four steps), or went on to overflow: refused as the lab's own run is.
  const OdeOptions unstable = options_of(Method::kRk4, 3.0);
  const auto [runaway_input, runaway_rule] = refusal([&] {
    Motion(kBody, kStart, unstable, 2, {}, {0.0, 3.0, 6.0, 9.0, 12.0});
  });
  CHECK(runaway_input == "--step");
  CHECK_THAT(runaway_rule, Catch::Contains("ran away"));
  // (sampled only at its ends, the run's invariants read 0 before its NaN at t = 60)
  const auto [diverged_input, diverged_rule] = refusal([&] {
    Motion(kBody, kStart, unstable, 2, {}, {0.0, 60.0});
  });
  CHECK(diverged_input == "--step");
  CHECK_THAT(diverged_rule, Catch::Contains("diverged"));
  // Before the start: no state, and not the user's input at fault.
  CHECK_THROWS_AS(short_run.state(-1.0), std::invalid_argument);
}
