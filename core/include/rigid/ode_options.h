// The integrators by name and how to run one, for any system: the methods'
// facts, the options of a run (OdeOptions, the one options type of core's
// integration) and what a run cost. Light on purpose: a caller that only names
// a method or sets its options need not compile the steppers (ode.h).
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

namespace rigid {

/// The integrators, by their command-line names.
enum class Method {
  kSplitting,
  kSplitting4,
  kRk4,
  kDopri5,
  kRkf78,
  kBulirschStoer,
  kVern6,
  kVern7,
  kVern8,
  kVern9
};

/// Every method, in the order of `method_name`.
inline constexpr std::array<Method, 10> kAllMethods = {
    Method::kSplitting,     Method::kSplitting4, Method::kRk4,   Method::kDopri5, Method::kRkf78,
    Method::kBulirschStoer, Method::kVern6,      Method::kVern7, Method::kVern8,  Method::kVern9};

/// The command-line name: "splitting", "splitting4", "rk4", "dopri5", "rkf78", "bulirsch-stoer",
/// "vern6", "vern7", "vern8", "vern9".
std::string_view method_name(Method m);
/// The method of a name; throws std::invalid_argument listing the valid names.
Method method_from_name(std::string_view name);
/// True for the error-controlled methods (dopri5, rkf78, bulirsch-stoer, vern6..vern9),
/// which take tolerances; the others take a fixed step.
bool is_adaptive(Method m);
/// True for the methods that apply an after-step hook (rk4, rkf78, vern6..vern9); dopri5
/// and bulirsch-stoer interpolate between steps, where a hook would not act.
bool takes_after_step(Method m);
/// The order of accuracy of a fixed-step method (2, 4, 4); 0 for the adaptive ones.
int fixed_step_order(Method m);
/// What kind of method it is and its order, in words for --help and the table:
/// "symplectic splitting, order 2", "adaptive Runge-Kutta, order 5(4)", ...
std::string_view method_kind(Method m);
/// Right-hand-side evaluations a fixed-step method makes a step (rk4: 4). A
/// splitting has no right-hand side: one Strang step (five rotations, or a kick and
/// a free flow) counts as one evaluation, so the fourth-order splitting (five Strang
/// steps) counts five; the comparison at equal cost counts evaluations so. 0 for the
/// adaptive methods, whose evaluations are counted as they happen.
int evaluations_per_step(Method m);
/// The work of one of method m's evaluations (a splitting's: one Strang step), in
/// evaluations of a Runge-Kutta method: the unit a budget counts, so that equal work
/// takes about equal time on any machine, unlike a count of evaluations alone. On the
/// labs' bodies (the free body, the heavy top; 7 doubles of state) a Strang step costs
/// 3 to 5 Runge-Kutta evaluations (its rotations' sines and cosines) and a
/// Bulirsch-Stoer evaluation 2 to 3 (its extrapolation tables): both count 4.
double evaluation_work(Method m);

/// The work (evaluations weighted by evaluation_work) of every run made on this
/// thread so far, its rejected steps and a run stopped at its cap included: a caller
/// that reads it before and after states what an answer cost.
double work_done();
namespace detail {
/// Adds a run's `evaluations` by method m to work_done.
void add_work(Method m, std::size_t evaluations);
}  // namespace detail

/// How to integrate, for any system. Set only what differs from the defaults.
struct OdeOptions {
  Method method = Method::kDopri5;
  double abs_tol = 1e-10;  ///< adaptive methods: absolute tolerance on each state component
  double rel_tol = 1e-10;  ///< adaptive methods: relative tolerance
  double step = 1e-2;      ///< fixed-step methods: the step, s
  std::size_t max_steps = 50'000'000;  ///< accepted steps; a run needing more throws
  /// Right-hand-side evaluations a run may make, rejected steps' included (0: no
  /// cap); a run that needs more throws std::runtime_error. The work of a run, the
  /// same on every machine: a step count alone does not bound it (a Bulirsch-Stoer
  /// step may cost hundreds of right-hand sides).
  std::size_t max_evaluations = 0;
  /// A problem's run (compare.h) with rk4, rkf78 or vern6..vern9 only: after every
  /// step, project the state back onto the problem's invariants (the standard
  /// projection, Hairer, Lubich & Wanner IV.4); other methods throw if asked.
  bool project_invariants = false;
};

/// True for the methods that can project onto the invariants (rk4, rkf78, vern6..vern9).
inline bool can_project(Method m) {
  return takes_after_step(m);
}

/// What a run cost.
struct OdeStats {
  std::size_t steps = 0;           ///< accepted steps (shortened ones included)
  std::size_t rejected_steps = 0;  ///< steps rejected by the error control (rkf78, vern*)
  std::size_t evaluations = 0;     ///< right-hand-side evaluations (see evaluations_per_step)
};

/// Throws std::invalid_argument unless `times` is nonempty, finite and
/// nondecreasing, the options suit their method (tolerances in [0, 1) and not
/// both 0; a positive finite step) and, with `after_step`, the method takes a hook.
void validate_run(const OdeOptions& options, const std::vector<double>& times,
                  bool after_step = false);

}  // namespace rigid
