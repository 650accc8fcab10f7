// Dynamic balancing of a wheel with a crooked axle (chapter sections 2.2-2.3).
//
// The wheel is a uniform disk of mass m and radius a in the y-z plane, so its
// symmetry axis is x. Its axle lies in the x-y plane at the angle theta from x.
// Two equal masses m0 sit at (x, y) = (-b, a) and (b, -a); they tilt a principal
// axis toward the axle (eqs. 57-61), which balances the wheel dynamically.
//
// Eq. 60 solved for m0 is m0 = m a^2 sin(theta) cos(theta) / (8 (b cos theta - a sin theta)
// (a cos theta + b sin theta)): linear in theta as theta -> 0 (eq. 61), and unbounded as
// theta -> atan(b/a), the direction of the masses' own line, beyond which no mass reaches.
// Near that limit b cos theta - a sin theta cancels, and the angle a double holds in
// radians is too coarse: the tilt is taken from its degrees where given (tilt_deg, as a
// top's theta0 is), and eq. 60 and the misalignments are formed in quadruple precision.
#pragma once

#include <optional>

#include "rigid/inertia.h"

namespace rigid {

/// Geometry of the crooked wheel; lengths in m, masses in kg, angle in rad.
struct CrookedWheel {
  double mass = 10.0;    ///< disk mass m
  double radius = 0.18;  ///< disk radius a
  double offset = 0.05;  ///< distance b of each balancing mass from the disk's plane
  double tilt = 0.0;     ///< angle theta between the axle and the symmetry axis
  /// The tilt as given in degrees, where it was: eq. 60 then takes the angle meant, where
  /// `tilt` keeps it only to ulp(theta) (at the limit atan(b/a), too coarse for the gap).
  /// Taken only while `tilt` is deg_to_rad of it (quad_angle): change tilt, and tilt rules.
  std::optional<double> tilt_deg = std::nullopt;

  /// Sets tilt (deg_to_rad(deg)) and tilt_deg from an angle in degrees.
  void set_tilt_deg(double deg);
};

/// The disk and, if m0 > 0, its two balancing masses as one body.
Body wheel_body(const CrookedWheel& wheel, double m0);

/// Unit vector along the axle, in the wheel's frame: (cos theta, sin theta, 0).
Vec3 axle_direction(const CrookedWheel& wheel);

/// The m0 that puts a principal axis exactly on the axle, solving
/// tan 2 theta = 4 a b m0 / (m a^2/4 + 2 m0 (a^2 - b^2)) (eq. 60) for m0, to the last bit
/// from a tilt of 1e-300 deg to one an ulp short of atan(b/a). 0 for a straight axle
/// (tilt 0, already balanced); throws std::invalid_argument when no positive m0 reaches
/// the tilt (a tan theta >= b).
double balance_mass_exact(const CrookedWheel& wheel);

/// The small-angle estimate m0 = theta a m / (8 b) from theta ~ 8 b m0 / (a m) (eq. 61).
double balance_mass_small_angle(const CrookedWheel& wheel);

/// Torque the bearings supply to turn the wheel (with balancing masses m0) at
/// constant spin omega about the axle, in the wheel's frame (eqs. 74-76).
Vec3 bearing_torque(const CrookedWheel& wheel, double m0, double omega);

/// Angular momentum at time t of the wheel spinning at omega about its fixed
/// axle, in the frame the wheel had at t = 0: L sweeps a cone about the axle.
Vec3 angular_momentum_at(const CrookedWheel& wheel, double m0, double omega, double t);

/// Torque the bearings supply at time t, in the frame the wheel had at t = 0:
/// N(t) = dL/dt = omega axle x L(t), bearing_torque turned with the wheel (eqs. 74-76).
Vec3 bearing_torque_at(const CrookedWheel& wheel, double m0, double omega, double t);

/// |bearing_torque(wheel, m0, omega)| from eqs. 57-59 in closed form: omega^2 |Ixy cos 2 theta
/// - (Ixx - Iyy) sin 2 theta / 2|, formed so that it vanishes at eq. 60's m0 and a double m0
/// leaves the torque its last bit makes, not the roundoff of omega^2 |I|.
double bearing_torque_size(const CrookedWheel& wheel, double m0, double omega);

/// Angle between the axle and the principal axis nearest to it (rad) with masses m0, from
/// tan(2 phi - 2 theta) for the principal angle phi of eqs. 57-59: its numerator vanishes
/// where eq. 60 holds, so the few ulps by which a double m0 misses are resolved at any tilt.
double principal_axis_misalignment(const CrookedWheel& wheel, double m0);

/// The same for eq. 61's mass m0 = theta a m / (8 b) taken exactly, not as a double: about
/// theta^2 (a^2 - b^2) / (a b) for small tilts, which the mass's own rounding would hide.
double small_angle_misalignment(const CrookedWheel& wheel);

/// d phi / d ln m0, rad: how far the principal axis turns for a relative change of m0 (about
/// theta for a small tilt), so the misalignment that half an ulp of m0 makes is eps / 2 times it.
double misalignment_per_mass(const CrookedWheel& wheel, double m0);

}  // namespace rigid
