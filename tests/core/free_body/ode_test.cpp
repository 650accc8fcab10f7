// The generic sampled-integration layer (ode.h) on a system that is not the free
// body: the harmonic oscillator x'' = -w^2 x, whose exact flow is a rotation of
// (x, v / w). Grid rules of the fixed-step loop, every method against the exact
// solution, order by step halving, the after-step hook, the total step cap.
#include "rigid/ode.h"

#include <Eigen/Core>
#include <array>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <functional>
#include <vector>

using namespace rigid;
using Catch::Matchers::Contains;

namespace {

using State = std::array<double, 2>;
constexpr double kW = 2.0;  // rad/s

// x'' = -w^2 x as a first-order system on (x, v); templated so Eigen state runs too.
struct Oscillator {
  template <class S>
  void operator()(const S& x, S& dxdt, double /*t*/) const {
    dxdt[0] = x[1];
    dxdt[1] = -kW * kW * x[0];
  }
};

// The exact solution from (1, 0) at t = 0.
State exact(double t) {
  return {std::cos(kW * t), -kW * std::sin(kW * t)};
}

// |(dx, dv / w)|: the error in the frame where the flow is a rotation, so an
// error made at one step is carried unchanged to the end (neither grows nor decays).
double error(const State& x, double t) {
  const State e = exact(t);
  return std::hypot(x[0] - e[0], (x[1] - e[1]) / kW);
}

// Every run goes through integrate_sampled with the observer and hook type-erased:
// each lambda type would otherwise instantiate all ten methods once more, which
// under the sanitizers costs minutes of compilation per call site.
template <class S>
using Observe = std::function<void(const S&, double)>;

template <class System, class S, class Observer>
OdeStats integrate(const System& system, const S& x0, const std::vector<double>& times,
                   const OdeOptions& options, Observer&& observe) {
  const Observe<S> erased = std::ref(observe);
  return integrate_sampled(system, x0, times, options, erased);
}

template <class System, class S, class Observer, class Hook>
OdeStats integrate(const System& system, const S& x0, const std::vector<double>& times,
                   const OdeOptions& options, Observer&& observe, Hook hook) {
  const Observe<S> erased = std::ref(observe);
  return integrate_sampled(system, x0, times, options, erased, std::function<void(S&)>(hook));
}

// Records each sample and the largest error at the samples.
struct Samples {
  std::vector<double> t;
  double worst = 0.0;
  State last{};
  void operator()(const State& x, double ts) {
    t.push_back(ts);
    worst = std::max(worst, error(x, ts));
    last = x;
  }
};

// rk4 that records where every step starts and how long it is.
struct RecordingRk4 {
  boost::numeric::odeint::runge_kutta4<State> rk4;
  std::vector<double> starts, lengths;
  template <class System>
  void do_step(System system, State& x, double t, double dt) {
    starts.push_back(t);
    lengths.push_back(dt);
    rk4.do_step(system, x, t, dt);
  }
};

OdeOptions options_for(Method m, double step_or_tol, std::size_t max_steps = 50'000'000) {
  OdeOptions o;
  o.method = m;
  o.step = step_or_tol;
  o.abs_tol = o.rel_tol = step_or_tol;
  o.max_steps = max_steps;
  return o;
}

// One rk4 run on the grid of step h from (1, 0), with its steps recorded.
struct GridRun {
  RecordingRk4 stepper;
  Samples seen;
  State x{1.0, 0.0};
  OdeStats stats;
  GridRun(const std::vector<double>& times, double h) {
    stats = integrate_on_grid(stepper, Oscillator{}, x, times, options_for(Method::kRk4, h), seen);
  }
};

}  // namespace

