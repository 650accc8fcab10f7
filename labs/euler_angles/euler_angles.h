// euler_angles: sections 6 and 7 of the chapter, as a library.
// Three turns take the fixed axes xyz to the body's 123 (eq. 121): phi about z to
// the line of nodes x', theta about x' to bring z to 3, psi about 3; their product
// is lambda = lambda_psi lambda_theta lambda_phi (eq. 122). The body's angular
// velocity is phi_dot about z, theta_dot about x' and psi_dot about 3 (eq. 124); the
// lab gives it in the intermediate frame (eqs. 128-130), the body (134-136) and space
// (137-139), each also as lambda applied to another frame's components, and the way
// back, omega in the body to the rates, of which a pole (theta = 0 or 180 deg) leaves
// only phi_dot +- psi_dot and theta_dot: everything else is given there too. With a
// body's moments, L and T = 1/2 sum I_i omega_i^2 (eq. 150, whose print lacks the 1/2).
// Section 7: each angle's Lagrange equation (eqs. 150-159), its terms exact but for a
// stated rounding bound and checked by differences along the exact motion; psi's
// momentum I3 omega_3 and force (I1 - I2) omega_1 omega_2, defined at a pole too;
// section 7.2 with a constant body torque and its generalized forces, in N m (eqs.
// 163-166). The text's errors are errata with the numbers of the run.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "common/figures.h"
#include "common/inputs.h"
#include "common/program.h"
#include "common/report.h"
#include "rigid/free_body_exact.h"
#include "rigid/rotation.h"

namespace rigid::lab::euler_angles {

/// The lab's inputs. The text works section 6 without numbers: the defaults are an
/// attitude away from the poles and rates of each sign's size.
struct Inputs {
  double phi_deg = 30.0;    ///< the first turn, about z
  double theta_deg = 50.0;  ///< the second, about the line of nodes x'
  double psi_deg = 70.0;    ///< the third, about 3
  double phi_dot = 1.0;     ///< rad/s
  double theta_dot = 0.5;   ///< rad/s
  double psi_dot = 2.0;     ///< rad/s
  /// I1, I2, I3 (kg m^2): with them, L and T.
  std::optional<Eigen::Vector3d> moments;
  /// A constant torque in the body (N m): section 7.2, the equations with torque.
  Eigen::Vector3d torque{0.5, -0.25, 1.0};
  /// omega in the body (rad/s): the rates from it, instead of the rates given.
  std::optional<Eigen::Vector3d> from_omega;
};

/// What the lab reports, and what its figures draw.
struct Report : lab::Report {
  using lab::Report::Report;
  EulerAngles angles;  ///< rad
  EulerRates rates;    ///< rad/s (from --from-omega where given and defined)
  /// false at a pole with --from-omega: rates then holds only theta_dot
  bool rates_defined = true;
  Eigen::Vector3d omega_space = Eigen::Vector3d::Zero();  ///< rad/s
  Eigen::Vector3d omega_body = Eigen::Vector3d::Zero();   ///< rad/s
  /// The free motion of section 7's body from these angles and rates (the CSV's).
  std::optional<FreeBodyExact> free_motion;
};

/// The inputs' rules: options, widgets and compute()'s checks.
const InputTable<Inputs>& input_table();
/// Everything the lab reports. Throws InputError naming a broken input.
Report compute(const Inputs& in);
/// The three rotations with the angles as arcs, omega as the sum of its parts (Figure
/// 9.6.2); gimbal lock.
void figures(const Report& report, FigureSink& sink);

/// The three turns applied in turn (the animation's own time, a second each).
Animation animation(const Report& report, const FrameTimes& frame_times);

/// The lab as one program.
LabProgram<Inputs, Report> program();

}  // namespace rigid::lab::euler_angles
