#include "common/free_body_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "rigid/units.h"

namespace rigid::lab {

namespace {
// The wall-clock budget of a lab's own run; the comparisons are capped in steps.
constexpr double kMaxRunSeconds = 4.0;
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
}  // namespace

InputTable<IntegrationInputs> integration_inputs(const std::string& method_help,
                                                 const std::string& step_default,
                                                 bool offer_project) {
  InputTable<IntegrationInputs> t;
  std::vector<std::string> methods{"exact"};
  for (const Method m : kAllMethods) methods.emplace_back(method_name(m));
  t.choice("--method", &IntegrationInputs::method, methods,
           method_help + " (exact: the closed form; " + method_help_list() + ")")
      .numerical();
  t.number("--tolerance", &IntegrationInputs::tolerance,
           "relative and absolute tolerance of adaptive methods")
      .open_range(0.0, 1.0)
      .numerical();
  t.number("--step", &IntegrationInputs::step, "step of fixed-step methods")
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

bool fixed_step(const IntegrationInputs& in) {
  return in.method != "exact" && !is_adaptive(method_from_name(in.method));
}

IntegrateOptions integration_options(Report& report, const IntegrationInputs& in, bool compared,
                                     double default_step, std::size_t max_steps) {
  // Below double precision no step meets a tolerance, and odeint's step control
  // then collapses (tolerances under 1e-150 crashed it).
  if (in.tolerance < 1e-16) {
    throw InputError("--tolerance", fmt::format("must be at least 1e-16, double precision's "
                                                "reach (got {:g})",
                                                in.tolerance));
  }
  IntegrateOptions options;
  options.abs_tol = options.rel_tol = in.tolerance;
  options.step = in.step.value_or(default_step);
  options.max_steps = max_steps;
  // Every lab finishes or refuses within seconds, whatever the step count.
  options.max_seconds = kMaxRunSeconds;
  options.method = in.method == "exact" ? Method::kDopri5 : method_from_name(in.method);
  options.project_invariants = in.project;
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

IntegrationResult run_free_body(Report& report, const FreeBodyExact& exact,
                                const IntegrationInputs& in, const IntegrateOptions& options,
                                const std::vector<double>& times) {
  if (in.method == "exact") return sample_exact(exact, times);
  if (in.project && !can_project(options.method)) {
    throw InputError("--project", "works with --method " + projecting_methods() + " only");
  }
  const char* option = fixed_step(in) ? "--step" : "--tolerance";
  IntegrationResult run;
  try {
    run = integrate_free_body(exact.moments(), exact.state(0.0), times, options);
  } catch (const std::exception& e) {
    throw InputError(option, e.what());
  }
  const std::vector<double> errors = omega_errors(run, exact);
  // A step beyond the method's stability region blows omega up.
  if (!std::all_of(errors.begin(), errors.end(), [](double e) { return std::isfinite(e); })) {
    throw InputError(option, "the integration diverged (omega overflowed); shorten the step");
  }
  // A run whose energy or |L| moved by more than itself has no digit left to print.
  refuse_runaway(option, std::max(run.energy_drift_rel, run.momentum_drift_rel));
  report.result("max_error_vs_exact", "max |omega - omega_exact| / |omega0|",
                *std::max_element(errors.begin(), errors.end()), "");
  report.count("steps", "steps taken", run.steps);
  return run;
}

namespace {

// A steady spin in words: about which axis, and whether a nudge grows.
std::pair<std::string, std::string> steady_in_words(const FreeBodyExact& motion) {
  const Eigen::Vector3d w = motion.omega_body(0.0), I = motion.moments().vector();
  if (w.isZero(0.0)) return {"at rest", "neutral"};
  if (I.minCoeff() == I.maxCoeff())
    return {"steady rotation of a spherical body: every axis is steady", "neutral"};
  Eigen::Index axis = 0;
  w.cwiseAbs().maxCoeff(&axis);
  const bool on_axis = (w.cwiseAbs().array() > 0.0).count() == 1;
  if (!on_axis) {
    // omega in the plane of two equal moments: every axis of that plane is principal
    return {"steady rotation about an axis of the plane of two equal moments", "neutral"};
  }
  const double Ii = I(axis);
  const int below = (I.array() < Ii).count(), above = (I.array() > Ii).count();
  const std::string name = fmt::format("axis {}", axis + 1);
  if (below > 0 && above > 0) {
    return {"steady rotation about the intermediate " + name +
                ": unstable, the least nudge grows and flips it (the tennis racquet theorem)",
            "unstable"};
  }
  if (below + above < 2) {
    return {"steady rotation about " + name + ", one of two equal moments: neutral", "neutral"};
  }
  return {"steady rotation about the " + std::string(above == 0 ? "largest " : "smallest ") + name +
              ": stable, a nudge only wobbles it",
          "stable"};
}

}  // namespace

void report_motion(Report& report, const FreeBodyExact& motion) {
  const FreeMotionRegime regime = motion.regime();
  report.result_text("regime", "motion", to_string(regime));
  std::string words, stability;
  if (regime == FreeMotionRegime::kSteady) {
    std::tie(words, stability) = steady_in_words(motion);
    report.result_none("complementary_parameter", "  k'^2", "", "a steady spin has no polhode");
  } else if (regime == FreeMotionRegime::kSeparatrix) {
    words =
        "on the separatrix: unstable, omega leaves the intermediate axis and only "
        "approaches it again, never returning";
    stability = "unstable";
    report.result("complementary_parameter", "  k'^2 (0: on the separatrix)", 0.0, "");
  } else {
    const double kp2 = motion.complementary_parameter();
    // k'^2 measures the distance to the separatrix; below 0.01 the period grows as
    // ln(4/k') and omega lingers by the intermediate axis between flips: the orbit of
    // a spin about that axis, nudged, whose fate a further nudge may change.
    if (kp2 < 0.01) {
      stability = "unstable";
      words = fmt::format(
          "near the separatrix (k'^2 = {:.2g}): unstable, omega lingers by the "
          "intermediate axis and the body flips over every {:.4g} s ({})",
          kp2, 0.5 * motion.period(), to_string(regime));
    } else {
      stability = "stable";
      words = to_string(regime) + ": stable, omega circles that axis";
    }
    report.result("complementary_parameter", "  k'^2 (1: far from the separatrix, 0: on it)", kp2,
                  "");
  }
  report.result_text("motion", "  in words", words);
  report.result_text("motion_stability", "  stability", stability);
}

double time_scale(const FreeBodyExact& motion) {
  return std::isfinite(motion.period()) ? motion.period()
                                        : 2.0 * kPi / motion.omega_body(0.0).norm();
}

void check_phase_digits(double t_end, double scale) {
  if (t_end > 1e9 * scale) {
    throw InputError("--t-end", fmt::format("at most 1e9 periods ({:g} s) for these inputs: "
                                            "beyond, the phase of the motion loses its digits",
                                            1e9 * scale));
  }
}

RunPlan plan_run(Report& report, const IntegrationInputs& in, bool compared, double t_end,
                 double scale, std::size_t max_steps) {
  check_phase_digits(t_end, scale);
  RunPlan plan;
  plan.options = integration_options(report, in, compared, scale / 2000.0, max_steps);
  plan.fixed = fixed_step(in);
  // A step asked for that is longer than the whole run would be silently cut to it.
  if (plan.fixed && in.step && plan.options.step > t_end) {
    throw InputError("--step", fmt::format("{:g} s is longer than the run itself (t_end = {:g} s)",
                                           plan.options.step, t_end));
  }
  plan.times = sample_times(t_end, scale, plan.fixed ? plan.options.step : 0.0);
  plan.t_end = t_end;
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

void report_drifts(Report& report, const IntegrationResult& run, double period, bool exact) {
  // Relative to the start; roundoff for the exact motion.
  std::vector<double> t, dT, dL;
  for (const FreeBodySample& s : run.samples) {
    t.push_back(s.t);
    dT.push_back(s.energy_error);
    dL.push_back(s.momentum_error);
  }
  const double roundoff = exact ? kClosedFormRoundoff : 0.0;
  report_invariant(report, "energy", "max |T - T0| / T0", t, dT, period, roundoff);
  report_invariant(report, "momentum", "max ||L| - |L0|| / |L0|", t, dL, period, roundoff);
  report.result_roundoff("L_space_drift_rel", "max |L_space - L_space0| / |L0|",
                         run.L_space_drift_rel, roundoff, "");
}

double end_time(const std::optional<double>& t_end, const std::optional<double>& periods,
                double scale, double default_t_end) {
  if (t_end) return *t_end;
  if (periods) return *periods * scale;
  return default_t_end;
}

void report_equal_cost(Report& report, const std::vector<EqualCostRow>& rows,
                       double evaluations_per_period, double periods) {
  report.section(
      fmt::format("which method drifts: every method at {:g} evaluations a period, "
                  "{:g} periods (a symplectic method's energy error stays in a band)",
                  evaluations_per_period, periods));
  report.result("equal_cost_evaluations_per_period", "evaluations a period (a Strang step: one)",
                evaluations_per_period, "");
  report.result("equal_cost_periods", "periods run", periods, "");
  const EqualCostRow* least = nullptr;
  for (const EqualCostRow& row : rows) {
    const std::string name(method_name(row.options.method));
    const std::string key = json_key(name);
    const std::string setting = is_adaptive(row.options.method)
                                    ? fmt::format("tol {:.2g}", row.options.rel_tol)
                                    : fmt::format("h = {:.3g} s", row.options.step);
    const std::string label = fmt::format("{:<15} {:<15} energy drift a period", name, setting);
    if (!row.completed) {
      report.result_none("equal_cost_energy_drift_per_period_rel_" + key, label, "",
                         "could not finish at this cost");
      report.result_none("equal_cost_energy_error_max_rel_" + key, "  max |T - T0| / T0", "",
                         "could not finish at this cost");
      continue;
    }
    report.result("equal_cost_energy_drift_per_period_rel_" + key, label,
                  row.energy.drift_per_period_rel, "");
    report.result("equal_cost_energy_error_max_rel_" + key, "  largest energy error",
                  row.energy.max_rel, "");
    if (least == nullptr ||
        std::abs(row.energy.drift_per_period_rel) < std::abs(least->energy.drift_per_period_rel)) {
      least = &row;
    }
  }
  if (least != nullptr) {
    const Method m = least->options.method;
    report.result_text("least_energy_drift", "least energy drift at equal cost",
                       std::string(method_name(m)));
    report.result_text("least_energy_drift_kind", "  its kind", std::string(method_kind(m)));
  }
}

std::string method_help_list() {
  std::string text;
  for (const Method m : kAllMethods) {
    text += fmt::format("{}{}: {}", text.empty() ? "" : "; ", method_name(m), method_kind(m));
  }
  return text;
}

}  // namespace rigid::lab
