#include "common/integrated_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "rigid/units.h"

namespace rigid::lab {

namespace {
// A run whose invariants drift by more than this share of themselves is refused.
constexpr double kMaxDrift = 1.0;
constexpr double kEps = std::numeric_limits<double>::epsilon();

// The methods --project works with, as a list: "rk4, rkf78, vern6, ..".
std::string projecting_methods() {
  std::string list;
  for (const Method m : kAllMethods) {
    if (can_project(m)) list += (list.empty() ? "" : ", ") + std::string(method_name(m));
  }
  return list;
}

// True when `ranked` falls short of the run's `periods` by more than their rounding (a
// run of --periods 1000 is 1000 periods to an ulp or two either way).
bool fewer_periods(double ranked, double periods) {
  return ranked < periods * (1.0 - 1e-12);
}
}  // namespace

InputTable<IntegrationInputs> integration_inputs(const std::string& method_help,
                                                 const std::string& step_default,
                                                 bool offer_project) {
  InputTable<IntegrationInputs> t;
  std::vector<std::string> methods{"exact"};
  for (const Method m : kAllMethods) methods.emplace_back(method_name(m));
  t.choice("--method", &IntegrationInputs::method, methods,
           method_help + " (exact: the closed form; " + method_help_list() + "); " + kMethodAdvice)
      .numerical();
  // Below double precision no step meets a tolerance, and odeint's step control then
  // collapses (tolerances under 1e-150 crashed it). Every method is compared, so both
  // settings act whatever --method is (an unused one is warned of: integration_options).
  t.number("--tolerance", &IntegrationInputs::tolerance,
           "relative and absolute tolerance of adaptive methods (with a fixed-step --method "
           "only the comparison of every method uses it)")
      .range_from(1e-16, 1.0)
      .numerical();
  t.number("--step", &IntegrationInputs::step,
           "step of fixed-step methods (with an adaptive --method only the comparison of every "
           "method uses it)")
      .unit("s")
      .positive()
      .numerical()
      .lab_default(step_default);
  if (!offer_project) return t;
  t.flag("--project", &IntegrationInputs::project,
         projecting_methods() + ": project omega back onto T and |L| after each step")
      .numerical();
  return t;
}

std::size_t max_run_evaluations(Method m) {
  return static_cast<std::size_t>(kMaxRunWork / evaluation_work(m));
}

bool fixed_step(const IntegrationInputs& in) {
  return in.method != "exact" && !is_adaptive(method_from_name(in.method));
}

OdeOptions integration_options(Report& report, const IntegrationInputs& in, bool compared,
                               double default_step) {
  OdeOptions options;
  options.abs_tol = options.rel_tol = in.tolerance;
  options.step = in.step.value_or(default_step);
  options.method = in.method == "exact" ? Method::kDopri5 : method_from_name(in.method);
  options.project_invariants = in.project;
  // Every lab finishes or refuses within a second, whatever the step count.
  options.max_evaluations = max_run_evaluations(options.method);
  const int per_step = evaluations_per_step(options.method);
  options.max_steps = per_step > 0 ? options.max_evaluations / static_cast<std::size_t>(per_step)
                                   : options.max_evaluations;
  // Never silent: an option nothing uses is said to be unused.
  const bool exact = in.method == "exact";
  const bool tolerance_set = in.tolerance != IntegrationInputs{}.tolerance;
  const auto unused = [&](const std::string& option, const std::string& why,
                          const std::string& instead) {
    report.warn(option, why + (compared ? "; only the comparison of every method uses it"
                                        : "; it is not used" + instead));
  };
  if (tolerance_set && exact) unused("--tolerance", "--method exact integrates nothing", "");
  if (in.step && exact) unused("--step", "--method exact integrates nothing", "");
  if (tolerance_set && !exact && !is_adaptive(options.method)) {
    unused("--tolerance", in.method + " takes a fixed step", " (--step sets it)");
  }
  if (in.step && !exact && is_adaptive(options.method)) {
    unused("--step", in.method + " chooses its own steps", " (--tolerance controls them)");
  }
  if (in.project && exact) {
    throw InputError("--project",
                     "--method exact integrates nothing to project; use --method "
                     "one of " +
                         projecting_methods());
  }
  return options;
}

std::string run_option(const IntegrationInputs& in, const OdeOptions& options) {
  if (in.project && !can_project(options.method)) {
    throw InputError("--project", "works with --method " + projecting_methods() + " only");
  }
  return step_input(options);
}

std::string step_input(const OdeOptions& options) {
  return is_adaptive(options.method) ? "--tolerance" : "--step";
}

double runaway_drift(const std::vector<double>& max_invariant_errors, std::size_t count) {
  double drift = max_invariant_errors.at(0);
  for (std::size_t k = 1; k < count; ++k) drift = std::max(drift, max_invariant_errors.at(k));
  return drift;
}

void report_run(Report& report, const std::string& option, const std::vector<double>& errors,
                const std::vector<double>& max_invariant_errors, std::size_t steps,
                const ExactErrorWords& words) {
  double worst = 0.0;
  for (const double e : errors) {
    // A step beyond the method's stability region blows the motion up.
    if (!std::isfinite(e)) throw InputError(option, words.diverged);
    worst = std::max(worst, e);
  }
  // A run whose conserved quantities moved by more than themselves has no digit left to print.
  refuse_runaway(option, runaway_drift(max_invariant_errors, words.runaway_invariants));
  report.result(words.key, words.label, words.in_unit ? words.in_unit(worst) : worst, words.unit);
  report.count("steps", "steps taken", steps);
}

RankedPeriods ranked_periods(double run_periods, double work_left,
                             const std::function<double(double)>& work_of) {
  RankedPeriods r{std::min(run_periods, kMaxRankedPeriods), ""};
  if (fewer_periods(r.periods, run_periods)) {
    r.limit = fmt::format("at most {:g} are ranked", kMaxRankedPeriods);
  }
  if (work_of(r.periods) <= work_left) return r;
  // The work grows with the periods: bisect for the most that fit, to a hundredth.
  double lo = 0.0, hi = r.periods;
  while (hi - lo > 0.01 * hi) {
    const double mid = 0.5 * (lo + hi);
    (work_of(mid) <= work_left ? lo : hi) = mid;
  }
  r.periods = lo >= 1.0 ? std::floor(lo) : 0.0;
  r.limit = "as many as the work budget left after the run pays for";
  return r;
}

void check_phase_digits(double t_end, double scale) {
  if (t_end > 1e9 * scale) {
    throw InputError("--t-end", fmt::format("at most 1e9 periods ({:g} s) for these inputs: "
                                            "beyond, the phase of the motion loses its digits",
                                            1e9 * scale));
  }
}

RunPlan plan_run(Report& report, const IntegrationInputs& in, bool compared, double t_end,
                 double scale, double fastest) {
  check_phase_digits(t_end, scale);
  RunPlan plan;
  plan.options =
      integration_options(report, in, compared, std::min(scale / 2000.0, fastest / 200.0));
  plan.fixed = fixed_step(in);
  // A step asked for that is longer than the whole run would be silently cut to it.
  if (plan.fixed && in.step && plan.options.step > t_end) {
    throw InputError("--step", fmt::format("{:g} s is longer than the run itself (t_end = {:g} s)",
                                           plan.options.step, t_end));
  }
  plan.times = sample_times(t_end, scale, plan.fixed ? plan.options.step : 0.0);
  plan.t_end = t_end;
  plan.work_start = work_done();
  return plan;
}

void report_plan(Report& report, const RunPlan& plan) {
  report.result("t_end_s", "end time t_end", plan.t_end, "s");
  if (!plan.fixed) return;
  const double h = plan.options.step;
  report.result("step_s", "step h", h, "s");
  // t_end is reached exactly: a last step shortened to it when t_end / h is not whole
  // (to roundoff, as the grid decides it).
  const double whole = std::floor(plan.t_end / h * (1.0 + 8.0 * kEps));
  const double last = plan.t_end - whole * h;
  if (last > 8.0 * kEps * plan.t_end) {
    report.result("last_step_s",
                  fmt::format("  the last, shortened to end at t_end ({:g} whole steps)", whole),
                  last, "s");
  }
}

void refuse_runaway(const std::string& option, double drift) {
  if (!(drift <= kMaxDrift)) {
    throw InputError(option, fmt::format("the run ran away: its conserved quantities drifted by "
                                         "{:.3g} of themselves (more than {:g}); shorten the step "
                                         "or tighten the tolerance",
                                         drift, kMaxDrift));
  }
}

void report_invariant(Report& report, const std::string& key, const std::string& error_label,
                      const std::vector<double>& t, const std::vector<double>& e, double period,
                      double roundoff) {
  const InvariantError error = invariant_error(t, e, period);
  report.result_roundoff(key + "_error_max_rel", error_label, error.max_rel, roundoff, "");
  report.result_roundoff(key + "_drift_per_period_rel", "  its drift: the fitted trend a period",
                         error.drift_per_period_rel, roundoff, "");
  report.alias(key + "_drift_rel", key + "_error_max_rel");  // the maximum's old name
}

void report_drifts(Report& report, const std::vector<double>& t,
                   const std::vector<std::vector<double>>& invariant_errors,
                   const std::vector<double>& max_invariant_errors, double period, bool exact,
                   const ExactErrorWords& words) {
  // Relative to the start; roundoff for the exact motion.
  const double roundoff = exact ? kClosedFormRoundoff : 0.0;
  for (const InvariantWords& w : words.invariants) {
    if (w.fitted) {
      report_invariant(report, w.key, w.label, t, invariant_errors.at(w.index), period, roundoff);
    } else {
      report.result_roundoff(w.key, w.label, max_invariant_errors.at(w.index), roundoff, "");
    }
  }
}

std::string method_choice(const OdeOptions& options) {
  return std::string(method_name(options.method)) +
         (options.project_invariants ? " --project" : "");
}

void rank_by_error(std::vector<MethodComparison>& at_cost) {
  const auto ranked = [](const MethodComparison& c) {
    return c.completed && std::isfinite(c.max_error);
  };
  std::stable_sort(at_cost.begin(), at_cost.end(),
                   [&](const MethodComparison& a, const MethodComparison& b) {
                     if (ranked(a) != ranked(b)) return ranked(a);
                     return ranked(a) && a.max_error < b.max_error;
                   });
}

void report_comparisons(Report& report, const MethodComparisons& comparisons,
                        const OdeOptions& settings, const ExactErrorWords& words) {
  report.section(
      fmt::format("every integrator against {} at its own cost: a fixed step of {:.4g} "
                  "s, an adaptive method at tolerance {:g} (equal cost: below)",
                  words.against, settings.step, settings.rel_tol));
  for (const MethodComparison& c : comparisons.at_settings) {
    const std::string name(method_name(c.options.method));
    const std::string key = words.method_key_prefix + json_key(name) + words.method_key_suffix;
    const std::string label = fmt::format("{:<15} {}", name, words.label);
    if (!c.completed) {
      report.result_none(key, label, words.unit,
                         fmt::format("not run: needs more than {} steps", kMaxComparisonSteps));
      continue;
    }
    if (!std::isfinite(c.max_error)) {
      report.result_none(key, label, words.unit, "diverged at this step");
    } else {
      report.result(key, label, words.in_unit ? words.in_unit(c.max_error) : c.max_error,
                    words.unit);
    }
    report.remark(fmt::format("({} evaluations, {} steps)", c.evaluations, c.steps));
    report.count_json("evaluations_" + json_key(name), c.evaluations);
    report.count_json("steps_" + json_key(name), c.steps);
  }
  if (!comparisons.at_cost.empty()) {
    report_equal_cost(report, comparisons, words);
  } else if (!comparisons.at_cost_limit.empty()) {
    report.section("which method to use");
    report.result_none("recommended_method", "use", "",
                       "not ranked: " + comparisons.at_cost_limit + " pays for no period");
  }
  report.result(
      "work",
      fmt::format("work done (Runge-Kutta evaluations' worth; at most {:g})", kMaxComputeWork),
      comparisons.work, "");
}

double end_time(const std::optional<double>& t_end, const std::optional<double>& periods,
                double scale, double default_t_end) {
  if (t_end) return *t_end;
  if (periods) return *periods * scale;
  return default_t_end;
}

void report_equal_cost(Report& report, const MethodComparisons& comparisons,
                       const ExactErrorWords& words) {
  const double periods = comparisons.at_cost_periods;
  const std::string over =
      fewer_periods(periods, comparisons.run_periods)
          ? fmt::format("the first {:g} of the run's {:.6g} periods ({})", periods,
                        comparisons.run_periods, comparisons.at_cost_limit)
          : fmt::format("the run's {:.4g} periods", periods);
  report.section(
      fmt::format("which method to use: every method at {:g} evaluations a period "
                  "over {}, the most accurate first ({})",
                  kEqualCostEvaluations, over, words.label));
  report.result("equal_cost_evaluations_per_period", "evaluations a period (a Strang step: one)",
                kEqualCostEvaluations, "");
  report.result("equal_cost_periods", "periods run", periods, "");
  const auto error_in_unit = [&](double e) { return words.in_unit ? words.in_unit(e) : e; };
  int rank = 0;
  for (const MethodComparison& c : comparisons.at_cost) {
    ++rank;
    const std::string choice = method_choice(c.options);
    const std::string key = json_key(std::string(method_name(c.options.method))) +
                            (c.options.project_invariants ? "_project" : "");
    const std::string error_key =
        "equal_cost_" + words.method_key_prefix + key + words.method_key_suffix;
    const std::string setting = is_adaptive(c.options.method)
                                    ? fmt::format("tol {:.2g}", c.options.rel_tol)
                                    : fmt::format("h = {:.3g} s", c.options.step);
    const std::string label = fmt::format("{:>2}. {:<24} {}", rank, choice, setting);
    report.count_json("equal_cost_rank_" + key, static_cast<std::size_t>(rank));
    if (!c.completed || !std::isfinite(c.max_error)) {
      const std::string why =
          c.completed ? "diverged at this cost" : "could not finish at this cost";
      report.result_none(error_key, label, words.unit, why);
      report.result_none("equal_cost_energy_drift_per_period_rel_" + key, "  energy drift", "",
                         why);
      report.result_none("equal_cost_energy_error_max_rel_" + key, "  largest energy error", "",
                         why);
      continue;
    }
    const InvariantError& energy = c.invariants.at(kEnergyInvariant);
    report.result(error_key, label, error_in_unit(c.max_error), words.unit);
    report.remark(
        fmt::format("({} evaluations, {} steps; energy drift {:.2g} a period, "
                    "largest {:.2g})",
                    c.evaluations, c.steps, energy.drift_per_period_rel, energy.max_rel));
    report.count_json("equal_cost_evaluations_" + key, c.evaluations);
    report.count_json("equal_cost_steps_" + key, c.steps);
    report.result_json("equal_cost_energy_drift_per_period_rel_" + key, energy.drift_per_period_rel,
                       "");
    report.result_json("equal_cost_energy_error_max_rel_" + key, energy.max_rel, "");
  }
  const MethodComparison& best = comparisons.at_cost.front();
  if (!best.completed || !std::isfinite(best.max_error)) {
    report.result_none("recommended_method", "use", "",
                       "no method finished at this cost: shorten the run");
    return;
  }
  report.result_text("recommended_method", "use", method_choice(best.options));
  std::string reason =
      fmt::format("the least {} over {} at equal cost: {:.2g}{}", words.label, over,
                  error_in_unit(best.max_error), words.unit.empty() ? "" : " " + words.unit);
  if (comparisons.at_cost.size() > 1) {
    const MethodComparison& next = comparisons.at_cost[1];
    if (next.completed && std::isfinite(next.max_error)) {
      reason += fmt::format(" (next: {}, {:.2g})", method_choice(next.options),
                            error_in_unit(next.max_error));
    }
  }
  report.result_text("recommended_method_reason", "  why", reason);
}

std::string method_help_list() {
  std::string text;
  for (const Method m : kAllMethods) {
    text += fmt::format("{}{}: {}", text.empty() ? "" : "; ", method_name(m), method_kind(m));
  }
  return text;
}

}  // namespace rigid::lab
