// euler_angles' library in-process: lambda against eq. 121's turns, omega in the
// three frames against each other and against the text's print, the rates back from
// omega and the poles, L and T with eq. 150's 1/2.
#include "euler_angles/euler_angles.h"

#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>

#include "lab_library.h"

using rigid::lab::InputError;
using rigid::lab::euler_angles::compute;
using rigid::lab::euler_angles::Inputs;
using rigid::test::element;
using rigid::test::names_input;
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
  // each residual within the error the lab states beside it (in the row's remark)
  for (const char* angle : {"phi", "theta", "psi"}) {
    INFO(angle);
    const std::string key = std::string("lagrange_residual_") + angle;
    bool within = false;
    for (const auto& row : report.rows()) {
      if (row.label.find(std::string("d/dt dT/d") + angle + "_dot") != 0) continue;
      const double error = std::stod(row.remark.substr(row.remark.find("+- ") + 3));
      within = std::abs(value(r, key.c_str())) <= error;
    }
    CHECK(within);
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
