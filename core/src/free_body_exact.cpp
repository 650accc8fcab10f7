#include "rigid/free_body_exact.h"

#include <algorithm>
#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "rigid/format.h"
#include "rigid/rotation.h"
#include "rigid/units.h"

namespace rigid {

std::string to_string(FreeMotionRegime regime) {
  switch (regime) {
    case FreeMotionRegime::kPolhodeAboutLargest:
      return "polhode about the largest axis";
    case FreeMotionRegime::kPolhodeAboutSmallest:
      return "polhode about the smallest axis";
    case FreeMotionRegime::kSeparatrix:
      return "separatrix";
    case FreeMotionRegime::kSteady:
      break;
  }
  return "steady rotation";
}

namespace {

// Double stays double inside Boost.Math: no silent long-double promotion.
using NoPromote = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

// Quadruple precision where the hardware's long double is not: for the few sums of
// products that cancel (113-bit significands hold a product of two doubles exactly).
#if defined(__SIZEOF_FLOAT128__)
using Quad = __float128;
#else
using Quad = long double;
#endif

// L^2 - 2 T I_m over I_m from the doubles given (the moments, omega in body axes), the
// separatrix test: I_l (I_l - I_m) w_l^2 - I_s (I_m - I_s) w_s^2, all over I_m, formed in
// quadruple precision. In double, near the separatrix its two terms cancel to a few ulps
// of their size and rounding in the squares and products decided k'^2 (poinsot at
// I = 1,2,3, omega = 1.73205080756887, 1e-8, 1: k'^2 8.2897e-15 for 8.3205e-15).
double separatrix_distance(double Is, double Im, double Il, double ws, double wl) {
  const Quad s = Quad(Is) * (Quad(Im) - Quad(Is)) * Quad(ws) * Quad(ws);
  const Quad l = Quad(Il) * (Quad(Il) - Quad(Im)) * Quad(wl) * Quad(wl);
  return static_cast<double>((l - s) / Quad(Im));
}

// AGM stops when |a - b| <= kAgmTol a; the neglected term is O(kAgmTol^2).
constexpr double kAgmTol = 1e-9;

// The descending Gauss transformation for sn, cn, dn (Bulirsch 1965, the
// algorithm of Numerical Recipes' sncndn) split into a table that depends only
// on k'^2 and an evaluation that depends on u.
struct GaussTable {
  static constexpr int kMax = 32;
  int levels = 0;
  double a[kMax] = {}, b[kMax] = {};
  double scale = 1.0;  // AGM(1, k') = pi / (2K)
};

GaussTable make_gauss_table(double kp2) {
  GaussTable g;
  double a = 1.0, emc = kp2, c = 1.0;
  for (int i = 0; i < GaussTable::kMax; ++i) {
    g.a[i] = a;
    emc = std::sqrt(emc);
    g.b[i] = emc;
    c = 0.5 * (a + emc);
    g.levels = i + 1;
    if (std::abs(a - emc) <= kAgmTol * a) break;
    emc *= a;
    a = c;
  }
  g.scale = c;
  return g;
}

void gauss_sn_cn_dn(int levels, const double* ta, const double* tb, double scale, double u,
                    double& sn, double& cn, double& dn) {
  const double v = u * scale;
  if (std::abs(v) < 1e-100) {  // sn = u + O(u^3): avoids overflow of cot(v)^2 below
    sn = u;
    cn = 1.0;
    dn = 1.0;
    return;
  }
  const double s = std::sin(v), co = std::cos(v);
  double a = co / s;
  double c = scale * a;
  dn = 1.0;
  for (int i = levels - 1; i >= 0; --i) {
    const double b = ta[i];
    a *= c;
    c *= dn;
    dn = (tb[i] + a) / (b + a);
    a = c / b;
  }
  a = 1.0 / std::sqrt(c * c + 1.0);
  sn = s >= 0.0 ? a : -a;
  cn = c * sn;
}

// sn = tanh, cn = dn = sech: the separatrix, k = 1.
void separatrix_sn_cn_dn(double u, double& sn, double& cn, double& dn) {
  sn = std::tanh(u);
  cn = dn = 1.0 / std::cosh(u);
}

[[noreturn]] void bad_input(const std::string& what) {
  throw std::invalid_argument(what);
}

}  // namespace

void jacobi_sn_cn_dn(double u, double kp2, double& sn, double& cn, double& dn) {
  if (!(kp2 >= 0.0 && kp2 <= 1.0)) {
    bad_input("jacobi_sn_cn_dn: complementary parameter k'^2 must lie in [0, 1], got " +
              format_number(kp2));
  }
  if (kp2 < std::numeric_limits<double>::min()) return separatrix_sn_cn_dn(u, sn, cn, dn);
  const GaussTable g = make_gauss_table(kp2);
  gauss_sn_cn_dn(g.levels, g.a, g.b, g.scale, u, sn, cn, dn);
}

JacobiElliptic::JacobiElliptic(double kp2) {
  if (!(kp2 >= 0.0 && kp2 <= 1.0)) {
    bad_input("JacobiElliptic: complementary parameter k'^2 must lie in [0, 1], got " +
              format_number(kp2));
  }
  separatrix_ = kp2 < std::numeric_limits<double>::min();
  if (separatrix_) return;
  const GaussTable g = make_gauss_table(kp2);
  levels_ = g.levels;
  std::copy(g.a, g.a + g.levels, a_);
  std::copy(g.b, g.b + g.levels, b_);
  scale_ = g.scale;
}

void JacobiElliptic::operator()(double u, double& sn, double& cn, double& dn) const {
  if (separatrix_) return separatrix_sn_cn_dn(u, sn, cn, dn);
  gauss_sn_cn_dn(levels_, a_, b_, scale_, u, sn, cn, dn);
}

FreeBodyExact::FreeBodyExact(const PrincipalMoments& I, const Eigen::Vector3d& omega0_body,
                             const Eigen::Quaterniond& q0, MomentsRule rule)
    : I_(I) {
  validate(I, rule);
  if (!omega0_body.allFinite()) {
    bad_input("omega_body must be finite, got " + format_vector(omega0_body));
  }
  const double qn = q0.norm();
  if (!std::isfinite(qn) || !(qn > 0.0))
    bad_input("attitude quaternion must be finite and nonzero");
  q0_ = Eigen::Quaterniond(q0.coeffs() / qn);
  omega0_ = omega0_body;

  const double mom[3] = {I.I1, I.I2, I.I3};
  const Eigen::Vector3d L0 = rigid::L_body(I, omega0_body);
  energy_ = kinetic_energy(I, omega0_body);
  L_norm_ = L0.norm();
  L_space_ = q0_ * L0;
  period_ = std::numeric_limits<double>::infinity();

  // Steady rotation: Euler's right-hand side exactly zero (spherical body, a principal
  // axis, omega in the plane of two equal moments, or rest).
  const Eigen::Vector3d& w0 = omega0_body;
  if ((I.I3 - I.I2) * w0.y() * w0.z() == 0.0 && (I.I1 - I.I3) * w0.z() * w0.x() == 0.0 &&
      (I.I2 - I.I1) * w0.x() * w0.y() == 0.0) {
    regime_ = FreeMotionRegime::kSteady;
    return;
  }

  // Sort the axes by moment: s[0] smallest, s[2] largest.
  int s[3] = {0, 1, 2};
  std::sort(s, s + 3, [&](int x, int y) { return mom[x] < mom[y]; });
  // The coefficients of the canonical equations L_o' = -a_o L_m L_p, L_m' = a_m L_p L_o,
  // L_p' = -a_p L_o L_m are |1/I - 1/I'| for pairs of moments, formed from differences of
  // the moments, not of their reciprocals: a_ml pairs the mid and largest, and so on.
  const double Is = mom[s[0]], Im = mom[s[1]], Il = mom[s[2]];
  const double a_ml = (Il - Im) / (Im * Il);
  const double a_sl = (Il - Is) / (Is * Il);
  const double a_sm = (Im - Is) / (Is * Im);
  // Separatrix test L^2 - 2 T I_mid, scaled: its sign selects the polhode's axis.
  const double delta = separatrix_distance(Is, Im, Il, w0[s[0]], w0[s[2]]);
  int o, p;
  double a_o, a_p;
  if (delta >= 0.0) {
    regime_ = delta > 0.0 ? FreeMotionRegime::kPolhodeAboutLargest : FreeMotionRegime::kSeparatrix;
    p = s[2], o = s[0], a_o = a_ml, a_p = a_sm;
  } else {
    regime_ = FreeMotionRegime::kPolhodeAboutSmallest;
    p = s[0], o = s[2], a_o = a_sm, a_p = a_ml;
  }
  const int m = s[1];
  const double a_m = a_sl;

  // Working frame rows e_o, e_m, e_p: right-handed (flip e_m if needed), then turned
  // by pi about e_o or e_p so that L_p > 0 and L_o >= 0.
  axis_[0] = o, axis_[1] = m, axis_[2] = p;
  sign_[0] = sign_[1] = sign_[2] = 1.0;
  const bool even = (m == (o + 1) % 3);  // (o, m, p) a cyclic order of (0, 1, 2)
  if (!even) sign_[1] = -1.0;
  if (L0[p] * sign_[2] < 0.0) sign_[1] = -sign_[1], sign_[2] = -sign_[2];
  if (L0[o] * sign_[0] < 0.0) sign_[0] = -sign_[0], sign_[1] = -sign_[1];
  double Lw[3];
  for (int i = 0; i < 3; ++i) Lw[i] = sign_[i] * L0[axis_[i]];
  Eigen::Matrix3d W = Eigen::Matrix3d::Zero();  // v_work = W v_body
  for (int i = 0; i < 3; ++i) W(i, axis_[i]) = sign_[i];
  q_W_ = Eigen::Quaterniond(W);

  // Amplitudes from conserved combinations (no cancellation):
  //   a_m L_o^2 + a_o L_m^2 = a_m A_o^2,  a_m L_p^2 + a_p L_m^2 = a_m A_p^2.
  const double Lo = Lw[0], Lm = Lw[1], Lp = Lw[2];
  const double Ao = std::sqrt(Lo * Lo + (a_o / a_m) * Lm * Lm);
  const double Am = std::sqrt(Lm * Lm + (a_m / a_o) * Lo * Lo);
  const double Ap = std::sqrt(Lp * Lp + (a_p / a_m) * Lm * Lm);
  const double Imom[3] = {mom[o], mom[m], mom[p]};
  const double A[3] = {Ao, Am, Ap};
  for (int i = 0; i < 3; ++i) {
    w_amp_[i] = A[i] / Imom[i];
    l_amp_[i] = A[i] / L_norm_;
  }
  // In a right-handed frame the equations take the canonical form L_o' = -a_o L_m L_p, ...
  // when p is the largest axis; about the smallest axis they are its time reversal.
  lambda_ = std::sqrt(a_o * a_m) * Ap;
  if (regime_ == FreeMotionRegime::kPolhodeAboutSmallest) lambda_ = -lambda_;
  const double delta_p = std::abs(delta);
  kp2_ = regime_ == FreeMotionRegime::kSeparatrix ? 0.0 : delta_p / (a_o * Ap * Ap);
  k2_ = std::min(1.0, a_p * Ao * Ao / (a_o * Ap * Ap));
  if (kp2_ < std::numeric_limits<double>::min()) {
    kp2_ = 0.0, k2_ = 1.0;
    regime_ = FreeMotionRegime::kSeparatrix;
  }
  kp2_ = std::min(kp2_, 1.0);

  // Initial phase u0 with sn u0 = L_m/A_m, cn u0 = L_o/A_o >= 0, so u0 in [-K, K].
  const double sn0 = Am > 0.0 ? std::clamp(Lm / Am, -1.0, 1.0) : 0.0;
  const double cn0 = Ao > 0.0 ? Lo / Ao : 1.0;
  nu_ = a_p / a_o;
  sqrt1nu_ = std::sqrt(1.0 + nu_);
  c_ = l_amp_[2];  // A_p / |L|
  psi_coef_ = std::sqrt(a_m / a_o);
  if (regime_ == FreeMotionRegime::kSeparatrix) {
    // tanh u0 = sn0 and sech u0 = cn0, so sinh u0 = sn0 / cn0: exact even near the saddle
    u0_ = std::asinh((Lm / Am) / cn0);
    // psi_dot = 2T/|L| - a_o^2 sqrt(a_m/a_o) lambda / (cosh u + c) on the separatrix
    psi_rate_ = 2.0 * energy_ / L_norm_;
  } else {
    const double dn0sq = kp2_ + k2_ * cn0 * cn0;
    u0_ = sn0 * boost::math::ellint_rf(cn0 * cn0, dn0sq, 1.0, NoPromote());
    K_ = boost::math::ellint_rf(0.0, kp2_, 1.0, NoPromote());
    two_K_ = 2.0 * K_;
    inv_two_K_ = 1.0 / two_K_;
    period_ = 4.0 * K_ / std::abs(lambda_);
    const GaussTable g = make_gauss_table(kp2_);
    agm_levels_ = g.levels;
    std::copy(g.a, g.a + kMaxAgm, agm_a_);
    std::copy(g.b, g.b + kMaxAgm, agm_b_);
    agm_scale_ = g.scale;
    // psi = |L|/I_o t - sqrt(a_m/a_o) (H(u) - H(u0)): the secular rate
    // 2T/|L| + sqrt(a_m/a_o) c lambda simplifies to |L|/I_o on both polhode families, and
    //   H(u) = atan2(sqrt(1+nu) sn, cn) / sqrt(1+nu)
    //          + c (nu + k^2)/3 sn^3 R_J(cn^2, dn^2, 1, 1 + nu sn^2),
    // the third-kind integral Pi(-nu; am u, k) in Carlson's form (DLMF 19.25.14).
    rj_coef_ = c_ * (nu_ + k2_) / 3.0;
    psi_rate_ = L_norm_ / Imom[0];
    H_half_period_ =
        2.0 * (0.5 * kPi / sqrt1nu_ +
               rj_coef_ * boost::math::ellint_rj(0.0, kp2_, 1.0, 1.0 + nu_, NoPromote()));
  }
  double sn, cn, dn;
  if (regime_ == FreeMotionRegime::kSeparatrix) {
    separatrix_sn_cn_dn(u0_, sn, cn, dn);
  } else {
    sn_cn_dn_reduced(u0_, sn, cn, dn);
  }
  H_u0_ = psi_periodic(sn, cn, dn);

  // Space side: q(0) = q_S * M(0) * q_W = q0.
  Elliptic e0{sn, cn, dn, u0_, 0.0, 1.0};
  q_S_ = Eigen::Quaterniond::Identity();
  const Eigen::Quaterniond body_part = attitude_from(0.0, e0);
  q_S_ = q0_ * body_part.conjugate();
}

double FreeBodyExact::modulus() const {
  return std::sqrt(k2_);
}

double FreeBodyExact::phase_precision(double t) const {
  if (regime_ == FreeMotionRegime::kSteady) return 0.0;
  // u = lambda t + u0 carries an absolute error of about eps (|lambda t| + |u0|)
  // (lambda's rounding scaled by t, then the reduction by 2K n); sn, cn, dn vary
  // on the scale K, or on the scale 1 of tanh and sech on the separatrix.
  const double scale = regime_ == FreeMotionRegime::kSeparatrix ? 1.0 : K_;
  return std::numeric_limits<double>::epsilon() * (std::abs(lambda_ * t) + std::abs(u0_)) / scale;
}

void FreeBodyExact::sn_cn_dn_reduced(double u, double& sn, double& cn, double& dn) const {
  gauss_sn_cn_dn(agm_levels_, agm_a_, agm_b_, agm_scale_, u, sn, cn, dn);
}

// The periodic part H of the psi integral at a phase u in [-K, K] (or any u on the separatrix).
double FreeBodyExact::psi_periodic(double sn, double cn, double dn) const {
  if (regime_ == FreeMotionRegime::kSeparatrix) {
    // on the separatrix the integrand is a_o^2 / (cosh u + c), whose integral is
    // 2 a_o atan(r tanh(u/2)), r = sqrt((1-c)/(1+c)); tanh(u/2) = sn / (1 + cn)
    const double ao = std::sqrt(std::max(0.0, 1.0 - c_ * c_));
    const double r = std::sqrt((1.0 - c_) / (1.0 + c_));
    return 2.0 * ao * std::atan(r * sn / (1.0 + cn));
  }
  const double s3 = sn * sn * sn;
  const double rj =
      s3 == 0.0 ? 0.0
                : boost::math::ellint_rj(cn * cn, dn * dn, 1.0, 1.0 + nu_ * sn * sn, NoPromote());
  return std::atan2(sqrt1nu_ * sn, cn) / sqrt1nu_ + rj_coef_ * s3 * rj;
}

FreeBodyExact::Elliptic FreeBodyExact::elliptic_at(double t) const {
  Elliptic e{};
  const double u = std::fma(lambda_, t, u0_);
  if (regime_ == FreeMotionRegime::kSeparatrix) {
    separatrix_sn_cn_dn(u, e.sn, e.cn, e.dn);
    e.u_reduced = u;
    e.flip = 1.0;
    return e;
  }
  // sn(u + 2K n) = (-1)^n sn u, cn likewise, dn unchanged. n stays a double:
  // no integer type holds it for every t, and beyond 2^53 every double is even.
  const double n = std::nearbyint(u * inv_two_K_);
  e.u_reduced = std::fma(-n, two_K_, u);
  e.half_periods = n;
  e.flip = std::fmod(n, 2.0) != 0.0 ? -1.0 : 1.0;
  sn_cn_dn_reduced(e.u_reduced, e.sn, e.cn, e.dn);
  return e;
}

Eigen::Vector3d FreeBodyExact::omega_from(const Elliptic& e) const {
  const double w_work[3] = {w_amp_[0] * e.cn * e.flip, w_amp_[1] * e.sn * e.flip, w_amp_[2] * e.dn};
  Eigen::Vector3d w;
  for (int i = 0; i < 3; ++i) w[axis_[i]] = sign_[i] * w_work[i];
  return w;
}

Eigen::Quaterniond FreeBodyExact::attitude_from(double t, const Elliptic& e) const {
  // l = L_body / |L| in the working frame
  const double lo = l_amp_[0] * e.cn * e.flip, lm = l_amp_[1] * e.sn * e.flip,
               lp = l_amp_[2] * e.dn;
  // psi: secular part plus the periodic part, continued over half periods
  const double H = psi_periodic(e.sn, e.cn, e.dn) + e.half_periods * H_half_period_;
  const double psi = psi_rate_ * t - psi_coef_ * (H - H_u0_);
  // M: minimal rotation taking l to e_p, quaternion (1 + l_p, l x e_p) normalised
  const double nm = 1.0 / std::sqrt(2.0 * (1.0 + lp));
  const double mw = (1.0 + lp) * nm, mx = lm * nm, my = -lo * nm;
  // R(psi) about e_p, times M
  const double cz = std::cos(0.5 * psi), sz = std::sin(0.5 * psi);
  const Eigen::Quaterniond zm(cz * mw, cz * mx - sz * my, cz * my + sz * mx, sz * mw);
  return q_S_ * zm * q_W_;
}

Eigen::Vector3d FreeBodyExact::omega_body(double t) const {
  if (regime_ == FreeMotionRegime::kSteady) return omega0_;
  return omega_from(elliptic_at(t));
}

Eigen::Quaterniond FreeBodyExact::attitude(double t) const {
  if (regime_ == FreeMotionRegime::kSteady) {
    const double w = omega0_.norm();
    if (w == 0.0) return q0_;
    return q0_ * axis_angle(omega0_ / w, w * t);
  }
  return attitude_from(t, elliptic_at(t));
}

RotationState FreeBodyExact::state(double t) const {
  if (regime_ == FreeMotionRegime::kSteady) return make_state(omega0_, attitude(t));
  const Elliptic e = elliptic_at(t);
  return make_state(omega_from(e), attitude_from(t, e));
}

}  // namespace rigid
