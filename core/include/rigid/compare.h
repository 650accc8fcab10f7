// Integrated bodies as problems: one sampled run and one comparison of every
// method against the body's exact motion or, where it has none, against a
// reference run, for any body. A problem type brings the physics; the stepping
// (ode.h), the bookkeeping of its invariants and the measuring of each method
// are written here once:
//
//   struct MyBody {
//     using State = RotationState;                    // fixed-size odeint state
//     using Exact = MyBodyExact;                      // optional: its closed form
//     static constexpr std::size_t kInvariantCount = 2;  // invariant 0: the energy
//     using Sample = RunSample<State, kInvariantCount>;
//     void validate(const State& x0) const;           // throws std::invalid_argument
//     Rhs rhs() const;                                // (x, dxdt, t), an odeint functor
//     Invariants invariants(const State& x0) const;   // (x) -> their signed relative errors
//     State sampled(const State& x) const;            // the state a sample keeps
//     Splitting splitting(int order, const State& x0) const;  // optional: its own stepper
//     Projection projection(const State& x0) const;   // optional: (State&) onto the invariants
//     State exact_state(const Exact&, double t) const;                            // with Exact
//     ExactErrors errors_against(const Exact&, const std::vector<Sample>&) const;  // with Exact
//     // optional: each sample against a reference run's at the same time
//     ExactErrors errors_against(const std::vector<Sample>& reference,
//                                const std::vector<Sample>&) const;
//   };
//
// A Splitting steps variables of its own (L_body and q, say): `enter(x0)` makes
// them, `leave(xs)` gives the State back, `do_step(self, xs, t, h)` advances
// them (odeint's Stepper concept, the splitting its own system). A body with no
// closed form (a rolling disk, a gyroscope with friction) has no Exact: it
// integrates, and its methods are compared with a Reference, the body integrated
// by a tighter, higher-order method at each run's own sample times; only a
// comparison with the exact motion is refused for it. The code that runs a
// problem is compiled once, in its .cpp, by `template struct
// detail::ProblemCode<MyBody>;` with compare_impl.h included there: no other
// translation unit compiles a stepper for it.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "rigid/drift.h"
#include "rigid/ode_options.h"

namespace rigid {

/// Every problem's first invariant: the energy (the comparison at equal cost reports its drift).
inline constexpr std::size_t kEnergyInvariant = 0;
/// The periods an adaptive method's tolerance is calibrated on for a comparison at
/// equal cost (compare_methods_at_cost): at most this many, however long the run.
inline constexpr double kCostCalibrationPeriods = 10.0;

/// A run of a comparison at equal cost is stopped (not completed) past this many times
/// its budget: its tolerance was calibrated to within 5 % of it on the first periods,
/// and a periodic motion costs the same in every period.
inline constexpr double kCostRunCap = 1.25;

/// One sample of a run.
template <class State, std::size_t K>
struct RunSample {
  double t = 0.0;
  State x{};  ///< the state as the problem samples it (its quaternion unit)
  std::array<double, K> invariant_errors{};  ///< each invariant's signed relative error
};

/// The samples of one run, the largest error of each invariant and what the run cost.
template <class State, std::size_t K>
struct SampledRun {
  using Sample = RunSample<State, K>;
  Method method = Method::kDopri5;
  std::vector<Sample> samples;
  std::array<double, K> max_invariant_error{};  ///< max over samples of |invariant_errors[k]|
  std::size_t steps = 0;                        ///< accepted steps (shortened ones included)
  std::size_t rejected_steps = 0;  ///< steps rejected by the error control (where known)
  std::size_t evaluations = 0;     ///< right-hand-side evaluations (ode.h's evaluations_per_step)

