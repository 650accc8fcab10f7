// Poinsot's construction (sections 4, 4.1): omega lies on both ellipsoids, the
// polhode is their intersection, the separatrix passes the intermediate axis.
#include <catch2/catch.hpp>
#include <cmath>

#include "rigid/free_body.h"
#include "rigid/free_body_integrate.h"
#include "rigid/poinsot.h"

using namespace rigid;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using Eigen::Vector3d;

namespace {
// Sum (w_i / a_i)^2: 1 on the ellipsoid of semi-axes a.
double on_ellipsoid(const Vector3d& w, const Vector3d& a) {
  return w.cwiseQuotient(a).squaredNorm();
}

// Energy and |L| are sums of three O(1) products: a few ulps, times the
// exact solution's own error along one period (the free-body tests bound it by 64 eps).
constexpr double kOnSurface = 1e-13;

const PrincipalMoments kEllipsoid{3.14159265358979323846, 2 * 3.14159265358979323846,
                                  13 * 3.14159265358979323846 / 5};
}  // namespace

TEST_CASE("poinsot: omega0 lies on the energy and the momentum ellipsoid") {
  for (const Vector3d& w : {Vector3d(1, 1, 1), Vector3d(0.1, -2, 0.3), Vector3d(3, 0, 0.01)}) {
    const PoinsotEllipsoids e = poinsot_ellipsoids(kEllipsoid, w);
    CHECK_THAT(on_ellipsoid(w, e.energy_semi_axes), WithinAbs(1.0, 1e-15));
    CHECK_THAT(on_ellipsoid(w, e.momentum_semi_axes), WithinAbs(1.0, 1e-15));
  }
}

TEST_CASE("poinsot: the polhode is the intersection of the two ellipsoids") {
  for (const Vector3d& w0 : {Vector3d(1, 1, 1), Vector3d(1, 0.2, 0.1), Vector3d(0.05, 0.3, 1)}) {
    const PoinsotEllipsoids e = poinsot_ellipsoids(kEllipsoid, w0);
    const auto curves = polhode(kEllipsoid, w0, 200);
    REQUIRE(curves.size() == 1);
    const auto& curve = curves.front();
    REQUIRE(curve.size() == 200);
    for (const Vector3d& w : curve) {
      CHECK_THAT(on_ellipsoid(w, e.energy_semi_axes), WithinAbs(1.0, kOnSurface));
      CHECK_THAT(on_ellipsoid(w, e.momentum_semi_axes), WithinAbs(1.0, kOnSurface));
    }
    // One full period: the curve closes.
    CHECK((curve.front() - curve.back()).norm() < 1e-12);
  }
}

TEST_CASE("poinsot: points of given energy and momentum, and the separatrix") {
  const double T = 2.5;
  const Vector3d I = kEllipsoid.vector();
  for (double f : {0.05, 0.4, 0.6, 0.95}) {
    const double L2 = 2 * T * (I.minCoeff() + f * (I.maxCoeff() - I.minCoeff()));
    const Vector3d w = omega_on_energy_ellipsoid(kEllipsoid, T, L2);
    CHECK_THAT(kinetic_energy(kEllipsoid, w), WithinAbs(T, 1e-14));
    CHECK_THAT(std::pow(angular_momentum_magnitude(kEllipsoid, w), 2), WithinAbs(L2, 1e-13));
  }
  const auto curves = separatrices(kEllipsoid, T, 101);
  REQUIRE(curves.size() == 2);
  for (const auto& curve : curves) {
    for (const Vector3d& w : curve) {
      CHECK_THAT(kinetic_energy(kEllipsoid, w), WithinAbs(T, 1e-14));
      // On the separatrix L^2 = 2 T I_mid (I_mid = I2 here).
      CHECK_THAT(std::pow(angular_momentum_magnitude(kEllipsoid, w), 2),
                 WithinAbs(2 * T * kEllipsoid.I2, 1e-13));
    }
  }
  // A symmetric body has no separatrix curve; a steady spin has a point for polhode.
  CHECK(separatrices({1, 1, 2}, T, 10).empty());
  CHECK(polhode(kEllipsoid, Vector3d(0, 1, 0), 10).empty());
  // Exactly on the separatrix the polhode is its two ellipses.
  const PrincipalMoments on_separatrix{3, 3.75, 5};  // L1 = L3: L^2 = 2 T I2 exactly
  CHECK(polhode(on_separatrix, Vector3d(5, 1, 3), 50).size() == 2);
}

