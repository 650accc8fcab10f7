// Euler's equations, diagnostics, validation and Euler angles (free_body.h, rotation.h).
#include "rigid/free_body.h"

#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "rigid/rotation.h"
#include "rigid/units.h"

using namespace rigid;
using Catch::Matchers::Contains;

namespace {}

TEST_CASE("free body: moments must be positive, finite and obey the triangle inequality") {
  CHECK_NOTHROW(validate({kPi, 2 * kPi, 13 * kPi / 5}));
  // a lamina sits exactly on the boundary I3 = I1 + I2, in any order of rounding
  const double I1 = 1.27e-3, I2 = 11.81e-3;
  CHECK_NOTHROW(validate({I1, I2, I1 + I2}));
  CHECK_NOTHROW(validate({0.1, 0.2, 0.30000000000000004}));
  CHECK_NOTHROW(validate({0.1, 0.2, 0.3}));
  CHECK_THROWS_WITH(validate({1.0, 2.0, 3.1}), Contains("triangle inequality I1 + I2 >= I3"));
  CHECK_THROWS_WITH(validate({3.1, 1.0, 2.0}), Contains("I2 + I3 >= I1"));
  CHECK_THROWS_WITH(validate({0.0, 1.0, 1.0}), Contains("I1 must be positive"));
  CHECK_THROWS_WITH(validate({1.0, -1.0, 1.0}), Contains("I2 must be positive"));
  CHECK_THROWS_WITH(validate({1.0, 1.0, NAN}), Contains("I3 must be positive and finite"));
  CHECK_THROWS_AS(validate({1.0, 1.0, INFINITY}), std::invalid_argument);
  // the numbers in the message show the violation, however small or close
  CHECK_THROWS_WITH(validate({1.0, 1.0, 2.0000001}), Contains("got 1 + 1 < 2.0000001"));
  // The slack is a few ulps (4 eps of I3), no more: 40 eps over the boundary is a body
  // that does not exist.
  constexpr double eps = std::numeric_limits<double>::epsilon();
  CHECK_NOTHROW(validate({1.0, 1.0, 2.0 * (1 + 2 * eps)}));
  CHECK_THROWS_WITH(validate({1.0, 1.0, 2.0 * (1 + 40 * eps)}), Contains("I1 + I2 >= I3"));
  CHECK_THROWS_WITH(validate({1e-320, 1e-320, 3e-320}), Contains("got 1e-320 + 1e-320 < 3e-320"));
  CHECK_THROWS_WITH(validate({-1e-320, 1.0, 1.0}), Contains("got -1e-320"));
  // Hairer-Lubich-Wanner's test body breaks the triangle inequality: allowed only as a test problem
  CHECK_THROWS_AS(validate({2.0, 1.0, 2.0 / 3.0}), std::invalid_argument);
  CHECK_NOTHROW(validate({2.0, 1.0, 2.0 / 3.0}, MomentsRule::kPositiveOnly));
}

TEST_CASE("free body: Euler's equations (eq. 73) and quaternion kinematics") {
  const PrincipalMoments I{1.0, 2.0, 3.0};
  const Eigen::Vector3d w(0.3, -0.7, 1.1), N(0.5, -0.25, 0.125);
  const Eigen::Quaterniond q = axis_angle(Eigen::Vector3d(1, 2, 3).normalized(), 0.4);
  RotationState dxdt{};
  EulerRhs{I, N}(make_state(w, q), dxdt, 0.0);
  // I w_dot + w x (I w) = N, the vector form of eq. 73
  const Eigen::Vector3d Iw = L_body(I, w);
  const Eigen::Vector3d wdot(dxdt[0], dxdt[1], dxdt[2]);
  CHECK((L_body(I, wdot) + w.cross(Iw) - N).norm() < 1e-15);
  // q_dot = 1/2 q (x) (0, w)
  const Eigen::Quaterniond expected((q * Eigen::Quaterniond(0.0, w.x(), w.y(), w.z())).coeffs() *
                                    0.5);
  const Eigen::Quaterniond got(dxdt[3], dxdt[4], dxdt[5], dxdt[6]);
  CHECK((got.coeffs() - expected.coeffs()).norm() < 1e-15);
}

