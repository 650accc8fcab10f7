// The code of compare.h that runs a problem, for the .cpp of a problem type only:
// it is instantiated there, once, by `template struct detail::ProblemCode<P>;`, so
// the steppers of ode.h are compiled for a body in one translation unit.
#pragma once

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "rigid/compare.h"
#include "rigid/ode.h"

namespace rigid::detail {

template <class P, class = void>
inline constexpr bool kHasSplitting = false;
template <class P>
inline constexpr bool kHasSplitting<P, std::void_t<decltype(std::declval<const P&>().splitting(
                                           2, std::declval<const typename P::State&>()))>> = true;

template <class P>
inline constexpr bool kHasExact = !std::is_same_v<ExactOf<P>, NoExact>;

template <class P, class = void>
inline constexpr bool kHasReferenceErrors = false;
template <class P>
inline constexpr bool
    kHasReferenceErrors<P, std::void_t<decltype(std::declval<const P&>().errors_against(
                               std::declval<const std::vector<typename Run<P>::Sample>&>(),
                               std::declval<const std::vector<typename Run<P>::Sample>&>()))>> =
        true;

// A method the problem can run: a splitting only where it has one of its own.
template <class P>
constexpr bool can_run(Method m) {
  return kHasSplitting<P> || (m != Method::kSplitting && m != Method::kSplitting4);
}

// The refusals of what a problem lacks.
[[noreturn]] inline void refuse_exact() {
  throw std::invalid_argument(
      "this problem has no exact solution: compare its methods with a reference run");
}
[[noreturn]] inline void refuse_reference() {
  throw std::invalid_argument(
      "this problem measures no run against a reference run (no errors_against of samples)");
}

template <class P, class = void>
inline constexpr bool kHasProjection = false;
template <class P>
inline constexpr bool kHasProjection<P, std::void_t<decltype(std::declval<const P&>().projection(
                                            std::declval<const typename P::State&>()))>> = true;

// The observer of a run: each sample as the problem keeps it, with its invariants'
// errors, and the largest error of each.
template <class Problem>
class Recorder {
 public:
  using State = typename Problem::State;
  Recorder(const Problem& problem, const State& x0, Run<Problem>& out, std::size_t n)
      : problem_(problem), invariants_(problem.invariants(x0)), out_(out) {
    out_.samples.reserve(n);
  }
  void operator()(const State& x, double t) {
    const auto errors = invariants_(x);
    for (std::size_t k = 0; k < errors.size(); ++k) {
      out_.max_invariant_error[k] = std::max(out_.max_invariant_error[k], std::abs(errors[k]));
    }
    out_.samples.push_back({t, problem_.sampled(x), errors});
  }