TEST_CASE("poinsot: section 4.1 axis ratios for I1 : I2 : I3 = 5 : 4 : 3") {
  const Vector3d I(5, 4, 3);
  const Vector3d m = momentum_ellipsoid_ratios(I), e = energy_ellipsoid_ratios(I);
  // Printed to two decimals: (0.20 : 0.25 : 0.33) and (0.44 : 0.50 : 0.58).
  CHECK_THAT(m(0), WithinAbs(0.20, 0.005));
  CHECK_THAT(m(1), WithinAbs(0.25, 0.005));
  CHECK_THAT(m(2), WithinAbs(0.33, 0.005));
  CHECK_THAT(e(1), WithinAbs(0.50, 0.005));
  CHECK_THAT(e(2), WithinAbs(0.58, 0.005));
  // Errata: 1/sqrt(5) = 0.447 rounds to 0.45; the text truncates it to 0.44.
  CHECK(std::floor(e(0) * 100) / 100 == 0.44);
  // Both ellipsoids touch on the chosen axis.
  for (int j = 0; j < 3; ++j) CHECK_THAT(momentum_ratios_touching(I, j)(j), WithinAbs(e(j), 1e-15));
  CHECK_THAT(momentum_ratios_touching(I, 2)(0), WithinAbs(0.35, 0.005));
  CHECK_THAT(momentum_ratios_touching(I, 2)(1), WithinAbs(0.43, 0.005));
  // Exactly: (1/5, 1/4, 1/3) and (1/sqrt5, 1/2, 1/sqrt3); touching on axis k scales the
  // first by sqrt(I_k): on 3, (sqrt3/5, sqrt3/4, 1/sqrt3); on 1, (1/sqrt5, sqrt5/4, sqrt5/3).
  const double s3 = std::sqrt(3.0), s5 = std::sqrt(5.0);
  CHECK_THAT(m(0), WithinRel(0.2, 1e-15));
  CHECK_THAT(e(0), WithinRel(1 / s5, 1e-15));
  CHECK_THAT(e(2), WithinRel(1 / s3, 1e-15));
  const Vector3d t3 = momentum_ratios_touching(I, 2), t1 = momentum_ratios_touching(I, 0);
  CHECK_THAT(t3(0), WithinRel(s3 / 5, 1e-15));
  CHECK_THAT(t3(1), WithinRel(s3 / 4, 1e-15));
  CHECK_THAT(t1(1), WithinRel(s5 / 4, 1e-15));
  CHECK_THAT(t1(2), WithinRel(s5 / 3, 1e-15));
}

