#include "rigid/balancing.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rigid/format.h"
#include "rigid/quad.h"
#include "rigid/units.h"

namespace rigid {
namespace {

// eq. 60's limit cancels b cos theta - a sin theta to the angle's last bits: in Quad
struct SinCos {
  Quad s, c;
};

// sin and cos of 0 <= x <= pi/2, to the last bit of a Quad.
SinCos sin_cos(const Quad& x) {
  return {sin(x), cos(x)};
}

// sin x - x cos x = x^3/3 - x^5/30 + ... = sum over k >= 1 of (-1)^(k+1) 2k x^(2k+1)/(2k+1)!,
// by its series: formed as a difference it would cancel to nothing as x -> 0.
Quad sin_minus_x_cos(const Quad& x) {
  const Quad x2 = x * x;
  Quad power = x, sum = 0;  // power: x^(2k+1) / (2k+1)!
  for (int k = 1; k <= 30; ++k) {
    power *= x2 / Quad((2 * k) * (2 * k + 1));
    sum += (k % 2 == 1 ? 1 : -1) * Quad(2 * k) * power;
  }
  return sum;
}

// The tilt as the wheel holds it (from its degrees where given), with its sine and cosine;
// refused outside [0, pi/2] (eq. 60 has no tilt beyond).
struct Tilt {
  Quad theta;
  SinCos sc;
};

Tilt tilt_of(const CrookedWheel& wheel) {
  const Quad theta = quad_angle(wheel.tilt, wheel.tilt_deg);
  if (!(theta >= 0 && theta <= boost::math::constants::half_pi<Quad>())) {
    throw std::invalid_argument("the tilt must lie in [0, 90] deg");
  }
  return {theta, sin_cos(theta)};
}

// Half the angle atan2(num, den), as a double: from the Quad ratio where it is small (a
// misalignment far below a double's range stays a ratio, not two underflows), else from
// both scaled to at most 1.
double half_angle(Quad num, Quad den) {
  const Quad size = num < 0 ? -num : num;
  if (den > 0 && size <= den) return 0.5 * std::atan(static_cast<double>(num / den));
  const Quad scale = size > (den < 0 ? -den : den) ? size : (den < 0 ? -den : den);
  return 0.5 * std::atan2(static_cast<double>(num / scale), static_cast<double>(den / scale));
}

// The principal axis nearest the axle: phi - theta is half of atan2(num, den), and the
// in-plane axes lie 90 deg apart (z, the third, is 90 deg from the axle).
double nearest_axis(double half) {
  return std::min(std::abs(half), 0.5 * kPi - std::abs(half));
}

// tan(2 phi - 2 theta) = num / den for masses m0: with x = Ixx - Iyy = m a^2/4 + 2 m0 (a^2 - b^2)
// and y = 2 Ixy = 4 a b m0 (eqs. 57-59), num = y cos 2 theta - x sin 2 theta and den = x cos 2
// theta + y sin 2 theta. The numerator is written as 4 m0 (b c - a s)(a c + b s) - m a^2 s c / 2,
// zero at eq. 60's m0.
Quad misalignment_numerator(const CrookedWheel& wheel, Quad m0, const SinCos& t) {
  const Quad a = wheel.radius, b = wheel.offset, m = wheel.mass;
  return 4 * m0 * (b * t.c - a * t.s) * (a * t.c + b * t.s) - m * a * a * t.s * t.c / 2;
}

Quad misalignment_denominator(const CrookedWheel& wheel, Quad m0, const SinCos& t) {
  const Quad a = wheel.radius, b = wheel.offset, m = wheel.mass;
  const Quad x = m * a * a / 4 + 2 * m0 * (a * a - b * b), y = 4 * a * b * m0;
  return x * (t.c * t.c - t.s * t.s) + 2 * y * t.s * t.c;
}

}  // namespace

void CrookedWheel::set_tilt_deg(double deg) {
  tilt = deg_to_rad(deg);
  tilt_deg = deg;
}

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
  const Tilt t = tilt_of(wheel);
  if (t.theta == 0) return 0.0;  // a straight axle: already balanced
  const Quad a = wheel.radius, b = wheel.offset, m = wheel.mass;
  const SinCos& sc = t.sc;
  // r sin(atan(b/a) - theta) with r = sqrt(a^2 + b^2): eq. 60's denominator, over cos 2 theta
  const Quad gap = b * sc.c - a * sc.s;
  if (!(gap > 0)) {
    throw std::invalid_argument(
        "no balancing mass reaches this tilt: need a tan theta < b (eq. 60: 4 a b > 2 (a^2 - "
        "b^2) tan 2 theta), got theta = " +
        format_number(rad_to_deg(wheel.tilt), 10) + " deg against atan(b/a) = " +
        format_number(rad_to_deg(std::atan2(wheel.offset, wheel.radius)), 10) + " deg");
  }
  return static_cast<double>(m * a * a * sc.s * sc.c / (8 * gap * (a * sc.c + b * sc.s)));
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
  const SinCos sc = tilt_of(wheel).sc;
  return nearest_axis(
      half_angle(misalignment_numerator(wheel, m0, sc), misalignment_denominator(wheel, m0, sc)));
}

double bearing_torque_size(const CrookedWheel& wheel, double m0, double omega) {
  // omega x I omega along z: omega^2 (Ixy (c^2 - s^2) - (Ixx - Iyy) s c) = omega^2 num / 2
  const Quad num = misalignment_numerator(wheel, m0, tilt_of(wheel).sc);
  return static_cast<double>(Quad(omega) * Quad(omega) * (num < 0 ? -num : num) / 2);
}

double small_angle_misalignment(const CrookedWheel& wheel) {
  const Tilt t = tilt_of(wheel);
  const Quad a = wheel.radius, b = wheel.offset, m = wheel.mass, theta = t.theta;
  const SinCos& sc = t.sc;
  // The numerator above with m0 = theta a m / (8 b), its terms in theta collected: (m a / 2)
  // (-a c (s - theta c) - a theta s^2 - theta s c (a^2 - b^2) / b); no term cancels another
  // but where the misalignment itself passes through 0.
  const Quad num = m * a / 2 *
                   (-a * sc.c * sin_minus_x_cos(theta) - a * theta * sc.s * sc.s -
                    theta * sc.s * sc.c * (a * a - b * b) / b);
  const Quad m0 = theta * a * m / (8 * b);
  return nearest_axis(half_angle(num, misalignment_denominator(wheel, m0, sc)));
}

double misalignment_per_mass(const CrookedWheel& wheel, double m0) {
  // phi = atan2(y, x) / 2 with x, y as above: d phi / d ln m0 = m0 (x y' - y x') / (2 (x^2 +
  // y^2)), and x y' - y x' = 4 a b m a^2 / 4 whatever m0.
  const Quad a = wheel.radius, b = wheel.offset, m = wheel.mass;
  const Quad x = m * a * a / 4 + 2 * Quad(m0) * (a * a - b * b), y = 4 * a * b * Quad(m0);
  return static_cast<double>(Quad(m0) * a * b * m * a * a / (2 * (x * x + y * y)));
}

}  // namespace rigid
