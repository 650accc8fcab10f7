// Poinsot's construction for a torque-free body (sections 4 and 4.1): in body
// axes omega lies on the energy ellipsoid sum I_i w_i^2 = 2T (eq. 81, semi-axes
// sqrt(2T/I_i), ratios 1/sqrt(I_i), eq. 82) and on the momentum ellipsoid
// sum I_i^2 w_i^2 = L^2 (eq. 79, semi-axes L/I_i, ratios 1/I_i, eq. 80); their
// intersection is the polhode. Moments may come in any order.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "rigid/free_body.h"
#include "rigid/free_body_exact.h"

namespace rigid {

/// Semi-axes of the two ellipsoids through omega_body, rad/s.
struct PoinsotEllipsoids {
  Eigen::Vector3d energy_semi_axes;    ///< sqrt(2T / I_i)
  Eigen::Vector3d momentum_semi_axes;  ///< |L| / I_i
};

/// The energy and momentum ellipsoids on which omega_body moves.
PoinsotEllipsoids poinsot_ellipsoids(const PrincipalMoments& I, const Eigen::Vector3d& omega_body);

/// Axis ratios 1/I_i of the momentum ellipsoid for moments given in any units (eq. 80).
Eigen::Vector3d momentum_ellipsoid_ratios(const Eigen::Vector3d& moments);
/// Axis ratios 1/sqrt(I_i) of the energy ellipsoid (eq. 82).
Eigen::Vector3d energy_ellipsoid_ratios(const Eigen::Vector3d& moments);
/// The momentum ratios scaled so that both ellipsoids touch on axis j (0, 1 or 2),
/// as for a spin about that axis (section 4.1).
Eigen::Vector3d momentum_ratios_touching(const Eigen::Vector3d& moments, int j);

/// The polhode through omega0_body as curves of `samples` points: one period of
/// omega_body(t) from the exact solution; on the separatrix, its two ellipses;
/// none for a steady rotation, whose polhode is the single point omega0_body.
std::vector<std::vector<Eigen::Vector3d>> polhode(const PrincipalMoments& I,
                                                  const Eigen::Vector3d& omega0_body, int samples);

/// The herpolhode (Poinsot's construction): omega in space over [0, t_end] at `samples`
/// times, each the point where the energy ellipsoid, turning with the body about the
/// fixed point, touches the invariable plane (normal to L, at distance 2T/|L| from the
/// point). In the motion's space frame (the attitude's), rad/s.
std::vector<Eigen::Vector3d> herpolhode(const FreeBodyExact& motion, double t_end, int samples);

/// The angle, rad, that the contact point turns about L in one polhode period (unwrapped:
/// a full turn and more counts as such): the herpolhode closes only if this is a rational
/// multiple of 2 pi, so in general it never does. NaN without a polhode period.
double herpolhode_turn_per_period(const FreeBodyExact& motion);

/// omega_body on the energy ellipsoid of energy T with |L|^2 = L2, chosen where
/// the intermediate component is zero; L2 must lie in [2 T I_min, 2 T I_max].
Eigen::Vector3d omega_on_energy_ellipsoid(const PrincipalMoments& I, double T, double L2);

/// The two separatrix ellipses on the energy ellipsoid of energy T (through the
/// intermediate axis, L^2 = 2 T I_mid), each `samples` points; empty if two
/// moments are equal.
std::vector<std::vector<Eigen::Vector3d>> separatrices(const PrincipalMoments& I, double T,
                                                       int samples);

}  // namespace rigid
