// euler_angles' section 7: each angle's Lagrange equation along the exact free motion
// (eqs. 150-159), and section 7.2's under a constant torque in the body along an
// integration (eqs. 163-166); compute() reports them after section 6.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "euler_angles/euler_angles.h"
#include "rigid/free_body.h"
#include "rigid/rotation.h"

namespace rigid::lab::euler_angles {

/// The passive turn by `angle` about `axis` (eq. 121's lambda_phi, lambda_theta,
/// lambda_psi): the transpose of the active rotation Eigen makes.
inline Eigen::Matrix3d passive(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis).toRotationMatrix().transpose();
}

/// Section 7 at the angles and rates (or the omega) of the inputs, for a body (its moments,
/// or I = 1, 2, 3 kg m^2): each angle's Lagrange equation exact but for rounding, checked
/// by differences along the exact torque-free motion started there; psi's is Euler's
/// (eqs. 150-159). Returns the free motion's time scale, s.
double report_section_7(Report& report, const Inputs& in, const EulerAngles& e, double sin_theta);

/// Section 7.2: the same body under the constant torque --torque in the body (eqs.
/// 163-166), integrated and checked a quarter of its time scale in (the free motion's
/// `free_scale`, or less where the torque turns the body sooner).
void report_torque(Report& report, const Inputs& in, const PrincipalMoments& I,
                   const EulerAngles& e, double free_scale);

}  // namespace rigid::lab::euler_angles
