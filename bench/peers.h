// The peers a user might pick instead of rigidlab, used as their documentation
// shows, on the same seven-dimensional free-body system (Euler's equations for
// omega_body plus the quaternion kinematics, the arithmetic of rigid::EulerRhs):
//  - Boost.Odeint with std::vector<double> state and
//    integrate_adaptive(make_controlled<stepper>(abs, rel), ...);
//  - GSL gsl_odeiv2_driver with rk8pd and rkf45 (only when GSL was found:
//    GSL is GPL and is linked into the bench executables only).
// Each run integrates from 0 to problem.t_end with abs = rel = tol and returns
// the end state and the number of accepted steps.
#pragma once

#include <string>

#include "problems.h"

namespace bench {

struct RunResult {
  rigid::RotationState x{};
  long long steps = 0;
  long long evaluations = 0;  ///< right-hand-side evaluations (a counter in the system)
};

RunResult odeint_vector_dopri5(const Problem& p, double tol);
RunResult odeint_vector_rkf78(const Problem& p, double tol);

/// A reference run (not a peer): odeint rkf78 on std::array<long double, 7>
/// state, abs = rel = tol; the end state rounded to double.
rigid::RotationState long_double_rkf78(const Problem& p, long double tol);

#ifdef RIGID_BENCH_HAVE_GSL
RunResult gsl_rk8pd(const Problem& p, double tol);
RunResult gsl_rkf45(const Problem& p, double tol);

/// Sum of sn + cn + dn of gsl_sf_elljac_e over n arguments u0 + i du at parameter m = k^2.
double gsl_elljac_sum(double u0, double du, int n, double m);
#endif

}  // namespace bench
