// What every lab that integrates a body shares (poinsot, tennis_racquet,
// top_nutation): its numerical options --method, --tolerance, --step and
// --project, the plan of its run, the run of the chosen method from the exact
// motion's start measured against the exact motion, the drifts of its
// invariants, and every method compared with the exact motion, at the lab's
// settings and at equal cost. A body comes in as a problem of core (compare.h)
// and the words its lab reports its errors in (ExactErrorWords).
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "common/inputs.h"
#include "common/report.h"
#include "rigid/compare.h"
#include "rigid/drift.h"

namespace rigid::lab {

/// The work (rigid::work_done's unit: a Runge-Kutta evaluation of these small bodies)
/// a lab's own run may do: 16M, rk4's 4M steps or vern9's 16M evaluations, 0.3 to 0.6 s
/// on a 2-core laptop. Counted, not timed, so every machine gives the same answer. A
/// fixed-step run that would pass it is refused by its step count before it starts; an
/// adaptive run is refused when it reaches it.
inline constexpr double kMaxRunWork = 16e6;
/// The evaluations of method m that make kMaxRunWork (rk4, vern*: 16M; a splitting,
/// Bulirsch-Stoer: 4M).
std::size_t max_run_evaluations(Method m);
/// All the work one answer may do: the lab's own run, every method at its settings and
/// the comparison at equal cost, which gets what the others left, over fewer periods if
/// it must (compare_every_method). About a second on a 2-core laptop (bench/).
inline constexpr double kMaxComputeWork = 40e6;
/// Each method of the comparison at the lab's settings takes at most this many steps:
/// the comparison is an aside, 2e5 steps in all whatever the lab's own run takes.
inline constexpr std::size_t kMaxComparisonSteps = 20'000;
/// The comparison at equal cost, which names the method to use: every method at this
/// many right-hand-side evaluations a period (rk4 at period / 250, a Strang splitting
/// at period / 1000), over the run's own length up to kMaxRankedPeriods periods
/// (1e6 evaluations a method), ranked by its largest error against the exact motion.
inline constexpr double kEqualCostEvaluations = 1000.0;
inline constexpr double kMaxRankedPeriods = 1000.0;

/// Which method to use, as --method's help (and so the man pages) and the user guide give
/// it: the answer of each lab's own ranking at equal cost ("which method to use") on
/// the bodies of its tests, over 10 and over 1000 periods.
inline constexpr char kMethodAdvice[] =
    "to use: vern9 or vern8, with --project where the lab offers it: at equal cost the most "
    "accurate here over 10 and 1000 periods (each run ranks every method for its own inputs)";

/// The numerical inputs; `method` is "exact" (no integration) or an integrator's name.
struct IntegrationInputs {
  std::string method = "exact";
  double tolerance = 1e-10;
  std::optional<double> step;  ///< the lab's default step unless set
  bool project = false;
  /// Compare every method with the exact motion (not an option: the command line always
  /// does). A live view's first look at new inputs leaves it out, as it is the one slow
  /// part (LabProgram::preview), and shows it when it is done.
  bool compare = true;
};

/// A lab's preview (LabProgram::preview) that leaves out only the comparison of every
/// method; `In` has its integration settings as `integration`.
template <class In>
void leave_out_comparisons(In& in) {
  in.integration.compare = false;
}

/// The table of the numerical inputs: --method, --tolerance, --step (whose default
/// the lab derives, described by `step_default`) and, if `offer_project`, --project.
InputTable<IntegrationInputs> integration_inputs(const std::string& method_help,
                                                 const std::string& step_default,
                                                 bool offer_project = true);

/// Adds --t-end (s) and --periods N to a lab's table: the end time as N times the lab's
/// `period_name` ("polhode period"); `default_text` says what the lab does when neither
/// is set.
template <class In, class Field>
void add_end_time_inputs(InputTable<In>& table, Field t_end, Field periods,
                         const std::string& period_name, const std::string& default_text) {
  table.number("--t-end", t_end, "end time")
      .unit("s")
      .positive()
      .numerical()
      .lab_default(default_text);
  table
      .number("--periods", periods,
              "end time as a number of " + period_name + "s (instead of --t-end)")
      .positive()
      .numerical()
      .lab_default("--t-end's")
      .excludes("--t-end", "give --t-end or --periods, not both");
}

/// True when the chosen method takes a fixed step (so its samples lie on its grid).
bool fixed_step(const IntegrationInputs& in);

/// The options of the chosen method: the tolerance, the step (`default_step` unless
/// --step was given), --project, at most kMaxRunSteps steps and kMaxRunEvaluations. Warns
/// (Report::warn) of --step or --tolerance given where nothing uses them.
OdeOptions integration_options(Report& report, const IntegrationInputs& in, bool compared,
                               double default_step);

/// What a run samples and how: the method's options (its step `scale` / 2000 unless
/// --step was given, and at most `fastest` / 200, the time the motion's fastest rate
/// takes to turn once: a long nutation period must not set the step of a fast spin),
/// 200 samples a `scale` up to t_end (a fixed step's on its own grid), after refusing a
/// t_end beyond check_phase_digits.
struct RunPlan {
  OdeOptions options;
  double work_start = 0.0;  ///< rigid::work_done() when the plan was made
  std::vector<double> times;
  bool fixed = false;
  double t_end = 0.0;
};
RunPlan plan_run(Report& report, const IntegrationInputs& in, bool compared, double t_end,
                 double scale, double fastest = std::numeric_limits<double>::infinity());
/// Reports the plan's end time (t_end_s) and, for a fixed step, the step (step_s) and,
/// when t_end is not a whole number of steps, the last one, shortened to end there
/// (last_step_s).
void report_plan(Report& report, const RunPlan& plan);

/// How a lab names one invariant of its body in the table and the JSON.
struct InvariantWords {
  std::size_t index = 0;  ///< the problem's invariant
  std::string key;        ///< <key>_error_max_rel and <key>_drift_per_period_rel
  std::string label;      ///< "max |T - T0| / T0"
  bool fitted = true;     ///< false: only its largest error, under `key` itself
};

/// How a lab words its body's error against the exact motion, and which invariants
/// it reports and holds a run to.
struct ExactErrorWords {
  std::string key;                      ///< the run's largest error: "max_error_vs_exact"
  std::string label;                    ///< "max |omega - omega_exact| / |omega0|"
  std::string unit;                     ///< the unit the error is reported in: "" or "deg"
  double (*in_unit)(double) = nullptr;  ///< the problem's error in `unit` (none: as it is)
  /// Each compared method's key: method_key_prefix + the method + method_key_suffix.
  std::string method_key_prefix, method_key_suffix;
  std::string against;   ///< the comparison's heading: "the exact solution"
  std::string diverged;  ///< why a run that diverged is refused
  /// A run that lost one of the first `runaway_invariants` invariants ran away.
  std::size_t runaway_invariants = 0;
  std::vector<InvariantWords> invariants;  ///< the invariants reported, in order
};

/// The input that governs a run's step, the one its failure names: "--step" for a
/// fixed-step method, "--tolerance" for an adaptive one.
std::string step_input(const OdeOptions& options);

/// The option a run of the chosen method answers to: step_input of its options.
/// Throws an InputError naming --project for a method that cannot project.
std::string run_option(const IntegrationInputs& in, const OdeOptions& options);

/// What refuse_runaway judges of a run: the largest of the first `count` of its
/// invariants' largest errors, and at least the first's (the energy's).
double runaway_drift(const std::vector<double>& max_invariant_errors, std::size_t count);

/// Reports a run's largest error against the exact motion (words.key) and its steps,
/// after refusing (InputErrors naming `option`) a run whose errors are not finite or
/// whose first invariants ran away (refuse_runaway).
void report_run(Report& report, const std::string& option, const std::vector<double>& errors,
                const std::vector<double>& max_invariant_errors, std::size_t steps,
                const ExactErrorWords& words);

/// Runs the chosen method from the exact motion's start through `times` (the exact
/// motion sampled, for "exact") and reports its error against the exact motion and
/// its steps (report_run). Bad settings and a run that diverges or runs away are
/// InputErrors naming --step, --tolerance or --project.
template <class Problem>
Run<Problem> run_chosen_method(Report& report, const Problem& problem,
                               const typename Problem::Exact& exact, const IntegrationInputs& in,
                               const OdeOptions& options, const std::vector<double>& times,
                               const ExactErrorWords& words) {
  if (in.method == "exact") return sample_exact(problem, exact, times);
  const std::string option = run_option(in, options);
  Run<Problem> run;
  try {
    run = integrate(problem, problem.exact_state(exact, 0.0), times, options);
  } catch (const std::exception& e) {
    throw InputError(option, e.what());
  }
  report_run(report, option, problem.errors_against(exact, run.samples).error,
             {run.max_invariant_error.begin(), run.max_invariant_error.end()}, run.steps, words);
  return run;
}

/// Reports each invariant of words.invariants, from the run's signed errors at its sample
/// times `t` (report_invariant; only the largest, `max_invariant_errors`, where not
/// fitted). With `exact` (a run of the closed form), roundoff prints as 0.
void report_drifts(Report& report, const std::vector<double>& t,
                   const std::vector<std::vector<double>>& invariant_errors,
                   const std::vector<double>& max_invariant_errors, double period, bool exact,
                   const ExactErrorWords& words);
/// report_drifts of a run.
template <class Run>
void report_drifts(Report& report, const Run& run, double period, bool exact,
                   const ExactErrorWords& words) {
  std::vector<std::vector<double>> errors;
  for (std::size_t k = 0; k < run.max_invariant_error.size(); ++k) {
    errors.push_back(run.invariant_errors(k));
  }
  report_drifts(report, run.times(), errors,
                {run.max_invariant_error.begin(), run.max_invariant_error.end()}, period, exact,
                words);
}

/// Every method compared with the exact motion.
struct MethodComparisons {
  std::vector<MethodComparison> at_settings;  ///< at the lab's step and tolerance
  /// At kEqualCostEvaluations a period, ranked: the most accurate first; or none.
  std::vector<MethodComparison> at_cost;
  double at_cost_periods = 0.0;  ///< the periods the comparison at equal cost ran
  double run_periods = 0.0;      ///< the run's own length in periods
  /// Why at_cost_periods is below run_periods: "" (it is not), or its limit in words.
  std::string at_cost_limit;
  double work = 0.0;  ///< the work of the whole answer (rigid::work_done's unit)
};

/// A method as a command line chooses it: "vern8", or "vern8 --project".
std::string method_choice(const OdeOptions& options);

/// The comparisons at equal cost, the most accurate first (a run that could not
/// finish or blew up last, in their order).
void rank_by_error(std::vector<MethodComparison>& at_cost);

/// Reports every method at the lab's settings (a section: each method's largest error,
/// words.method_key_*, with its evaluations and steps) and, if there are any, at equal
/// cost (report_equal_cost).
void report_comparisons(Report& report, const MethodComparisons& comparisons,
                        const OdeOptions& settings, const ExactErrorWords& words);

/// The periods the comparison at equal cost ranks over for a run of `run_periods`:
/// at most kMaxRankedPeriods, and no more than `work_left` pays for (`work_of(periods)`,
/// rigid::work_at_cost, grows with them), with why it is fewer than the run's, in
/// words (MethodComparisons::at_cost_limit); none (0) where not even one period fits.
struct RankedPeriods {
  double periods = 0.0;
  std::string limit;
};
RankedPeriods ranked_periods(double run_periods, double work_left,
                             const std::function<double(double)>& work_of);

/// Every method against the exact motion at the plan's settings (at most
/// kMaxComparisonSteps steps each) and, with `at_cost`, at kEqualCostEvaluations
/// evaluations a `period` over the run's length (ranked_periods: within kMaxComputeWork
/// with the work done since the plan), ranked (rank_by_error), reported
/// (report_comparisons) with the whole answer's work ("work").
template <class Problem>
MethodComparisons compare_every_method(Report& report, const Problem& problem,
                                       const typename Problem::Exact& exact, const RunPlan& plan,
                                       double period, bool at_cost, const ExactErrorWords& words) {
  MethodComparisons c;
  c.at_settings =
      compare_methods(problem, exact, plan.times, period, plan.options, kMaxComparisonSteps);
  c.run_periods = plan.t_end / period;
  if (at_cost) {
    const RankedPeriods ranked =
        ranked_periods(c.run_periods, kMaxComputeWork - (work_done() - plan.work_start),
                       [](double p) { return work_at_cost<Problem>(p, kEqualCostEvaluations); });
    c.at_cost_periods = ranked.periods;
    c.at_cost_limit = ranked.limit;
    if (c.at_cost_periods > 0.0) {
      c.at_cost =
          compare_methods_at_cost(problem, exact, period, c.at_cost_periods, kEqualCostEvaluations);
      rank_by_error(c.at_cost);
    }
  }
  c.work = work_done() - plan.work_start;
  report_comparisons(report, c, plan.options, words);
  return c;
}

/// Refuses (a InputError naming --t-end) a run longer than 1e9 times the motion's
/// time scale: beyond, the phase of the exact motion keeps fewer than 7 of its 16 digits.
void check_phase_digits(double t_end, double scale);

/// Refuses (a InputError naming `option`) a run whose conserved quantities drifted by
/// more than themselves (relative drift > 1): a step far too long, whose numbers
/// would mean nothing.
void refuse_runaway(const std::string& option, double drift);

/// Reports one invariant's signed relative errors `e` at times `t`: its largest
/// (<key>_error_max_rel, labelled `error_label`) and its drift per `period`
/// (<key>_drift_per_period_rel), and <key>_drift_rel, the maximum's old name, in JSON.
/// With `roundoff` > 0 (a run of the closed form), values within it print as 0.
void report_invariant(Report& report, const std::string& key, const std::string& error_label,
                      const std::vector<double>& t, const std::vector<double>& e, double period,
                      double roundoff = 0.0);
/// The closed form's own rounding of a relative invariant: a few ulps (64 eps bounds it).
inline constexpr double kClosedFormRoundoff = 64 * 2.220446049250313e-16;

/// The end time asked for: t_end, or periods times `scale`; neither: `default_t_end`.
double end_time(const std::optional<double>& t_end, const std::optional<double>& periods,
                double scale, double default_t_end);

/// The section that answers "which method to use": every run of `comparisons.at_cost`
/// (each at kEqualCostEvaluations a period), most accurate first, with its error
/// (equal_cost_<words.method_key_prefix><method><suffix>), rank, evaluations, steps,
/// energy drift per period and largest energy error (equal_cost_*_<method>, a projected
/// run's <method>_project), and the method to use: the first, with the reason
/// (recommended_method, recommended_method_reason).
void report_equal_cost(Report& report, const MethodComparisons& comparisons,
                       const ExactErrorWords& words);
/// A method and its kind for --help: "splitting (symplectic splitting, order 2)".
std::string method_help_list();

}  // namespace rigid::lab
