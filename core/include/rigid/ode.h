// Sampled integration of any ODE on fixed-size state, one layer for every
// system (the free body, the heavy top): a system brings its right-hand side
// (an odeint functor `void operator()(const State& x, State& dxdt, double t) const`),
// an observer of its invariants `observe(const State& x, double t)` and, if it
// wants one, an after-step hook (a projection onto its invariants); the
// stepping is done here, once.
//
//  - "rk4": Boost.Odeint runge_kutta4 on the fixed grid t0 + n h.
//  - "dopri5": runge_kutta_dopri5, error-controlled, with dense output.
//  - "rkf78": runge_kutta_fehlberg78, error-controlled.
//  - "bulirsch-stoer": bulirsch_stoer_dense_out.
//  - "vern6", "vern7", "vern8", "vern9": Verner's most efficient pairs 6(5) ..
//    9(8) (verner.h) under a PI step-size controller, with Verner's
//    interpolants between steps (dense output); with an after-step hook they
//    run as odeint controlled steppers instead, which land on every sample.
//  - "splitting", "splitting4": a problem's own structure-preserving splitting,
//    order 2 and 4 (the free body's Lie-Poisson splitting, the heavy top's
//    kicks and free flows); named here so one Method lists every integrator,
//    they step through integrate_on_grid with the problem's stepper (compare.h).
//
// Samples land exactly on the requested times. The error-controlled methods go
// through odeint's integrate_times (dense output interpolates, the controlled
// stepper shortens the step that would pass a sample). A fixed-step method
// steps on the grid t0 + n h, each grid time computed by multiplication, never
// accumulated; a sample on the grid (to roundoff) is reached by whole steps;
// the last sample is reached by shortening only the last step; a sample
// between grid points and before the last costs one shortened step to reach
// it and one to rejoin the grid, so the grid never shifts.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

// GCC 12 sees odeint's steppers copy their (never read) scratch states when
// they are built and warns -Wmaybe-uninitialized inside Boost; silence only
// that, only for the code of this header.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/numeric/odeint/integrate/integrate_times.hpp>
// Before Bulirsch-Stoer: its binomial coefficients, multiplied out exactly.
#include <boost/numeric/odeint/stepper/bulirsch_stoer_dense_out.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>

#include "rigid/ode_options.h"
#include "rigid/odeint_binomial.h"
#include "rigid/verner.h"
// odeint's Eigen support must follow its own headers (it specialises their templates).
#include <boost/numeric/odeint/external/eigen/eigen.hpp>

namespace rigid {

/// The after-step hook that does nothing.
struct NoAfterStep {
  template <class State>
  void operator()(State& /*x*/) const {}
};

namespace detail {
template <class T, class = void>
inline constexpr bool kHasReset = false;
template <class T>
inline constexpr bool kHasReset<T, std::void_t<decltype(std::declval<T&>().reset())>> = true;
}  // namespace detail

/// An odeint stepper (simple or controlled) that applies `after_step` to the
/// state after every accepted step of `Stepper`, and counts rejected steps.
template <class Stepper, class AfterStep>
class AfterStepStepper {
 public:
  using stepper_category = typename Stepper::stepper_category;
  using state_type = typename Stepper::state_type;
  using value_type = typename Stepper::value_type;
  using deriv_type = typename Stepper::deriv_type;
  using time_type = typename Stepper::time_type;

  /// Wraps a stepper and a hook `void(State&)`.
  AfterStepStepper(Stepper stepper, AfterStep after_step)
      : stepper_(std::move(stepper)), after_step_(std::move(after_step)) {}

  /// odeint's Stepper concept: one step of dt from t, then the hook.
  template <class System, class State>
  void do_step(System system, State& x, time_type t, time_type dt) {
    stepper_.do_step(system, x, t, dt);
    after_step_(x);
  }

  /// odeint's ControlledStepper concept: the hook after a success, a count after a failure.
  template <class System, class State>
  boost::numeric::odeint::controlled_step_result try_step(System system, State& x, time_type& t,
                                                          time_type& dt) {
    const auto r = stepper_.try_step(system, x, t, dt);
    if (r == boost::numeric::odeint::success) {
      after_step_(x);
      // an FSAL stepper keeps f(x) for its next step: after a real hook x has moved
      if constexpr (!std::is_same_v<AfterStep, NoAfterStep> && detail::kHasReset<Stepper>) {
        stepper_.reset();
      }
    } else {
      ++rejected_;
    }
    return r;
  }

  /// Steps rejected by the error control so far.
  std::size_t rejected_steps() const { return rejected_; }

