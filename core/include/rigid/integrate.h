// Numerical integration of the torque-free rigid body (Euler's equations,
// eq. 73 with N = 0, and the attitude quaternion), by a method chosen by name.
//
//  - "splitting", "splitting4": Lie-Poisson splittings (splitting.h), fixed step,
//    order 2 and 4; |L| and |q| kept to roundoff, energy without drift.
//  - "rk4": Boost.Odeint runge_kutta4, fixed step.
//  - "dopri5": runge_kutta_dopri5, error-controlled, with dense output.
//  - "rkf78": runge_kutta_fehlberg78, error-controlled.
//  - "bulirsch-stoer": bulirsch_stoer with dense output.
// All run through the generic layer of ode.h on the fixed-size FreeBodyState
// (the splittings on L_body and q). Samples are produced exactly at the
// requested times: dense-output methods interpolate, the controlled one
// shortens the step that would pass a sample time, the fixed-step ones keep
// their grid t0 + n h (ode.h). The Runge-Kutta methods do not keep
// |q| = 1; their quaternion is not touched during the run, its norm drift is
// reported and the sampled attitudes are normalised.
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

#include "rigid/drift.h"
#include "rigid/free_body.h"
#include "rigid/free_body_exact.h"
#include "rigid/ode.h"

namespace rigid {

/// True for the methods that can project onto the invariants (rk4, rkf78, vern6..vern9).
inline bool can_project(Method m) {
  return takes_after_step(m);
}

/// How to integrate the free body: the generic options (method, abs_tol,
/// rel_tol, step, max_steps) and the free body's own. Set only what differs.
struct IntegrateOptions : OdeOptions {
  MomentsRule moments_rule = MomentsRule::kPhysical;
  /// rk4, rkf78 and vern6..vern9 only: after every step, pull omega back onto the energy and
  /// |L| of the start (the standard projection, Hairer, Lubich & Wanner IV.4),
  /// so both invariants hold to roundoff; other methods throw if asked.
  bool project_invariants = false;
};

/// One output sample.
struct FreeBodySample {
  double t = 0.0;
  Eigen::Vector3d omega_body = Eigen::Vector3d::Zero();
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();  ///< unit, body to space
  double energy_error = 0.0;                                     ///< (T - T0) / T0, signed
  double momentum_error = 0.0;                                   ///< (|L| - |L0|) / |L0|, signed
};

/// The samples of one run and what it cost and kept.
struct IntegrationResult {
  Method method = Method::kDopri5;
  std::vector<FreeBodySample> samples;
  double energy_drift_rel = 0.0;       ///< max over samples of |T - T0| / T0
  double momentum_drift_rel = 0.0;     ///< max over samples of ||L| - |L0|| / |L0|
  double L_space_drift_rel = 0.0;      ///< max over samples of |L_space - L_space0| / |L0|
  double quaternion_norm_drift = 0.0;  ///< max over samples of ||q| - 1| before normalising
  std::size_t steps = 0;               ///< accepted steps (shortened ones included)
  std::size_t rejected_steps = 0;      ///< steps rejected by the error control (where known)
  std::size_t evaluations = 0;  ///< right-hand-side evaluations (ode.h's evaluations_per_step)
};

/// Integrates from the state x0 at t = times.front() and samples at every entry
/// of `times` (finite, nondecreasing). Throws std::invalid_argument for bad
/// moments, state, times or options (tolerance outside [0, 1) or both zero, step
/// not positive, a fixed-step run needing more than max_steps), and
/// std::runtime_error when an adaptive run needs more than max_steps steps.
IntegrationResult integrate_free_body(const PrincipalMoments& I, const FreeBodyState& x0,
                                      const std::vector<double>& times,
                                      const IntegrateOptions& options = {});

/// n equally spaced times from t0 to t1 inclusive (n >= 2), or {t0} for n = 1.
std::vector<double> uniform_times(double t0, double t1, std::size_t n);

/// Sample times from 0 to exactly t_end, `per_period` samples per `period` and at
/// most `max_samples` in all. With `step` > 0 (a fixed-step method) every sample
/// but the last falls on the step grid n * step, every k-th step, and the last
/// is t_end itself: only the run's last step is shortened, when step does not divide t_end.
std::vector<double> sample_times(double t_end, double period, double step = 0.0,
                                 double per_period = 200.0, std::size_t max_samples = 20001);

/// The exact motion sampled at `times` as a run of its own (no steps), with the
/// same drift measures as an integrator's run: roundoff only.
IntegrationResult sample_exact(const FreeBodyExact& exact, const std::vector<double>& times);

/// |omega - omega_exact(t)| / |omega_exact(0)| at each sample of a run.
std::vector<double> omega_errors(const IntegrationResult& run, const FreeBodyExact& exact);

/// |T - T_exact| / T_exact at each sample of a run (eq. 81).
std::vector<double> energy_errors(const IntegrationResult& run, const FreeBodyExact& exact);

/// One method's run measured against the exact solution, sample by sample.
struct MethodComparison {
  IntegrateOptions options;          ///< the method and the settings it ran with
  bool completed = false;            ///< false: it would have needed more than max_steps
  std::vector<double> t;             ///< its sample times (a fixed step's on its own grid)
  std::vector<double> omega_error;   ///< |omega - omega_exact| / |omega0|
  std::vector<double> energy_error;  ///< |T - T0| / T0
  double max_omega_error = 0.0;      ///< the largest omega_error (infinite if it diverged)
  std::size_t evaluations = 0;       ///< right-hand-side evaluations of the run
  InvariantError energy, momentum;   ///< T's and |L|'s largest error and drift per period
};

/// Every method of kAllMethods at `options` (no projection, at most `max_steps`
/// steps each) against the exact motion from t = 0 to times.back(): adaptive
/// methods at `times`, fixed-step ones on their step grid with `period /
/// per_period` spacing as sample_times makes it, so each run is the one a
/// caller choosing that method alone would get.
std::vector<MethodComparison> compare_methods(const FreeBodyExact& exact,
                                              const std::vector<double>& times, double period,
                                              const IntegrateOptions& options,
                                              std::size_t max_steps);

/// Every method at the same cost, the question "which method drifts" answered fairly:
/// `evaluations_per_period` right-hand-side evaluations a period (options_at_cost:
/// fixed steps from evaluations_per_step, tolerances found by bisection) over
/// `periods` periods of length `period`, each run sampled `samples_per_period` times a
/// period (a fixed step's on its grid). A method that cannot finish is not completed.
std::vector<MethodComparison> compare_methods_at_cost(const FreeBodyExact& exact, double period,
                                                      double periods, double evaluations_per_period,
                                                      double samples_per_period = 8.0);

}  // namespace rigid
