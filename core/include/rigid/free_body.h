// A rigid body rotating about its centre of mass: Euler's equations (section 3,
// eq. 73) for the body-frame angular velocity, with the attitude carried as a
// unit quaternion.
//
// Conventions:
//  - Body axes are the principal axes, with principal moments I1, I2, I3 in any
//    order (they need not be sorted).
//  - The attitude q maps body to space: L_space = q * L_body. Its kinematics is
//    q_dot = 1/2 q (x) (0, omega_body).
//  - Euler's equations with a body-frame torque N (eq. 73):
//      I1 w1_dot = N1 - w2 w3 (I3 - I2), and cyclically.
//  - The fixed-size state is rotation.h's RotationState (w1, w2, w3, qw, qx, qy, qz), SI units.
#pragma once

#include <Eigen/Geometry>

#include "rigid/rotation.h"

namespace rigid {

/// Principal moments of inertia I1, I2, I3 about the centre of mass, kg m^2.
struct PrincipalMoments {
  double I1 = 1.0;
  double I2 = 1.0;
  double I3 = 1.0;

  /// The moments as a vector (I1, I2, I3).
  Eigen::Vector3d vector() const { return {I1, I2, I3}; }
};

/// Which moments are accepted. A rigid body must satisfy the triangle
/// inequality; some classic test problems do not (Hairer, Lubich & Wanner's
/// free body I = (2, 1, 2/3) has I2 + I3 < I1), and the equations and the
/// closed form only need positive moments.
enum class MomentsRule {
  kPhysical,      ///< positive, finite, I_i + I_j >= I_k for every order
  kPositiveOnly,  ///< positive and finite: Euler's equations as a test problem
};

/// Throws std::invalid_argument naming the rule and the values unless every
/// moment is positive and finite and (kPhysical) I_i + I_j >= I_k for every
/// order, to a relative tolerance of a few ulps so a lamina with I3 = I1 + I2 passes.
void validate(const PrincipalMoments& I, MomentsRule rule = MomentsRule::kPhysical);

/// Right-hand side of Euler's equations (eq. 73) with a constant body-frame
/// torque, and the quaternion kinematics; an odeint system functor.
struct EulerRhs {
  PrincipalMoments I;
  Eigen::Vector3d torque_body = Eigen::Vector3d::Zero();

  void operator()(const RotationState& x, RotationState& dxdt, double /*t*/) const {
    const double w1 = x[0], w2 = x[1], w3 = x[2];
    // eq. 73 solved for omega_dot
    dxdt[0] = (torque_body.x() - w2 * w3 * (I.I3 - I.I2)) / I.I1;
    dxdt[1] = (torque_body.y() - w3 * w1 * (I.I1 - I.I3)) / I.I2;
    dxdt[2] = (torque_body.z() - w1 * w2 * (I.I2 - I.I1)) / I.I3;
    // q_dot = 1/2 q (x) (0, omega_body)
    const double qw = x[3], qx = x[4], qy = x[5], qz = x[6];
    dxdt[3] = 0.5 * (-qx * w1 - qy * w2 - qz * w3);
    dxdt[4] = 0.5 * (qw * w1 + qy * w3 - qz * w2);
    dxdt[5] = 0.5 * (qw * w2 + qz * w1 - qx * w3);
    dxdt[6] = 0.5 * (qw * w3 + qx * w2 - qy * w1);
  }
};

/// Body-frame angular momentum L_body = (I1 w1, I2 w2, I3 w3), kg m^2/s.
Eigen::Vector3d L_body(const PrincipalMoments& I, const Eigen::Vector3d& omega_body);
/// Space-frame angular momentum L_space = q * L_body (q is normalised first).
Eigen::Vector3d L_space(const PrincipalMoments& I, const RotationState& x);
/// Rotational kinetic energy 1/2 (I1 w1^2 + I2 w2^2 + I3 w3^2) (eq. 81), J.
double kinetic_energy(const PrincipalMoments& I, const Eigen::Vector3d& omega_body);
/// |L| = sqrt(I1^2 w1^2 + I2^2 w2^2 + I3^2 w3^2) (eq. 79), kg m^2/s.
double angular_momentum_magnitude(const PrincipalMoments& I, const Eigen::Vector3d& omega_body);

}  // namespace rigid
