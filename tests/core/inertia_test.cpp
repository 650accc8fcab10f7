// Inertia core: every worked number of sections 1-3.1 and the theorems behind them.
#include "rigid/inertia.h"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

#include "rigid/units.h"

using namespace rigid;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

// Closed-form results are sums of a handful of products: a few ulps of the
// largest term, which is O(1) for the unit lamina.
constexpr double kRoundoff = 1e-14;

// The text prints 3 decimals; a value reproduces it if it rounds to it, i.e.
// lies within half a unit in the last printed place.
bool prints_as(double value, double printed, int decimals) {
  return std::abs(value - printed) <= 0.5 * std::pow(10.0, -decimals) + 1e-12;
}

Mat3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

const Lamina kTextLamina{1.0, 1.0, 2.0, true};  // m = 1, a = 1, b = 2a: units of m a^2

}  // namespace

TEST_CASE("inertia: the lamina about its corner is eq. 20") {
  const Mat3 I = lamina_tensor(kTextLamina);
  // Ixx = m b^2/3, Iyy = m a^2/3, Ixy = -m a b/4 (eqs. 17-19), Izz = Ixx + Iyy.
  CHECK_THAT(I(0, 0), WithinAbs(4.0 / 3.0, kRoundoff));
  CHECK_THAT(I(1, 1), WithinAbs(1.0 / 3.0, kRoundoff));
  CHECK_THAT(I(2, 2), WithinAbs(5.0 / 3.0, kRoundoff));
  CHECK_THAT(I(0, 1), WithinAbs(-0.5, kRoundoff));
  CHECK_THAT(I(1, 0), WithinAbs(-0.5, kRoundoff));
  CHECK_THAT(I(0, 2), WithinAbs(0.0, kRoundoff));
  CHECK_THAT(I(1, 2), WithinAbs(0.0, kRoundoff));
}

TEST_CASE("inertia: a narrow lamina's small moment keeps its relative accuracy") {
  // b / a up to 1e6: m a^2 / 3 is 1e-12 of m b^2 / 3, and the parallel-axis shift must
  // not form it as a difference of the large terms (it lost eps (b/a)^2 relatively)
  for (const double ratio : {1e2, 1e3, 1e4, 1e6}) {
    const Lamina narrow{1e-3, 1e-3, 1e-3 * ratio, true};
    const Mat3 I = lamina_tensor(narrow);
    const double expected = narrow.mass * narrow.a * narrow.a / 3.0;
    INFO("b/a = " << ratio << ": I_yy = " << I(1, 1) << ", m a^2/3 = " << expected);
    // a few roundings of the terms m a^2/12 and m (a/2)^2
    CHECK(std::abs(I(1, 1) - expected) <= 4 * std::numeric_limits<double>::epsilon() * expected);
  }
}

TEST_CASE("inertia: the lamina about its centre is diagonal, eq. 70") {
  const Mat3 I = lamina_tensor({1.0, 1.0, 2.0, false});
  CHECK_THAT(I(0, 0), WithinAbs(1.0 / 3.0, kRoundoff));
  CHECK_THAT(I(1, 1), WithinAbs(1.0 / 12.0, kRoundoff));
  CHECK_THAT(I(2, 2), WithinAbs(5.0 / 12.0, kRoundoff));
  CHECK_THAT(I(0, 1), WithinAbs(0.0, kRoundoff));
}

TEST_CASE("inertia: sections 1-1.2 worked numbers about the 37 degree axis") {
  const Mat3 I = lamina_tensor(kTextLamina);
  const Vec3 n(0.8, 0.6, 0.0);
  CHECK(prints_as(moment_about_axis(I, n), 0.493, 3));  // eq. 21
  const Vec3 L = angular_momentum(I, n);
  CHECK(prints_as(L(0), 0.767, 3));  // eq. 28
  CHECK(prints_as(L(1), -0.20, 2));
  // Errata: |L| is 0.7923 and prints as 0.792; the text's 0.793 is the norm of
  // its rounded components.
  CHECK(prints_as(L.norm(), 0.792, 3));
  CHECK(prints_as(Vec3(0.767, -0.20, 0.0).norm(), 0.793, 3));
  CHECK(prints_as(rad_to_deg(angle_between(L, n)), 51.0, 0));
  CHECK_THAT(kinetic_energy(I, n), WithinRel(0.5 * moment_about_axis(I, n), kRoundoff));
}