TEST_CASE("ode: a fixed-step run ends exactly at t_end, only its last step shortened") {
  // h = 0.3 does not divide 10: 33 whole steps to 9.9 and one of 0.1. Samples
  // every 3rd step, as n * h, then t_end.
  const double h = 0.3, t_end = 10.0;
  std::vector<double> times;
  for (int n = 0; n * h < t_end; n += 3) times.push_back(n * h);
  times.push_back(t_end);
  const GridRun run(times, h);
  const auto& [stepper, seen, x, stats] = run;
  CHECK(seen.t == times);
  REQUIRE(stats.steps == 34);
  REQUIRE(stepper.lengths.size() == 34);
  for (std::size_t n = 0; n < 34; ++n) {
    INFO("step " << n);
    // every step starts on the grid, t0 + n h by multiplication, bit for bit
    CHECK(stepper.starts[n] == static_cast<double>(n) * h);
    if (n < 33) CHECK(stepper.lengths[n] == (n + 1) * h - n * h);
  }
  // the one shortened step: exactly to t_end
  CHECK(stepper.starts.back() + stepper.lengths.back() == t_end);
  CHECK(stepper.lengths.back() < h);
  // 34 steps of rk4 at w h = 0.6: w t (w h)^4 / 120 ~ 0.02 (see the next test)
  CHECK(error(x, t_end) < 0.05);
}

TEST_CASE("ode: a step that divides t_end to roundoff takes no roundoff-sized step") {
  // 0.1 * 100 is 10 to roundoff only: the last sample is grid point 100, reached
  // by a whole step that lands on 10 exactly.
  const GridRun run({0.0, 5.0, 10.0}, 0.1);
  const auto& [stepper, seen, x, stats] = run;
  CHECK(stats.steps == 100);
  CHECK(stepper.starts.back() + stepper.lengths.back() == 10.0);
  for (double dt : stepper.lengths) CHECK(std::abs(dt - 0.1) < 1e-13);
}

TEST_CASE("ode: a sample between grid points is reached without moving the grid") {
  // 0.35 lies between grid points 0.3 and 0.6: one step to it, one back to 0.6.
  const GridRun run({0.0, 0.35, 0.9}, 0.3);
  const auto& [stepper, seen, x, stats] = run;
  CHECK(seen.t == std::vector<double>{0.0, 0.35, 0.9});
  CHECK(stats.steps == 4);
  CHECK(stepper.starts == std::vector<double>{0.0, 0.3, 0.35, 2 * 0.3});
}

TEST_CASE("ode: every method integrates the harmonic oscillator within its own accuracy") {
  // Two samples per second over 10 s (20 rad), the last at 10.01 s off every grid.
  std::vector<double> times;
  for (int i = 0; i <= 20; ++i) times.push_back(0.5 * i);
  times.push_back(10.01);
  SECTION("rk4") {
    // RK4's stability function matches e^{i theta} but for i theta^5 / 120: a
    // phase error of (w h)^5 / 120 per step, w t (w h)^4 / 120 in all; bound twice it.
    const double h = 0.01;
    Samples seen;
    const OdeStats stats =
        integrate(Oscillator{}, State{1, 0}, times, options_for(Method::kRk4, h), seen);
    CHECK(seen.t == times);
    CHECK(stats.steps == 1001);
    const double bound = 2 * kW * 10.01 * std::pow(kW * h, 4) / 120;
    INFO("rk4 error " << seen.worst << ", bound " << bound);
    CHECK(seen.worst < bound);
    CHECK(seen.worst > bound / 10);  // and the estimate is not loose
  }
  SECTION("error-controlled methods") {
    for (Method m : {Method::kDopri5, Method::kRkf78, Method::kBulirschStoer}) {
      for (double tol : {1e-6, 1e-9, 1e-12}) {
        Samples seen;
        const OdeStats stats =
            integrate(Oscillator{}, State{1, 0}, times, options_for(m, tol), seen);
        CHECK(seen.t == times);
        // odeint holds each step's local error below tol (1 + |x| + h |x'|) <= 5 tol
        // per component here (|x|, |v| <= 2); the flow is a rotation, so the global
        // error is at most the sum over steps: 5 tol steps, and 1e-14 of roundoff.
        const double bound = 5 * tol * static_cast<double>(stats.steps) + 1e-14;
        INFO(method_name(m) << " tol " << tol << ": error " << seen.worst << " in " << stats.steps
                            << " steps (" << stats.rejected_steps << " rejected), bound " << bound);
        CHECK(seen.worst < bound);
      }
    }
  }
  SECTION("Eigen fixed-size state gives the std::array answer") {
    for (Method m : {Method::kRk4, Method::kDopri5, Method::kRkf78, Method::kBulirschStoer}) {
      const OdeOptions o = options_for(m, is_adaptive(m) ? 1e-10 : 0.01);
      Samples arr;
      integrate(Oscillator{}, State{1, 0}, times, o, arr);
      Eigen::Vector2d last;
      integrate(Oscillator{}, Eigen::Vector2d(1, 0), times, o,
                [&](const Eigen::Vector2d& x, double) { last = x; });
      INFO(method_name(m));
      // the same steps in another algebra: roundoff apart
      CHECK(std::abs(last[0] - arr.last[0]) < 1e-13);
      CHECK(std::abs(last[1] - arr.last[1]) < 1e-13);
    }
  }
}