TEST_CASE("poinsot: the herpolhode touches the invariable plane, and its turn a period two ways") {
  // the text's ellipsoid (section 5.1): I = (pi, 2 pi, 8.168), omega0 = (1, 1, 1)
  const rigid::PrincipalMoments I{M_PI, 2 * M_PI, 8.168140899333462};
  const Eigen::Vector3d w0(1, 1, 1);
  const rigid::FreeBodyExact motion(I, w0);
  const double T = motion.period();
  const Eigen::Vector3d L = I.vector().cwiseProduct(w0);  // in space: the attitude starts at 1
  const double d = 2 * motion.energy() / motion.angular_momentum_magnitude();
  for (const Eigen::Vector3d& p : rigid::herpolhode(motion, 3 * T, 97)) {
    // on the plane omega . L / |L| = 2T / |L| (to the exact solution's roundoff)
    CHECK(std::abs(p.dot(L.normalized()) - d) < 1e-13 * d);
  }
  // the turn about L in one polhode period, against the same angle from an rkf78
  // integration of Euler's equations and the attitude at tolerance 1e-13 (a second
  // method: no elliptic function), unwrapped the same way
  const double turn = rigid::herpolhode_turn_per_period(motion);
  rigid::OdeOptions o;
  o.method = rigid::Method::kRkf78;
  o.abs_tol = o.rel_tol = 1e-13;
  const auto times = rigid::uniform_times(0.0, T, 257);
  const auto run = rigid::integrate(
      rigid::FreeBodyProblem(I), rigid::make_state(w0, Eigen::Quaterniond::Identity()), times, o);
  const Eigen::Vector3d n = L.normalized(), e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  double turned = 0, previous = 0;
  for (std::size_t k = 0; k < run.samples.size(); ++k) {
    const Eigen::Vector3d p =
        rigid::attitude(run.samples[k].x) * rigid::omega_body(run.samples[k].x);
    const double a = std::atan2(p.dot(e2), p.dot(e1));
    if (k > 0) turned += std::remainder(a - previous, 2 * M_PI);
    previous = a;
  }
  INFO("exact " << turn << " rad, integrated " << turned << " rad");
  // tolerance 1e-13 per step over ~100 steps, amplified by 1/|omega_perp| ~ 1: 1e-9
  CHECK(std::abs(turn - turned) < 1e-9);
  // it is not a whole number of turns: the herpolhode does not close (in general)
  CHECK(std::abs(std::remainder(turn, 2 * M_PI)) > 1e-3);
}

TEST_CASE(
    "poinsot: a symmetric body's herpolhode turns as the space cone does, many turns a period") {
  // I1 = I2 exactly, omega nearly across the symmetry axis: the polhode period
  // 2 pi / |Omega| is long (1257 s) and the contact point goes round L ~200 times in it,
  // at |L| / I1 (section 6). Sampling the angle once per ~1/256 period missed whole
  // turns here (it gave -20156 deg for 72003.6).
  const double I1 = 1.0, I3 = 2.0;
  for (const double w3 : {0.005, 0.001, 0.3}) {
    const rigid::PrincipalMoments I{I1, I1, I3};
    const Eigen::Vector3d w0(1.0, 0.0, w3);
    const rigid::FreeBodyExact motion(I, w0);
    const double L = I.vector().cwiseProduct(w0).norm();
    const double expected = L / I1 * 2 * M_PI / (w3 * (I3 - I1) / I1);
    const double turn = rigid::herpolhode_turn_per_period(motion);
    INFO("omega3 " << w3 << ": turn " << turn << " rad, closed form " << expected);
    // the trapezoidal rule on a constant rate: exact but for rounding in the sum
    CHECK(std::abs(turn - expected) < 1e-12 * expected);
  }
}

TEST_CASE("poinsot: near a symmetric body the herpolhode turns as the space cone does") {
  // I1 = I2 (1 + 1e-9): omega precesses about L at |L| / I1 (section 6) while the
  // polhode, a circle, takes 2 pi / |Omega|, Omega = omega3 (I3 - I1) / I1
  const double I1 = 1.0, I3 = 2.0;
  const rigid::PrincipalMoments I{I1, I1 * (1 + 1e-9), I3};
  const Eigen::Vector3d w0(0.3, 0.0, 1.0);
  const rigid::FreeBodyExact motion(I, w0);
  const double L = I.vector().cwiseProduct(w0).norm();
  const double Omega = w0.z() * (I3 - I1) / I1;
  const double expected = L / I1 * 2 * M_PI / std::abs(Omega);
  INFO("turn " << rigid::herpolhode_turn_per_period(motion) << " rad, symmetric limit "
               << expected);
  // the asymmetry 1e-9 moves both by about that much, relatively
  CHECK(std::abs(std::abs(rigid::herpolhode_turn_per_period(motion)) - expected) < 1e-6 * expected);
}
