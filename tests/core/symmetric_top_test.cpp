// The free symmetric top's closed forms (symmetric_top.h) against the exact
// torque-free motion of free_body_exact.h, which knows nothing of them: it is
// Jacobi's solution (k = 0 for a symmetric body) and the attitude by R_J.
#include "rigid/symmetric_top.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "rigid/free_body_exact.h"
#include "rigid/inertia.h"
#include "rigid/units.h"

using rigid::Vec3;

namespace {

struct Case {
  const char* name;
  double I, Is, omega, alpha_deg;
};

// Prolate (the lab's football), oblate (a thin disk, Is = 2I), nearly spherical, steep alpha.
const Case kCases[] = {
    {"football", 0.0022533, 0.0012138, 60.0, 10.0},
    {"disk", 1.0, 2.0, 30.0, 5.0},
    {"near sphere", 1.0, 1.01, 2.0, 40.0},
    {"rod-like, steep", 3.0, 0.5, 1.5, 75.0},
};

rigid::FreeBodyExact exact_of(const Case& c) {
  const double a = rigid::deg_to_rad(c.alpha_deg);
  return rigid::FreeBodyExact({c.I, c.I, c.Is},
                              Vec3(c.omega * std::sin(a), 0.0, c.omega * std::cos(a)));
}

rigid::SymmetricPrecession closed_form(const Case& c) {
  return rigid::free_symmetric_precession(c.I, c.Is, c.omega, rigid::deg_to_rad(c.alpha_deg));
}

// The angle of v about the unit axis n, measured from the reference direction ref.
double angle_about(const Vec3& v, const Vec3& n, const Vec3& ref) {
  const Vec3 u = v - v.dot(n) * n, r = ref - ref.dot(n) * n;
  return std::atan2(r.cross(u).dot(n), r.dot(u));
}

}  // namespace

TEST_CASE("symmetric top: Omega is the body-frame rate of omega about 3 (Euler's equations)") {
  for (const Case& c : kCases) {
    INFO(c.name);
    const auto p = closed_form(c);
    const rigid::FreeBodyExact exact = exact_of(c);
    // Eq. 110: d omega_1/dt = -Omega omega_2, by a central difference at a time where
    // omega_2 != 0. Truncation ~ h^2 |Omega|^3 omega_0 / 6; h = 1e-4 / |Omega| makes it
    // ~1e-9 relative, above roundoff (eps / h relative ~ 1e-12).
    const double t = 0.3 * p.body_period, h = 1e-4 / std::abs(p.body_rate);
    const Vec3 w = exact.omega_body(t);
    const double dw1 = (exact.omega_body(t + h)(0) - exact.omega_body(t - h)(0)) / (2 * h);
    CHECK(dw1 == Approx(-p.body_rate * w(1)).epsilon(1e-7));
    // omega_1 + i omega_2 turns through Omega t, sign and all (eqs. 114-115), within roundoff.
    const Vec3 z = Vec3::UnitZ();
    CHECK(angle_about(w, z, exact.omega_body(0.0)) == Approx(p.body_rate * t).margin(1e-10));
  }
}

TEST_CASE("symmetric top: theta, the cones and coplanarity from L's direction") {
  for (const Case& c : kCases) {
    INFO(c.name);
    const double alpha = rigid::deg_to_rad(c.alpha_deg);
    const auto p = rigid::free_symmetric_precession(c.I, c.Is, c.omega, alpha);
    const rigid::FreeBodyExact exact = exact_of(c);
    for (double t : {0.0, 0.37 * p.space_period, 2.9 * p.space_period}) {
      const auto q = exact.attitude(t);
      const Vec3 axis3 = q * Vec3::UnitZ(), w = q * exact.omega_body(t);
      const Vec3 L = exact.L_space();
      // Roundoff of the exact motion over a few periods: 1e-12 rad is ample.
      CHECK(rigid::angle_between(L, axis3) == Approx(p.theta).margin(1e-11));
      CHECK(rigid::angle_between(w, axis3) == Approx(p.body_cone).margin(1e-11));
      CHECK(p.body_cone == alpha);
      CHECK(rigid::angle_between(w, L) == Approx(p.space_cone).margin(1e-11));
      // omega, L and 3 in one plane (eq. 141): their triple product vanishes.
      CHECK(std::abs(w.normalized().cross(L.normalized()).dot(axis3)) < 1e-12);
    }
    CHECK(p.L == Approx(exact.angular_momentum_magnitude()).epsilon(1e-14));
  }
}

