// Attitude helpers: unit quaternions (body to space) and the z-x-z Euler angles
// of section 6.
//
// The text's Euler angles (eqs. 121-122): rotate by phi about the space z axis,
// by theta about the line of nodes x', then by psi about the body 3 axis. The
// space-to-body matrix is lambda = lambda_psi lambda_theta lambda_phi (eq. 122),
// so the body-to-space quaternion is q = Rz(phi) Rx(theta) Rz(psi).
// Euler angles are for output only; attitude is always carried as a quaternion.
//
// The state of a turning body, RotationState, is what every integrated body
// (the free body, the heavy top) carries: omega in body axes and the attitude.
#pragma once

#include <Eigen/Geometry>
#include <array>

namespace rigid {

/// z-x-z Euler angles of section 6, rad: phi and psi in (-pi, pi], theta in [0, pi].
struct EulerAngles {
  double phi = 0.0;
  double theta = 0.0;
  double psi = 0.0;
};

/// The Euler angles of a body-to-space quaternion (need not be normalised).
/// At theta = 0 (or pi) only phi + psi (or phi - psi) is defined; psi is then 0.
EulerAngles euler_zxz(const Eigen::Quaterniond& q);
/// The body-to-space quaternion Rz(phi) Rx(theta) Rz(psi) of the Euler angles.
Eigen::Quaterniond quaternion_from_euler_zxz(const EulerAngles& e);
/// The space-to-body matrix lambda of eq. 122 for the Euler angles.
Eigen::Matrix3d space_to_body_matrix(const EulerAngles& e);

/// The unit quaternion of a rotation by `angle` rad about the unit `axis`.
Eigen::Quaterniond axis_angle(const Eigen::Vector3d& axis, double angle);

/// The angle between two attitudes, rad in [0, pi]; q and -q are the same attitude.
double attitude_distance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

/// The state of a turning rigid body (w1, w2, w3, qw, qx, qy, qz): omega_body in
/// rad/s, then the body-to-space quaternion. Fixed size, as the odeint steppers want.
using RotationState = std::array<double, 7>;

/// Packs omega_body and the attitude into a state.
RotationState make_state(const Eigen::Vector3d& omega_body, const Eigen::Quaterniond& q);
/// The angular velocity in body axes, rad/s.
inline Eigen::Vector3d omega_body(const RotationState& x) {
  return {x[0], x[1], x[2]};
}
/// The attitude quaternion (body to space), as stored (not renormalised).
inline Eigen::Quaterniond attitude(const RotationState& x) {
  return Eigen::Quaterniond(x[3], x[4], x[5], x[6]);
}
/// Throws std::invalid_argument unless every component of a starting state is
/// finite and its quaternion is nonzero.
void validate_start(const RotationState& x0);

}  // namespace rigid
