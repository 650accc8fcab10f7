#include "rigid/euler_lagrange.h"

#include <algorithm>
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
    const LagrangeSteps& steps) {
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
  for (int k = 0; k < 3; ++k) {
    terms.dT_dq[k] = central_derivative(
        [&](double d) {
          const EulerState s = moved(*now, k, d);
          return euler_kinetic_energy(I, s.angles, s.rates);
        },
        steps.angle, T_noise(k));
    terms.momentum[k] = momentum(*now, k);
    terms.momentum_rate[k] = central_derivative(
        [&](double dt) {
          const std::optional<EulerState> s = at(t + dt);
          defined = defined && s.has_value();
          return s ? momentum(*s, k) : 0.0;
        },
        steps.time, p_noise);
    terms.residual[k] = {terms.momentum_rate[k].value - terms.dT_dq[k].value,
                         terms.momentum_rate[k].error + terms.dT_dq[k].error};
  }
  if (!defined) return std::nullopt;
  return terms;
}

}  // namespace rigid