TEST_CASE("symmetric top: 3 and omega turn about L at phi_dot and return after 2 pi / phi_dot") {
  for (const Case& c : kCases) {
    INFO(c.name);
    const auto p = closed_form(c);
    const rigid::FreeBodyExact exact = exact_of(c);
    const Vec3 n = exact.L_space().normalized();
    const Vec3 axis0 = exact.attitude(0.0) * Vec3::UnitZ();
    const Vec3 w0 = exact.attitude(0.0) * exact.omega_body(0.0);
    const double t = 0.21 * p.space_period;
    const auto q = exact.attitude(t);
    CHECK(angle_about(q * Vec3::UnitZ(), n, axis0) == Approx(p.space_rate * t).epsilon(1e-10));
    CHECK(angle_about(q * exact.omega_body(t), n, w0) == Approx(p.space_rate * t).epsilon(1e-10));
    // After one period the symmetry axis is back (roundoff of the attitude ~1e-13).
    const Vec3 back = exact.attitude(p.space_period) * Vec3::UnitZ();
    CHECK((back - axis0).norm() < 1e-11);
    // Eq. 147 is the same rate written with alpha.
    const double a = rigid::deg_to_rad(c.alpha_deg), r = c.Is / c.I;
    CHECK(p.space_rate ==
          Approx(c.omega * std::sqrt(1 + (r * r - 1) * std::cos(a) * std::cos(a))).epsilon(1e-14));
    // The spin about 3 relative to the precessing frame: psi_dot = omega_3 - phi_dot cos theta.
    CHECK(p.spin_rate ==
          Approx(c.omega * std::cos(a) - p.space_rate * std::cos(p.theta)).margin(1e-12 * c.omega));
  }
}

TEST_CASE("symmetric top: which cone rolls on which") {
  const double a = rigid::deg_to_rad(20.0);
  CHECK(rigid::free_symmetric_precession(2.0, 1.0, 1.0, a).contact == rigid::ConeContact::kOutside);
  CHECK(rigid::free_symmetric_precession(1.0, 2.0, 1.0, a).contact == rigid::ConeContact::kInside);
  const auto sphere = rigid::free_symmetric_precession(1.0, 1.0, 1.0, a);
  CHECK(sphere.contact == rigid::ConeContact::kNone);
  CHECK(sphere.space_cone == 0.0);
  CHECK(sphere.body_rate == 0.0);
  // A hair either side of the sphere (I - Is = +-1e-12 of I, far above roundoff of the
  // difference): the verdict follows the sign, at any alpha.
  for (const double deg : {0.001, 20.0, 89.999}) {
    const double alpha = rigid::deg_to_rad(deg);
    CHECK(rigid::free_symmetric_precession(1.0 + 1e-12, 1.0, 1.0, alpha).contact ==
          rigid::ConeContact::kOutside);
    CHECK(rigid::free_symmetric_precession(1.0 - 1e-12, 1.0, 1.0, alpha).contact ==
          rigid::ConeContact::kInside);
  }
  CHECK(std::isinf(sphere.body_period));
  CHECK(rigid::to_string(rigid::ConeContact::kInside) == "inside");
  // Earth: theta - alpha is ~3e-9 rad and keeps full precision. For small alpha,
  // theta - alpha = alpha (I - Is)/Is (1 + O(alpha^2)); alpha^2 ~ 1e-12.
  const double alpha = rigid::deg_to_rad(0.2 / 3600);
  const auto earth = rigid::free_symmetric_precession(1.0, 1.00327, 1.0, alpha);
  CHECK(earth.contact == rigid::ConeContact::kInside);
  CHECK(earth.space_cone == Approx(alpha * 0.00327 / 1.00327).epsilon(1e-11));
}

