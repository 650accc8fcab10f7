// euler_angles' library in-process: lambda against eq. 121's turns, omega in the
// three frames against each other and against the text's print, the rates back from
// omega and the poles, L and T with eq. 150's 1/2, and section 7's Lagrange equations.
// At and near the poles to 40 digits, the errata and the figures' numbers:
// euler_angles_poles_test.cpp.
#include "euler_angles/euler_angles.h"

#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "lab_library.h"

using rigid::lab::InputError;
using rigid::lab::euler_angles::compute;
using rigid::lab::euler_angles::Inputs;
using rigid::test::contains;
using rigid::test::element;
using rigid::test::kRoundoff;
using rigid::test::names_input;
using rigid::test::notes_starting;
using rigid::test::value;

TEST_CASE("euler_angles: lambda is eq. 121's three turns and omega agrees in three frames") {
  const auto report = compute(Inputs{});
  const auto& r = report.results();
  // checks the lab makes itself, each printed as roundoff
  CHECK(value(r, "lambda_vs_composed") < 16 * DBL_EPSILON);
  CHECK(value(r, "lambda_orthogonality") < 16 * DBL_EPSILON);
  CHECK(value(r, "lambda_determinant") == Approx(1).epsilon(16 * DBL_EPSILON));
  // eq. 139 by hand: omega_z = phi_dot + psi_dot cos(theta)
  const double theta = 50 * M_PI / 180;
  CHECK(element(r, "omega_space_rad_s", 2) == Approx(1.0 + 2.0 * std::cos(theta)).epsilon(1e-15));
  // eqs. 128-130 by hand
  CHECK(element(r, "omega_intermediate_rad_s", 0) == 0.5);
  CHECK(element(r, "omega_intermediate_rad_s", 1) == Approx(std::sin(theta)).epsilon(1e-15));
  // the print of eqs. 137-138 differs, and an errata note says so with the numbers
  CHECK(std::abs(element(r, "omega_space_printed_rad_s", 0) - element(r, "omega_space_rad_s", 0)) >
        0.1);
  bool errata = false;
  for (const auto& note : report.notes())
    errata = errata || note.rfind("errata: eqs. 137-138", 0) == 0;
  CHECK(errata);
}

TEST_CASE("euler_angles: the rates from omega - round trip, and none at a pole") {
  Inputs in;
  in.from_omega = Eigen::Vector3d(0.3, -1.2, 2.0);
  const auto r = compute(in).results();
  CHECK(value(r, "omega_round_trip") < 64 * DBL_EPSILON * 10);
  for (const double pole : {0.0, 180.0}) {
    Inputs at;
    at.theta_deg = pole;
    at.from_omega = Eigen::Vector3d(0.3, -1.2, 2.0);
    const auto p = compute(at).results();
    CHECK(p.at("rates_rad_s").is_null());
    CHECK(value(p, "rates_sum_rad_s") == (pole == 0 ? 2.0 : -2.0));
  }
}

TEST_CASE("euler_angles: L and T with a body's moments, T with eq. 150's 1/2") {
  Inputs in;
  in.moments = Eigen::Vector3d(1, 2, 3);
  const auto report = compute(in);
  const auto& r = report.results();
  double sum = 0;
  for (int i = 0; i < 3; ++i) {
    sum += (i + 1) * element(r, "omega_body_rad_s", i) * element(r, "omega_body_rad_s", i);
  }
  CHECK(value(r, "kinetic_energy_j") == Approx(0.5 * sum).epsilon(1e-15));
  // |L| the same in both frames
  double body = 0, space = 0;
  for (int i = 0; i < 3; ++i) {
    body += std::pow(element(r, "angular_momentum_body", i), 2);
    space += std::pow(element(r, "angular_momentum_space", i), 2);
  }
  CHECK(std::sqrt(space) == Approx(std::sqrt(body)).epsilon(8 * DBL_EPSILON));
}

TEST_CASE("euler_angles: a broken rule is an InputError naming the input") {
  Inputs in;
  in.theta_deg = 181;
  CHECK_THROWS_MATCHES(compute(in), InputError, names_input("--theta-deg"));
  in.theta_deg = -1;
  CHECK_THROWS_MATCHES(compute(in), InputError, names_input("--theta-deg"));
}

TEST_CASE("euler_angles: section 7 - each angle's Lagrange equation holds and psi's is Euler's") {
  Inputs in;
  in.moments = Eigen::Vector3d(1, 2, 3);
  const auto report = compute(in);
  const auto& r = report.results();
  // each residual within the error the lab states beside it (its remark, JSON _error)
  for (const char* angle : {"phi", "theta", "psi"}) {
    INFO(angle);
    const std::string key = std::string("lagrange_residual_") + angle;
    CHECK(std::abs(value(r, key.c_str())) <= value(r, (key + "_error").c_str()));
    CHECK(value(r, (key + "_error").c_str()) < 1e-6);  // J, beside T = 13 J: not vacuous
  }
  // psi's: dT/dpsi is Euler's (I1 - I2) omega_1 omega_2 to the differences' error
  CHECK(value(r, "lagrange_psi_force") == Approx(value(r, "euler_psi_rate")).epsilon(1e-9));
  CHECK(value(r, "lagrange_psi_momentum") ==
        Approx(3 * element(r, "omega_body_rad_s", 2)).epsilon(1e-12));
  bool errata = false;
  for (const auto& note : report.notes())
    errata = errata || note.rfind("errata: eqs. 154-156", 0) == 0;
  CHECK(errata);
}