 private:
  Stepper stepper_;
  AfterStep after_step_;
  std::size_t rejected_ = 0;
};

/// An odeint StepOverflowChecker that caps the total steps of a run: odeint
/// calls reset() at every observation, which leaves the total alone.
class TotalStepCap {
 public:
  /// A cap of max_steps for a run of method m to t_end.
  TotalStepCap(Method m, std::size_t max_steps, double t_end);
  /// Counts one step; throws std::runtime_error naming the method, the cap and t_end past the cap.
  void operator()();
  /// Called by odeint at each observation: a cap per run, not per sample, so nothing to do.
  void reset() {}

 private:
  Method method_;
  std::size_t max_steps_;
  double t_end_;
  std::size_t steps_ = 0;
};

namespace detail {

// Where a sample time falls on the grid t0 + n h: the last grid index at or
// before it (to roundoff), and whether it is that grid point.
struct GridSample {
  std::size_t n = 0;
  bool on_grid = true;
};

// The grid position of every sample time (validated); throws
// std::invalid_argument naming the method, step and t_end when the run would
// need more than options.max_steps steps, before any is taken.
std::vector<GridSample> plan_grid(const std::vector<double>& times, const OdeOptions& options);

// The one wording of "this run needs more than options.max_evaluations evaluations".
std::string too_many_evaluations(const OdeOptions& options);

// Throws std::invalid_argument unless every component of x is finite.
template <class State>
void require_finite(const State& x) {
  for (const double v : x) {
    if (!std::isfinite(v)) throw std::invalid_argument("initial state must be finite");
  }
}

// A first trial step for an error-controlled method of order p (Hairer, Norsett
// & Wanner, Solving ODEs I, II.4, "starting step size"): the step whose local
// error, estimated from f and a difference quotient of f, is about the tolerance.
template <class System, class State>
double starting_step(const System& system, const State& x0, double t0, double span, int order,
                     const OdeOptions& o) {
  const std::size_t n = static_cast<std::size_t>(x0.size());
  State f0 = x0, x1 = x0, f1 = x0;
  system(x0, f0, t0);
  // RMS norm weighted by the tolerance each component is held to; a zero
  // component under a purely relative tolerance has no scale and is left out
  const auto norm = [&](const auto& component) {
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double scale = o.abs_tol + o.rel_tol * std::abs(x0[i]);
      if (scale > 0.0) sum += (component(i) / scale) * (component(i) / scale);
    }
    return std::sqrt(sum / static_cast<double>(n));
  };
  const double d0 = norm([&](std::size_t i) { return x0[i]; });
  const double d1 = norm([&](std::size_t i) { return f0[i]; });
  const double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 * span : 0.01 * d0 / d1;
  for (std::size_t i = 0; i < n; ++i) x1[i] = x0[i] + h0 * f0[i];
  system(x1, f1, t0 + h0);
  const double d2 = norm([&](std::size_t i) { return f1[i] - f0[i]; }) / h0;
  const double d = std::max(d1, d2);
  const double h1 =
      d <= 1e-15 ? std::max(1e-6 * span, 1e-3 * h0) : std::pow(0.01 / d, 1.0 / (order + 1));
  return std::min({100.0 * h0, h1, span});
}

// Error-controlled runs: odeint's integrate_times with a cap on the total steps.
template <class Stepper, class System, class State, class Observer>
std::size_t integrate_times_capped(Stepper& stepper, const System& system, State& x,
                                   const std::vector<double>& times, double dt0,
                                   const OdeOptions& o, Observer& observe, double t_end) {
  // t_end in the caller's time, for its message
  TotalStepCap cap(o.method, o.max_steps, t_end);
  return boost::numeric::odeint::integrate_times(std::ref(stepper), system, x, times.begin(),
                                                 times.end(), dt0, std::ref(observe),
                                                 std::ref(cap));
}

// odeint's integrate_times treats sample times less than machine epsilon apart (in
// absolute time) as one and steps nothing between them, and its dense-output steppers
// break down for steps below ~1e-15 (dopri5 returns NaN, Bulirsch-Stoer's interpolation
// reads out of bounds: seen for runs shorter than 1e-14 s; rkf78 took 0 steps over a
// 2.6e-15 s run). So a short run goes in tau = (t - t0) / span, the whole run one unit
// of time: dx/dtau = span f(x, t). The control acts on the state; only the starting
// step's rule is not scale-free, so runs of a millisecond or more keep their own time and
// their results (and the system is called as given, with nothing wrapped round it).
// `run(system, times, dt0, observe)` integrates with the system and times it is given.
template <class System, class State, class Observer, class Run>
std::size_t in_run_time(const System& system, const State& x, const std::vector<double>& times,
                        int order, const OdeOptions& options, Observer& observe, Run run) {
  const double t0 = times.front(), span = times.back() - t0;
  if (!(span > 0.0 && span < 1e-3)) {
    return run(system, times, starting_step(system, x, t0, span, order, options), observe);
  }
  const double scale = span;
  const auto scaled = [&system, t0, scale](const State& xs, State& dxdtau, double tau) {
    system(xs, dxdtau, t0 + tau * scale);
    for (auto& v : dxdtau) v *= scale;
  };
  std::vector<double> tau(times.size());
  for (std::size_t i = 0; i < times.size(); ++i) tau[i] = (times[i] - t0) / scale;
  tau.back() = span / scale;
  std::size_t next = 0;  // the observer sees the times asked for, not tau
  auto observe_t = [&](const State& xs, double) { observe(xs, times[next++]); };
  return run(scaled, tau, starting_step(scaled, x, 0.0, span / scale, order, options), observe_t);
}

// An error-controlled stepper (order `order`) through the sample times, in run time.
template <class Stepper, class System, class State, class Observer>
std::size_t integrate_controlled(Stepper& stepper, int order, const System& system, State& x,
                                 const std::vector<double>& times, const OdeOptions& options,
                                 Observer& observe) {
  return in_run_time(system, x, times, order, options, observe,
                     [&](const auto& sys, const std::vector<double>& ts, double dt0, auto& obs) {
                       return integrate_times_capped(stepper, sys, x, ts, dt0, options, obs,
                                                     times.back());
                     });
}

// A dense-output stepper (order `order`) through the sample times, in run time.
template <class Stepper, class System, class State, class Observer>
std::size_t integrate_dense(Stepper& stepper, int order, const System& system, State& x,
                            const std::vector<double>& times, const OdeOptions& options,
                            Observer& observe) {
  // A sample time repeated at the start is the initial state each time: odeint's dense
  // output would interpolate a step it has not taken yet (dopri5 returned garbage there)
  if (times.size() > 1 && times[1] == times.front()) {
    std::size_t first = 0;
    while (first + 1 < times.size() && times[first + 1] == times.front())
      observe(x, times[first++]);
    const std::vector<double> rest(times.begin() + static_cast<std::ptrdiff_t>(first), times.end());
    return integrate_dense(stepper, order, system, x, rest, options, observe);
  }
  return integrate_controlled(stepper, order, system, x, times, options, observe);
}

// A Verner pair: dense output under the PI controller; with a hook, odeint's
// controlled stepper with the same controller, which lands on every sample.
template <class Tableau, class System, class State, class Observer, class AfterStep>
OdeStats integrate_verner(const System& system, State& x, const std::vector<double>& times,
                          const OdeOptions& o, Observer& observe, AfterStep after_step,
                          const std::size_t& evaluations) {
  namespace odeint = boost::numeric::odeint;
  if constexpr (std::is_same_v<AfterStep, NoAfterStep>) {
    VernerDenseOutput<Tableau, State> stepper(o.abs_tol, o.rel_tol);
    const std::size_t steps =
        integrate_dense(stepper, Tableau::kOrder, system, x, times, o, observe);
    return {steps, stepper.rejected_steps(), evaluations};
  } else {
    using Stepper = VernerStepper<Tableau, State>;
    using Checker = odeint::default_error_checker<double, typename Stepper::algebra_type,
                                                  typename Stepper::operations_type>;
    AfterStepStepper stepper(
        odeint::controlled_runge_kutta<Stepper, Checker, PiStepAdjuster>(
            Checker(o.abs_tol, o.rel_tol), PiStepAdjuster(Tableau::kErrorOrder)),
        std::move(after_step));
    const std::size_t steps =
        integrate_controlled(stepper, Tableau::kOrder, system, x, times, o, observe);
    return {steps, stepper.rejected_steps(), evaluations};
  }
}

}  // namespace detail

