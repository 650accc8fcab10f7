// The heavy symmetric top integrated (the cross-check of heavy_top.h's exact
// motion, and the path for starts it does not cover): omega in body axes and
// the attitude quaternion, never Euler angles, so an upright top (theta = 0)
// is an ordinary point. Euler's equations about the pivot with the moments
// (I, I, Is) and the gravity torque N_body = -mgl e3 x (R^T z).
//
//  - rk4, dopri5, rkf78, bulirsch-stoer: Boost.Odeint through ode.h's one
//    integration layer on the fixed-size FreeBodyState (w, q).
//  - splitting, splitting4: the exact flow of the free symmetric top composed
//    with gravity kicks (Strang, and Suzuki's fourth-order composition). Each
//    piece is a rotation of L or of the attitude, and a kick changes L by a
//    torque normal to both z and 3: p_phi = L_z and p_psi = L_3 are kept to
//    roundoff, the energy without drift (the method is symplectic).
#pragma once

#include <cstddef>
#include <vector>

#include "rigid/drift.h"
#include "rigid/free_body.h"
#include "rigid/heavy_top.h"
#include "rigid/ode.h"

namespace rigid {

/// Right-hand side of the heavy top: Euler's equations with the gravity torque
/// and the quaternion kinematics; an odeint system functor on FreeBodyState.
/// The coefficients are formed once, so an evaluation costs one division.
class HeavyTopRhs {
 public:
  explicit HeavyTopRhs(const HeavyTop& top)
      : mgl_over_I_(top.mgl / top.I), spin_coupling_((top.Is - top.I) / top.I) {}
  void operator()(const FreeBodyState& x, FreeBodyState& dxdt, double /*t*/) const {
    const double w1 = x[0], w2 = x[1], w3 = x[2];
    const double qw = x[3], qx = x[4], qy = x[5], qz = x[6];
    // R^T z for the (not renormalised) quaternion: z in body axes, times 1/|q|^2.
    const double inv_n2 = 1.0 / (qw * qw + qx * qx + qy * qy + qz * qz);
    const double ux = 2.0 * (qx * qz - qw * qy) * inv_n2, uy = 2.0 * (qy * qz + qw * qx) * inv_n2;
    // I w_dot = N - w x (I w), N = -mgl e3 x (R^T z) = mgl (uy, -ux, 0); Is w3_dot = 0
    dxdt[0] = mgl_over_I_ * uy - spin_coupling_ * w2 * w3;
    dxdt[1] = -mgl_over_I_ * ux + spin_coupling_ * w3 * w1;
    dxdt[2] = 0.0;
    // q_dot = 1/2 q (x) (0, omega_body)
    dxdt[3] = 0.5 * (-qx * w1 - qy * w2 - qz * w3);
    dxdt[4] = 0.5 * (qw * w1 + qy * w3 - qz * w2);
    dxdt[5] = 0.5 * (qw * w2 + qz * w1 - qx * w3);
    dxdt[6] = 0.5 * (qw * w3 + qx * w2 - qy * w1);
  }

 private:
  double mgl_over_I_, spin_coupling_;
};

/// The state (omega_body, attitude) of Euler angles and rates.
FreeBodyState heavy_top_state(const TopAngles& angles);

/// theta, the tilt of the symmetry axis from z, of an attitude (exact at theta = 0).
double tilt_of(const Eigen::Quaterniond& q);

/// One sample of an integrated run.
struct TopSample {
  double t = 0.0;
  double theta = 0.0;         ///< rad
  double energy_error = 0.0;  ///< |E - E0| / (T0 + mgl)
  Eigen::Vector3d omega_body = Eigen::Vector3d::Zero();
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();  ///< unit
  /// Signed errors of the three invariants: (E - E0) / (T0 + mgl), (p_phi - p_phi0) / |L0|,
  /// (p_psi - p_psi0) / |L0|.
  Eigen::Vector3d invariant_errors = Eigen::Vector3d::Zero();
};

/// The samples of one run and the drift of its invariants.
struct TopRun {
  Method method = Method::kDopri5;
  std::vector<TopSample> samples;
  double energy_drift_rel = 0.0;  ///< max |E - E0| / (T0 + mgl)
  double p_phi_drift_rel = 0.0;   ///< max |p_phi - p_phi0| / |L0|
  double p_psi_drift_rel = 0.0;   ///< max |p_psi - p_psi0| / |L0|
  std::size_t steps = 0;
  std::size_t evaluations = 0;  ///< right-hand-side evaluations (ode.h's evaluations_per_step)
};

/// Integrates from x0 at times.front(), sampling at `times`. Throws like
/// integrate_sampled (ode.h) for bad options, and std::invalid_argument for a bad top.
TopRun integrate_heavy_top(const HeavyTop& top, const FreeBodyState& x0,
                           const std::vector<double>& times, const OdeOptions& options);

/// The exact motion sampled at `times` as a run of its own (no steps), its
/// invariants measured as an integrator's are: roundoff only.
TopRun sample_exact(const HeavyTopExact& exact, const std::vector<double>& times);

/// One method's run measured against the exact motion, sample by sample.
struct TopComparison {
  OdeOptions options;                ///< the method and the settings it ran with
  bool completed = false;            ///< false: it would have needed more than max_steps
  std::vector<double> t;             ///< its sample times (a fixed step's on its own grid)
  std::vector<double> theta_error;   ///< |theta - theta_exact|, rad
  std::vector<double> energy_error;  ///< |E - E0| / (T0 + mgl)
  double max_theta_error = 0.0;      ///< rad; infinite if the run blew up
  std::size_t evaluations = 0;       ///< right-hand-side evaluations of the run
  InvariantError energy;             ///< E's largest error and drift per period
};

/// Every method of kAllMethods at `options` with at most `max_steps` steps against the
/// exact motion from 0 to times.back(): adaptive methods at `times`, fixed-step ones on
/// their step grid, `period` / 200 apart (sample_times), as each would run alone.
std::vector<TopComparison> compare_top_methods(const HeavyTopExact& exact,
                                               const std::vector<double>& times, double period,
                                               const OdeOptions& options, std::size_t max_steps);

/// Every method at the same cost (compare_methods_at_cost in integrate.h, for the top):
/// `evaluations_per_period` evaluations a period over `periods` nutation periods.
std::vector<TopComparison> compare_top_methods_at_cost(const HeavyTopExact& exact, double period,
                                                       double periods,
                                                       double evaluations_per_period,
                                                       double samples_per_period = 8.0);

}  // namespace rigid
