// The tennis racquet theorem (section 4.1, eqs. 83-103; Barger & Olsson's model
// of Figure 5): a spin about the axis of the largest or the smallest principal
// moment is stable, about the intermediate one it is not.
//
// Conventions. The model racquet is a thin ring (the head, mass m_a, radius a)
// and a thin rod (the handle, mass m_l, length l) attached at the rim, both in
// one plane. Body axes, with the origin at the centre of mass: 1 along the
// handle (pointing from the head to the handle's end), 2 in the racquet's
// plane, 3 normal to it. The head's centre lies at -R along 1 (eq. 83). For
// this model I1 < I2 < I3 = I1 + I2 always: 2 is the intermediate axis.
//
// Euler's equations with no torque (eqs. 86-88) are written
//   omega_i_dot = c_i omega_j omega_k   for (i, j, k) = (1, 2, 3) cyclically,
// c_1 = (I2 - I3)/I1, c_2 = (I3 - I1)/I2, c_3 = (I1 - I2)/I3. A spin Omega about
// axis i, disturbed, obeys omega_j_ddot = c_j c_k Omega^2 omega_j to first order:
// it grows as exp(Omega sqrt(c_j c_k) t) when c_j c_k > 0 and wobbles at
// Omega sqrt(-c_j c_k) when c_j c_k < 0. The text's simplified equations
// (eqs. 89-92, the lamina's I3 = I1 + I2 and (I2 - I1)/(I2 + I1) set to 1) are
// c = (-1, 1, -1): every rate is the spin itself.
#pragma once

#include <Eigen/Core>
#include <cstddef>

#include "rigid/free_body.h"
#include "rigid/free_body_exact.h"
#include "rigid/inertia.h"

namespace rigid {

/// The model of Figure 5, with the text's numbers.
struct RacquetModel {
  double head_mass = 0.15;      ///< m_a, kg (the ring)
  double head_radius = 0.13;    ///< a, m
  double handle_mass = 0.18;    ///< m_l, kg (the rod)
  double handle_length = 0.38;  ///< l, m
};

/// The racquet as a rigid body, in the body axes of the header comment.
struct Racquet {
  Body body;                 ///< mass, centre of mass (the origin) and tensor about it
  double cm_offset = 0.0;    ///< R, centre of mass from the head's centre along 1, m (eq. 83)
  PrincipalMoments moments;  ///< I1 (handle), I2 (in the plane), I3 (normal), kg m^2 (eqs. 84-85)
  Eigen::Vector3d head_centre = Eigen::Vector3d::Zero();   ///< (-R, 0, 0), m
  Eigen::Vector3d handle_start = Eigen::Vector3d::Zero();  ///< where the handle meets the rim, m
  Eigen::Vector3d handle_end = Eigen::Vector3d::Zero();    ///< the handle's far end, m
};

/// Builds the racquet from core's thin ring and thin rod and the parallel-axis
/// theorem. Throws std::invalid_argument unless every input is positive and finite.
Racquet make_racquet(const RacquetModel& model);

/// The coefficients c_i of omega_i_dot = c_i omega_j omega_k.
struct EulerCoefficients {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
};

/// c_i from the moments: Euler's equations in full (eqs. 86-88).
EulerCoefficients euler_coefficients(const PrincipalMoments& I);
/// c_i of the text's simplified racquet equations (eqs. 89-92): (I3 - I2)/I1 and
/// (I3 - I1)/I2 are 1 for a lamina, and (I2 - I1)/(I2 + I1) is taken as 1.
EulerCoefficients simplified_racquet_coefficients();

/// The first-order fate of a disturbed spin about one principal axis.
struct SpinStability {
  bool unstable = false;
  /// Unstable: the growth rate of the disturbance, 1/s. Stable: the angular frequency
  /// at which omega's transverse part goes round, rad/s (0 for a neutral spin).
  double rate = 0.0;
  /// The disturbance's shape: |omega_j| / |omega_k| in its mode, for the axes j, k
  /// after `axis` in cyclic order, sqrt(|c_j / c_k|) (1: a circle, as eqs. 96-97 draw it).
  double axis_ratio = 1.0;
};

/// The linear prediction for a spin `spin` (rad/s) about axis `axis` (0, 1, 2).
SpinStability linear_stability(const EulerCoefficients& c, int axis, double spin);

/// omega at launch: |omega| = spin, its transverse share `perturbation` (in [0, 1))
/// along the next axis in cyclic order (1 -> 2 -> 3 -> 1), the rest along `axis`.
Eigen::Vector3d launch_omega(int axis, double spin, double perturbation);

/// |omega - (omega . e_axis) e_axis| / |omega|: the transverse share of omega.
double transverse_share(const Eigen::Vector3d& omega_body, int axis);

/// A growth rate measured from the exact motion.
struct GrowthFit {
  double rate = 0.0;     ///< 1/s
  double t_begin = 0.0;  ///< the fitted interval, s
  double t_end = 0.0;
  double share_begin = 0.0;  ///< the transverse share at its ends
  double share_end = 0.0;
  double rms_residual = 0.0;  ///< of the fit, relative to the largest fitted value
  std::size_t samples = 0;
};

/// Measures the growth rate of a disturbed spin about the unstable axis `axis`
/// from the exact motion: each transverse component is fitted, by least squares
/// with one shared rate, to A e^{lambda t} + B e^{-lambda t} (the linear
/// solution, eqs. 100-103) from launch to the first time the transverse share
/// reaches `share_limit` (in (share at launch, 1)). The fit's error against the
/// linear rate is of order share_limit^2, the nonlinear terms dropped.
/// Throws std::invalid_argument if the share never reaches share_limit before
/// omega_axis first changes sign or the motion has no finite period.
GrowthFit measure_growth_rate(const FreeBodyExact& motion, int axis, double share_limit,
                              std::size_t samples = 400);

/// The first time after t = 0 at which omega_body(axis) changes sign (a flip of the
/// racquet), by bisection on the exact motion within the first half-period;
/// +inf if it keeps its sign (a stable spin, a steady rotation).
double first_sign_change(const FreeBodyExact& motion, int axis);

/// The smallest and largest L_axis / |L| over [0, t_span]: the direction cosine of
/// a body axis with the fixed L, sampled from the exact motion and refined by
/// Brent's method at the extremes.
struct CosineRange {
  double min = 0.0, max = 0.0;
};
CosineRange direction_cosine_range(const FreeBodyExact& motion, int axis, double t_span);

}  // namespace rigid