TEST_CASE("ode: rk4 through the generic layer converges at order 4 when the step is halved") {
  // t_end = 10.03 is a multiple of none of the steps: the shortened last step
  // must not spoil the order. w h from 0.2 down to 0.05: errors 1e-4..1e-7, asymptotic.
  double errors[3];
  for (int k = 0; k < 3; ++k) {
    Samples seen;
    integrate(Oscillator{}, State{1, 0}, {0.0, 10.03}, options_for(Method::kRk4, 0.1 / (1 << k)),
              seen);
    errors[k] = seen.worst;
  }
  const double p1 = std::log2(errors[0] / errors[1]), p2 = std::log2(errors[1] / errors[2]);
  INFO("errors " << errors[0] << ", " << errors[1] << ", " << errors[2] << "; orders " << p1 << ", "
                 << p2);
  CHECK(std::abs(p1 - fixed_step_order(Method::kRk4)) <= 0.1);
  CHECK(std::abs(p2 - fixed_step_order(Method::kRk4)) <= 0.1);
}

TEST_CASE(
    "ode: the after-step hook keeps the energy of rk4, rkf78 and Verner's pairs to roundoff") {
  // Rescale (x, v / w) back to the unit circle after each step.
  const auto onto_energy = [](State& x) {
    const double r = std::hypot(x[0], x[1] / kW);
    x[0] /= r;
    x[1] /= r;
  };
  const std::vector<double> times = {0.0, 50.0};
  for (Method m : {Method::kRk4, Method::kRkf78, Method::kVern6, Method::kVern7, Method::kVern8,
                   Method::kVern9}) {
    State end{};
    const OdeStats stats = integrate(
        Oscillator{}, State{1, 0}, times, options_for(m, is_adaptive(m) ? 1e-8 : 0.05),
        [&](const State& x, double) { end = x; }, onto_energy);
    INFO(method_name(m) << ": " << stats.steps << " steps");
    // one division per component: a few ulps
    CHECK(std::abs(std::hypot(end[0], end[1] / kW) - 1.0) < 1e-15);
  }
  // dense output interpolates between steps the hook never sees: refused
  CHECK_THROWS_WITH(integrate(
                        Oscillator{}, State{1, 0}, times, options_for(Method::kDopri5, 1e-8),
                        [](const State&, double) {}, onto_energy),
                    Contains("cannot apply an after-step projection"));
  // the free body's splittings need no right-hand side: not here
  CHECK_THROWS_AS(integrate(Oscillator{}, State{1, 0}, times, options_for(Method::kSplitting, 0.1),
                            [](const State&, double) {}),
                  std::invalid_argument);
}

