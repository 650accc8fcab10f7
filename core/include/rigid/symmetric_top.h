// The free symmetric top (chapter sections "Analysis of a football" and 6.1,
// eqs. 104-115 and 142-149): a body with moments I about every transverse axis
// and Is about its symmetry axis 3, spinning with |omega| at angle alpha to 3.
//
// Conventions. Omega is signed as in eq. 109, Omega = omega_3 (Is - I) / I with
// omega_3 = omega cos alpha: seen in the body, omega turns about +3 at rate
// Omega (omega_1 = omega_0 cos(Omega t + a), omega_2 = omega_0 sin(Omega t + a),
// eqs. 114-115), counterclockwise looking down +3 when Omega > 0 (oblate,
// Is > I) and clockwise when Omega < 0 (prolate, Is < I). phi_dot = |L| / I > 0
// is the rate at which the symmetry axis and omega turn about L in space.
// omega, L and 3 lie in one plane (eq. 141); theta (L to 3, eq. 144) and
// alpha (omega to 3) are measured on the same side of 3.
#pragma once

#include <cstddef>
#include <string>

namespace rigid {

/// Which cone rolls on which, from the signed angle theta - alpha.
enum class ConeContact {
  kOutside,  ///< prolate (Is < I): the body cone rolls on the outside of the space cone
  kInside,   ///< oblate (Is > I): the body cone surrounds the space cone and rolls on it
  kNone,     ///< sphere (Is == I) or a spin along 3 (alpha = 0): omega is along L, both
             ///< cones are lines
};

/// "outside", "inside" or "none".
std::string to_string(ConeContact contact);

/// The closed-form free precession of a symmetric body (all angles in radians).
struct SymmetricPrecession {
  double body_rate = 0.0;   ///< Omega, rad/s, signed (eq. 109)
  double space_rate = 0.0;  ///< phi_dot = |L| / I, rad/s (eqs. 146-147)
  double spin_rate = 0.0;   ///< psi_dot = omega_3 - phi_dot cos theta = -Omega, rad/s
  double theta = 0.0;       ///< angle between L and the symmetry axis (eq. 144)
  double body_cone = 0.0;   ///< half-angle of the body cone about 3: alpha
  double space_cone = 0.0;  ///< half-angle of the space cone about L: |theta - alpha|
  double L = 0.0;           ///< |L|, kg m^2/s
  ConeContact contact = ConeContact::kNone;
  double body_period = 0.0;   ///< 2 pi / |Omega|, s (+inf for a sphere)
  double space_period = 0.0;  ///< 2 pi / phi_dot, s
};

/// Throws std::invalid_argument unless I and Is are positive and finite and
/// Is <= 2 I (the triangle inequality of a symmetric body; rigid::validate).
void validate_symmetric(double I, double Is);

/// The free precession for moments I (transverse) and Is (symmetry), |omega| > 0
/// finite and 0 <= alpha < pi/2. Throws std::invalid_argument otherwise. At alpha = 0
/// nothing precesses: omega, L and 3 lie on one line and both cones are lines; the
/// rates are then their limits as alpha -> 0, those of a wobble as it starts.
/// theta - alpha is formed without cancellation (tan(theta - alpha) =
/// (I - Is) sin a cos a / (Is cos^2 a + I sin^2 a)), so the Earth's cones of
/// nanoradians keep full precision.
SymmetricPrecession free_symmetric_precession(double I, double Is, double omega, double alpha);

/// A cross-check of the closed form by integration (free_body_integrate.h, dopri5).
struct PrecessionCheck {
  double space_rate =
      0.0;  ///< phi_dot measured: the turn of 3 about L over a quarter period, rad/s
  double axis_return = 0.0;        ///< angle between 3 at t = 0 and at t = 2 pi / phi_dot, rad
  double L_space_drift_rel = 0.0;  ///< max |L_space - L_space0| / |L0| over the run
  double energy_drift_rel = 0.0;   ///< max |T - T0| / T0 over the run
  std::size_t steps = 0;
};

/// Integrates the free symmetric body (moments I, I, Is; omega at alpha to 3, 3 along z
/// at t = 0) for one space-precession period 2 pi / phi_dot with dopri5 at relative and
/// absolute tolerance `tol`. The run is in units of the moments I and of time 1/|omega|,
/// so that one tolerance fits every body (the Earth's omega is 7e-5 rad/s); the rate
/// is scaled back by omega. Throws like free_symmetric_precession, and at alpha = 0
/// (3 along L: no turn to measure).
/// At most `max_steps` steps: a run needing more (a body whose precession is slower
/// than its spin by many orders) throws std::runtime_error.
PrecessionCheck integrated_precession(double I, double Is, double omega, double alpha,
                                      double tol = 1e-12, std::size_t max_steps = 2'000'000);

}  // namespace rigid
