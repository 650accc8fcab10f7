// What every lab that integrates a rigid body shares (poinsot, tennis_racquet,
// top_nutation):
// its numerical options --method, --tolerance, --step and --project, and the
// run of the chosen method from the exact motion's start, measured against the
// exact motion and reported with the drifts of its invariants.
#pragma once

#include <string>
#include <vector>

#include "common/lab.h"
#include "rigid/free_body_exact.h"
#include "rigid/integrate.h"

namespace rigid::lab {

/// The numerical inputs; `method` is "exact" (no integration) or an integrator's name.
struct IntegrationInputs {
  std::string method = "exact";
  double tolerance = 1e-10;
  double step = 0.0;  ///< 0: the lab's default step
  bool project = false;
};

/// Declares --method (its default is in.method), --tolerance, --step (whose default
/// the lab derives, described by `step_default`) and, if `offer_project`, --project.
void declare_integration_options(Lab& lab, IntegrationInputs& in, const std::string& method_help,
                                 const std::string& step_default, bool offer_project = true);

/// True when the chosen method takes a fixed step (so its samples lie on its grid).
bool fixed_step(const IntegrationInputs& in);

/// The options of the chosen method: the tolerance, the step (`default_step` unless
/// --step was given) and at most `max_steps` steps.
IntegrateOptions integration_options(const Lab& lab, const IntegrationInputs& in,
                                     double default_step, std::size_t max_steps);

/// Runs the chosen method from exact.state(0) through `times` (the exact motion
/// sampled, for "exact"), and reports its error against the exact motion
/// (max_error_vs_exact) and its steps. Bad settings and a run that diverges are
/// UsageErrors naming --step, --tolerance or --project.
IntegrationResult run_free_body(Lab& lab, const FreeBodyExact& exact, const IntegrationInputs& in,
                                const IntegrateOptions& options, const std::vector<double>& times);

/// What a run samples and how: the method's options (its step `scale` / 2000 unless
/// --step was given), 200 samples a `scale` up to t_end (a fixed step's on its own
/// grid), after refusing a t_end beyond check_phase_digits.
struct RunPlan {
  IntegrateOptions options;
  std::vector<double> times;
  bool fixed = false;
  double t_end = 0.0;
};
RunPlan plan_run(const Lab& lab, const IntegrationInputs& in, double t_end, double scale,
                 std::size_t max_steps);
/// Reports the plan's end time (t_end_s) and, for a fixed step, the step (step_s).
void report_plan(Lab& lab, const RunPlan& plan);

/// The motion's time scale: its polhode period, or one turn for a steady rotation
/// (no polhode to go round).
double time_scale(const FreeBodyExact& motion);

/// Refuses (a UsageError naming --t-end) a run longer than 1e9 times the motion's
/// time scale: beyond, the phase of the exact motion keeps fewer than 7 of its 16 digits.
void check_phase_digits(double t_end, double scale);

/// Refuses (a UsageError naming `option`) a run whose conserved quantities drifted by
/// more than themselves (relative drift > 1): a step far too long, whose numbers
/// would mean nothing.
void refuse_runaway(const std::string& option, double drift);

/// Reports the run's drift of T, |L| and L in space, relative to the start
/// (energy_drift_rel, momentum_drift_rel, L_space_drift_rel).
void report_drifts(Lab& lab, const IntegrationResult& run);

}  // namespace rigid::lab
