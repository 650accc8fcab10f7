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
#include <optional>

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

/// The rates of the Euler angles, rad/s.
struct EulerRates {
  double phi_dot = 0.0;
  double theta_dot = 0.0;
  double psi_dot = 0.0;
};

/// omega = phi_dot z + theta_dot x' + psi_dot 3 (eq. 124: phi_dot about the fixed z,
/// theta_dot about the line of nodes x', psi_dot about the body's 3) in the
/// intermediate frame x'y'z' (eqs. 128-130): (theta_dot, phi_dot sin(theta), phi_dot
/// cos(theta) + psi_dot). `sin_theta`, where given, replaces sin(e.theta), as below.
Eigen::Vector3d omega_intermediate(const EulerAngles& e, const EulerRates& r,
                                   std::optional<double> sin_theta = std::nullopt);
/// The same omega in the body frame 123 (eqs. 134-136). `sin_theta`, where given,
/// replaces sin(e.theta) (known more accurately than the rounded theta gives it near a
/// pole).
Eigen::Vector3d omega_in_body(const EulerAngles& e, const EulerRates& r,
                              std::optional<double> sin_theta = std::nullopt);
/// The same omega in the fixed frame xyz: eq. 139, omega_z = phi_dot + psi_dot
/// cos(theta), and eqs. 137-138 as they are (the text's print has psi and phi
/// swapped): omega_x = theta_dot cos(phi) + psi_dot sin(theta) sin(phi), omega_y =
/// theta_dot sin(phi) - psi_dot sin(theta) cos(phi). `sin_theta` as for omega_in_body.
Eigen::Vector3d omega_in_space(const EulerAngles& e, const EulerRates& r,
                               std::optional<double> sin_theta = std::nullopt);
/// Eqs. 137-139 as the text prints them, for its errata: omega_x = theta_dot cos(psi) -
/// psi_dot sin(theta) cos(phi), omega_y = theta_dot sin(psi) - psi_dot sin(theta)
/// sin(phi), omega_z = phi_dot + psi_dot cos(theta). `sin_theta` as for omega_in_body.
Eigen::Vector3d omega_in_space_as_printed(const EulerAngles& e, const EulerRates& r,
                                          std::optional<double> sin_theta = std::nullopt);
/// The rates from omega in the body frame, eqs. 134-136 inverted: theta_dot = w1 cos(psi)
/// - w2 sin(psi), phi_dot = (w1 sin(psi) + w2 cos(psi)) / sin(theta), psi_dot = w3 -
/// phi_dot cos(theta). At a pole (theta = 0 or pi, to its rounding: 2 ulps) phi and psi
/// turn about the same axis and only phi_dot + psi_dot (or phi_dot - psi_dot) is
/// defined: none then, as where phi_dot would overflow. `sin_theta`, where given,
/// replaces sin(e.theta) (known more accurately than the rounded theta gives it near a
/// pole: theta = 179.9999999999 deg in radians leaves sin(theta) 1e-4 off).
std::optional<EulerRates> rates_from_body_omega(const EulerAngles& e,
                                                const Eigen::Vector3d& omega_body,
                                                std::optional<double> sin_theta = std::nullopt);

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
