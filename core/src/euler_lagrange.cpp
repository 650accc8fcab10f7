#include "rigid/euler_lagrange.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "rigid/units.h"

namespace rigid {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// The Euler state with angle k moved by d.
EulerState moved(EulerState s, int k, double d) {
  double* angles[3] = {&s.angles.phi, &s.angles.theta, &s.angles.psi};
  *angles[k] += d;
  return s;
}

double rate_sum(const EulerRates& r) {
  return std::abs(r.phi_dot) + std::abs(r.theta_dot) + std::abs(r.psi_dot);
}

// The offsets of the differences: h, 2h and 4h each way. Multiplying by a power of two
// is exact, so t + kOffsets[i] * h is the same double wherever it is formed.
constexpr double kOffsets[] = {1.0, 2.0, 4.0};

// A number computed in floating point with a bound on its distance from the exact value
// of what it stands for (running error analysis, Higham, "Accuracy and Stability of
// Numerical Algorithms", sec. 3.3): each operation passes on its operands' bounds as it
// propagates them and adds its own rounding, u |result| (u = eps / 2, round to nearest).
// The bound is summed in floating point too; its own rounding, a few u of itself, is far
// below the two ulps allowed each sine and cosine.
struct Bounded {
  double v = 0.0;  // the value
  double e = 0.0;  // |v - exact| <= e
};
constexpr double kU = kEps / 2;

Bounded operator+(Bounded a, Bounded b) {
  const double v = a.v + b.v;
  return {v, a.e + b.e + kU * std::abs(v)};
}
Bounded operator-(Bounded a, Bounded b) {
  const double v = a.v - b.v;
  return {v, a.e + b.e + kU * std::abs(v)};
}
Bounded operator-(Bounded a) {
  return {-a.v, a.e};
}
Bounded operator*(Bounded a, Bounded b) {
  const double v = a.v * b.v;
  return {v, std::abs(a.v) * b.e + std::abs(b.v) * a.e + a.e * b.e + kU * std::abs(v)};
}
// |A/B - a/b| <= (a.e + |a/b| b.e) / (|b| - b.e) where |A - a| <= a.e, |B - b| <= b.e
Bounded operator/(Bounded a, Bounded b) {
  const double v = a.v / b.v, margin = std::abs(b.v) - b.e;
  if (!(margin > 0)) return {v, HUGE_VAL};
  return {v, (a.e + std::abs(v) * b.e) / margin + kU * std::abs(v)};
}
// The library's sine and cosine: within two ulps (2 eps |value|) of the exact one, more
// than common libms' one; an angle off by x.e moves them by at most x.e.
Bounded sin_of(Bounded x) {
  const double v = std::sin(x.v);
  return {v, 2 * kEps * std::abs(v) + x.e};
}
Bounded cos_of(Bounded x) {
  const double v = std::cos(x.v);
  return {v, 2 * kEps * std::abs(v) + x.e};
}

// A quantity and its derivative along one direction (time, or one angle), both Bounded:
// forward-mode automatic differentiation.
struct Jet {
  Bounded v, d;
};
Jet operator+(const Jet& a, const Jet& b) {
  return {a.v + b.v, a.d + b.d};
}
Jet operator-(const Jet& a) {
  return {-a.v, -a.d};
}
Jet operator*(const Jet& a, const Jet& b) {
  return {a.v * b.v, a.d * b.v + a.v * b.d};
}
using JetVector = std::array<Jet, 3>;
// A quantity that does not move along the jet's direction.
Jet held(const Bounded& x) {
  return {x, {}};
}

Jet dot(const JetVector& a, const JetVector& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The axes the three rates turn about, in the body (eqs. 131-133): z = (sin theta sin
// psi, sin theta cos psi, cos theta), x' = (cos psi, -sin psi, 0) and 3, from theta's and
// psi's sines and cosines as jets.
std::array<JetVector, 3> rate_axes(const Jet& st, const Jet& ct, const Jet& sp, const Jet& cp) {
  const Jet zero{}, one{{1.0, 0.0}, {}};
  return {{{st * sp, st * cp, ct}, {cp, -sp, zero}, {zero, zero, one}}};
}

// A sine and cosine of an angle moving at `rate` along the jet's direction.
std::array<Jet, 2> sin_cos(const Bounded& s, const Bounded& c, const Bounded& rate) {
  return {{{s, c * rate}, {c, -(s * rate)}}};
}

}  // namespace

double euler_kinetic_energy(const PrincipalMoments& I, const EulerAngles& e, const EulerRates& r) {
  const Eigen::Vector3d w = omega_in_body(e, r);
  return 0.5 * (I.I1 * w(0) * w(0) + I.I2 * w(1) * w(1) + I.I3 * w(2) * w(2));
}

std::optional<EulerState> euler_state(const Eigen::Quaterniond& attitude,
                                      const Eigen::Vector3d& omega_body, const EulerAngles& near) {
  EulerState s;
  s.angles = euler_zxz(attitude);
  s.angles.phi = near.phi + std::remainder(s.angles.phi - near.phi, 2 * kPi);
  s.angles.psi = near.psi + std::remainder(s.angles.psi - near.psi, 2 * kPi);
  const std::optional<EulerRates> r = rates_from_body_omega(s.angles, omega_body);
  if (!r) return std::nullopt;
  s.rates = *r;
  return s;
}

Eigen::Matrix3d rate_axes_in_body(const EulerAngles& e) {
  Eigen::Matrix3d axes;
  axes.col(0) = omega_in_body(e, {1, 0, 0});
  axes.col(1) = omega_in_body(e, {0, 1, 0});
  axes.col(2) = omega_in_body(e, {0, 0, 1});
  return axes;
}

Eigen::Vector3d generalized_force(const EulerAngles& e, const Eigen::Vector3d& torque_body) {
  return rate_axes_in_body(e).transpose() * torque_body;
}

namespace {

// theta's and psi's sines and cosines, each with its bound: where sin(theta) comes from
// the degrees meant, theta in radians is taken as within 2 eps of them (pi / 180 and the
// product each rounded)
struct Trig {
  Bounded st, ct, sp, cp;
};
Trig trig_of(const EulerAngles& e, std::optional<double> sin_theta) {
  const Bounded theta{e.theta, sin_theta ? 2 * kEps * std::abs(e.theta) : 0.0};
  return {sin_theta ? Bounded{*sin_theta, 2 * kEps * std::abs(*sin_theta)} : sin_of(theta),
          cos_of(theta), sin_of({e.psi, 0.0}), cos_of({e.psi, 0.0})};
}

// The terms at a state given as omega in the body and the rates, one computed from the
// other (their bounds say how well), under the body torque N.
std::optional<LagrangeTerms> terms_at(const PrincipalMoments& I, const Trig& a,
                                      const std::array<Bounded, 3>& w,
                                      const std::array<Bounded, 3>& rate,
                                      const Eigen::Vector3d& torque_body) {
  const Bounded N[3] = {{torque_body(0)}, {torque_body(1)}, {torque_body(2)}};
  // L = I omega (eq. 153's dT/d omega_i) and its rate in the body, I omega_dot = N -
  // omega x L (Euler's equations, eq. 163)
  const Bounded moments[3] = {{I.I1}, {I.I2}, {I.I3}};
  JetVector L;
  for (int i = 0; i < 3; ++i) L[i].v = moments[i] * w[i];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    L[i].d = N[i] - (w[j] * L[k].v - w[k] * L[j].v);
  }
  LagrangeTerms terms;
  // dT/dq_dot_k = L . (axis k) along the motion: the angles move at their rates
  const auto [st_t, ct_t] = sin_cos(a.st, a.ct, rate[1]);
  const auto [sp_t, cp_t] = sin_cos(a.sp, a.cp, rate[2]);
  const std::array<JetVector, 3> axes_t = rate_axes(st_t, ct_t, sp_t, cp_t);
  const JetVector torque{held(N[0]), held(N[1]), held(N[2])};
  const JetVector rates{held(rate[0]), held(rate[1]), held(rate[2])};
  const JetVector L_held{held(L[0].v), held(L[1].v), held(L[2].v)};
  for (int k = 0; k < 3; ++k) {
    const Jet p = dot(L, axes_t[k]);
    terms.momentum[k] = {p.v.v, p.v.e};
    terms.momentum_rate[k] = {p.d.v, p.d.e};
    const Bounded Q = dot(torque, axes_t[k]).v;
    terms.force[k] = {Q.v, Q.e};
    // dT/dq_k = L . d omega / dq_k, omega = phi_dot z + theta_dot x' + psi_dot 3 with
    // the rates held and angle k moved (eqs. 152-153; omega has no phi)
    const Bounded seed_theta{k == 1 ? 1.0 : 0.0}, seed_psi{k == 2 ? 1.0 : 0.0};
    const auto [st_q, ct_q] = sin_cos(a.st, a.ct, seed_theta);
    const auto [sp_q, cp_q] = sin_cos(a.sp, a.cp, seed_psi);
    const std::array<JetVector, 3> axes_q = rate_axes(st_q, ct_q, sp_q, cp_q);
    JetVector omega;
    for (int i = 0; i < 3; ++i) {
      omega[i] = rates[0] * axes_q[0][i] + rates[1] * axes_q[1][i] + rates[2] * axes_q[2][i];
    }
    const Bounded dT = dot(L_held, omega).d;
    terms.dT_dq[k] = {dT.v, dT.e};
    const Bounded residual = p.d - dT - Q;
    terms.residual[k] = {residual.v, residual.e};
  }
  for (int k = 0; k < 3; ++k) {
    for (const Measured& m : {terms.dT_dq[k], terms.momentum[k], terms.momentum_rate[k],
                              terms.force[k], terms.residual[k]}) {
      if (!std::isfinite(m.value) || !std::isfinite(m.error)) return std::nullopt;
    }
  }
  return terms;
}

}  // namespace

std::optional<LagrangeTerms> lagrange_terms_exact(const PrincipalMoments& I, const EulerAngles& e,
                                                  const Eigen::Vector3d& omega_body,
                                                  const Eigen::Vector3d& torque_body,
                                                  std::optional<double> sin_theta) {
  // a pole as rates_from_body_omega has it: there phi_dot and psi_dot are undefined
  if (!rates_from_body_omega(e, omega_body, sin_theta)) return std::nullopt;
  const Trig a = trig_of(e, sin_theta);
  const std::array<Bounded, 3> w{{{omega_body(0)}, {omega_body(1)}, {omega_body(2)}}};
  // the rates: eqs. 134-136 inverted
  const Bounded phi_dot = (w[0] * a.sp + w[1] * a.cp) / a.st;
  return terms_at(I, a, w, {phi_dot, w[0] * a.cp - w[1] * a.sp, w[2] - phi_dot * a.ct},
                  torque_body);
}

std::optional<LagrangeTerms> lagrange_terms_exact(const PrincipalMoments& I, const EulerAngles& e,
                                                  const EulerRates& r,
                                                  const Eigen::Vector3d& torque_body,
                                                  std::optional<double> sin_theta) {
  const Trig a = trig_of(e, sin_theta);
  const std::array<Bounded, 3> rate{{{r.phi_dot}, {r.theta_dot}, {r.psi_dot}}};
  // omega by eqs. 134-136
  return terms_at(I, a,
                  {rate[0] * a.st * a.sp + rate[1] * a.cp, rate[0] * a.st * a.cp - rate[1] * a.sp,
                   rate[0] * a.ct + rate[2]},
                  rate, torque_body);
}

PsiTerms psi_terms(const PrincipalMoments& I, const Eigen::Vector3d& omega_body) {
  const Bounded w1{omega_body(0)}, w2{omega_body(1)}, w3{omega_body(2)};
  const Bounded momentum = Bounded{I.I3} * w3;
  const Bounded force = Bounded{I.I1} * w1 * w2 + Bounded{I.I2} * w2 * (-w1);
  return {{momentum.v, momentum.e}, {force.v, force.e}};
}

std::optional<LagrangeSteps> lagrange_steps(const EulerState& s, double time_scale) {
  const double sin_theta = std::abs(std::sin(s.angles.theta));
  LagrangeSteps steps;
  steps.noise = 64 * kEps / sin_theta;
  // Below sin(theta) = 64 eps / 1e-6 the angles an attitude gives hold fewer than six
  // digits: the equations would hold only to their own noise, which checks nothing.
  if (!(steps.noise <= 1e-6)) return std::nullopt;
  steps.angle = std::min(1e-3, sin_theta / 16);
  // omega turns the 3 axis by at most |omega| dt: in sin(theta) / (16 |omega|) theta
  // moves by at most a 16th of itself, and the stencil's 4h by a quarter
  const double omega = omega_in_body(s.angles, s.rates).norm();
  steps.time = std::min(1e-4 * time_scale, sin_theta / (16 * omega));
  // at rest every term is 0 whatever the step
  if (!(steps.time > 0 && std::isfinite(steps.time))) steps.time = 1.0;
  return steps;
}

std::vector<double> lagrange_times(double t, double h) {
  std::vector<double> times{t};
  for (const double k : kOffsets) times.push_back(t + k * h), times.push_back(t + -k * h);
  std::sort(times.begin(), times.end());
  return times;
}

// Central differences at steps h, 2h and 4h, combined by Richardson: R_h = (4 D_h - D_2h)
// / 3 has error c h^4, R_2h 16 times it, so |R_h - R_2h| / 15 estimates R_h's error where
// the h^4 term rules; |R_h - R_2h| itself, R_2h's error, bounds it also where the next
// terms are not yet small (a fast spin: 15 times safer, and needed in 2 of 1600 random
// starts). f's noise e in each value comes on top: D_h carries e / h, R_h (4 e/h + e/2h) / 3.
Measured central_derivative(const std::function<double(double)>& f, double h, double noise) {
  double d[3];
  for (int i = 0; i < 3; ++i) {
    const double k = kOffsets[i];
    d[i] = (f(k * h) - f(-k * h)) / (2 * k * h);
  }
  const double r1 = (4 * d[0] - d[1]) / 3, r2 = (4 * d[1] - d[2]) / 3;
  return {r1, std::abs(r1 - r2) + 1.5 * noise / h};
}

std::optional<LagrangeTerms> lagrange_terms(
    const PrincipalMoments& I, const std::function<std::optional<EulerState>(double)>& at, double t,
    const LagrangeSteps& steps, const Eigen::Vector3d& torque_body) {
  const std::optional<EulerState> now = at(t);
  if (!now) return std::nullopt;
  // T is quadratic in the rates and omega linear in them: dT/dq_dot_k = (I omega) .
  // d omega / dq_dot_k, and d omega / dq_dot_k is omega of the unit rate k (eqs. 153-156's
  // chain rule, exact: a difference of T over the rates would lose L's digits to T's
  // curvature I_max where the moments differ by decades).
  const auto momentum = [&](const EulerState& s, int k) {
    const Eigen::Vector3d w = omega_in_body(s.angles, s.rates);
    return I.vector().cwiseProduct(w).dot(rate_axes_in_body(s.angles).col(k));
  };
  // Noise, absolute: omega from rates R = sum |rates| holds eps R (near a pole omega_3 =
  // phi_dot cos(theta) + psi_dot cancels two rates of 1 / sin(theta)), T then eps |L| R;
  // a momentum is L along an axis read from the attitude, off by |L| times the attitude's
  // noise and its own roundoff.
  const Eigen::Vector3d w_now = omega_in_body(now->angles, now->rates);
  const double L = I.vector().cwiseProduct(w_now).norm(), R = rate_sum(now->rates);
  const double p_noise = (steps.noise + 64 * kEps) * L;
  // T's noise at the angles the differences move to: there omega (and L) can be far
  // larger than here, where a body's moments differ by decades
  const auto T_noise = [&](int k) {
    double largest_L = L;
    for (const double offset : kOffsets) {
      for (const double sign : {-1.0, 1.0}) {
        const EulerState s = moved(*now, k, sign * offset * steps.angle);
        largest_L =
            std::max(largest_L, I.vector().cwiseProduct(omega_in_body(s.angles, s.rates)).norm());
      }
    }
    return 64 * kEps * largest_L * R;
  };
  bool defined = true;
  LagrangeTerms terms;
  // Q by the axes the attitude gives: their noise, and a dot product's roundoff
  const Eigen::Vector3d Q = generalized_force(now->angles, torque_body);
  const double Q_noise = (steps.noise + 4 * kEps) * torque_body.norm();
  for (int k = 0; k < 3; ++k) {
    terms.dT_dq[k] = central_derivative(
        [&](double d) {
          const EulerState s = moved(*now, k, d);
          return euler_kinetic_energy(I, s.angles, s.rates);
        },
        steps.angle, T_noise(k));
    terms.momentum[k] = {momentum(*now, k), p_noise};
    terms.force[k] = {Q(k), Q_noise};
    terms.momentum_rate[k] = central_derivative(
        [&](double dt) {
          const std::optional<EulerState> s = at(t + dt);
          defined = defined && s.has_value();
          return s ? momentum(*s, k) : 0.0;
        },
        steps.time, p_noise);
    terms.residual[k] = {
        terms.momentum_rate[k].value - terms.dT_dq[k].value - terms.force[k].value,
        terms.momentum_rate[k].error + terms.dT_dq[k].error + terms.force[k].error};
  }
  if (!defined) return std::nullopt;
  return terms;
}

}  // namespace rigid
