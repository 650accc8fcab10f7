// The exact torque-free motion of a rigid body (sections 4 and 5.1; Landau &
// Lifshitz, Mechanics, section 37): omega_body(t) by Jacobi elliptic functions
// and the attitude by the elliptic integral of the third kind.
//
// Method. The body axes are relabelled into a right-handed working frame
// (o, m, p): p is the axis the polhode circles (the largest moment when
// L^2 > 2 T I_mid, the smallest when L^2 < 2 T I_mid), m the intermediate one.
// There, with u = lambda t + u0 and modulus k,
//   L_o = A_o cn u,  L_m = A_m sn u,  L_p = A_p dn u,
// and on the separatrix (k = 1) sn = tanh, cn = dn = sech. The amplitudes,
// k^2 and k'^2 = 1 - k^2 are formed from the initial data without cancellation
// (k'^2 carries only the inherent one of the separatrix test), and sn, cn, dn
// are computed from k'^2 by the descending Gauss transformation with the AGM
// table precomputed, so k -> 1 and k -> 0 lose no accuracy.
// The attitude is q(t) = q_S * Rz_p(psi(t)) * M(t) * q_W: q_W relabels body
// axes, M(t) is the minimal rotation taking L_body/|L| to the p axis, and the
// angle psi about L has psi_dot = 2T/|L| - (l x l_dot)_p / (1 + l_p), which
// integrates to an elementary term plus Carlson's R_J (the third-kind integral,
// as in Celledoni, Fasso, Safstrom & Zanna 2008, whose signs are not copied but
// checked here against numerical integration). Symmetric bodies (k = 0) and
// steady rotations (spherical body, rotation about a principal axis) are the
// smooth limits of the same formulas or a constant rotation.
#pragma once

#include <Eigen/Geometry>
#include <string>

#include "rigid/free_body.h"

namespace rigid {

/// Which closed form a torque-free motion follows.
enum class FreeMotionRegime {
  kSteady,                ///< omega constant: spherical body or rotation about a principal axis
  kPolhodeAboutLargest,   ///< polhode circles the axis of the largest moment (L^2 > 2 T I_mid)
  kPolhodeAboutSmallest,  ///< polhode circles the axis of the smallest moment (L^2 < 2 T I_mid)
  kSeparatrix,            ///< L^2 = 2 T I_mid, not at rest on the intermediate axis
};

/// "steady rotation", "polhode about the largest axis", "polhode about the smallest
/// axis" or "separatrix".
std::string to_string(FreeMotionRegime regime);

/// Sine, cosine and delta amplitude sn, cn, dn of u for the complementary
/// parameter kp2 = k'^2 = 1 - k^2 in [0, 1] (kp2 = 0 gives tanh, sech, sech).
/// Accurate for k'^2 -> 0, unlike an interface that takes k.
void jacobi_sn_cn_dn(double u, double kp2, double& sn, double& cn, double& dn);

/// sn, cn, dn for one complementary parameter k'^2 in [0, 1], the Gauss
/// transformation's table made once, so each evaluation costs one sin, one cos
/// and a short loop (what jacobi_sn_cn_dn does per call).
class JacobiElliptic {
 public:
  explicit JacobiElliptic(double kp2);
  void operator()(double u, double& sn, double& cn, double& dn) const;

 private:
  static constexpr int kMax = 32;
  bool separatrix_ = false;
  int levels_ = 0;
  double a_[kMax] = {}, b_[kMax] = {};
  double scale_ = 1.0;
};

/// Exact torque-free motion from omega_body and the attitude at t = 0.
/// Everything independent of t is computed in the constructor; a sample costs
/// one sn/cn/dn evaluation (plus one Carlson R_J for the attitude).
class FreeBodyExact {
 public:
  /// Throws std::invalid_argument for invalid moments (see validate), a
  /// non-finite omega0_body, or a zero or non-finite q0 (q0 is normalised).
  FreeBodyExact(const PrincipalMoments& I, const Eigen::Vector3d& omega0_body,
                const Eigen::Quaterniond& q0 = Eigen::Quaterniond::Identity(),
                MomentsRule rule = MomentsRule::kPhysical);