/// Steps any fixed-step stepper (odeint's Stepper concept, `do_step(system, x, t, dt)`)
/// from x at times.front() on the grid t0 + n h, h = options.step, and calls
/// observe(x, t) at every sample time; the grid rules are in the header comment.
template <class Stepper, class System, class State, class Observer>
OdeStats integrate_on_grid(Stepper& stepper, const System& system, State& x,
                           const std::vector<double>& times, const OdeOptions& options,
                           Observer& observe) {
  const std::vector<detail::GridSample> plan = detail::plan_grid(times, options);
  const double t0 = times.front(), h = options.step;
  OdeStats stats;
  std::size_t n = 0;  // the last grid point reached or passed
  double t = t0;      // the time of x
  // the step count was checked by plan_grid
  TotalStepCap cap(options.method, std::numeric_limits<std::size_t>::max(), times.back());
  const auto advance = [&](double t_next) {
    stepper.do_step(system, x, t, t_next - t);
    t = t_next;
    ++stats.steps;
    cap();
  };
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double ts = times[i];
    // whole steps to grid point m (the first shortened if a sample left x off the
    // grid); a sample on the grid is landed on exactly, not on its rounded twin
    for (const detail::GridSample s = plan[i]; n < s.n; ++n) {
      advance(s.on_grid && n + 1 == s.n ? ts : t0 + static_cast<double>(n + 1) * h);
    }
    // a sample between grid points: one shortened step to it
    if (t != ts) advance(ts);
    observe(static_cast<const State&>(x), ts);
  }
  return stats;
}