TEST_CASE("euler_angles: section 7 at and near a pole - exact terms, the bound covering") {
  // The rates given: the terms are defined at the pole too (they need only the rates),
  // and theta's stay bounded, so every residual is resolved, within its rounding bound
  for (const double theta_deg : {0.0, 180.0, 1e-60, 1e-9, 1e-3, 0.01, 0.1, 179.99, 179.9}) {
    Inputs in;
    in.theta_deg = theta_deg;
    const auto r = compute(in).results();
    INFO("theta " << theta_deg << " deg");
    for (const char* angle : {"phi", "theta", "psi"}) {
      const std::string key = std::string("lagrange_residual_") + angle;
      REQUIRE_FALSE(r.at(key).is_null());
      CHECK(std::abs(value(r, key.c_str())) <= value(r, (key + "_error").c_str()));
      // the rates (1, 0.5, 2) rad/s and |L| below 10: a few hundred eps of that
      CHECK(value(r, (key + "_error").c_str()) < 1e-13);
    }
  }
}

TEST_CASE("euler_angles: --from-omega shows omega as given, sin(theta) near 180 deg from degrees") {
  // a body whose moments differ by 60 decades: omega rebuilt from the rates lost its
  // 1e-60 component, and L_2 with it
  Inputs in;
  in.moments = Eigen::Vector3d(1e-60, 1, 1);
  in.from_omega = Eigen::Vector3d(1, 1e-60, 0);
  const auto r = compute(in).results();
  CHECK(element(r, "omega_body_rad_s", 1) == 1e-60);
  CHECK(element(r, "angular_momentum_body", 1) == 1e-60);
  // theta = 179.9999999999 deg: sin(theta) is sin(180 deg - theta), which theta in
  // radians gives only to 1e-4; phi_dot = omega_1 sin(psi) / sin(theta) at psi = 90 deg
  Inputs near;
  near.theta_deg = 179.9999999999;
  near.psi_deg = 90;
  near.from_omega = Eigen::Vector3d(1, 0, 0);
  const double exact = 1 / std::sin((180 - near.theta_deg) * M_PI / 180);
  CHECK(element(compute(near).results(), "rates_rad_s", 0) == Approx(exact).epsilon(1e-13));
}

TEST_CASE("euler_angles: phi and psi of any size are their turns") {
  // whole turns in degrees are exact: 1e15 + 30 deg is its remainder by 360; in radians
  // first it would keep no digit of its turn
  Inputs a, b;
  a.phi_deg = 1e15 + 30, b.phi_deg = std::remainder(1e15 + 30, 360.0);
  a.psi_deg = -7.5e14, b.psi_deg = std::remainder(-7.5e14, 360.0);
  const auto ra = compute(a).results(), rb = compute(b).results();
  for (int i = 0; i < 3; ++i) {
    CHECK(element(ra, "omega_space_rad_s", i) == element(rb, "omega_space_rad_s", i));
    CHECK(element(ra, "omega_body_rad_s", i) == element(rb, "omega_body_rad_s", i));
  }
  for (const char* angle : {"phi", "theta", "psi"}) {
    const std::string key = std::string("lagrange_residual_") + angle;
    CHECK(std::abs(value(ra, key.c_str())) <= value(ra, (key + "_error").c_str()));
  }
}

TEST_CASE(
    "euler_angles: section 7.2 - with a torque, Lagrange's equations hold with Q along an "
    "integration") {
  for (const Eigen::Vector3d& torque :
       {Eigen::Vector3d(0.5, -0.25, 1.0), Eigen::Vector3d(-2, 3, 0), Eigen::Vector3d(0, 0, 0)}) {
    Inputs in;
    in.torque = torque;
    in.moments = Eigen::Vector3d(2, 3, 4);
    const auto report = compute(in);
    const auto& r = report.results();
    INFO("N = " << torque.transpose());
    // rkf78 and vern9 at 1e-13 agree to a few times that at t1
    CHECK(value(r, "torque_integration_error") < 1e-12);
    for (const char* angle : {"phi", "theta", "psi"}) {
      INFO(angle);
      const std::string key = std::string("torque_lagrange_residual_") + angle;
      CHECK(std::abs(value(r, key.c_str())) <= value(r, (key + "_error").c_str()));
      CHECK(value(r, (key + "_error").c_str()) < 1e-12);
      // and by differences along the run, Q included, to their own error
      CHECK(std::abs(value(r, (key + "_differences").c_str())) <=
            value(r, (key + "_differences_error").c_str()));
      CHECK(value(r, (key + "_differences_error").c_str()) < 1e-6);
    }
    // Q_psi is N_3: without it psi's equation misses by exactly that
    CHECK(element(r, "generalized_force", 2) == torque(2));
    CHECK(std::abs(value(r, "torque_free_residual_psi") - torque(2)) <=
          value(r, "torque_lagrange_residual_psi_error"));
    // Q_phi and Q_theta are N along z and x', at right angles: together no more than |N|
    CHECK(std::hypot(element(r, "generalized_force", 0), element(r, "generalized_force", 1)) <=
          torque.norm() * (1 + 1e-15) + 1e-300);
    // eq. 166 for each axis (eq. 164 its third) along the run
    for (int k = 1; k <= 3; ++k) {
      const std::string key = "euler_torque_residual_" + std::to_string(k);
      CHECK(std::abs(value(r, key.c_str())) <= value(r, (key + "_error").c_str()));
    }
  }
}
