// Section 7, "Mr. Euler, Meet Mr. Lagrange", made concrete: the kinetic energy as a
// function of the Euler angles and their rates, T = 1/2 sum I_i omega_i^2 (eq. 150,
// with the 1/2 its print lacks), and each angle's Euler-Lagrange equation, d/dt
// dT/dq_dot - dT/dq = Q (eq. 151 for psi; Q the torque's generalized force, section
// 7.2), evaluated at a state of a motion in two ways:
//  - exactly but for rounding: dT/dq by the chain rule through omega (eqs. 152-156),
//    dT/dq_dot = L . (the axis of rate q), and its rate with omega_dot from Euler's
//    equations (eq. 163) and the angles' rates by the chain rule, all by forward-mode
//    automatic differentiation, each carrying a running bound on its rounding error.
//    A true motion's residual is 0: it comes out within that bound.
//  - by differences along the motion, which checks the motion itself: each derivative
//    by central differences at steps h, 2h and 4h, Richardson's combination of the
//    first two as the value and its distance from the next one's as its error.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <optional>
#include <vector>

#include "rigid/free_body.h"
#include "rigid/rotation.h"

namespace rigid {

/// T = 1/2 (I1 omega_1^2 + I2 omega_2^2 + I3 omega_3^2) with omega in the body from the
/// Euler angles and rates (eqs. 134-136, 150).
double euler_kinetic_energy(const PrincipalMoments& I, const EulerAngles& e, const EulerRates& r);

/// The Euler angles and their rates at a time: the angles continuous in time (not
/// wrapped), as differences in time need them.
struct EulerState {
  EulerAngles angles;
  EulerRates rates;
};

/// The Euler state of a body at `attitude` turning at `omega_body`: the angles with phi
/// and psi by whole turns nearest `near`'s (continuous along a motion), the rates by
/// eqs. 134-136 inverted; none at a pole, where the rates are undefined.
std::optional<EulerState> euler_state(const Eigen::Quaterniond& attitude,
                                      const Eigen::Vector3d& omega_body, const EulerAngles& near);

/// The axes the three rates turn about, in the body: columns z, x' and 3, that is
/// d omega / d(phi_dot, theta_dot, psi_dot) (eqs. 131-133). omega is linear in the rates,
/// so dT/dq_dot_k = L . column k exactly (eqs. 152-156's chain rule).
Eigen::Matrix3d rate_axes_in_body(const EulerAngles& e);

/// A body-frame torque's generalized forces on the angles, Q_k = N . (axis of rate k): the
/// torque's virtual work N . (z dphi + x' dtheta + 3 dpsi), which each angle's Lagrange
/// equation with torque gains (eqs. 163-166 in Lagrange's form).
Eigen::Vector3d generalized_force(const EulerAngles& e, const Eigen::Vector3d& torque_body);

/// A value and a bound on (exact terms) or an estimate of (differences) its error.
struct Measured {
  double value = 0.0;
  double error = 0.0;
};

/// Each angle's terms of its Euler-Lagrange equation at one time, in the order phi,
/// theta, psi: dT/dq, the momentum dT/dq_dot, its rate d/dt dT/dq_dot, the torque's
/// generalized force Q and the residual d/dt dT/dq_dot - dT/dq - Q, each with its error.
/// Units: dT/dq, the rate, Q and the residual N m; the momentum kg m^2/s.
struct LagrangeTerms {
  Measured dT_dq[3];
  Measured momentum[3];
  Measured momentum_rate[3];
  Measured force[3];
  Measured residual[3];
};

/// The terms at the state (angles `e`, `omega_body`) of a body under the body-frame
/// torque `torque_body`, exact but for rounding, each with a running bound on its
/// rounding error (the inputs taken as exact; `sin_theta`, where given, replaces
/// sin(e.theta) and is taken as within 2 eps of sin of the theta meant, as a sine
/// from degrees is). None at a pole, where phi_dot and psi_dot are undefined (as
/// rates_from_body_omega says), or where a term overflows. Near a pole theta's terms
/// grow as 1/sin(theta) and cancel: their bound grows with them, phi's and psi's stay
/// the size of L omega times eps.
std::optional<LagrangeTerms> lagrange_terms_exact(
    const PrincipalMoments& I, const EulerAngles& e, const Eigen::Vector3d& omega_body,
    const Eigen::Vector3d& torque_body = Eigen::Vector3d::Zero(),
    std::optional<double> sin_theta = std::nullopt);
/// The same at the state given by the angles and their rates (omega by eqs. 134-136):
/// defined at a pole too, where the terms need only the rates (phi's and psi's equations
/// are then one, their axes z and 3 the same); none where a term overflows.
std::optional<LagrangeTerms> lagrange_terms_exact(
    const PrincipalMoments& I, const EulerAngles& e, const EulerRates& rates,
    const Eigen::Vector3d& torque_body = Eigen::Vector3d::Zero(),
    std::optional<double> sin_theta = std::nullopt);

/// psi's terms, defined at a pole too, each with a bound on its rounding:
/// dT/dpsi_dot = I3 omega_3 (eqs. 153, 156) and dT/dpsi = I1 omega_1 omega_2 + I2
/// omega_2 (-omega_1) (eq. 157: d omega_1/dpsi = omega_2, d omega_2/dpsi = -omega_1 by
/// eqs. 154-155).
struct PsiTerms {
  Measured momentum;  ///< kg m^2/s
  Measured force;     ///< N m
};
PsiTerms psi_terms(const PrincipalMoments& I, const Eigen::Vector3d& omega_body);

/// The steps the terms take at a state of the motion, and the noise of the motion's
/// values. Near a pole (theta -> 0 or pi) phi and psi turn about nearly one axis, their
/// rates grow as 1/sin(theta) and the angles read from an attitude lose digits as
/// eps/sin(theta): the steps shrink to keep the differences away from the pole and the
/// stated error takes the lost digits.
struct LagrangeSteps {
  double angle = 0.0;  ///< rad, for dT/dq
  double time = 0.0;   ///< s, for d/dt
  /// The relative error of the attitude `at` gives (64 eps for a closed form or one run of
  /// an integrator through the sample times: smooth errors cancel in the differences).
  double noise = 0.0;
};

/// The steps at state s of a motion of time scale `time_scale` (a period): 1e-3 rad and
/// 1e-4 of the time scale, cut to a 16th of sin(theta) and of the time omega takes to
/// turn by it; the noise 64 eps / sin(theta). None at a pole (the rates undefined).
std::optional<LagrangeSteps> lagrange_steps(const EulerState& s, double time_scale);

/// The times at which lagrange_terms evaluates the motion for time step h: t and t +- h,
/// 2h, 4h, sorted (an integrator can be run through exactly these).
std::vector<double> lagrange_times(double t, double h);

/// A derivative by central differences of f at steps h, 2h and 4h (f takes the offset):
/// Richardson's value (error h^4) with, as its error, its distance from the value steps 2h
/// and 4h give (15 times the asymptotic estimate), plus f's noise `noise` (absolute)
/// magnified by 1.5 / h.
Measured central_derivative(const std::function<double(double)>& f, double h, double noise);

/// The terms at time t of the motion `at` (t -> its EulerState, none where the rates are
/// undefined) under the body-frame torque `torque_body`, with `steps` from
/// lagrange_steps: dT/dq by differences in q (the rates held), the momentum by the chain
/// rule (exact: omega is linear in the rates), its rate by differences in time along the
/// motion, Q exact. None if `at` gives none at a time the differences need.
std::optional<LagrangeTerms> lagrange_terms(
    const PrincipalMoments& I, const std::function<std::optional<EulerState>(double)>& at, double t,
    const LagrangeSteps& steps, const Eigen::Vector3d& torque_body = Eigen::Vector3d::Zero());

}  // namespace rigid