/// The settings at which method `options.method` costs about `evaluations_per_period`
/// right-hand-side evaluations a period, for comparing methods at equal cost. A
/// fixed-step method gets the step period * evaluations_per_step / evaluations_per_period.
/// An adaptive method gets the tolerance (abs = rel) whose run costs that: `cost(o)`
/// runs with options o and returns its evaluations a period (infinity if it could not
/// finish). Cost falls as the tolerance loosens, though not strictly (the step control
/// jumps), so bisection on log10(tol) over [1e-14, 1e-1] keeps the tolerance whose cost
/// came nearest the target from below (5 % over allowed); if even 1e-1 costs more, 1e-1
/// (by one trial where 1e-1 cannot finish at all).
template <class Cost>
OdeOptions options_at_cost(OdeOptions options, double period, double evaluations_per_period,
                           Cost cost) {
  if (!is_adaptive(options.method)) {
    options.step = period * evaluations_per_step(options.method) / evaluations_per_period;
    return options;
  }
  const auto at = [&options](double log_tol) {
    OdeOptions o = options;
    o.abs_tol = o.rel_tol = std::pow(10.0, log_tol);
    return o;
  };
  double lo = -14.0, hi = -1.0;  // log10 of the tolerance: tight, loose
  // Where even the loosest tolerance cannot finish within its step cap (4x the budget:
  // a fast spin the budget cannot resolve), one trial says so, not 24 at the cap. A
  // finite cost above the target is searched on: Bulirsch-Stoer's can fall again.
  if (std::isinf(cost(at(hi)))) return at(hi);
  double best = hi, best_miss = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 24; ++k) {
    const double mid = 0.5 * (lo + hi);
    const double c = cost(at(mid));
    const double miss = std::abs(c / evaluations_per_period - 1.0);
    if (c <= 1.05 * evaluations_per_period && miss < best_miss) best = mid, best_miss = miss;
    if (best_miss < 0.02) break;
    (c > evaluations_per_period ? lo : hi) = mid;  // too dear: loosen
  }
  return at(best);
}

/// A trial of settings_at_cost's search stops at this many times its budget (its
/// periods times the evaluations a period): too dear, whatever it would have cost.
inline constexpr double kCostTrialCap = 4.0;
/// All the trials of one search spend at most this many times the budget (the searches
/// on the labs' bodies spent 2 to 10); once a trial could pass it, the search ends
/// and the best tolerance found so far stands. Work bounded, the same on any machine.
inline constexpr double kCostSearchCap = 16.0;

/// The settings of method `m` for a run of `periods` periods that costs about
/// `evaluations_per_period` a period (options_at_cost), each trial run by
/// `evaluations_of(options)`, which returns its evaluations; a trial that throws
/// (past its cap, kCostTrialCap times the budget) costs infinity, and so does every
/// trial once kCostSearchCap would be passed (none is run).
template <class Evaluations>
OdeOptions settings_at_cost(Method m, double period, double periods, double evaluations_per_period,
                            Evaluations evaluations_of) {
  const double budget = periods * evaluations_per_period;
  OdeOptions o;
  o.method = m;
  o.max_evaluations = static_cast<std::size_t>(std::ceil(kCostTrialCap * budget));
  double left = kCostSearchCap * budget;
  return options_at_cost(o, period, evaluations_per_period, [&](const OdeOptions& trial) {
    constexpr double kTooDear = std::numeric_limits<double>::infinity();
    if (left < static_cast<double>(trial.max_evaluations)) return kTooDear;
    try {
      const auto evaluations = static_cast<double>(evaluations_of(trial));
      left -= evaluations;
      return evaluations / periods;
    } catch (const std::exception&) {
      left -= static_cast<double>(trial.max_evaluations);
      return kTooDear;
    }
  });
}

