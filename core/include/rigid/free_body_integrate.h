// The torque-free rigid body integrated (Euler's equations, eq. 73 with N = 0,
// and the attitude quaternion): the free body as a problem of compare.h, run by
// any method of ode.h on RotationState and compared with FreeBodyExact.
//
//  - "splitting", "splitting4": Lie-Poisson splittings (splitting.h), fixed step,
//    order 2 and 4, on L_body and q; |L| and |q| kept to roundoff, energy without drift.
//  - the Runge-Kutta methods and Bulirsch-Stoer through ode.h's integrate_sampled;
//    with OdeOptions::project_invariants (rk4, rkf78, vern*), omega is pulled back
//    onto the energy and |L| of the start after every step.
// The Runge-Kutta methods do not keep |q| = 1; their quaternion is not touched
// during the run, its norm drift is reported (invariant kQuaternionNorm) and the
// sampled attitudes are normalised.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "rigid/compare.h"
#include "rigid/free_body.h"
#include "rigid/free_body_exact.h"

namespace rigid {

/// The torque-free body as a problem for compare.h: its moments and the rule they are held to.
class FreeBodyProblem {
 public:
  using State = RotationState;
  using Exact = FreeBodyExact;
  /// The invariants, in the order of a run's errors: (T - T0) / T0, (|L| - |L0|) / |L0|,
  /// |L_space - L_space0| / |L0| (L is fixed in space: the attitude's error shows in
  /// it) and |q| - 1 before the sample normalises q.
  enum Invariant : std::size_t { kEnergy, kMomentum, kLSpace, kQuaternionNorm };
  static constexpr std::size_t kInvariantCount = 4;
  using Sample = RunSample<State, kInvariantCount>;

  /// A body of moments I, held to `rule` (a test problem may break the triangle inequality).
  explicit FreeBodyProblem(const PrincipalMoments& I, MomentsRule rule = MomentsRule::kPhysical)
      : I_(I), rule_(rule) {}
  /// The principal moments.
  const PrincipalMoments& moments() const { return I_; }

  /// Throws std::invalid_argument for moments breaking the rule, or a start that is
  /// not finite or has a zero quaternion.
  void validate(const State& x0) const;
  /// Euler's equations with no torque, and the quaternion kinematics.
  EulerRhs rhs() const { return EulerRhs{I_}; }
  /// The signed errors of the invariants against those of x0 (defined in the .cpp).
  class Invariants;
  Invariants invariants(const State& x0) const;
  /// The state as a sample keeps it: the quaternion normalised.
  State sampled(const State& x) const;
  /// The Lie-Poisson splitting of order 2 or 4 on L_body and q (defined in the .cpp).
  class Splitting;
  Splitting splitting(int order, const State& x0) const;
  /// The projection of omega onto the energy and |L| of x0 (Hairer, Lubich & Wanner
  /// IV.4), so both hold to roundoff (defined in the .cpp).
  class Projection;
  Projection projection(const State& x0) const;

  /// The exact motion's state at t.
  State exact_state(const Exact& exact, double t) const { return exact.state(t); }
  /// Each sample's |omega - omega_exact| / |omega_exact(0)| and |T / T_exact - 1| (eq. 81).
  ExactErrors errors_against(const Exact& exact, const std::vector<Sample>& samples) const;
  /// The same against a reference run's samples at the same times: |omega - omega_ref| /
  /// |omega_ref(0)| and |T / T_ref - 1|.
  ExactErrors errors_against(const std::vector<Sample>& reference,
                             const std::vector<Sample>& samples) const;

 private:
  PrincipalMoments I_;
  MomentsRule rule_;
};

/// A run of the free body.
using FreeBodyRun = Run<FreeBodyProblem>;

extern template struct detail::ProblemCode<FreeBodyProblem>;

}  // namespace rigid
