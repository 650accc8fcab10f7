// Section 7, "Mr. Euler, Meet Mr. Lagrange", made concrete: the kinetic energy as a
// function of the Euler angles and their rates, T = 1/2 sum I_i omega_i^2 (eq. 150,
// with the 1/2 its print lacks), and each angle's Euler-Lagrange equation, d/dt
// dT/dq_dot - dT/dq = 0 (eq. 151 for psi), evaluated along a motion by differences
// whose error is measured, not assumed: each derivative by central differences at
// steps h, 2h and 4h, Richardson's combination of the first two as the value and its
// distance from the next one's as its error.
#pragma once

#include <Eigen/Core>
#include <functional>

#include "rigid/free_body.h"
#include "rigid/rotation.h"

namespace rigid {

/// T = 1/2 (I1 omega_1^2 + I2 omega_2^2 + I3 omega_3^2) with omega in the body from the
/// Euler angles and rates (eqs. 134-136, 150).
double euler_kinetic_energy(const PrincipalMoments& I, const EulerAngles& e, const EulerRates& r);

/// The Euler angles and their rates at a time: the angles continuous in time (not
/// wrapped), as differences in time need them.
struct EulerState {
  EulerAngles angles;
  EulerRates rates;
};

/// A derivative by differences: the value and an estimate of its error.
struct Measured {
  double value = 0.0;
  double error = 0.0;
};

/// Each angle's terms of its Euler-Lagrange equation at one time, in the order phi,
/// theta, psi: dT/dq (by differences in q, the rates held), the momentum dT/dq_dot (T
/// is quadratic in the rates: a central difference gives it to roundoff), its rate
/// d/dt dT/dq_dot (by differences in time along the motion), and the residual d/dt
/// dT/dq_dot - dT/dq, each with its error.
struct LagrangeTerms {
  Measured dT_dq[3];
  double momentum[3] = {0.0, 0.0, 0.0};
  Measured momentum_rate[3];
  Measured residual[3];
};

/// The terms at time t of the motion `at` (t -> its EulerState), with steps `angle_step`
/// (rad) for dT/dq and `time_step` (s) for d/dt: Richardson's value (error h^4) and
/// twice the estimate of its error that steps 2h and 4h give, plus the roundoff.
LagrangeTerms lagrange_terms(const PrincipalMoments& I, const std::function<EulerState(double)>& at,
                             double t, double angle_step, double time_step);

}  // namespace rigid