TEST_CASE("inertia: section 2.3 principal angles from tan 2 theta") {
  const InPlaneAxes axes = in_plane_principal_axes(lamina_tensor(kTextLamina));
  CHECK_THAT(std::tan(axes.two_theta), WithinAbs(-1.0, kRoundoff));  // eq. 54
  CHECK_THAT(rad_to_deg(axes.theta), WithinAbs(-22.5, 1e-12));
  CHECK_THAT(rad_to_deg(axes.theta_other), WithinAbs(67.5, 1e-12));
  // The -22.5 degree axis carries 1.540 ma^2 and the 67.5 degree one 0.126 ma^2.
  CHECK(prints_as(axes.moment, 1.540, 3));
  CHECK(prints_as(axes.moment_other, 0.126, 3));
}

TEST_CASE("inertia: in-plane principal angles lie in the conventional range") {
  // A rectangle about its centre has Ixy = 0: its axes are x and y, at 0 and 90 deg (not
  // 90 and 180, nor -0), whichever side is longer.
  for (const auto& [a, b] : {std::pair{2.0, 1.0}, std::pair{1.0, 2.0}, std::pair{1.0, 1.0}}) {
    const Mat3 I = Vec3(b * b, a * a, a * a + b * b).asDiagonal();
    const InPlaneAxes axes = in_plane_principal_axes(I);
    INFO("a " << a << ", b " << b);
    CHECK(std::signbit(axes.theta) == false);
    CHECK(axes.theta == 0.0);
    CHECK(axes.theta_other == Approx(0.5 * rigid::kPi).epsilon(1e-15));
  }
  // Any lamina: 2 theta is the arctangent's principal value, each axis lies in (-90, 90]
  // deg, the two are 90 deg apart, and the moments about them are the tensor's in-plane
  // eigenvalues (Eigen's solver, a second method), to a few roundings of the largest.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double Ixx = 1.0 + u(rng), Iyy = 1.0 + u(rng);
    const double Ixy = 0.999 * std::sqrt(Ixx * Iyy) * u(rng);
    Mat3 I = Mat3::Zero();
    I << Ixx, Ixy, 0, Ixy, Iyy, 0, 0, 0, Ixx + Iyy;
    const InPlaneAxes axes = in_plane_principal_axes(I);
    INFO("Ixx " << Ixx << ", Iyy " << Iyy << ", Ixy " << Ixy);
    CHECK(axes.two_theta > -0.5 * rigid::kPi);
    CHECK(axes.two_theta <= 0.5 * rigid::kPi);
    for (const double t : {axes.theta, axes.theta_other}) {
      CHECK(t > -0.5 * rigid::kPi);
      CHECK(t <= 0.5 * rigid::kPi);
    }
    CHECK(std::abs(axes.theta - axes.theta_other) == Approx(0.5 * rigid::kPi).epsilon(1e-15));
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(I.topLeftCorner<2, 2>());
    const double lo = std::min(axes.moment, axes.moment_other);
    const double hi = std::max(axes.moment, axes.moment_other);
    const double scale = eig.eigenvalues().cwiseAbs().maxCoeff();
    CHECK_THAT(lo, WithinAbs(eig.eigenvalues()(0), 8 * kRoundoff * scale));
    CHECK_THAT(hi, WithinAbs(eig.eigenvalues()(1), 8 * kRoundoff * scale));
  }
}