  /// The sample times.
  std::vector<double> times() const {
    std::vector<double> t;
    t.reserve(samples.size());
    for (const Sample& s : samples) t.push_back(s.t);
    return t;
  }
  /// Invariant k's signed relative error at every sample.
  std::vector<double> invariant_errors(std::size_t k) const {
    std::vector<double> e;
    e.reserve(samples.size());
    for (const Sample& s : samples) e.push_back(s.invariant_errors[k]);
    return e;
  }
};

/// The run of a problem.
template <class Problem>
using Run = SampledRun<typename Problem::State, Problem::kInvariantCount>;

/// A run's samples measured against the exact motion (or a reference run), as a
/// problem measures them.
struct ExactErrors {
  std::vector<double> error;         ///< the problem's error (omega's, theta's), each sample
  std::vector<double> energy_error;  ///< |the energy's relative error|, each sample
};

/// The exact motion of a problem with none: an exact comparison asked of it is refused.
struct NoExact {};

namespace detail {
template <class P, class = void>
struct ExactType {
  using type = NoExact;
};
template <class P>
struct ExactType<P, std::void_t<typename P::Exact>> {
  using type = typename P::Exact;
};
}  // namespace detail

/// A problem's exact motion: Problem::Exact, or NoExact where it has no closed form.
template <class Problem>
using ExactOf = typename detail::ExactType<Problem>::type;

/// The settings of a reference run: Verner's 9(8) pair at a tolerance of 1e-13, four
/// orders of magnitude below the lab's default tolerance and within reach of double
/// precision over a few hundred periods.
OdeOptions reference_options();

/// What a problem with no closed form is measured against: the problem integrated from
/// x0 at t = 0 by `options`, at the sample times of each run it measures.
template <class State>
struct Reference {
  State x0{};
  OdeOptions options = reference_options();
};

/// One method's run measured against the exact motion (or a reference run), sample by sample.
struct MethodComparison {
  OdeOptions options;                ///< the method and the settings it ran with
  bool completed = false;            ///< false: it would have needed more than its step budget
  std::vector<double> t;             ///< its sample times (a fixed step's on its own grid)
  std::vector<double> error;         ///< the problem's error against the exact motion
  std::vector<double> energy_error;  ///< |the energy's relative error|
  double max_error = 0.0;            ///< the largest error (infinite if the run blew up)
  std::size_t evaluations = 0;       ///< right-hand-side evaluations of the run
  std::size_t steps = 0;             ///< its accepted steps
  /// Each invariant's largest error and drift per period, by the problem's index (none
  /// if not completed).
  std::vector<InvariantError> invariants;
};

namespace detail {

// The code that runs a problem, defined in compare_impl.h and instantiated once
// for each problem type, in its .cpp.
template <class Problem>
struct ProblemCode {
  using State = typename Problem::State;
  using Exact = ExactOf<Problem>;
  static Run<Problem> integrate(const Problem& problem, const State& x0,
                                const std::vector<double>& times, const OdeOptions& options);
  static Run<Problem> sample_exact(const Problem& problem, const Exact& exact,
                                   const std::vector<double>& times);
  static std::vector<MethodComparison> compare_methods(const Problem& problem, const Exact& exact,
                                                       const std::vector<double>& times,
                                                       double period, const OdeOptions& options,
                                                       std::size_t max_steps);
  static std::vector<MethodComparison> compare_methods(const Problem& problem,
                                                       const Reference<State>& reference,
                                                       const std::vector<double>& times,
                                                       double period, const OdeOptions& options,
                                                       std::size_t max_steps);
  static std::vector<MethodComparison> compare_methods_at_cost(const Problem& problem,
                                                               const Exact& exact, double period,
                                                               double periods,
                                                               double evaluations_per_period,
                                                               double samples_per_period);
  static std::vector<MethodComparison> compare_methods_at_cost(const Problem& problem,
                                                               const Reference<State>& reference,
                                                               double period, double periods,
                                                               double evaluations_per_period,
                                                               double samples_per_period);
  static double work_at_cost(double periods, double evaluations_per_period);
};

}  // namespace detail

/// Integrates the problem from x0 at t = times.front() by options.method and samples
/// it at every entry of `times` (finite, nondecreasing): a splitting by the problem's
/// own stepper, the others through integrate_sampled (ode.h), with the problem's
/// projection after every step if options.project_invariants. Throws
/// std::invalid_argument for a bad problem, state, times or options (ode.h's
/// validate_run; a splitting or a projection the problem has not), and
/// std::runtime_error when an adaptive run needs more than options.max_steps steps.
template <class Problem>
Run<Problem> integrate(const Problem& problem, const typename Problem::State& x0,
                       const std::vector<double>& times, const OdeOptions& options) {
  return detail::ProblemCode<Problem>::integrate(problem, x0, times, options);
}

/// The exact motion sampled at `times` as a run of its own (no steps), its
/// invariants measured as an integrator's are: roundoff only. Throws
/// std::invalid_argument for a problem with no exact motion (NoExact).
template <class Problem>
Run<Problem> sample_exact(const Problem& problem, const ExactOf<Problem>& exact,
                          const std::vector<double>& times) {
  return detail::ProblemCode<Problem>::sample_exact(problem, exact, times);
}

/// Every method of kAllMethods the problem can run (a splitting only where it has one)
/// at `options` (no projection, at most `max_steps` steps each) against the exact
/// motion from t = 0 to times.back(): adaptive methods at `times`, fixed-step ones on
/// their step grid with `period` / 200 spacing as sample_times makes it, so each run is
/// the one a caller choosing that method alone would get. A method that cannot finish
/// is not completed. Throws std::invalid_argument for a problem with no exact motion.
template <class Problem>
std::vector<MethodComparison> compare_methods(const Problem& problem, const ExactOf<Problem>& exact,
                                              const std::vector<double>& times, double period,
                                              const OdeOptions& options, std::size_t max_steps) {
  return detail::ProblemCode<Problem>::compare_methods(problem, exact, times, period, options,
                                                       max_steps);
}
/// compare_methods against a reference run from reference.x0 instead (a reference run
/// that cannot finish leaves its method not completed). Throws std::invalid_argument
/// for a problem that measures no run against a reference (no errors_against of samples).
template <class Problem>
std::vector<MethodComparison> compare_methods(const Problem& problem,
                                              const Reference<typename Problem::State>& reference,
                                              const std::vector<double>& times, double period,
                                              const OdeOptions& options, std::size_t max_steps) {
  return detail::ProblemCode<Problem>::compare_methods(problem, reference, times, period, options,
                                                       max_steps);
}

/// Every method at the same cost, the question "which method is most accurate for
/// the work" answered fairly: `evaluations_per_period` right-hand-side evaluations a
/// period (options_at_cost: fixed steps from evaluations_per_step, tolerances found by
/// bisection on the first kCostCalibrationPeriods periods, as an adaptive method's
/// cost a period is the same in every period of a periodic motion) over `periods`
/// periods of length `period`, each run sampled `samples_per_period` times a period (a
/// fixed step's on its grid), against the exact motion. Where the problem has a
/// projection, each method that can project runs a second time with it
/// (options.project_invariants; the projection is not an evaluation). A method that
/// cannot finish is not completed. Throws std::invalid_argument for a problem with no
/// exact motion.
template <class Problem>
std::vector<MethodComparison> compare_methods_at_cost(const Problem& problem,
                                                      const ExactOf<Problem>& exact, double period,
                                                      double periods, double evaluations_per_period,
                                                      double samples_per_period = 8.0) {
  return detail::ProblemCode<Problem>::compare_methods_at_cost(
      problem, exact, period, periods, evaluations_per_period, samples_per_period);
}
/// compare_methods_at_cost against a reference run from reference.x0 instead.
template <class Problem>
std::vector<MethodComparison> compare_methods_at_cost(
    const Problem& problem, const Reference<typename Problem::State>& reference, double period,
    double periods, double evaluations_per_period, double samples_per_period = 8.0) {
  return detail::ProblemCode<Problem>::compare_methods_at_cost(
      problem, reference, period, periods, evaluations_per_period, samples_per_period);
}

/// The most work (work_done's unit) compare_methods_at_cost over `periods` periods at
/// `evaluations_per_period` can do: every run stopped at kCostRunCap times its budget,
/// every adaptive method's tolerance search at kCostSearchCap times its calibration's.
/// (Against a reference run, the reference runs come on top.)
template <class Problem>
double work_at_cost(double periods, double evaluations_per_period) {
  return detail::ProblemCode<Problem>::work_at_cost(periods, evaluations_per_period);
}

/// n equally spaced times from t0 to t1 inclusive (n >= 2), or {t0} for n = 1.
std::vector<double> uniform_times(double t0, double t1, std::size_t n);

/// Sample times from 0 to exactly t_end, `per_period` samples per `period` and at
/// most `max_samples` in all. With `step` > 0 (a fixed-step method) every sample
/// but the last falls on the step grid n * step, every k-th step, and the last
/// is t_end itself: only the run's last step is shortened, when step does not divide t_end.
std::vector<double> sample_times(double t_end, double period, double step = 0.0,
                                 double per_period = 200.0, std::size_t max_samples = 20001);

}  // namespace rigid
