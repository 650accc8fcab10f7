// What every lab that integrates a rigid body shares (poinsot, tennis_racquet,
// top_nutation):
// its numerical options --method, --tolerance, --step and --project, and the
// run of the chosen method from the exact motion's start, measured against the
// exact motion and reported with the drifts of its invariants.
#pragma once

#include <string>
#include <vector>

#include "common/lab.h"
#include "rigid/drift.h"
#include "rigid/free_body_exact.h"
#include "rigid/integrate.h"

namespace rigid::lab {

/// The numerical inputs; `method` is "exact" (no integration) or an integrator's name.
struct IntegrationInputs {
  std::string method = "exact";
  double tolerance = 1e-10;
  double step = 0.0;  ///< 0: the lab's default step
  bool project = false;
  /// The lab also compares every method at --step and --tolerance (poinsot,
  /// top_nutation): neither is then unused, whichever method is chosen.
  bool compared = false;
};

/// Declares --method (its default is in.method), --tolerance, --step (whose default
/// the lab derives, described by `step_default`) and, if `offer_project`, --project.
void declare_integration_options(Lab& lab, IntegrationInputs& in, const std::string& method_help,
                                 const std::string& step_default, bool offer_project = true);

/// True when the chosen method takes a fixed step (so its samples lie on its grid).
bool fixed_step(const IntegrationInputs& in);

/// The options of the chosen method: the tolerance, the step (`default_step` unless
/// --step was given) and at most `max_steps` steps. Warns (Lab::warn) of --step or
/// --tolerance given where nothing uses them.
IntegrateOptions integration_options(Lab& lab, const IntegrationInputs& in, double default_step,
                                     std::size_t max_steps);

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
RunPlan plan_run(Lab& lab, const IntegrationInputs& in, double t_end, double scale,
                 std::size_t max_steps);
/// Reports the plan's end time (t_end_s) and, for a fixed step, the step (step_s) and,
/// when t_end is not a whole number of steps, the last one, shortened to end there
/// (last_step_s).
void report_plan(Lab& lab, const RunPlan& plan);

/// The motion in words, for the table: its regime with its stability and, near
/// the separatrix, how near. Reports "regime" (to_string of the regime, as before),
/// "motion" (the sentence), "motion_stability" (stable, unstable or neutral) and
/// "complementary_parameter" (k'^2: 0 on the separatrix, null for a steady spin).
void report_motion(Lab& lab, const FreeBodyExact& motion);

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

/// Reports one invariant's signed relative errors `e` at times `t`: its largest
/// (<key>_error_max_rel, labelled `error_label`) and its drift per `period`
/// (<key>_drift_per_period_rel), and <key>_drift_rel, the maximum's old name, in JSON.
/// With `roundoff` > 0 (a run of the closed form), values within it print as 0.
void report_invariant(Lab& lab, const std::string& key, const std::string& error_label,
                      const std::vector<double>& t, const std::vector<double>& e, double period,
                      double roundoff = 0.0);
/// The closed form's own rounding of a relative invariant: a few ulps (64 eps bounds it).
inline constexpr double kClosedFormRoundoff = 64 * 2.220446049250313e-16;

/// Reports how the run kept T and |L| (report_invariant): for each, its largest relative error
/// (energy_error_max_rel, momentum_error_max_rel) and its secular drift, the fitted
/// trend per `period` (energy_drift_per_period_rel, momentum_drift_per_period_rel);
/// and L's largest error in space (L_space_drift_rel). energy_drift_rel and
/// momentum_drift_rel stay one release as JSON aliases of the maxima.
void report_drifts(Lab& lab, const IntegrationResult& run, double period, bool exact);

/// Declares --t-end (s) and --periods N, the end time as N times the lab's `period_name`
/// ("polhode period"); `default_text` says what the lab does when neither is given.
void declare_end_time(Lab& lab, double& t_end, double& periods, const std::string& period_name,
                      const std::string& default_text);
/// The end time asked for: --t-end, or --periods times `scale`; neither: `default_t_end`.
/// Both given is a UsageError naming --periods.
double end_time(const Lab& lab, double t_end, double periods, double scale, double default_t_end);

/// One method of a comparison at equal cost, as the table reports it.
struct EqualCostRow {
  OdeOptions options;  ///< the method and the step or tolerance that cost the budget
  bool completed = false;
  std::size_t evaluations = 0;  ///< of the whole run
  InvariantError energy;        ///< the energy's largest error and drift per period
};
/// The section that answers "which method drifts": every method at the same
/// `evaluations_per_period` over `periods` periods, its energy drift per period and
/// largest energy error (equal_cost_energy_drift_per_period_rel_<method>,
/// equal_cost_energy_error_max_rel_<method>), and the method that drifts least.
void report_equal_cost(Lab& lab, const std::vector<EqualCostRow>& rows,
                       double evaluations_per_period, double periods);
/// A method and its kind for --help: "splitting (symplectic splitting, order 2)".
std::string method_help_list();

}  // namespace rigid::lab