TEST_CASE("symmetric top: bad input throws std::invalid_argument") {
  const double a = rigid::deg_to_rad(10.0);
  CHECK_THROWS_AS(rigid::free_symmetric_precession(1.0, 2.5, 1.0, a), std::invalid_argument);
  CHECK_NOTHROW(rigid::free_symmetric_precession(1.0, 2.0, 1.0, a));  // a thin disk
  CHECK_THROWS_AS(rigid::free_symmetric_precession(-1.0, 1.0, 1.0, a), std::invalid_argument);
  CHECK_THROWS_AS(rigid::free_symmetric_precession(1.0, NAN, 1.0, a), std::invalid_argument);
  CHECK_THROWS_AS(rigid::free_symmetric_precession(1.0, 1.0, 0.0, a), std::invalid_argument);
  CHECK_THROWS_AS(rigid::free_symmetric_precession(1.0, 1.0, 1.0, -1e-300), std::invalid_argument);
  CHECK_THROWS_AS(rigid::free_symmetric_precession(1.0, 1.0, 1.0, rigid::kPi / 2),
                  std::invalid_argument);
  // At alpha = 0 there is no turn of 3 about L to measure.
  CHECK_THROWS_AS(rigid::integrated_precession(2.0, 1.0, 1.0, 0.0), std::invalid_argument);
}

TEST_CASE("symmetric top: a spin along 3 (alpha = 0) does not precess, its rates the limits") {
  for (const Case& c : kCases) {
    INFO(c.name);
    const auto p = rigid::free_symmetric_precession(c.I, c.Is, c.omega, 0.0);
    CHECK(p.theta == 0.0);
    CHECK(p.body_cone == 0.0);
    CHECK(p.space_cone == 0.0);
    CHECK(p.contact == rigid::ConeContact::kNone);
    CHECK(p.L == Approx(c.Is * c.omega).epsilon(1e-15));
    // The rates as alpha -> 0: at alpha = 1e-8 they differ from the limits by O(alpha^2)
    // = 1e-16 relative, below the 1e-14 asked here (a few roundings of the products).
    const auto near = rigid::free_symmetric_precession(c.I, c.Is, c.omega, 1e-8);
    CHECK(p.body_rate == Approx(near.body_rate).epsilon(1e-14));
    CHECK(p.space_rate == Approx(near.space_rate).epsilon(1e-14));
    CHECK(p.space_rate == Approx(c.omega * c.Is / c.I).epsilon(1e-15));
    // The exact motion launched along 3 keeps omega there: nothing wobbles.
    const rigid::FreeBodyExact exact({c.I, c.I, c.Is}, Vec3(0.0, 0.0, c.omega));
    for (const double t : {0.5, 3.0, 40.0}) {
      CHECK(exact.omega_body(t).head<2>().norm() <= 1e-15 * c.omega);
    }
  }
}

TEST_CASE("symmetric top: the integrated run agrees with phi_dot and brings 3 back") {
  for (const Case& c : kCases) {
    INFO(c.name);
    const auto p = closed_form(c);
    const auto check =
        rigid::integrated_precession(c.I, c.Is, c.omega, rigid::deg_to_rad(c.alpha_deg));
    // dopri5 at 1e-12 per step over one period of a few hundred steps: global error
    // well below 1e-9 (observed ~1e-12).
    CHECK(check.space_rate == Approx(p.space_rate).epsilon(1e-9));
    CHECK(check.axis_return < 1e-9);
    CHECK(check.L_space_drift_rel < 1e-9);
  }
}

TEST_CASE("symmetric top: the integrated turn is measured however small alpha is") {
  // 3 lies alpha from L: at 1e-200 rad the parts of 3 across L are ~1e-200 and their
  // cross product underflowed (the turn read 0); scaled first, the rate is the closed
  // form's to the integration's 1e-9, as in the test above.
  for (const double alpha : {1e-8, 1e-100, 1e-200, 1e-300}) {
    const auto p = rigid::free_symmetric_precession(1.0, 0.5, 1.0, alpha);
    const auto check = rigid::integrated_precession(1.0, 0.5, 1.0, alpha);
    INFO("alpha " << alpha << ": integrated " << check.space_rate << ", closed form "
                  << p.space_rate);
    CHECK(check.space_rate == Approx(p.space_rate).epsilon(1e-9));
  }
}
