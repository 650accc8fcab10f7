// Lie-Poisson splitting for the torque-free rigid body (McLachlan 1993;
// Touma & Wisdom 1994; Dullweber, Leimkuhler & McLachlan 1997).
//
// The energy H = L1^2/(2 I1) + L2^2/(2 I2) + L3^2/(2 I3) splits into three
// pieces, each exactly solvable: under H_i alone the body spins about its
// principal axis i at the constant rate w_i = L_i / I_i, so over a time tau
//  - L_body rotates about axis i by the angle -w_i tau (L_space stays put),
//  - the attitude turns by +w_i tau about body axis i: q <- q * (cos, sin e_i).
// Strang composition gives a symmetric second-order method; a symmetric
// composition of that (Suzuki 1990's five-stage "fractal") gives fourth order.
// Every sub-step is a rotation, so |L| and |q| are kept to roundoff and the
// method is symplectic and Poisson: no secular energy drift.
#pragma once

#include <Eigen/Geometry>

#include "rigid/free_body.h"

namespace rigid {

/// Suzuki's fourth-order composition of a symmetric second-order step S2:
/// S2(p h) S2(p h) S2((1 - 4p) h) S2(p h) S2(p h), p = 1 / (4 - 4^(1/3)).
inline constexpr double kSuzukiP = 0.41449077179437573714;

/// One step of the second- or fourth-order Lie-Poisson splitting.
class LiePoissonSplitting {
 public:
  /// order must be 2 (Strang: 1/2, 2/2, 3, 2/2, 1/2) or 4 (Suzuki's composition).
  LiePoissonSplitting(const PrincipalMoments& I, int order);

  /// Advances the body angular momentum L_body and the body-to-space attitude q by h.
  void step(Eigen::Vector3d& L_body, Eigen::Quaterniond& q, double h) const;

  /// The order of accuracy, 2 or 4.
  int order() const { return order_; }

 private:
  double inv_I_[3];
  int order_;
};

}  // namespace rigid
