// Section 7 along the exact torque-free motion: each Euler angle's Lagrange equation
// holds to the error its differences state, and is Euler's equation (eqs. 151-159).
#include "rigid/euler_lagrange.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "rigid/free_body_exact.h"
#include "rigid/units.h"

using namespace rigid;

namespace {

// The exact motion as Euler angles and rates, the angles kept continuous from t = 0
// (phi and psi moved by whole turns to the nearest of the start's); none at a pole.
std::function<std::optional<EulerState>(double)> euler_motion(const FreeBodyExact& motion) {
  const EulerAngles start = euler_zxz(motion.attitude(0.0));
  return [&motion, start](double t) {
    return euler_state(motion.attitude(t), motion.omega_body(t), start);
  };
}

double kinetic_energy_of(const PrincipalMoments& I, const Eigen::Vector3d& omega) {
  return 0.5 *
         (I.I1 * omega(0) * omega(0) + I.I2 * omega(1) * omega(1) + I.I3 * omega(2) * omega(2));
}

}  // namespace

TEST_CASE("section 7: each Euler angle's Lagrange equation holds along the exact motion") {
  // The text's ellipsoid and a book near its separatrix, an attitude away from the poles.
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
      const std::optional<EulerState> now = at(t);
      REQUIRE(now);
      if (std::abs(std::sin(now->angles.theta)) < 0.1) continue;  // near a pole: below
      const std::optional<LagrangeSteps> steps = lagrange_steps(*now, period);
      REQUIRE(steps);
      const std::optional<LagrangeTerms> terms = lagrange_terms(I, at, t, *steps);
      REQUIRE(terms);
      const Eigen::Vector3d omega = motion.omega_body(t);
      const double T = kinetic_energy_of(I, omega);
      INFO("t = " << t);
      for (int k = 0; k < 3; ++k) {
        INFO("angle " << k << ": d/dt dT/dq_dot " << terms->momentum_rate[k].value << " +- "
                      << terms->momentum_rate[k].error << ", dT/dq " << terms->dT_dq[k].value
                      << " +- " << terms->dT_dq[k].error);
        // the equation holds to its stated error, and that error is small beside T's
        // own rate scale (T / period): the check is not vacuous
        CHECK(std::abs(terms->residual[k].value) <= terms->residual[k].error);
        CHECK(terms->residual[k].error < 1e-5 * T);
      }
      // psi's equation is Euler's (eqs. 154-158): dT/dpsi = (I1 - I2) omega_1 omega_2 and
      // dT/dpsi_dot = I3 omega_3, so d/dt (I3 omega_3) = (I1 - I2) omega_1 omega_2
      CHECK(std::abs(terms->dT_dq[2].value - (I.I1 - I.I2) * omega(0) * omega(1)) <=
            terms->dT_dq[2].error);
      CHECK(terms->momentum[2].value == Approx(I.I3 * omega(2)).epsilon(1e-12));
      const double euler_rate = (I.I1 - I.I2) * omega(0) * omega(1);  // I3 omega_3_dot
      INFO("psi: d/dt I3 omega_3 " << terms->momentum_rate[2].value << " +- "
                                   << terms->momentum_rate[2].error << ", Euler " << euler_rate);
      CHECK(std::abs(terms->momentum_rate[2].value - euler_rate) <= terms->momentum_rate[2].error);
    }
  }
}

