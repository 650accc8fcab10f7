#include "rigid/euler_lagrange.h"

#include <cmath>
#include <limits>

namespace rigid {

namespace {

// The Euler state with angle (or rate, if `rate`) k moved by d.
EulerState moved(EulerState s, int k, double d, bool rate) {
  double* angles[3] = {&s.angles.phi, &s.angles.theta, &s.angles.psi};
  double* rates[3] = {&s.rates.phi_dot, &s.rates.theta_dot, &s.rates.psi_dot};
  *(rate ? rates[k] : angles[k]) += d;
  return s;
}

// Central differences of f at steps h, 2h and 4h, combined by Richardson: R_h = (4 D_h
// - D_2h) / 3 has error c h^4, R_2h 16 times it, so |R_h - R_2h| / 15 estimates R_h's
// error (doubled here for safety); the noise of f's values divided by h comes on top,
// 64 eps |f| / h: a closed form's motion holds its digits to ~1e-14 (64 eps), not to
// the last bit, and a difference magnifies that by the value over h.
Measured differentiated(const std::function<double(double)>& f, double h, double scale) {
  const auto D = [&](double k) { return (f(k * h) - f(-k * h)) / (2 * k * h); };
  const double d1 = D(1), d2 = D(2), d4 = D(4);
  const double r1 = (4 * d1 - d2) / 3, r2 = (4 * d2 - d4) / 3;
  const double eps = std::numeric_limits<double>::epsilon();
  return {r1, 2 * std::abs(r1 - r2) / 15 + 64 * eps * scale / h};
}

}  // namespace

double euler_kinetic_energy(const PrincipalMoments& I, const EulerAngles& e, const EulerRates& r) {
  const Eigen::Vector3d w = omega_in_body(e, r);
  return 0.5 * (I.I1 * w(0) * w(0) + I.I2 * w(1) * w(1) + I.I3 * w(2) * w(2));
}

LagrangeTerms lagrange_terms(const PrincipalMoments& I, const std::function<EulerState(double)>& at,
                             double t, double angle_step, double time_step) {
  const EulerState now = at(t);
  const double T = euler_kinetic_energy(I, now.angles, now.rates);
  // T is quadratic in the rates: a central difference of any step is its derivative to
  // roundoff; a step of the rates' own size keeps that roundoff near eps T / rate.
  const auto momentum = [&](const EulerState& s, int k) {
    const double rate_size = std::abs(s.rates.phi_dot) + std::abs(s.rates.theta_dot) +
                             std::abs(s.rates.psi_dot) + std::numeric_limits<double>::min();
    const EulerState up = moved(s, k, rate_size, true), down = moved(s, k, -rate_size, true);
    return (euler_kinetic_energy(I, up.angles, up.rates) -
            euler_kinetic_energy(I, down.angles, down.rates)) /
           (2 * rate_size);
  };
  LagrangeTerms terms;
  for (int k = 0; k < 3; ++k) {
    terms.dT_dq[k] = differentiated(
        [&](double d) {
          const EulerState s = moved(now, k, d, false);
          return euler_kinetic_energy(I, s.angles, s.rates);
        },
        angle_step, T);
    terms.momentum[k] = momentum(now, k);
    terms.momentum_rate[k] =
        differentiated([&](double dt) { return momentum(at(t + dt), k); }, time_step,
                       std::abs(terms.momentum[k]) + std::numeric_limits<double>::min());
    terms.residual[k] = {terms.momentum_rate[k].value - terms.dT_dq[k].value,
                         terms.momentum_rate[k].error + terms.dT_dq[k].error};
  }
  return terms;
}

}  // namespace rigid