TEST_CASE("inertia: section 2.4 diagonalisation gives eqs. 67-69") {
  const PrincipalAxes p = principal_axes(lamina_tensor(kTextLamina));
  CHECK(prints_as(p.moments(0), 0.126, 3));
  CHECK(prints_as(p.moments(1), 1.540, 3));
  CHECK(prints_as(p.moments(2), 1.667, 3));
  const Mat3 printed = (Mat3() << -0.3827, -0.9239, 0, 0.9239, -0.3827, 0, 0, 0, 1).finished();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) CHECK(prints_as(p.axes(i, j), printed(i, j), 4));
  }
}

TEST_CASE("inertia: section 3.1 torque about the short side is 0.500 ma^2 omega^2") {
  const Mat3 I = lamina_tensor(kTextLamina);
  const Vec3 N = fixed_axis_torque(I, Vec3::UnitX());
  const PrincipalAxes p = principal_axes(I);
  const Vec3 N_principal = p.axes * N;
  CHECK_THAT(N_principal(0), WithinAbs(0.0, kRoundoff));
  CHECK_THAT(N_principal(1), WithinAbs(0.0, kRoundoff));
  // Errata: the size is the text's 0.500; the sign is negative (eq. 76 with its axes).
  CHECK_THAT(N_principal(2), WithinAbs(-0.5, kRoundoff));
  // Eq. 76 in the principal frame agrees with omega x I omega.
  const Vec3 w = p.axes * Vec3::UnitX();
  CHECK_THAT(w(0) * w(1) * (p.moments(1) - p.moments(0)), WithinAbs(-0.5, kRoundoff));
}

TEST_CASE("inertia: section 2.1 paddle, block and cube from primitives") {
  const double m = 1.3, a = 0.7;
  const Body paddle = model_paddle(m, a);
  CHECK_THAT(paddle.com.norm(), WithinAbs(0.0, kRoundoff));
  CHECK_THAT(paddle.I_com(0, 0), WithinRel(m * a * a / 8.0, kRoundoff));
  CHECK_THAT(paddle.I_com(1, 1), WithinRel(31.0 * m * a * a / 24.0, kRoundoff));
  CHECK_THAT(paddle.I_com(2, 2), WithinRel(17.0 * m * a * a / 12.0, kRoundoff));
  const Mat3 cube = solid_box(m, a, a, a).I_com;
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  for (int k = 0; k < 20; ++k) {
    const Vec3 n(normal(rng), normal(rng), normal(rng));
    CHECK_THAT(moment_about_axis(cube, n), WithinRel(m * a * a / 6.0, kRoundoff));
  }
}

TEST_CASE("inertia: section 5.1 solid ellipsoid x^2/9 + y^2/4 + z^2 = 1 of mass pi") {
  const Body e = solid_ellipsoid(kPi, 3.0, 2.0, 1.0);
  CHECK_THAT(e.I_com(0, 0), WithinRel(kPi, kRoundoff));
  CHECK_THAT(e.I_com(1, 1), WithinRel(2.0 * kPi, kRoundoff));
  CHECK(prints_as(e.I_com(2, 2), 8.168, 3));
}

TEST_CASE("inertia: parallel-axis shift of a rod to its end gives m l^2 / 3") {
  const double m = 2.0, l = 3.0;
  const Body rod = shifted(thin_rod(m, l), Vec3(l / 2.0, 0.0, 0.0));
  const Mat3 I = inertia_about(rod, Vec3::Zero());
  CHECK_THAT(I(1, 1), WithinRel(m * l * l / 3.0, kRoundoff));
  CHECK_THAT(I(2, 2), WithinRel(m * l * l / 3.0, kRoundoff));
  CHECK_THAT(I(0, 0), WithinAbs(0.0, kRoundoff));
}

TEST_CASE("inertia: perpendicular-axis theorem for every lamina primitive") {
  for (const Body& b : {thin_disk(1.5, 0.4), thin_ring(0.7, 1.1), rectangular_lamina(2, 3, 0.5),
                        shifted(rectangular_lamina(1, 1, 2), Vec3(0.5, 1.0, 0.0))}) {
    const Mat3 I = inertia_about(b, Vec3::Zero());
    CHECK_THAT(I(2, 2), WithinRel(I(0, 0) + I(1, 1), kRoundoff));
  }
}