TEST_CASE("section 7: near a pole the equations hold to their stated error, at one none") {
  // Starts ever nearer theta = 0 and pi: the Euler rates grow as 1/sin(theta) and the
  // angles read from the attitude lose digits; the steps shrink and the error grows with
  // them, and it must still cover the residual (exactly 0: the motion is exact). At the
  // pole itself, or within the noise floor, there are no terms: never NaN.
  const PrincipalMoments I{1, 2, 3};
  int checked = 0, refused = 0;
  for (const double distance : {0.3, 1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-13, 0.0}) {
    for (const double pole : {0.0, kPi}) {
      for (const EulerRates r : {EulerRates{1, 0.5, 2}, EulerRates{-3, 0, 0.2}}) {
        const EulerAngles e{0.5, pole == 0.0 ? distance : pole - distance, -1.2};
        const FreeBodyExact motion(I, omega_in_body(e, r), quaternion_from_euler_zxz(e));
        const auto at = euler_motion(motion);
        INFO("theta " << e.theta << ", rates " << r.phi_dot << ", " << r.theta_dot << ", "
                      << r.psi_dot);
        const std::optional<EulerState> now = at(0.0);
        const std::optional<LagrangeSteps> steps =
            now ? lagrange_steps(*now, motion.period()) : std::nullopt;
        const std::optional<LagrangeTerms> terms =
            steps ? lagrange_terms(I, at, 0.0, *steps) : std::nullopt;
        if (!terms) {
          // refused only within the noise floor: 64 eps / sin(theta) > 1e-6
          CHECK(std::abs(std::sin(e.theta)) < 64 * 2.3e-16 / 1e-6);
          ++refused;
          continue;
        }
        ++checked;
        const double T = kinetic_energy_of(I, motion.omega_body(0.0));
        for (int k = 0; k < 3; ++k) {
          INFO("angle " << k << ": residual " << terms->residual[k].value << " +- "
                        << terms->residual[k].error);
          CHECK(std::isfinite(terms->residual[k].value));
          CHECK(std::abs(terms->residual[k].value) <= terms->residual[k].error);
          // the error stays below the terms' own size down to sin(theta) ~ 1e-4
          if (distance >= 1e-4) CHECK(terms->residual[k].error < 1e-2 * T);
        }
      }
    }
  }
  CHECK(checked > 0);
  CHECK(refused > 0);
}

