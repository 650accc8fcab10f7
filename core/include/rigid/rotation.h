// Attitude helpers: unit quaternions (body to space) and the z-x-z Euler angles
// of section 6.
//
// The text's Euler angles (eqs. 121-122): rotate by phi about the space z axis,
// by theta about the line of nodes x', then by psi about the body 3 axis. The
// space-to-body matrix is lambda = lambda_psi lambda_theta lambda_phi (eq. 122),
// so the body-to-space quaternion is q = Rz(phi) Rx(theta) Rz(psi).
// Euler angles are for output only; attitude is always carried as a quaternion.
#pragma once

#include <Eigen/Geometry>

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

}  // namespace rigid