 private:
  const Problem& problem_;
  decltype(std::declval<const Problem&>().invariants(std::declval<const State&>())) invariants_;
  Run<Problem>& out_;
};

template <class Problem>
Run<Problem> ProblemCode<Problem>::integrate(const Problem& problem, const State& x0,
                                             const std::vector<double>& times,
                                             const OdeOptions& o) {
  problem.validate(x0);
  // the generic rules here too: a splitting does not pass through integrate_sampled
  validate_run(o, times, o.project_invariants);
  Run<Problem> out;
  out.method = o.method;
  Recorder<Problem> record(problem, x0, out, times.size());
  OdeStats stats;
  if (o.method == Method::kSplitting || o.method == Method::kSplitting4) {
    if constexpr (kHasSplitting<Problem>) {
      // the splitting carries its own variables between samples, not the State
      auto split = problem.splitting(fixed_step_order(o.method), x0);
      auto xs = split.enter(x0);
      const auto observe = [&](const decltype(xs)& s, double t) { record(split.leave(s), t); };
      stats = integrate_on_grid(split, split, xs, times, o, observe);
      stats.evaluations = stats.steps * static_cast<std::size_t>(evaluations_per_step(o.method));
      add_work(o.method, stats.evaluations);
    } else {
      throw std::invalid_argument(std::string(method_name(o.method)) +
                                  ": this problem has no splitting");
    }
  } else if (o.project_invariants) {
    if constexpr (kHasProjection<Problem>) {
      stats = integrate_sampled(problem.rhs(), x0, times, o, record, problem.projection(x0));
    } else {
      throw std::invalid_argument("this problem has no projection onto its invariants");
    }
  } else {
    stats = integrate_sampled(problem.rhs(), x0, times, o, record);
  }
  out.steps = stats.steps;
  out.rejected_steps = stats.rejected_steps;
  out.evaluations = stats.evaluations;
  return out;
}

template <class Problem>
Run<Problem> ProblemCode<Problem>::sample_exact(const Problem& problem, const Exact& exact,
                                                const std::vector<double>& times) {
  if constexpr (kHasExact<Problem>) {
    Run<Problem> out;
    if (times.empty()) return out;
    Recorder<Problem> record(problem, problem.exact_state(exact, times.front()), out, times.size());
    for (const double t : times) record(problem.exact_state(exact, t), t);
    return out;
  } else {
    refuse_exact();
  }
}

// A completed run measured (its errors sample by sample, as `errors_of` gives them): its
// cost, and each invariant's largest error and drift per period.
template <class Problem, class ErrorsOf>
void measure(MethodComparison& c, const Run<Problem>& run, const ErrorsOf& errors_of,
             double period) {
  c.completed = true;
  c.evaluations = run.evaluations;
  c.steps = run.steps;
  c.t = run.times();
  ExactErrors errors = errors_of(run);
  c.error = std::move(errors.error);
  c.energy_error = std::move(errors.energy_error);
  for (const double e : c.error) {
    // A NaN (a run that blew up) counts as an infinite error.
    c.max_error =
        std::isfinite(e) ? std::max(c.max_error, e) : std::numeric_limits<double>::infinity();
  }
  for (std::size_t k = 0; k < Problem::kInvariantCount; ++k) {
    c.invariants.push_back(invariant_error(c.t, run.invariant_errors(k), period));
  }
}

// The comparison with only its settings: a run that could not finish.
inline MethodComparison not_completed(const OdeOptions& options) {
  MethodComparison c;
  c.options = options;
  return c;
}

// Each sample of a run against the exact motion.
template <class Problem>
auto exact_errors(const Problem& problem, const ExactOf<Problem>& exact) {
  return [&problem, &exact](const Run<Problem>& run) {
    return problem.errors_against(exact, run.samples);
  };
}

// Each sample of a run against a reference run at the same times.
template <class Problem>
auto reference_errors(const Problem& problem, const Reference<typename Problem::State>& reference) {
  return [&problem, &reference](const Run<Problem>& run) {
    const Run<Problem> truth =
        ProblemCode<Problem>::integrate(problem, reference.x0, run.times(), reference.options);
    return problem.errors_against(truth.samples, run.samples);
  };
}

// compare_methods (compare.h) from x0, each run measured by `errors_of`.
template <class Problem, class ErrorsOf>
std::vector<MethodComparison> compare_at_settings(const Problem& problem,
                                                  const typename Problem::State& x0,
                                                  const ErrorsOf& errors_of,
                                                  const std::vector<double>& times, double period,
                                                  const OdeOptions& options,
                                                  std::size_t max_steps) {
  std::vector<MethodComparison> out;
  for (const Method m : kAllMethods) {
    if (!can_run<Problem>(m)) continue;
    OdeOptions o = options;
    o.method = m;
    o.project_invariants = false;
    o.max_steps = max_steps;
    const std::vector<double> each_times =
        is_adaptive(m) ? times : sample_times(times.back(), period, options.step);
    MethodComparison c;
    c.options = o;
    try {
      measure<Problem>(c, ProblemCode<Problem>::integrate(problem, x0, each_times, o), errors_of,
                       period);
    } catch (const std::exception&) {
      c = not_completed(o);  // more steps than allowed
    }
    out.push_back(std::move(c));
  }
  return out;
}

// Calls f(m, project) for every run of a comparison at equal cost: each method the
// problem can run, and again with its projection where it has one and m can project.
template <class Problem, class F>
void for_each_run_at_cost(F f) {
  for (const Method m : kAllMethods) {
    if (!can_run<Problem>(m)) continue;
    for (const bool project : {false, true}) {
      if (project && !(kHasProjection<Problem> && can_project(m))) continue;
      f(m, project);
    }
  }
}

// compare_methods_at_cost (compare.h) from x0, each run measured by `errors_of`.
template <class Problem, class ErrorsOf>
std::vector<MethodComparison> compare_at_cost(const Problem& problem,
                                              const typename Problem::State& x0,
                                              const ErrorsOf& errors_of, double period,
                                              double periods, double evaluations_per_period,
                                              double samples_per_period) {
  const double calibration = std::min(periods, kCostCalibrationPeriods);
  std::vector<MethodComparison> out;
  for_each_run_at_cost<Problem>([&](Method m, bool project) {
    const auto run_with = [&](OdeOptions o, double over) {
      o.project_invariants = project;
      const auto max_samples = static_cast<std::size_t>(std::ceil(over * samples_per_period)) + 1;
      const std::vector<double> times = sample_times(
          over * period, period, is_adaptive(m) ? 0.0 : o.step, samples_per_period, max_samples);
      return ProblemCode<Problem>::integrate(problem, x0, times, o);
    };
    OdeOptions o = settings_at_cost(
        m, period, calibration, evaluations_per_period,
        [&](const OdeOptions& trial) { return run_with(trial, calibration).evaluations; });
    o.project_invariants = project;
    o.max_evaluations =
        static_cast<std::size_t>(std::ceil(kCostRunCap * periods * evaluations_per_period));
    MethodComparison c;
    c.options = o;
    try {
      measure<Problem>(c, run_with(o, periods), errors_of, period);
    } catch (const std::exception&) {
      c = not_completed(o);
    }
    out.push_back(std::move(c));
  });
  return out;
}

template <class Problem>
double ProblemCode<Problem>::work_at_cost(double periods, double evaluations_per_period) {
  const double run = kCostRunCap * periods * evaluations_per_period;
  const double search =
      kCostSearchCap * std::min(periods, kCostCalibrationPeriods) * evaluations_per_period;
  double work = 0.0;
  for_each_run_at_cost<Problem>([&](Method m, bool) {
    work += evaluation_work(m) * (run + (is_adaptive(m) ? search : 0.0));
  });
  return work;
}

template <class Problem>
std::vector<MethodComparison> ProblemCode<Problem>::compare_methods(
    const Problem& problem, const Exact& exact, const std::vector<double>& times, double period,
    const OdeOptions& options, std::size_t max_steps) {
  if constexpr (kHasExact<Problem>) {
    return compare_at_settings(problem, problem.exact_state(exact, 0.0),
                               exact_errors(problem, exact), times, period, options, max_steps);
  } else {
    refuse_exact();
  }
}

template <class Problem>
std::vector<MethodComparison> ProblemCode<Problem>::compare_methods(
    const Problem& problem, const Reference<State>& reference, const std::vector<double>& times,
    double period, const OdeOptions& options, std::size_t max_steps) {
  if constexpr (kHasReferenceErrors<Problem>) {
    return compare_at_settings(problem, reference.x0, reference_errors(problem, reference), times,
                               period, options, max_steps);
  } else {
    refuse_reference();
  }
}

template <class Problem>
std::vector<MethodComparison> ProblemCode<Problem>::compare_methods_at_cost(
    const Problem& problem, const Exact& exact, double period, double periods,
    double evaluations_per_period, double samples_per_period) {
  if constexpr (kHasExact<Problem>) {
    return compare_at_cost(problem, problem.exact_state(exact, 0.0), exact_errors(problem, exact),
                           period, periods, evaluations_per_period, samples_per_period);
  } else {
    refuse_exact();
  }
}

template <class Problem>
std::vector<MethodComparison> ProblemCode<Problem>::compare_methods_at_cost(
    const Problem& problem, const Reference<State>& reference, double period, double periods,
    double evaluations_per_period, double samples_per_period) {
  if constexpr (kHasReferenceErrors<Problem>) {
    return compare_at_cost(problem, reference.x0, reference_errors(problem, reference), period,
                           periods, evaluations_per_period, samples_per_period);
  } else {
    refuse_reference();
  }
}

}  // namespace rigid::detail