TEST_CASE("section 7: the torque's generalized forces are its virtual work on each angle") {
  // Q_k = N . (axis of rate k): N along the body's 3 gives Q_psi = N_3, Q_phi = N_3
  // cos(theta) (3 . z) and Q_theta = 0 (3 is at right angles to x').
  const EulerAngles e{0.3, 1.1, -0.4};
  const Eigen::Vector3d Q = generalized_force(e, Eigen::Vector3d(0, 0, 2));
  CHECK(Q(0) == Approx(2 * std::cos(1.1)).epsilon(1e-15));
  CHECK(std::abs(Q(1)) < 1e-15);
  CHECK(Q(2) == 2.0);
  // and the rate axes are z, x' and 3 seen from the body: lambda of each
  const Eigen::Matrix3d axes = rate_axes_in_body(e), lambda = space_to_body_matrix(e);
  CHECK((axes.col(0) - lambda * Eigen::Vector3d::UnitZ()).norm() < 1e-15);
  CHECK((axes.col(1) - lambda * Eigen::Vector3d(std::cos(0.3), std::sin(0.3), 0)).norm() < 1e-15);
  CHECK((axes.col(2) - Eigen::Vector3d::UnitZ()).norm() == 0);
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

namespace {

// A state, by omega in the body or by the rates, and its terms at 80 digits
// (make_lagrange_exact.py): dT/dq_dot, d/dt dT/dq_dot, dT/dq and Q for phi, theta, psi.
struct ExactCase {
  bool given_rates;
  double I[3], angles[3], velocity[3], torque[3];
  double terms[3][4];
};
const ExactCase kExactCases[] = {
#include "reference_lagrange_exact.inc"
};

}  // namespace

TEST_CASE("section 7: the exact terms against 80-digit references, within their bounds") {
  // Each term within the running bound on its rounding it states, and that bound tight:
  // within 64 eps of the sizes that meet in the equations, |L| times omega's and the
  // rates' sizes, and |N| (near a pole the rates grow as 1/sin(theta), and theta's terms
  // and their bound with them); the residual, 0, within its bound.
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  for (const ExactCase& c : kExactCases) {
    const PrincipalMoments I{c.I[0], c.I[1], c.I[2]};
    const EulerAngles e{c.angles[0], c.angles[1], c.angles[2]};
    const Eigen::Vector3d v(c.velocity[0], c.velocity[1], c.velocity[2]);
    const Eigen::Vector3d N(c.torque[0], c.torque[1], c.torque[2]);
    INFO("theta " << e.theta << (c.given_rates ? ", rates " : ", omega ") << v.transpose() << ", N "
                  << N.transpose());
    const EulerRates given{v(0), v(1), v(2)};
    const std::optional<LagrangeTerms> terms =
        c.given_rates ? lagrange_terms_exact(I, e, given, N) : lagrange_terms_exact(I, e, v, N);
    REQUIRE(terms);
    const Eigen::Vector3d w = c.given_rates ? omega_in_body(e, given) : v;
    const EulerRates r = c.given_rates ? given : *rates_from_body_omega(e, w);
    const double scale =
        I.vector().cwiseProduct(w).norm() *
            (w.norm() + std::abs(r.phi_dot) + std::abs(r.theta_dot) + std::abs(r.psi_dot)) +
        N.norm();
    for (int k = 0; k < 3; ++k) {
      const Measured got[4] = {terms->momentum[k], terms->momentum_rate[k], terms->dT_dq[k],
                               terms->force[k]};
      for (int m = 0; m < 4; ++m) {
        INFO("angle " << k << ", term " << m << ": " << got[m].value << " +- " << got[m].error
                      << " against " << c.terms[k][m]);
        CHECK(std::abs(got[m].value - c.terms[k][m]) <= got[m].error);
      }
      INFO("angle " << k << ": residual " << terms->residual[k].value << " +- "
                    << terms->residual[k].error << ", scale " << scale);
      CHECK(std::abs(terms->residual[k].value) <= terms->residual[k].error);
      CHECK(terms->residual[k].error <= 64 * kEps * scale);
    }
    // psi's two terms, the same by eqs. 154-157's closed form, defined at a pole too (with
    // omega from the rates rounded, each component within 4 eps of the rates' sum, on top)
    const PsiTerms psi = psi_terms(I, w);
    const double dw =
        c.given_rates ? 4 * kEps * (std::abs(v(0)) + std::abs(v(1)) + std::abs(v(2))) : 0.0;
    CHECK(std::abs(psi.momentum.value - c.terms[2][0]) <= psi.momentum.error + I.I3 * dw);
    CHECK(std::abs(psi.force.value - c.terms[2][2]) <=
          psi.force.error + (I.I1 + I.I2) * (std::abs(w(0)) + std::abs(w(1)) + dw) * dw);
    // three roundings of (I1 + I2) |omega_1 omega_2| at most: I1 - I2 may cancel
    CHECK(psi.force.error <= 2 * kEps * (I.I1 + I.I2) * std::abs(w(0) * w(1)));
  }
}

TEST_CASE("section 7: the exact terms from omega are none at a pole, psi's defined there") {
  // theta = 0 and pi exactly: omega leaves phi_dot and psi_dot undefined, only their sum
  // or difference (from the rates the terms are defined there: the references above)
  const PrincipalMoments I{1, 2, 3};
  const Eigen::Vector3d w(1, 2, 3);
  for (const double pole : {0.0, kPi}) {
    CHECK_FALSE(lagrange_terms_exact(I, {0.5, pole, 1.2}, w));
    // dT/dpsi_dot = I3 omega_3 = 9, dT/dpsi = (I1 - I2) omega_1 omega_2 = -2: exact
    const PsiTerms psi = psi_terms(I, w);
    CHECK(psi.momentum.value == 9.0);
    CHECK(psi.force.value == -2.0);
  }
  // a sine given exactly is the pole only where it is 0: 1e-300 is a state
  CHECK(lagrange_terms_exact(I, {0.5, 1e-300, 1.2}, w, Eigen::Vector3d::Zero(), 1e-300));
  CHECK_FALSE(lagrange_terms_exact(I, {0.5, 0.0, 1.2}, w, Eigen::Vector3d::Zero(), 0.0));
}
