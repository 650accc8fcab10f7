// The heavy symmetric top integrated (the cross-check of heavy_top.h's exact
// motion, and the path for starts it does not cover): omega in body axes and
// the attitude quaternion, never Euler angles, so an upright top (theta = 0)
// is an ordinary point. Euler's equations about the pivot with the moments
// (I, I, Is) and the gravity torque N_body = -mgl e3 x (R^T z).
//
//  - rk4, dopri5, rkf78, bulirsch-stoer, vern*: through ode.h's one integration
//    layer on the fixed-size RotationState (w, q), as a problem of compare.h.
//  - splitting, splitting4: the exact flow of the free symmetric top composed
//    with gravity kicks (Strang, and Suzuki's fourth-order composition). Each
//    piece is a rotation of L or of the attitude, and a kick changes L by a
//    torque normal to both z and 3: p_phi = L_z and p_psi = L_3 are kept to
//    roundoff, the energy without drift (the method is symplectic).
#pragma once

#include <cstddef>
#include <vector>

#include "rigid/compare.h"
#include "rigid/heavy_top.h"
#include "rigid/rotation.h"

namespace rigid {

/// Right-hand side of the heavy top: Euler's equations with the gravity torque
/// and the quaternion kinematics; an odeint system functor on RotationState.
/// The coefficients are formed once, so an evaluation costs one division.
class HeavyTopRhs {
 public:
  explicit HeavyTopRhs(const HeavyTop& top)
      : mgl_over_I_(top.mgl / top.I), spin_coupling_((top.Is - top.I) / top.I) {}
  void operator()(const RotationState& x, RotationState& dxdt, double /*t*/) const {
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
RotationState heavy_top_state(const TopAngles& angles);

/// theta, the tilt of the symmetry axis from z, of an attitude (exact at theta = 0).
double tilt_of(const Eigen::Quaterniond& q);

/// The heavy top as a problem for compare.h.
class HeavyTopProblem {
 public:
  using State = RotationState;
  using Exact = HeavyTopExact;
  /// The invariants, in the order of a run's errors: (E - E0) / (T0 + mgl),
  /// (p_phi - p_phi0) / |L0| and (p_psi - p_psi0) / |L0|.
  enum Invariant : std::size_t { kEnergy, kPPhi, kPPsi };
  static constexpr std::size_t kInvariantCount = 3;
  using Sample = RunSample<State, kInvariantCount>;

  /// The top's moments and gravity.
  explicit HeavyTopProblem(const HeavyTop& top) : top_(top) {}
  /// The top.
  const HeavyTop& top() const { return top_; }

  /// Throws std::invalid_argument for a bad top, or a start that is not finite or
  /// has a zero quaternion.
  void validate(const State& x0) const;
  /// Euler's equations with the gravity torque, and the quaternion kinematics.
  HeavyTopRhs rhs() const { return HeavyTopRhs(top_); }
  /// The signed errors of E, p_phi and p_psi against those of x0 (defined in the .cpp).
  class Invariants;
  Invariants invariants(const State& x0) const;
  /// The state as a sample keeps it: the quaternion normalised.
  State sampled(const State& x) const;
  /// The free symmetric top's exact flow and gravity kicks, order 2 or 4 (defined in the .cpp).
  class Splitting;
  Splitting splitting(int order, const State& x0) const;

  /// The exact motion's state at t.
  State exact_state(const Exact& exact, double t) const;
  /// Each sample's |theta - theta_exact| (rad) and |E - E0| / (T0 + mgl).
  ExactErrors errors_against(const Exact& exact, const std::vector<Sample>& samples) const;

 private:
  HeavyTop top_;
};

/// A run of the heavy top.
using HeavyTopRun = Run<HeavyTopProblem>;

extern template struct detail::ProblemCode<HeavyTopProblem>;

}  // namespace rigid
