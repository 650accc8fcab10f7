// Numerical integration of the torque-free rigid body (Euler's equations,
// eq. 73 with N = 0, and the attitude quaternion), by a method chosen by name.
//
//  - "splitting", "splitting4": Lie-Poisson splittings (splitting.h), fixed step,
//    order 2 and 4; |L| and |q| kept to roundoff, energy without drift.
//  - "rk4": Boost.Odeint runge_kutta4, fixed step.
//  - "dopri5": runge_kutta_dopri5, error-controlled, with dense output.
//  - "rkf78": runge_kutta_fehlberg78, error-controlled.
//  - "bulirsch-stoer": bulirsch_stoer with dense output.
// All run on the fixed-size FreeBodyState. Samples are produced exactly at the
// requested times: dense-output methods interpolate, the others shorten the
// one step that would pass a sample time. The Runge-Kutta methods do not keep
// |q| = 1; their quaternion is not touched during the run, its norm drift is
// reported and the sampled attitudes are normalised.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

#include "rigid/free_body.h"
#include "rigid/free_body_exact.h"

namespace rigid {

/// The integrators, by their command-line names.
enum class Method { kSplitting, kSplitting4, kRk4, kDopri5, kRkf78, kBulirschStoer };

/// Every method, in the order of `method_name`.
inline constexpr std::array<Method, 6> kAllMethods = {Method::kSplitting, Method::kSplitting4,
                                                      Method::kRk4,       Method::kDopri5,
                                                      Method::kRkf78,     Method::kBulirschStoer};

/// The command-line name: "splitting", "splitting4", "rk4", "dopri5", "rkf78", "bulirsch-stoer".
std::string_view method_name(Method m);
/// The method of a name; throws std::invalid_argument listing the valid names.
Method method_from_name(std::string_view name);
/// True for the error-controlled methods (dopri5, rkf78, bulirsch-stoer), which take
/// tolerances; the others take a fixed step.
bool is_adaptive(Method m);
/// True for the methods that can project onto the invariants (rk4, rkf78).
bool can_project(Method m);
/// The order of accuracy of a fixed-step method (2, 4, 4); 0 for the adaptive ones.
int fixed_step_order(Method m);

/// How to integrate. Set only what differs from the defaults.
struct IntegrateOptions {
  Method method = Method::kDopri5;
  double abs_tol = 1e-10;  ///< adaptive methods: absolute tolerance on each state component
  double rel_tol = 1e-10;  ///< adaptive methods: relative tolerance
  double step = 1e-2;      ///< fixed-step methods: the step, s
  std::size_t max_steps = 50'000'000;  ///< a run needing more steps throws instead of hanging
  MomentsRule moments_rule = MomentsRule::kPhysical;
  /// rk4 and rkf78 only: after every step, pull omega back onto the energy and
  /// |L| of the start (the standard projection, Hairer, Lubich & Wanner IV.4),
  /// so both invariants hold to roundoff; other methods throw if asked.
  bool project_invariants = false;
};

/// One output sample.
struct FreeBodySample {
  double t = 0.0;
  Eigen::Vector3d omega_body = Eigen::Vector3d::Zero();
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();  ///< unit, body to space
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

/// Sample times from 0 to about t_end, `per_period` samples per `period` and at
/// most `max_samples` in all. With `step` > 0 (a fixed-step method) they fall on
/// the step grid, every k-th step, so no step is shortened to land on a sample,
/// and t_end rounds up to a whole step: the last time is the end actually reached.
std::vector<double> sample_times(double t_end, double period, double step = 0.0,
                                 double per_period = 200.0, std::size_t max_samples = 20001);

/// The exact motion sampled at `times` as a run of its own (no steps), with the
/// same drift measures as an integrator's run: roundoff only.
IntegrationResult sample_exact(const FreeBodyExact& exact, const std::vector<double>& times);

/// |omega - omega_exact(t)| / |omega_exact(0)| at each sample of a run.
std::vector<double> omega_errors(const IntegrationResult& run, const FreeBodyExact& exact);

/// |T - T_exact| / T_exact at each sample of a run (eq. 81).
std::vector<double> energy_errors(const IntegrationResult& run, const FreeBodyExact& exact);

}  // namespace rigid