TEST_CASE("inertia: principal moments are unchanged by rotating the body") {
  std::mt19937 rng(42);
  const Body block = solid_box(2.0, 1.0, 2.0, 3.0) + shifted(solid_sphere(1.0, 0.5), Vec3(1, 0, 0));
  const Vec3 reference = principal_axes(block.I_com).moments;
  for (int k = 0; k < 50; ++k) {
    const Mat3 R = random_rotation(rng);
    const Vec3 moments = principal_axes(rotated(block, R).I_com).moments;
    // The eigen-solver is backward stable: errors of a few ulps of the largest moment.
    for (int i = 0; i < 3; ++i) CHECK_THAT(moments(i), WithinAbs(reference(i), 1e-13));
  }
}

TEST_CASE("inertia: principal axes are orthonormal, right-handed and diagonalise I") {
  std::mt19937 rng(3);
  for (int k = 0; k < 50; ++k) {
    const Mat3 I = rotated(solid_ellipsoid(1.0, 1.0 + k % 3, 2.0, 0.5), random_rotation(rng)).I_com;
    const PrincipalAxes p = principal_axes(I);
    CHECK((p.axes * p.axes.transpose() - Mat3::Identity()).norm() < 1e-14);
    CHECK_THAT(p.axes.determinant(), WithinAbs(1.0, 1e-14));
    const Mat3 D = p.axes * I * p.axes.transpose();
    CHECK((D - Mat3(p.moments.asDiagonal())).norm() < 1e-13 * I.norm());
  }
}

TEST_CASE("inertia: every primitive satisfies the triangle inequality") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> size(0.01, 10.0);
  for (int k = 0; k < 200; ++k) {
    const double m = size(rng), a = size(rng), b = size(rng), c = size(rng);
    for (const Body& body :
         {thin_rod(m, a), thin_ring(m, a), thin_disk(m, a), rectangular_lamina(m, a, b),
          solid_box(m, a, b, c), solid_ellipsoid(m, a, b, c), solid_sphere(m, a)}) {
      // A rod's tensor is singular about its centre, so test it off-centre.
      const Mat3 I = inertia_about(body, Vec3(0.3 * a, 0.2 * a, 0.1 * a));
      CHECK_NOTHROW(validate_inertia_tensor(I));
    }
  }
}

TEST_CASE("inertia: invalid input throws with the rule") {
  CHECK_THROWS_WITH(thin_disk(-1.0, 1.0), Catch::Contains("positive"));
  CHECK_THROWS_WITH(thin_disk(1.0, std::nan("")), Catch::Contains("finite"));
  CHECK_THROWS_WITH(solid_box(1.0, 1.0, 0.0, 1.0), Catch::Contains("positive"));
  CHECK_THROWS_WITH(moment_about_axis(Mat3::Identity(), Vec3::Zero()), Catch::Contains("zero"));
  CHECK_THROWS_WITH(validate_inertia_tensor(Vec3(1.0, 1.0, 3.0).asDiagonal()),
                    Catch::Contains("I1 + I2 >= I3"));
  CHECK_THROWS_WITH(validate_inertia_tensor(Vec3(1.0, -1.0, 1.0).asDiagonal()),
                    Catch::Contains("positive definite"));
  // tiny and near-boundary values print as themselves, not as 0.000000 or rounded equal
  CHECK_THROWS_WITH(thin_disk(-1e-320, 1.0), Catch::Contains("got -1e-320"));
  CHECK_THROWS_WITH(validate_inertia_tensor(Vec3(1.0, 1.0, 2.0000001).asDiagonal()),
                    Catch::Contains("(got 1 + 1 < 2.0000001)"));
  CHECK_THROWS_WITH(validate_inertia_tensor(Vec3(1e-300, 1e-300, 3e-300).asDiagonal()),
                    Catch::Contains("e-300 < 3e-300") && !Catch::Contains("0.000000"));
  Mat3 skew = Mat3::Identity();
  skew(0, 1) = 0.1;
  CHECK_THROWS_WITH(validate_inertia_tensor(skew), Catch::Contains("symmetric"));
  // A lamina sits exactly on the boundary I1 + I2 = I3 and is valid.
  CHECK_NOTHROW(validate_inertia_tensor(lamina_tensor(kTextLamina)));
  // The slack there is the eigen-solver's roundoff, 64 eps of I3: 640 eps beyond is a
  // body that does not exist, however it is rounded.
  const double eps = 2.2e-16;
  CHECK_THROWS_WITH(validate_inertia_tensor(Vec3(1.0, 1.0, 2.0 * (1 + 640 * eps)).asDiagonal()),
                    Catch::Contains("I1 + I2 >= I3"));
}