TEST_CASE("ode: the step cap counts the whole run and stops it at once") {
  const auto start = std::chrono::steady_clock::now();
  // 1001 samples, each a step or two apart: odeint's own checker, reset at every
  // sample, would never fire; the cap of 50 is on the run.
  std::vector<double> times;
  for (int i = 0; i <= 1000; ++i) times.push_back(0.1 * i);
  for (Method m : {Method::kDopri5, Method::kRkf78, Method::kBulirschStoer}) {
    INFO(method_name(m));
    CHECK_THROWS_AS(integrate(Oscillator{}, State{1, 0}, times, options_for(m, 1e-10, 50),
                              [](const State&, double) {}),
                    std::runtime_error);
    CHECK_THROWS_WITH(integrate(Oscillator{}, State{1, 0}, times, options_for(m, 1e-10, 50),
                                [](const State&, double) {}),
                      Contains(std::string(method_name(m))) && Contains("more than 50 steps") &&
                          Contains("t = 100 s"));
  }
  // A fixed step is refused before the first step: 1e5 steps asked, 1000 allowed.
  CHECK_THROWS_WITH(integrate(Oscillator{}, State{1, 0}, {0.0, 100.0},
                              options_for(Method::kRk4, 1e-3, 1000), [](const State&, double) {}),
                    Contains("rk4") && Contains("more than 1000 steps") && Contains("t = 100 s"));
  // Exactly the cap is allowed: 1000 steps of 0.1 to t = 100.
  CHECK_NOTHROW(integrate(Oscillator{}, State{1, 0}, {0.0, 100.0},
                          options_for(Method::kRk4, 0.1, 1000), [](const State&, double) {}));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(seconds < 0.5);
}

TEST_CASE("ode: a purely relative tolerance copes with a zero component") {
  // v(0) = 0 has no relative scale: the starting step must leave it out, not divide by 0.
  for (Method m : {Method::kDopri5, Method::kRkf78, Method::kBulirschStoer}) {
    OdeOptions o = options_for(m, 1e-10);
    o.abs_tol = 0.0;
    Samples seen;
    const OdeStats stats = integrate(Oscillator{}, State{1, 0}, {0.0, 1.0, 10.0}, o, seen);
    INFO(method_name(m) << ": " << stats.steps << " steps, error " << seen.worst);
    // as above, 5 tol per step (|x| + h |x'| <= 4 here), summed over the steps
    CHECK(seen.worst < 5e-10 * static_cast<double>(stats.steps));
  }
}

TEST_CASE("ode: bad input is refused by name") {
  const auto none = [](const State&, double) {};
  CHECK_THROWS_WITH(
      integrate(Oscillator{}, State{NAN, 0}, {0.0, 1.0}, options_for(Method::kRk4, 0.1), none),
      Contains("finite"));
  CHECK_THROWS_WITH(
      integrate(Oscillator{}, State{1, 0}, {1.0, 0.0}, options_for(Method::kRk4, 0.1), none),
      Contains("nondecreasing"));
  CHECK_THROWS_WITH(
      integrate(Oscillator{}, State{1, 0}, {0.0, 1.0}, options_for(Method::kRk4, 0.0), none),
      Contains("step must be positive"));
  CHECK_THROWS_WITH(
      integrate(Oscillator{}, State{1, 0}, {0.0, 1.0}, options_for(Method::kDopri5, 2.0), none),
      Contains("tolerances must lie in [0, 1)"));
}

TEST_CASE("ode: an adaptive run may take exactly max_steps steps, and not one more") {
  const std::vector<double> times{0.0, 5.0, 10.0};
  for (const Method m : {Method::kDopri5, Method::kRkf78, Method::kBulirschStoer}) {
    INFO(method_name(m));
    const auto run = [&](std::size_t cap) {
      Samples seen;
      return integrate(Oscillator{}, State{1, 0}, times, options_for(m, 1e-8, cap), seen);
    };
    const std::size_t n = run(1'000'000).steps;
    REQUIRE(n > 2);
    CHECK(run(n).steps == n);
    CHECK_THROWS_AS(run(n - 1), std::runtime_error);
  }
}