/// Integrates `system` from x0 at t = times.front() by options.method (rk4, dopri5,
/// rkf78, bulirsch-stoer or a Verner pair), calls observe(x, t) at every entry of
/// `times`, and applies after_step(x) after every accepted step (rk4, rkf78, vern*). Throws
/// std::invalid_argument for bad input (validate_run, a nonfinite x0, a fixed-step
/// run needing more than max_steps, a splitting method) and std::runtime_error
/// when an adaptive run needs more than max_steps steps.
template <class System, class State, class Observer, class AfterStep = NoAfterStep>
OdeStats integrate_sampled(const System& system, const State& x0, const std::vector<double>& times,
                           const OdeOptions& options, Observer&& observe,
                           AfterStep after_step = {}) {
  namespace odeint = boost::numeric::odeint;
  constexpr bool kHasHook = !std::is_same_v<AfterStep, NoAfterStep>;
  validate_run(options, times, kHasHook);
  detail::require_finite(x0);
  State x = x0;
  // Every evaluation counted, the starting step's two included: the cost of a run,
  // capped by options.max_evaluations.
  std::size_t evaluations = 0;
  // Counted as work whether the run finishes or stops at its cap.
  struct Tally {
    Method method;
    const std::size_t& evaluations;
    ~Tally() { detail::add_work(method, evaluations); }
  } const tally{options.method, evaluations};
  const std::size_t cap = options.max_evaluations > 0 ? options.max_evaluations
                                                      : std::numeric_limits<std::size_t>::max();
  const auto counted = [&system, &evaluations, cap, &options](const State& xs, State& dxdt,
                                                              double t) {
    if (++evaluations > cap) throw std::runtime_error(detail::too_many_evaluations(options));
    system(xs, dxdt, t);
  };
  switch (options.method) {
    case Method::kRk4: {
      AfterStepStepper stepper(odeint::runge_kutta4<State>(), std::move(after_step));
      OdeStats stats = integrate_on_grid(stepper, counted, x, times, options, observe);
      stats.evaluations = evaluations;
      return stats;
    }
    case Method::kRkf78: {
      AfterStepStepper stepper(odeint::make_controlled(options.abs_tol, options.rel_tol,
                                                       odeint::runge_kutta_fehlberg78<State>()),
                               std::move(after_step));
      const std::size_t steps =
          detail::integrate_controlled(stepper, 8, counted, x, times, options, observe);
      return {steps, stepper.rejected_steps(), evaluations};
    }
    // the dense-output methods take no hook (validate_run has thrown if given one)
    case Method::kDopri5:
      if constexpr (!kHasHook) {
        auto stepper = odeint::make_dense_output(options.abs_tol, options.rel_tol,
                                                 odeint::runge_kutta_dopri5<State>());
        const std::size_t steps =
            detail::integrate_dense(stepper, 5, counted, x, times, options, observe);
        return {steps, 0, evaluations};
      }
      break;
    case Method::kBulirschStoer:
      if constexpr (!kHasHook) {
        odeint::bulirsch_stoer_dense_out<State> stepper(options.abs_tol, options.rel_tol);
        const std::size_t steps =
            detail::integrate_dense(stepper, 8, counted, x, times, options, observe);
        return {steps, 0, evaluations};
      }
      break;
    case Method::kVern6:
      return detail::integrate_verner<verner::Vern6>(counted, x, times, options, observe,
                                                     std::move(after_step), evaluations);
    case Method::kVern7:
      return detail::integrate_verner<verner::Vern7>(counted, x, times, options, observe,
                                                     std::move(after_step), evaluations);
    case Method::kVern8:
      return detail::integrate_verner<verner::Vern8>(counted, x, times, options, observe,
                                                     std::move(after_step), evaluations);
    case Method::kVern9:
      return detail::integrate_verner<verner::Vern9>(counted, x, times, options, observe,
                                                     std::move(after_step), evaluations);
    case Method::kSplitting:
    case Method::kSplitting4:
      break;
  }
  throw std::invalid_argument(std::string(method_name(options.method)) +
                              " steps a problem's own splitting, not a right-hand side: "
                              "integrate the problem (compare.h)");
}

}  // namespace rigid

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