  /// Angular velocity in body axes at time t, rad/s.
  Eigen::Vector3d omega_body(double t) const;
  /// Unit body-to-space quaternion at time t.
  Eigen::Quaterniond attitude(double t) const;
  /// omega_body and attitude at time t, sharing the elliptic-function evaluation.
  RotationState state(double t) const;

  /// Polhode period 4K/lambda, s: omega_body(t + T) = omega_body(t); the
  /// component along the polhode's axis repeats after T/2. +inf on the
  /// separatrix and for a steady rotation (no polhode to go round).
  double period() const { return period_; }
  /// The regime the initial data select.
  FreeMotionRegime regime() const { return regime_; }
  /// The elliptic modulus k (0 for a symmetric body or a steady rotation).
  double modulus() const;
  /// Relative precision left in the elliptic phase u = lambda t + u0 at time t,
  /// about eps (|lambda t| + |u0|) / K (K -> 1 on the separatrix, 0 when steady):
  /// omega_body(t) is meaningless once this nears 1.
  double phase_precision(double t) const;
  /// The complementary parameter k'^2 = 1 - k^2, computed without cancellation.
  double complementary_parameter() const { return kp2_; }
  /// Kinetic energy T, J.
  double energy() const { return energy_; }
  /// |L|, kg m^2/s.
  double angular_momentum_magnitude() const { return L_norm_; }
  /// The constant space-frame angular momentum, kg m^2/s.
  Eigen::Vector3d L_space() const { return L_space_; }
  /// The moments the motion was built for.
  const PrincipalMoments& moments() const { return I_; }

 private:
  struct Elliptic {  // sn, cn, dn at one u, and u reduced to [-K, K]
    double sn, cn, dn, u_reduced;
    double half_periods;  // n in u = u_reduced + 2K n, an integer held in a double
    double flip;          // (-1)^n
  };
  Elliptic elliptic_at(double t) const;
  Eigen::Vector3d omega_from(const Elliptic& e) const;
  Eigen::Quaterniond attitude_from(double t, const Elliptic& e) const;
  double psi_periodic(double sn, double cn, double dn) const;

  PrincipalMoments I_;
  FreeMotionRegime regime_ = FreeMotionRegime::kSteady;
  double energy_ = 0.0, L_norm_ = 0.0;
  Eigen::Vector3d L_space_ = Eigen::Vector3d::Zero();
  double period_ = 0.0;

  // steady rotation
  Eigen::Vector3d omega0_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q0_ = Eigen::Quaterniond::Identity();

  // working frame: working axis i is user axis axis_[i] times sign_[i]
  int axis_[3] = {0, 1, 2};
  double sign_[3] = {1.0, 1.0, 1.0};
  double w_amp_[3] = {0.0, 0.0, 0.0};  // A_i / I_i: omega amplitudes in the working frame
  double l_amp_[3] = {0.0, 0.0, 0.0};  // A_i / |L|
  double lambda_ = 0.0, u0_ = 0.0;
  double kp2_ = 1.0, k2_ = 0.0, K_ = 0.0, two_K_ = 0.0, inv_two_K_ = 0.0;
  // Gauss-transformation table for sn, cn, dn at this k'^2
  static constexpr int kMaxAgm = 32;
  int agm_levels_ = 0;
  double agm_a_[kMaxAgm] = {}, agm_b_[kMaxAgm] = {};
  double agm_scale_ = 1.0;
  // attitude: psi(t) = psi_rate_ t - psi_coef_ (H(u) - H(u0))
  double nu_ = 0.0, sqrt1nu_ = 1.0, rj_coef_ = 0.0, c_ = 0.0, psi_rate_ = 0.0, psi_coef_ = 0.0;
  double H_half_period_ = 0.0, H_u0_ = 0.0;
  Eigen::Quaterniond q_S_ = Eigen::Quaterniond::Identity();  // space side, constant
  Eigen::Quaterniond q_W_ = Eigen::Quaterniond::Identity();  // body relabelling, constant

  void sn_cn_dn_reduced(double u, double& sn, double& cn, double& dn) const;
};

}  // namespace rigid
