#include "rigid/balancing.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rigid/units.h"

namespace rigid {

Body wheel_body(const CrookedWheel& wheel, double m0) {
  const double a = wheel.radius, b = wheel.offset;
  // The disk primitive lies in x-y; turn it into the y-z plane (symmetry axis x).
  Mat3 to_yz;
  to_yz << 0, 0, 1,  //
      0, 1, 0,       //
      -1, 0, 0;
  Body body = rotated(thin_disk(wheel.mass, a), to_yz);
  if (m0 > 0.0) {
    body = body + point_mass(m0, Vec3(-b, a, 0.0)) + point_mass(m0, Vec3(b, -a, 0.0));
  }
  return body;
}

Vec3 axle_direction(const CrookedWheel& wheel) {
  return Vec3(std::cos(wheel.tilt), std::sin(wheel.tilt), 0.0);
}

double balance_mass_exact(const CrookedWheel& wheel) {
  const double m = wheel.mass, a = wheel.radius, b = wheel.offset;
  const double t = std::tan(2.0 * wheel.tilt);
  // Eq. 60 is linear in m0: t (m a^2/4 + 2 m0 (a^2 - b^2)) = 4 a b m0.
  const double denominator = 4.0 * a * b - 2.0 * t * (a * a - b * b);
  if (t == 0.0) return 0.0;  // a straight axle: already balanced
  if (!(t > 0.0) || !(denominator > 0.0)) {
    throw std::invalid_argument(
        "no balancing mass reaches this tilt: need 4 a b > 2 (a^2 - b^2) tan 2 theta");
  }
  return t * m * a * a / 4.0 / denominator;
}

double balance_mass_small_angle(const CrookedWheel& wheel) {
  return wheel.tilt * wheel.radius * wheel.mass / (8.0 * wheel.offset);
}

Vec3 bearing_torque(const CrookedWheel& wheel, double m0, double omega) {
  const Body body = wheel_body(wheel, m0);
  return fixed_axis_torque(body.I_com, omega * axle_direction(wheel));
}

Vec3 angular_momentum_at(const CrookedWheel& wheel, double m0, double omega, double t) {
  const Vec3 axle = axle_direction(wheel);
  const Vec3 L_body = angular_momentum(wheel_body(wheel, m0).I_com, omega * axle);
  return Eigen::AngleAxisd(omega * t, axle) * L_body;
}

Vec3 bearing_torque_at(const CrookedWheel& wheel, double m0, double omega, double t) {
  // L turns rigidly at omega about the fixed axle, so dL/dt = (omega axle) x L
  return (omega * axle_direction(wheel)).cross(angular_momentum_at(wheel, m0, omega, t));
}

double principal_axis_misalignment(const CrookedWheel& wheel, double m0) {
  const PrincipalAxes principal = principal_axes(wheel_body(wheel, m0).I_com);
  const Vec3 axle = axle_direction(wheel);
  double best = kPi;
  for (int i = 0; i < 3; ++i) {
    // An axis is a line: the angle to it is at most 90 degrees.
    const Vec3 e = principal.axes.row(i).transpose();
    best = std::min(best, std::min(angle_between(e, axle), angle_between(-e, axle)));
  }
  return best;
}

}  // namespace rigid