TEST_CASE("ode: a run may make exactly max_evaluations evaluations, and not one more") {
  // The work cap counts every right-hand side, rejected steps' included, so it refuses
  // the same run on every machine; every method, fixed-step ones too.
  const std::vector<double> times{0.0, 5.0, 10.0};
  for (const Method m : kAllMethods) {
    if (m == Method::kSplitting || m == Method::kSplitting4) continue;  // no right-hand side
    INFO(method_name(m));
    const auto run = [&](std::size_t cap) {
      Samples seen;
      OdeOptions o = options_for(m, is_adaptive(m) ? 1e-8 : 0.01);
      o.max_evaluations = cap;
      return integrate(Oscillator{}, State{1, 0}, times, o, seen);
    };
    const std::size_t n = run(0).evaluations;  // 0: no cap
    REQUIRE(n > 10);
    CHECK(run(n).evaluations == n);
    CHECK_THROWS_WITH(run(n - 1), Contains(std::string(method_name(m)) + " needs more than " +
                                           std::to_string(n - 1) + " right-hand-side evaluations"));
  }
}

TEST_CASE("ode: a sample time repeated, at the start or later, gives the same state each time") {
  // dense output asked for a state before its first step once interpolated a step not
  // yet taken: dopri5 returned a wrong state, the Verner pairs threw, at a repeated t0
  const std::vector<double> times = {0.5, 0.5, 0.5, 1.0, 1.0, 2.0};
  for (const Method m : kAllMethods) {
    if (!is_adaptive(m)) continue;
    std::vector<double> seen;
    double worst = 0.0;
    integrate(Oscillator{}, exact(0.5), times, options_for(m, 1e-10),
              [&](const State& x, double t) {
                seen.push_back(t);
                // exact() starts at t = 0: the run starts at 0.5 from exact(0.5)
                worst = std::max(worst, error(x, t));
              });
    INFO(method_name(m) << ": worst error " << worst);
    CHECK(seen == times);
    CHECK(worst < 1e-8);  // tolerance 1e-10 over 1.5 s of a period-pi oscillation
  }
}

TEST_CASE("ode: a run shorter than machine epsilon in absolute time is integrated, not skipped") {
  // The oscillator slowed by 1e15: the same motion over 10 s / 1e15. odeint's
  // integrate_times takes sample times closer than epsilon as one and steps nothing
  // between them (rkf78 took 0 steps over a 2.6e-15 s run and returned the initial
  // state); every adaptive method, with and without the hook, must give the 10 s
  // answer of the slow oscillator within its tolerance's bound (as in the test above).
  constexpr double kScale = 1e15;
  struct Fast {
    void operator()(const State& x, State& dxdt, double /*t*/) const {
      dxdt[0] = kScale * x[1];
      dxdt[1] = -kScale * kW * kW * x[0];
    }
  };
  std::vector<double> times;
  for (int i = 0; i <= 20; ++i) times.push_back(0.5 * i / kScale);
  const std::vector<Method> methods = {Method::kDopri5, Method::kRkf78, Method::kBulirschStoer,
                                       Method::kVern6,  Method::kVern7, Method::kVern8,
                                       Method::kVern9};
  for (const Method m : methods) {
    for (const bool hooked : {false, true}) {
      if (hooked && (m == Method::kDopri5 || m == Method::kBulirschStoer)) continue;
      const double tol = 1e-10;
      double worst = 0.0;
      std::size_t seen = 0;
      const auto observe = [&](const State& x, double t) {
        worst = std::max(worst, error(x, t * kScale));
        ++seen;
      };
      const OdeStats stats =
          hooked
              ? integrate(Fast{}, State{1, 0}, times, options_for(m, tol), observe, [](State&) {})
              : integrate(Fast{}, State{1, 0}, times, options_for(m, tol), observe);
      INFO(method_name(m) << (hooked ? " with a hook" : "") << ": " << stats.steps
                          << " steps, error " << worst);
      CHECK(seen == times.size());
      CHECK(stats.steps > 10);
      CHECK(worst < 5 * tol * static_cast<double>(stats.steps) + 1e-14);
    }
  }
}