TEST_CASE("inertia: every primitive with unequal sides is its standard closed form") {
  // The textbook formulas typed here, for sides that differ so a swapped axis or a
  // lost factor shows: m = 2.5 kg, a = 0.3, b = 0.7, c = 1.1 m. Relative 1e-15: one
  // or two roundings on either side.
  const double m = 2.5, a = 0.3, b = 0.7, c = 1.1;
  const auto diag = [](const rigid::Body& body) { return Vec3(body.I_com.diagonal()); };
  const auto off_diagonal_zero = [](const rigid::Body& body) {
    return body.I_com(0, 1) == 0 && body.I_com(0, 2) == 0 && body.I_com(1, 2) == 0;
  };
  const struct {
    const char* name;
    rigid::Body body;
    Vec3 expected;
  } cases[] = {
      {"thin rod along x", rigid::thin_rod(m, c), {0, m * c * c / 12, m * c * c / 12}},
      {"thin ring in x-y", rigid::thin_ring(m, a), {m * a * a / 2, m * a * a / 2, m * a * a}},
      {"thin disk in x-y", rigid::thin_disk(m, a), {m * a * a / 4, m * a * a / 4, m * a * a / 2}},
      {"rectangular lamina a x b",
       rigid::rectangular_lamina(m, a, b),
       {m * b * b / 12, m * a * a / 12, m * (a * a + b * b) / 12}},
      {"solid box a x b x c",
       rigid::solid_box(m, a, b, c),
       {m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12}},
      {"solid ellipsoid a, b, c",
       rigid::solid_ellipsoid(m, a, b, c),
       {m * (b * b + c * c) / 5, m * (a * a + c * c) / 5, m * (a * a + b * b) / 5}},
      {"solid sphere",
       rigid::solid_sphere(m, b),
       {0.4 * m * b * b, 0.4 * m * b * b, 0.4 * m * b * b}},
  };
  for (const auto& k : cases) {
    INFO(k.name);
    CHECK(k.body.mass == m);
    CHECK(k.body.com.isZero(0.0));
    CHECK(off_diagonal_zero(k.body));
    for (int i = 0; i < 3; ++i) {
      if (k.expected(i) == 0) {
        CHECK(diag(k.body)(i) == 0);
      } else {
        CHECK_THAT(diag(k.body)(i), WithinRel(k.expected(i), 1e-15));
      }
    }
  }
  // A point mass at (a, b, c): m (|r|^2 - x_i^2) on the diagonal, -m x_i x_j off it (eqs. 6-11).
  const rigid::Body p = rigid::shifted(rigid::point_mass(m, Vec3::Zero()), Vec3(a, b, c));
  const Mat3 Ip = rigid::inertia_about(p, Vec3::Zero());
  CHECK_THAT(Ip(0, 0), WithinRel(m * (b * b + c * c), 1e-15));
  CHECK_THAT(Ip(1, 1), WithinRel(m * (a * a + c * c), 1e-15));
  CHECK_THAT(Ip(2, 2), WithinRel(m * (a * a + b * b), 1e-15));
  CHECK_THAT(Ip(0, 1), WithinRel(-m * a * b, 1e-15));
  CHECK_THAT(Ip(0, 2), WithinRel(-m * a * c, 1e-15));
  CHECK_THAT(Ip(1, 2), WithinRel(-m * b * c, 1e-15));
}
