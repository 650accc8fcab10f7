#include "rigid/rotation.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "rigid/units.h"

namespace rigid {

namespace {

// Wraps an angle into (-pi, pi].
double wrap_pi(double a) {
  a = std::remainder(a, 2.0 * kPi);
  return a <= -kPi ? a + 2.0 * kPi : a;
}
}  // namespace

EulerAngles euler_zxz(const Eigen::Quaterniond& q) {
  // q = Rz(phi) Rx(theta) Rz(psi) has, with half angles,
  //   w = cos(theta/2) cos((phi+psi)/2),  z = cos(theta/2) sin((phi+psi)/2),
  //   x = sin(theta/2) cos((phi-psi)/2),  y = sin(theta/2) sin((phi-psi)/2),
  // so theta comes from atan2 (accurate near 0 and pi, unlike acos of eq. 122's lambda_33).
  const double c = std::hypot(q.w(), q.z());
  const double s = std::hypot(q.x(), q.y());
  EulerAngles e;
  e.theta = 2.0 * std::atan2(s, c);
  // Within roundoff of theta = 0 or pi one of phi +- psi is noise: report it as psi = 0.
  constexpr double kTiny = 4.0 * std::numeric_limits<double>::epsilon();
  if (s <= kTiny * c) {  // theta = 0: only phi + psi is defined
    e.phi = wrap_pi(2.0 * std::atan2(q.z(), q.w()));
    e.psi = 0.0;
  } else if (c <= kTiny * s) {  // theta = pi: only phi - psi is defined
    e.phi = wrap_pi(2.0 * std::atan2(q.y(), q.x()));
    e.psi = 0.0;
  } else {
    const double sum = 2.0 * std::atan2(q.z(), q.w());
    const double diff = 2.0 * std::atan2(q.y(), q.x());
    e.phi = wrap_pi(0.5 * (sum + diff));
    e.psi = wrap_pi(0.5 * (sum - diff));
  }
  return e;
}

Eigen::Quaterniond quaternion_from_euler_zxz(const EulerAngles& e) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ(), x = Eigen::Vector3d::UnitX();
  return axis_angle(z, e.phi) * axis_angle(x, e.theta) * axis_angle(z, e.psi);
}

Eigen::Matrix3d space_to_body_matrix(const EulerAngles& e) {
  const double cf = std::cos(e.phi), sf = std::sin(e.phi);
  const double ct = std::cos(e.theta), st = std::sin(e.theta);
  const double cp = std::cos(e.psi), sp = std::sin(e.psi);
  Eigen::Matrix3d lambda;                                             // eq. 122
  lambda << cf * cp - sf * ct * sp, sf * cp + cf * ct * sp, st * sp,  //
      -cf * sp - sf * ct * cp, -sf * sp + cf * ct * cp, st * cp,      //
      sf * st, -cf * st, ct;
  return lambda;
}

Eigen::Vector3d omega_intermediate(const EulerAngles& e, const EulerRates& r,
                                   std::optional<double> sin_theta) {
  return {r.theta_dot, r.phi_dot * sin_theta.value_or(std::sin(e.theta)),  // eqs. 128-130
          r.phi_dot * std::cos(e.theta) + r.psi_dot};
}

Eigen::Vector3d omega_in_body(const EulerAngles& e, const EulerRates& r,
                              std::optional<double> sin_theta) {
  // cos(theta) is flat near the poles, so the rounded theta gives it to roundoff.
  const double st = sin_theta ? *sin_theta : std::sin(e.theta), ct = std::cos(e.theta);
  const double sp = std::sin(e.psi), cp = std::cos(e.psi);
  return {r.phi_dot * st * sp + r.theta_dot * cp,  // eqs. 134-136
          r.phi_dot * st * cp - r.theta_dot * sp, r.phi_dot * ct + r.psi_dot};
}

Eigen::Vector3d omega_in_space(const EulerAngles& e, const EulerRates& r,
                               std::optional<double> sin_theta) {
  // z along z, the line of nodes (cos phi, sin phi, 0), the body's 3 (eq. 122's third
  // row) (sin theta sin phi, -sin theta cos phi, cos theta)
  const double cf = std::cos(e.phi), sf = std::sin(e.phi);
  const double st = sin_theta.value_or(std::sin(e.theta)), ct = std::cos(e.theta);
  return {r.theta_dot * cf + r.psi_dot * st * sf, r.theta_dot * sf - r.psi_dot * st * cf,
          r.phi_dot + r.psi_dot * ct};
}

Eigen::Vector3d omega_in_space_as_printed(const EulerAngles& e, const EulerRates& r,
                                          std::optional<double> sin_theta) {
  const double st = sin_theta.value_or(std::sin(e.theta));
  return {r.theta_dot * std::cos(e.psi) - r.psi_dot * st * std::cos(e.phi),  // eq. 137
          r.theta_dot * std::sin(e.psi) - r.psi_dot * st * std::sin(e.phi),  // eq. 138
          r.phi_dot + r.psi_dot * std::cos(e.theta)};                        // eq. 139
}

std::optional<EulerRates> rates_from_body_omega(const EulerAngles& e, const Eigen::Vector3d& w,
                                                std::optional<double> sin_theta) {
  // A theta within its own rounding (2 ulps) of a pole is the pole: the double nearest
  // pi has sin 1.2e-16, which would make phi_dot 1e16 times omega where theta meant,
  // and all the input can tell, has it undefined. A sin(theta) given exactly is the
  // pole only where it is 0.
  const double st = sin_theta.value_or(std::sin(e.theta));
  const double ulp = std::nextafter(std::abs(e.theta), HUGE_VAL) - std::abs(e.theta);
  if (sin_theta ? st == 0.0 : std::abs(st) <= 2.0 * ulp) return std::nullopt;
  const double sp = std::sin(e.psi), cp = std::cos(e.psi);
  EulerRates r;
  r.theta_dot = w(0) * cp - w(1) * sp;
  r.phi_dot = (w(0) * sp + w(1) * cp) / st;
  r.psi_dot = w(2) - r.phi_dot * std::cos(e.theta);
  // a theta so near a pole that phi_dot overflows is one too
  if (!std::isfinite(r.phi_dot) || !std::isfinite(r.psi_dot)) return std::nullopt;
  return r;
}

Eigen::Quaterniond axis_angle(const Eigen::Vector3d& axis, double angle) {
  const double h = 0.5 * angle;
  const double s = std::sin(h);
  return Eigen::Quaterniond(std::cos(h), s * axis.x(), s * axis.y(), s * axis.z());
}

double attitude_distance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  // angle of a^-1 b from its quaternion, sign-blind; atan2 keeps small angles accurate
  const Eigen::Quaterniond d = a.normalized().conjugate() * b.normalized();
  return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

RotationState make_state(const Eigen::Vector3d& omega_body, const Eigen::Quaterniond& q) {
  return {omega_body.x(), omega_body.y(), omega_body.z(), q.w(), q.x(), q.y(), q.z()};
}

void validate_start(const RotationState& x0) {
  for (const double v : x0) {
    if (!std::isfinite(v)) throw std::invalid_argument("initial state must be finite");
  }
  if (!(attitude(x0).norm() > 0.0)) {
    throw std::invalid_argument("initial attitude quaternion must be nonzero");
  }
}

}  // namespace rigid
