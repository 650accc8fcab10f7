// What the labs of the free body share beyond the integrated run (poinsot,
// tennis_racquet): the motion in words, its time scale, and the words the free
// body's error against its exact motion and its invariants are reported in.
#pragma once

#include <optional>
#include <vector>

#include "common/figures.h"
#include "common/integrated_run.h"
#include "common/report.h"
#include "rigid/free_body_exact.h"
#include "rigid/free_body_integrate.h"

namespace rigid::lab {

/// The motion in words, for the table: its regime with its stability and, near
/// the separatrix, how near. Reports "regime" (to_string of the regime, as before),
/// "motion" (the sentence), "motion_stability" (stable, unstable or neutral) and
/// "complementary_parameter" (k'^2: 0 on the separatrix, null for a steady spin).
void report_motion(Report& report, const FreeBodyExact& motion);

/// The flip of a body spun near its intermediate axis (the tennis racquet theorem, for
/// any body): the linear growth rate of a disturbance, lambda = |omega_m(0)| sqrt((I_m -
/// I_s)(I_l - I_m) / (I_s I_l)) with omega_m(0) the spin's component on the intermediate
/// axis m (eqs. 86-88), the rate fitted to the exact motion, the first time omega_m
/// changes sign (the first flip) and the time between flips (half the polhode period).
/// Reports growth_rate_per_s, growth_rate_measured_per_s, first_flip_s and
/// flip_interval_s, each null with the reason where the body does not flip: a stable
/// spin, two equal moments, a spin exactly on the axis (it never starts) or on the
/// separatrix (it never finishes).
void report_flips(Report& report, const FreeBodyExact& motion);

/// The motion's time scale: its polhode period, or one turn for a steady rotation
/// (no polhode to go round).
double time_scale(const FreeBodyExact& motion);

/// The free body's error against the exact motion, |omega - omega_exact| / |omega0|
/// (max_error_vs_exact, max_error_<method>), and its invariants: T's and |L|'s largest
/// relative error and drift a period (energy_*, momentum_*; a run that lost either ran
/// away) and L's largest error in space (L_space_drift_rel).
const ExactErrorWords& free_body_words();

/// The free body at any time: the closed form `exact`, or with `integrator` the run that
/// kept `samples` integrated on from the nearest earlier one (IntegratedMotion, held to
/// free_body_words()'s invariants); at the samples' times, their states bit for bit.
BodyMotion free_body_motion(const FreeBodyExact& exact, const std::optional<OdeOptions>& integrator,
                            const std::vector<FreeBodyRun::Sample>& samples);

}  // namespace rigid::lab