TEST_CASE("free body: energy, |L| and L_space diagnostics") {
  const PrincipalMoments I{kPi, 2 * kPi, 13 * kPi / 5};
  const Eigen::Vector3d w(1, 1, 1);
  // T = (pi + 2 pi + 13 pi / 5) / 2, |L|^2 = pi^2 (1 + 4 + 169/25)
  CHECK_THAT(kinetic_energy(I, w), Catch::WithinRel(0.5 * kPi * (3.0 + 2.6), 1e-15));
  CHECK_THAT(angular_momentum_magnitude(I, w),
             Catch::WithinRel(kPi * std::sqrt(5.0 + 6.76), 1e-15));
  const Eigen::Quaterniond q = axis_angle(Eigen::Vector3d::UnitZ(), kPi / 2);
  const Eigen::Vector3d Ls = L_space(I, make_state(w, q));
  // a quarter turn about z takes body (L1, L2, L3) to space (-L2, L1, L3)
  CHECK(std::abs(Ls.x() + 2 * kPi) < 1e-14);
  CHECK(std::abs(Ls.y() - kPi) < 1e-14);
  CHECK(std::abs(Ls.z() - 2.6 * kPi) < 1e-14);
}

TEST_CASE("free body: omega from the Euler rates in the three frames of section 6") {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ(), x = Eigen::Vector3d::UnitX();
  for (const auto& [e, r] : {std::pair{EulerAngles{0.3, 1.1, -2.0}, EulerRates{0.7, -0.4, 2.5}},
                             std::pair{EulerAngles{-3.0, 0.2, 2.5}, EulerRates{-1.5, 0.9, 0.1}},
                             std::pair{EulerAngles{1.0, 2.9, 0.2}, EulerRates{0.05, 3.0, -7.0}}}) {
    const Eigen::Matrix3d lambda = space_to_body_matrix(e);
    // lambda is eq. 121's three turns composed, lambda_psi lambda_theta lambda_phi (a
    // passive turn is the transpose of the active one Eigen's AngleAxis makes)
    const Eigen::Matrix3d composed = Eigen::AngleAxisd(e.psi, z).toRotationMatrix().transpose() *
                                     Eigen::AngleAxisd(e.theta, x).toRotationMatrix().transpose() *
                                     Eigen::AngleAxisd(e.phi, z).toRotationMatrix().transpose();
    CHECK((lambda - composed).norm() < 8 * DBL_EPSILON);
    CHECK((lambda * lambda.transpose() - Eigen::Matrix3d::Identity()).norm() < 8 * DBL_EPSILON);
    CHECK(std::abs(lambda.determinant() - 1) < 8 * DBL_EPSILON);
    // one omega, three frames: body = lambda space, intermediate = lambda_theta lambda_phi
    // space, each formula computed on its own (eqs. 128-130, 134-136, 137-139 corrected)
    const Eigen::Vector3d space = omega_in_space(e, r), body = omega_in_body(e, r);
    const Eigen::Matrix3d to_intermediate =
        Eigen::AngleAxisd(e.theta, x).toRotationMatrix().transpose() *
        Eigen::AngleAxisd(e.phi, z).toRotationMatrix().transpose();
    const double scale =
        8 * DBL_EPSILON * (std::abs(r.phi_dot) + std::abs(r.theta_dot) + std::abs(r.psi_dot));
    CHECK((lambda * space - body).norm() < scale);
    CHECK((to_intermediate * space - omega_intermediate(e, r)).norm() < scale);
    // and a second method: the attitude's own rate of change, q_dot = omega_space q / 2,
    // by a central difference of q(t) = q(phi + phi_dot t, ...) (its error h^2 ~ 1e-10)
    const double h = 1e-5;
    const auto q_at = [&](double t) {
      return quaternion_from_euler_zxz(
          {e.phi + r.phi_dot * t, e.theta + r.theta_dot * t, e.psi + r.psi_dot * t});
    };
    const Eigen::Quaterniond q = q_at(0), ahead = q_at(h), behind = q_at(-h);
    const Eigen::Quaterniond dq((ahead.coeffs() - behind.coeffs()) / (2 * h));
    const Eigen::Vector3d from_q = 2 * (dq * q.conjugate()).vec();
    CHECK((from_q - space).norm() < 1e-8 * (1 + space.norm()));
    // the text's eqs. 137-138 as printed are not omega: they miss it by far
    CHECK((omega_in_space_as_printed(e, r) - space).norm() > 0.1);
    CHECK(omega_in_space_as_printed(e, r).z() == space.z());  // eq. 139 is right
    // the rates back from omega in the body, away from the poles
    const std::optional<EulerRates> back = rates_from_body_omega(e, body);
    REQUIRE(back);
    const double rates = std::abs(r.phi_dot) + std::abs(r.theta_dot) + std::abs(r.psi_dot);
    const double tolerance = 16 * DBL_EPSILON * rates / std::sin(e.theta);
    CHECK(std::abs(back->phi_dot - r.phi_dot) < tolerance);
    CHECK(std::abs(back->theta_dot - r.theta_dot) < tolerance);
    CHECK(std::abs(back->psi_dot - r.psi_dot) < tolerance);
  }
  // At a pole phi and psi turn about one axis: the rates are not defined, and are not made up.
  CHECK(!rates_from_body_omega({0.3, 0.0, 0.0}, Eigen::Vector3d(0, 0, 1)));
  CHECK(!rates_from_body_omega({0.3, kPi, 0.0}, Eigen::Vector3d(0, 0, 1)));
}

