// Section 7 along the exact torque-free motion: each Euler angle's Lagrange equation
// holds to the error its differences state, and is Euler's equation (eqs. 151-159).
#include "rigid/euler_lagrange.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "rigid/free_body_exact.h"
#include "rigid/units.h"

using namespace rigid;

namespace {

// The exact motion as Euler angles and rates, the angles kept continuous from t = 0
// (phi and psi moved by whole turns to the nearest of the last ones seen).
std::function<EulerState(double)> euler_motion(const FreeBodyExact& motion) {
  const EulerAngles start = euler_zxz(motion.attitude(0.0));
  return [&motion, start](double t) {
    EulerState s;
    s.angles = euler_zxz(motion.attitude(t));
    const auto near = [](double a, double to) { return to + std::remainder(a - to, 2 * kPi); };
    s.angles.phi = near(s.angles.phi, start.phi);
    s.angles.psi = near(s.angles.psi, start.psi);
    const std::optional<EulerRates> r = rates_from_body_omega(s.angles, motion.omega_body(t));
    REQUIRE(r);
    s.rates = *r;
    return s;
  };
}

}  // namespace

TEST_CASE("section 7: each Euler angle's Lagrange equation holds along the exact motion") {
  // The text's ellipsoid and a book near its separatrix, an attitude away from the poles
  // (the Euler rates are defined there).
  const double pi = kPi;
  for (const auto& [I, w] :
       {std::pair{PrincipalMoments{pi, 2 * pi, 13 * pi / 5}, Eigen::Vector3d(1, 1, 1)},
        std::pair{PrincipalMoments{0.0018133, 0.0039467, 0.0055467},
                  Eigen::Vector3d(0.06, 6, 0.06)}}) {
    const Eigen::Quaterniond tilted = quaternion_from_euler_zxz({0.4, 1.0, -0.7});
    const FreeBodyExact motion(I, w, tilted);
    const auto at = euler_motion(motion);
    const double period = motion.period();
    for (const double t : {0.0, 0.13 * period, 0.41 * period}) {
      if (std::abs(std::sin(at(t).angles.theta)) < 0.1) continue;  // near a pole: skip
      const LagrangeTerms terms = lagrange_terms(I, at, t, 1e-3, 1e-4 * period);
      const Eigen::Vector3d omega = motion.omega_body(t);
      const double T = 0.5 * (I.I1 * omega(0) * omega(0) + I.I2 * omega(1) * omega(1) +
                              I.I3 * omega(2) * omega(2));
      INFO("t = " << t);
      for (int k = 0; k < 3; ++k) {
        INFO("angle " << k << ": d/dt dT/dq_dot " << terms.momentum_rate[k].value << " +- "
                      << terms.momentum_rate[k].error << ", dT/dq " << terms.dT_dq[k].value
                      << " +- " << terms.dT_dq[k].error);
        // the equation holds to its stated error, and that error is small beside T's
        // own rate scale (T / period): the check is not vacuous
        CHECK(std::abs(terms.residual[k].value) <= terms.residual[k].error);
        CHECK(terms.residual[k].error < 1e-5 * T);
      }
      // psi's equation is Euler's (eqs. 154-158): dT/dpsi = (I1 - I2) omega_1 omega_2 and
      // dT/dpsi_dot = I3 omega_3, so d/dt (I3 omega_3) = (I1 - I2) omega_1 omega_2
      CHECK(std::abs(terms.dT_dq[2].value - (I.I1 - I.I2) * omega(0) * omega(1)) <=
            terms.dT_dq[2].error);
      CHECK(terms.momentum[2] == Approx(I.I3 * omega(2)).epsilon(1e-12));
      const double euler_rate = (I.I1 - I.I2) * omega(0) * omega(1);  // I3 omega_3_dot
      INFO("psi: d/dt I3 omega_3 " << terms.momentum_rate[2].value << " +- "
                                   << terms.momentum_rate[2].error << ", Euler " << euler_rate);
      CHECK(std::abs(terms.momentum_rate[2].value - euler_rate) <= terms.momentum_rate[2].error);
    }
  }
}

TEST_CASE("section 7: eq. 150 needs its 1/2: T is half of sum I_i omega_i^2") {
  const PrincipalMoments I{1, 2, 3};
  const EulerAngles e{0.3, 1.1, -0.4};
  const EulerRates r{0.5, -0.2, 1.5};
  const Eigen::Vector3d w = omega_in_body(e, r);
  const double sum = I.I1 * w(0) * w(0) + I.I2 * w(1) * w(1) + I.I3 * w(2) * w(2);
  CHECK(euler_kinetic_energy(I, e, r) == Approx(0.5 * sum).epsilon(1e-15));
  // and it is L.omega / 2 (eq. 81's T), the energy the rest of the chapter uses
  const Eigen::Vector3d L(I.I1 * w(0), I.I2 * w(1), I.I3 * w(2));
  CHECK(euler_kinetic_energy(I, e, r) == Approx(0.5 * L.dot(w)).epsilon(1e-15));
}
