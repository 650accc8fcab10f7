// The two free-body test problems of the work-precision benchmark and how an
// integrated end state is scored against the exact one.
//
//  - "hlw": Hairer, Lubich & Wanner, Geometric Numerical Integration, the free
//    rigid body of section I.5.3 / VII.5: I = (2, 1, 2/3), body angular
//    momentum (cos 1.1, 0, sin 1.1), t_end = 100.
//  - "separatrix": I = (3, 5, 9), body angular momentum (0, 2, 0.01): almost
//    a pure rotation about the intermediate axis, so the motion hugs the
//    separatrix and is exponentially sensitive; t_end = 500.
// Both start from the identity attitude. The state is rigid::RotationState
// (omega_body, then the body-to-space quaternion): seven numbers for every
// solver, rigidlab's and the peers'.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include "rigid/free_body.h"
#include "rigid/rotation.h"

namespace bench {

struct Problem {
  std::string name;
  std::string title;  ///< for tables and plots (text.h markup)
  rigid::PrincipalMoments I;
  Eigen::Vector3d L0_body;
  double t_end = 0.0;

  Eigen::Vector3d omega0_body() const { return L0_body.cwiseQuotient(I.vector()); }
  rigid::RotationState initial_state() const {
    return rigid::make_state(omega0_body(), Eigen::Quaterniond::Identity());
  }
};

inline std::vector<Problem> problems() {
  return {
      {"hlw",
       "Hairer-Lubich-Wanner: I = (2, 1, 2/3), L_0 = (cos 1.1, 0, sin 1.1), t_{end} = 100 s",
       {2.0, 1.0, 2.0 / 3.0},
       {std::cos(1.1), 0.0, std::sin(1.1)},
       100.0},
      {"separatrix",
       "near the separatrix: I = (3, 5, 9), L_0 = (0, 2, 0.01), t_{end} = 500 s",
       {3.0, 5.0, 9.0},
       {0.0, 2.0, 0.01},
       500.0},
  };
}

/// Max-norm of the omega_body error relative to |omega_exact| (2-norm).
inline double omega_error(const rigid::RotationState& x, const rigid::RotationState& exact) {
  const Eigen::Vector3d w = rigid::omega_body(x), we = rigid::omega_body(exact);
  return (w - we).lpNorm<Eigen::Infinity>() / we.norm();
}

/// The attitude error as the angle of the rotation between the two, rad.
inline double attitude_error(const rigid::RotationState& x, const rigid::RotationState& exact) {
  return rigid::attitude_distance(rigid::attitude(x).normalized(), rigid::attitude(exact));
}

}  // namespace bench
