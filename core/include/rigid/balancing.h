// Dynamic balancing of a wheel with a crooked axle (chapter sections 2.2-2.3).
//
// The wheel is a uniform disk of mass m and radius a in the y-z plane, so its
// symmetry axis is x. Its axle lies in the x-y plane at the angle theta from x.
// Two equal masses m0 sit at (x, y) = (-b, a) and (b, -a); they tilt a principal
// axis toward the axle (eqs. 57-61), which balances the wheel dynamically.
#pragma once

#include "rigid/inertia.h"

namespace rigid {

/// Geometry of the crooked wheel; lengths in m, masses in kg, angle in rad.
struct CrookedWheel {
  double mass = 10.0;    ///< disk mass m
  double radius = 0.18;  ///< disk radius a
  double offset = 0.05;  ///< distance b of each balancing mass from the disk's plane
  double tilt = 0.0;     ///< angle theta between the axle and the symmetry axis
};

/// The disk and, if m0 > 0, its two balancing masses as one body.
Body wheel_body(const CrookedWheel& wheel, double m0);

/// Unit vector along the axle, in the wheel's frame: (cos theta, sin theta, 0).
Vec3 axle_direction(const CrookedWheel& wheel);

/// The m0 that puts a principal axis exactly on the axle, solving
/// tan 2 theta = 4 a b m0 / (m a^2/4 + 2 m0 (a^2 - b^2)) (eq. 60) for m0.
/// 0 for a straight axle (tilt 0, already balanced); throws std::invalid_argument
/// when no positive m0 reaches the tilt.
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

/// Angle between the axle and the principal axis nearest to it (rad).
double principal_axis_misalignment(const CrookedWheel& wheel, double m0);

}  // namespace rigid
