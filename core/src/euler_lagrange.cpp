#include "rigid/euler_lagrange.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigid {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// The Euler state with angle (or rate, if `rate`) k moved by d.
EulerState moved(EulerState s, int k, double d, bool rate) {
  double* angles[3] = {&s.angles.phi, &s.angles.theta, &s.angles.psi};
  double* rates[3] = {&s.rates.phi_dot, &s.rates.theta_dot, &s.rates.psi_dot};
  *(rate ? rates[k] : angles[k]) += d;
  return s;
}

double rate_sum(const EulerRates& r) {
  return std::abs(r.phi_dot) + std::abs(r.theta_dot) + std::abs(r.psi_dot);
}

double largest(const PrincipalMoments& I) {
  return std::max({I.I1, I.I2, I.I3});
}

// The offsets of the differences: h, 2h and 4h each way. Multiplying by a power of two
// is exact, so t + kOffsets[i] * h is the same double wherever it is formed.
constexpr double kOffsets[] = {1.0, 2.0, 4.0};

}  // namespace

double euler_kinetic_energy(const PrincipalMoments& I, const EulerAngles& e, const EulerRates& r) {
  const Eigen::Vector3d w = omega_in_body(e, r);
  return 0.5 * (I.I1 * w(0) * w(0) + I.I2 * w(1) * w(1) + I.I3 * w(2) * w(2));
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
// / 3 has error c h^4, R_2h 16 times it, so |R_h - R_2h| / 15 estimates R_h's error
// (doubled here for safety); f's noise divided by h comes on top.
Measured central_derivative(const std::function<double(double)>& f, double h, double noise) {
  double d[3];
  for (int i = 0; i < 3; ++i) {
    const double k = kOffsets[i];
    d[i] = (f(k * h) - f(-k * h)) / (2 * k * h);
  }
  const double r1 = (4 * d[0] - d[1]) / 3, r2 = (4 * d[1] - d[2]) / 3;
  return {r1, 2 * std::abs(r1 - r2) / 15 + noise / h};
}

std::optional<LagrangeTerms> lagrange_terms(
    const PrincipalMoments& I, const std::function<std::optional<EulerState>(double)>& at, double t,
    const LagrangeSteps& steps) {
  const std::optional<EulerState> now = at(t);
  if (!now) return std::nullopt;
  // T is quadratic in the rates: a central difference of any step is its derivative to
  // roundoff; a step of the rates' own size keeps that roundoff near eps T / rate.
  const auto momentum = [&](const EulerState& s, int k) {
    const double size = rate_sum(s.rates) + std::numeric_limits<double>::min();
    const EulerState up = moved(s, k, size, true), down = moved(s, k, -size, true);
    return (euler_kinetic_energy(I, up.angles, up.rates) -
            euler_kinetic_energy(I, down.angles, down.rates)) /
           (2 * size);
  };
  // Noise, absolute: omega from rates R = sum |rates| holds eps R, T then eps I |omega|
  // R; a momentum is L along an axis read from the attitude, off by its noise, and a
  // difference quotient of T over the rates' size, off by eps I (|omega| + R).
  const double omega = omega_in_body(now->angles, now->rates).norm(), R = rate_sum(now->rates);
  const double T_noise = 64 * kEps * largest(I) * omega * R;
  const double p_noise = (steps.noise + 64 * kEps) * largest(I) * (omega + R);
  bool defined = true;
  LagrangeTerms terms;
  for (int k = 0; k < 3; ++k) {
    terms.dT_dq[k] = central_derivative(
        [&](double d) {
          const EulerState s = moved(*now, k, d, false);
          return euler_kinetic_energy(I, s.angles, s.rates);
        },
        steps.angle, T_noise);
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