TEST_CASE("free body: z-x-z Euler angles match eq. 122 and survive theta = 0") {
  for (const EulerAngles e : {EulerAngles{0.3, 1.1, -2.0}, EulerAngles{-3.0, 0.01, 2.5},
                              EulerAngles{1.0, 3.1, 0.2}, EulerAngles{2.0, 1e-9, 0.5}}) {
    const Eigen::Quaterniond q = quaternion_from_euler_zxz(e);
    // lambda (space -> body) is the transpose of the body-to-space matrix of q
    CHECK((space_to_body_matrix(e) - q.toRotationMatrix().transpose()).norm() < 1e-14);
    const EulerAngles back = euler_zxz(q);
    CHECK(std::abs(back.phi - e.phi) < 1e-12);
    CHECK(std::abs(back.theta - e.theta) < 1e-15 + 1e-14 * e.theta);
    CHECK(std::abs(back.psi - e.psi) < 1e-12);
    // and for -q, the same attitude
    const EulerAngles neg = euler_zxz(Eigen::Quaterniond(-q.coeffs()));
    CHECK(std::abs(neg.phi - e.phi) < 1e-12);
    CHECK(std::abs(neg.psi - e.psi) < 1e-12);
  }
  // theta = 0: only phi + psi is defined; it is reported as phi, with psi = 0
  const EulerAngles sleeping = euler_zxz(quaternion_from_euler_zxz({0.4, 0.0, 0.7}));
  CHECK(sleeping.theta == 0.0);
  CHECK(std::abs(sleeping.phi - 1.1) < 1e-15);
  CHECK(sleeping.psi == 0.0);
  // theta = pi: only phi - psi is defined
  const EulerAngles flipped = euler_zxz(quaternion_from_euler_zxz({0.4, kPi, 0.1}));
  CHECK(std::abs(flipped.theta - kPi) < 1e-15);
  CHECK(std::abs(flipped.phi - 0.3) < 1e-14);
}

TEST_CASE("free body: attitude distance is sign-blind and accurate for small angles") {
  const Eigen::Quaterniond a = axis_angle(Eigen::Vector3d(0, 0.6, 0.8), 1.0);
  const Eigen::Quaterniond b = a * axis_angle(Eigen::Vector3d::UnitX(), 1e-10);
  CHECK_THAT(attitude_distance(a, b), Catch::WithinRel(1e-10, 1e-6));
  CHECK(attitude_distance(a, Eigen::Quaterniond(-a.coeffs())) == 0.0);
}
