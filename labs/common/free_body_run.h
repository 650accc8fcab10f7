// What every lab that integrates a rigid body shares (poinsot, tennis_racquet,
// top_nutation):
// its numerical options --method, --tolerance, --step and --project, and the
// run of the chosen method from the exact motion's start, measured against the
// exact motion and reported with the drifts of its invariants.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/inputs.h"
#include "common/report.h"
#include "rigid/drift.h"
#include "rigid/free_body_exact.h"
#include "rigid/integrate.h"

namespace rigid::lab {

/// The numerical inputs; `method` is "exact" (no integration) or an integrator's name.
struct IntegrationInputs {
  std::string method = "exact";
  double tolerance = 1e-10;
  std::optional<double> step;  ///< the lab's default step unless set
  bool project = false;
};

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
/// --step was given) and at most `max_steps` steps. Warns (Report::warn) of --step or
/// --tolerance given where nothing uses them.
IntegrateOptions integration_options(Report& report, const IntegrationInputs& in, bool compared,
                                     double default_step, std::size_t max_steps);

/// Runs the chosen method from exact.state(0) through `times` (the exact motion
/// sampled, for "exact"), and reports its error against the exact motion
/// (max_error_vs_exact) and its steps. Bad settings and a run that diverges are
/// InputErrors naming --step, --tolerance or --project.
IntegrationResult run_free_body(Report& report, const FreeBodyExact& exact,
                                const IntegrationInputs& in, const IntegrateOptions& options,
                                const std::vector<double>& times);

/// What a run samples and how: the method's options (its step `scale` / 2000 unless
/// --step was given), 200 samples a `scale` up to t_end (a fixed step's on its own
/// grid), after refusing a t_end beyond check_phase_digits.
struct RunPlan {
  IntegrateOptions options;
  std::vector<double> times;
  bool fixed = false;
  double t_end = 0.0;
};
RunPlan plan_run(Report& report, const IntegrationInputs& in, bool compared, double t_end,
                 double scale, std::size_t max_steps);
/// Reports the plan's end time (t_end_s) and, for a fixed step, the step (step_s) and,
/// when t_end is not a whole number of steps, the last one, shortened to end there
/// (last_step_s).
void report_plan(Report& report, const RunPlan& plan);

/// The motion in words, for the table: its regime with its stability and, near
/// the separatrix, how near. Reports "regime" (to_string of the regime, as before),
/// "motion" (the sentence), "motion_stability" (stable, unstable or neutral) and
/// "complementary_parameter" (k'^2: 0 on the separatrix, null for a steady spin).
void report_motion(Report& report, const FreeBodyExact& motion);

/// The motion's time scale: its polhode period, or one turn for a steady rotation
/// (no polhode to go round).
double time_scale(const FreeBodyExact& motion);

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

/// Reports how the run kept T and |L| (report_invariant): for each, its largest relative error
/// (energy_error_max_rel, momentum_error_max_rel) and its secular drift, the fitted
/// trend per `period` (energy_drift_per_period_rel, momentum_drift_per_period_rel);
/// and L's largest error in space (L_space_drift_rel). energy_drift_rel and
/// momentum_drift_rel stay one release as JSON aliases of the maxima.
void report_drifts(Report& report, const IntegrationResult& run, double period, bool exact);

/// The end time asked for: t_end, or periods times `scale`; neither: `default_t_end`.
double end_time(const std::optional<double>& t_end, const std::optional<double>& periods,
                double scale, double default_t_end);

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
void report_equal_cost(Report& report, const std::vector<EqualCostRow>& rows,
                       double evaluations_per_period, double periods);
/// A method and its kind for --help: "splitting (symplectic splitting, order 2)".
std::string method_help_list();

}  // namespace rigid::lab
