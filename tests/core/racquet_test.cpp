// The tennis racquet (racquet.h) against formulas written out here from the
// text's eqs. 83-85 and Euler's equations, against the exact free body
// (free_body_exact.h, which knows nothing of the linear analysis) and against
// an integrated run (free_body_integrate.h).
#include "rigid/racquet.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "rigid/free_body_integrate.h"

using Catch::Matchers::WithinRel;

namespace {

// The text's racquet, and one with other proportions so no relation holds by accident.
const rigid::RacquetModel kText{};
const rigid::RacquetModel kOther{0.31, 0.11, 0.07, 0.52};

// eqs. 83-85, written out: R = m_l (a + l/2) / (m_a + m_l); I1 = m_a a^2 / 2;
// I2 = m_a a^2 / 2 + m_a R^2 + m_l l^2 / 12 + m_l (a + l/2 - R)^2; I3 = I1 + I2 + m_l * 0
// (a thin rod has no moment about its own axis, the ring's polar moment is m_a a^2).
struct Written {
  double R, I1, I2, I3;
};
Written written(const rigid::RacquetModel& m) {
  const double ma = m.head_mass, a = m.head_radius, ml = m.handle_mass, l = m.handle_length;
  const double R = ml * (a + l / 2) / (ma + ml);
  const double I1 = ma * a * a / 2;
  const double I2 = ma * a * a / 2 + ma * R * R + ml * l * l / 12 + ml * std::pow(a + l / 2 - R, 2);
  const double I3 = ma * a * a + ma * R * R + ml * l * l / 12 + ml * std::pow(a + l / 2 - R, 2);
  return {R, I1, I2, I3};
}

}  // namespace

TEST_CASE(
    "racquet: centre of mass and moments are eqs. 83-85 (and the text's 0.175, 1.27, 11.81, "
    "13.08)") {
  for (const auto& model : {kText, kOther}) {
    const rigid::Racquet r = rigid::make_racquet(model);
    const Written w = written(model);
    // A handful of roundings in either computation: 1e-14 relative.
    CHECK_THAT(r.cm_offset, WithinRel(w.R, 1e-14));
    CHECK_THAT(r.moments.I1, WithinRel(w.I1, 1e-14));
    CHECK_THAT(r.moments.I2, WithinRel(w.I2, 1e-14));
    CHECK_THAT(r.moments.I3, WithinRel(w.I3, 1e-14));
    // The perpendicular-axis theorem of a lamina, I3 = I1 + I2.
    CHECK_THAT(r.moments.I3, WithinRel(r.moments.I1 + r.moments.I2, 1e-14));
    // Principal axes are the body axes: no products of inertia.
    CHECK(r.body.I_com(0, 1) == 0.0);
    CHECK(r.body.I_com(0, 2) == 0.0);
    CHECK(r.body.I_com(1, 2) == 0.0);
    // The head's centre and the handle lie on axis 1 about the centre of mass.
    CHECK_THAT(-r.head_centre.x(), WithinRel(w.R, 1e-14));
    CHECK_THAT(r.handle_end.x() - r.handle_start.x(), WithinRel(model.handle_length, 1e-14));
  }
  // The text's printed values, to the digits printed.
  const rigid::Racquet r = rigid::make_racquet(kText);
  CHECK(std::round(r.cm_offset * 1e3) == 175);
  CHECK(std::round(r.moments.I1 * 1e5) == 127);
  CHECK(std::round(r.moments.I2 * 1e5) == 1181);
  CHECK(std::round(r.moments.I3 * 1e5) == 1308);
}

TEST_CASE("racquet: bad models are refused naming the rule") {
  CHECK_THROWS_AS(rigid::make_racquet({0.0, 0.13, 0.18, 0.38}), std::invalid_argument);
  CHECK_THROWS_AS(rigid::make_racquet({0.15, -0.13, 0.18, 0.38}), std::invalid_argument);
  CHECK_THROWS_AS(rigid::make_racquet({0.15, 0.13, NAN, 0.38}), std::invalid_argument);
  CHECK_THROWS_AS(rigid::make_racquet({0.15, 0.13, 0.18, INFINITY}), std::invalid_argument);
}

TEST_CASE("racquet: the linear rates from Euler's equations, in full and as eq. 92 has them") {
  const rigid::Racquet r = rigid::make_racquet(kText);
  const double I1 = r.moments.I1, I2 = r.moments.I2, I3 = r.moments.I3, spin = 10;
  const rigid::EulerCoefficients c = rigid::euler_coefficients(r.moments);
  // Axis 2: omega_1 and omega_3 grow at spin sqrt((I3 - I2)(I2 - I1)/(I1 I3)).
  const auto s2 = rigid::linear_stability(c, 1, spin);
  CHECK(s2.unstable);
  CHECK_THAT(s2.rate, WithinRel(spin * std::sqrt((I3 - I2) * (I2 - I1) / (I1 * I3)), 1e-14));
  // Axes 1 and 3 wobble at spin sqrt((I3 - I1)(I2 - I1)/(I2 I3)) and spin sqrt((I3 - I1)(I3 -
  // I2)/(I1 I2)).
  const auto s1 = rigid::linear_stability(c, 0, spin);
  const auto s3 = rigid::linear_stability(c, 2, -spin);  // the sign of the spin does not matter
  CHECK_FALSE(s1.unstable);
  CHECK_FALSE(s3.unstable);
  CHECK_THAT(s1.rate, WithinRel(spin * std::sqrt((I3 - I1) * (I2 - I1) / (I2 * I3)), 1e-14));
  CHECK_THAT(s3.rate, WithinRel(spin * std::sqrt((I3 - I1) * (I3 - I2) / (I1 * I2)), 1e-14));
  // For a lamina (I3 = I1 + I2) the spin about 3 wobbles at the spin itself, on a circle.
  CHECK_THAT(s3.rate, WithinRel(spin, 1e-14));
  CHECK_THAT(s3.axis_ratio, WithinRel(1.0, 1e-14));
  // About 1 the wobble is an ellipse: omega_2 / omega_3 = sqrt(I3 (I3 - I1) / (I2 (I2 - I1))).
  CHECK_THAT(s1.axis_ratio, WithinRel(std::sqrt(I3 * (I3 - I1) / (I2 * (I2 - I1))), 1e-14));
  // The text's simplified equations give the spin for every axis.
  const rigid::EulerCoefficients text = rigid::simplified_racquet_coefficients();
  for (int axis = 0; axis < 3; ++axis) {
    const auto s = rigid::linear_stability(text, axis, spin);
    CHECK(s.unstable == (axis == 1));
    CHECK(s.rate == spin);
  }
}

TEST_CASE("racquet: a launch has |omega| = spin and the asked transverse share") {
  for (int axis = 0; axis < 3; ++axis) {
    for (const double p : {1e-9, 0.01, 0.3, 0.49}) {
      const Eigen::Vector3d w = rigid::launch_omega(axis, 7.0, p);
      CHECK_THAT(w.norm(), WithinRel(7.0, 1e-15));
      CHECK_THAT(rigid::transverse_share(w, axis), WithinRel(p, 1e-14));
      CHECK(w((axis + 2) % 3) == 0.0);
    }
  }
}

TEST_CASE(
    "racquet: the exact wobble converges to the linear frequency as the disturbance shrinks") {
  // The exact polhode frequency differs from the linear one by O(p^2): each tenfold
  // smaller p cuts the difference a hundredfold (to within 10 %).
  for (const auto& model : {kText, kOther}) {
    const rigid::Racquet r = rigid::make_racquet(model);
    const rigid::EulerCoefficients c = rigid::euler_coefficients(r.moments);
    for (const int axis : {0, 2}) {
      const double linear = rigid::linear_stability(c, axis, 10.0).rate;
      double previous = 0;
      for (const double p : {1e-2, 1e-3, 1e-4}) {
        const rigid::FreeBodyExact motion(r.moments, rigid::launch_omega(axis, 10.0, p));
        const double deviation = std::abs(2 * M_PI / motion.period() / linear - 1);
        if (previous > 0) CHECK(deviation / previous == Approx(0.01).epsilon(0.1));
        previous = deviation;
      }
    }
  }
}

TEST_CASE("racquet: the measured growth rate approaches the linear one as share_limit^2") {
  for (const auto& model : {kText, kOther}) {
    const rigid::Racquet r = rigid::make_racquet(model);
    const double linear = rigid::linear_stability(rigid::euler_coefficients(r.moments), 1, 10).rate;
    for (const double p : {1e-2, 1e-4, 1e-12}) {
      INFO("perturbation " << p);
      const rigid::FreeBodyExact motion(r.moments, rigid::launch_omega(1, 10.0, p));
      const rigid::GrowthFit wide = rigid::measure_growth_rate(motion, 1, 0.1);
      const rigid::GrowthFit narrow = rigid::measure_growth_rate(motion, 1, 0.05);
      // The nonlinear terms lower the rate by O(s^2) at share s: below s^2/2 at the end
      // of the fit, and, once the launch is well below both shares (p <= 1e-4), halving
      // the share cuts the deviation about fourfold (3 to 5).
      const double d_wide = linear - wide.rate, d_narrow = linear - narrow.rate;
      CHECK(d_wide > 0);
      CHECK(d_narrow > 0);
      CHECK(d_wide < 0.1 * 0.1 / 2 * linear);
      CHECK(d_narrow < 0.05 * 0.05 / 2 * linear);
      if (p <= 1e-4) {
        CHECK(d_wide / d_narrow > 3);
        CHECK(d_wide / d_narrow < 5);
      }
      // The window ends where the share reaches the limit.
      CHECK_THAT(wide.share_end, WithinRel(0.1, 1e-9));
      CHECK(wide.share_begin == Approx(p).epsilon(1e-12));
      CHECK(wide.rms_residual < 1e-3);
    }
  }
  // A stable spin has no growth to measure.
  const rigid::Racquet r = rigid::make_racquet(kText);
  const rigid::FreeBodyExact stable(r.moments, rigid::launch_omega(0, 10.0, 0.01));
  CHECK_THROWS_AS(rigid::measure_growth_rate(stable, 0, 0.1), std::invalid_argument);
  const rigid::FreeBodyExact unstable(r.moments, rigid::launch_omega(1, 10.0, 0.2));
  CHECK_THROWS_AS(rigid::measure_growth_rate(unstable, 1, 0.1), std::invalid_argument);
}

TEST_CASE("racquet: the growth fit's residual is the rms over both transverse components") {
  // Recomputed here at the fit's rate: the two transverse components at its n samples
  // on [0, t_end], each fitted by A e^{rate t} + B e^{-rate t} (normal equations), the
  // rms of all 2n residuals over the largest |component|. The minimum is flat in the
  // rate, so the rate's own precision (half the digits) moves the residual by far less
  // than the 1e-6 asked (a count of n instead of 2n moves it by sqrt 2).
  const rigid::Racquet r = rigid::make_racquet(kText);
  for (const double p : {1e-2, 1e-3}) {
    INFO("perturbation " << p);
    const rigid::FreeBodyExact motion(r.moments, rigid::launch_omega(1, 10.0, p));
    const rigid::GrowthFit fit = rigid::measure_growth_rate(motion, 1, 0.1);
    const int n = static_cast<int>(fit.samples);
    REQUIRE(n >= 8);
    double sum = 0, largest = 0;
    for (const int c : {2, 0}) {
      Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
      Eigen::Vector2d rhs = Eigen::Vector2d::Zero();
      std::vector<Eigen::Vector2d> basis(n);
      std::vector<double> y(n);
      for (int i = 0; i < n; ++i) {
        const double t = fit.t_end * i / (n - 1);
        basis[i] = {std::exp(fit.rate * (t - fit.t_end)), std::exp(-fit.rate * t)};
        y[i] = motion.omega_body(t)(c);
        normal += basis[i] * basis[i].transpose();
        rhs += basis[i] * y[i];
        largest = std::max(largest, std::abs(y[i]));
      }
      const Eigen::Vector2d amplitude = normal.ldlt().solve(rhs);
      for (int i = 0; i < n; ++i) sum += std::pow(basis[i].dot(amplitude) - y[i], 2);
    }
    const double rms = std::sqrt(sum / (2 * n)) / largest;
    CHECK_THAT(fit.rms_residual, WithinRel(rms, 1e-6));
  }
}

TEST_CASE("racquet: flips found on the exact motion match an integrated run's zero crossings") {
  const rigid::Racquet r = rigid::make_racquet(kOther);
  const rigid::FreeBodyExact motion(r.moments, rigid::launch_omega(1, 10.0, 0.01));
  const double first = rigid::first_sign_change(motion, 1);
  REQUIRE(std::isfinite(first));
  // dopri5 at tolerance 1e-12 over a fine grid; the crossing by linear interpolation
  // between samples dt apart is good to ~dt^2 |omega_2''| / |omega_2'|, far below 1e-6 s.
  rigid::OdeOptions options;
  options.abs_tol = options.rel_tol = 1e-12;
  const double span = first + 0.75 * motion.period();
  const auto times = rigid::uniform_times(0.0, span, 20001);
  const rigid::FreeBodyRun run =
      rigid::integrate(rigid::FreeBodyProblem(r.moments), motion.state(0.0), times, options);
  std::vector<double> crossings;
  for (std::size_t n = 1; n < run.samples.size(); ++n) {
    const double a = rigid::omega_body(run.samples[n - 1].x)(1);
    const double b = rigid::omega_body(run.samples[n].x)(1);
    if (a * b < 0) crossings.push_back(times[n - 1] + (times[n] - times[n - 1]) * a / (a - b));
  }
  REQUIRE(crossings.size() == 2);
  CHECK(std::abs(crossings[0] - first) < 1e-6);
  // Flips come every half-period of omega_2.
  CHECK(std::abs(crossings[1] - crossings[0] - 0.5 * motion.period()) < 1e-6);
  // A stable spin never flips.
  const rigid::FreeBodyExact stable(r.moments, rigid::launch_omega(2, 10.0, 0.01));
  CHECK(std::isinf(rigid::first_sign_change(stable, 2)));
}

TEST_CASE(
    "racquet: the handle's largest tilt out of the plane across L is the closed form at L_2 = 0") {
  // On the polhode, L_1^2 is largest where L_2 = 0: there L_1^2 + L_3^2 = L^2 and
  // L_1^2/I1 + L_3^2/I3 = 2T, so L_1^2 = I1 (2T I3 - L^2) / (I3 - I1).
  for (const auto& model : {kText, kOther}) {
    const rigid::Racquet r = rigid::make_racquet(model);
    const double I1 = r.moments.I1, I3 = r.moments.I3;
    for (const double p : {0.3, 0.01, 1e-8}) {
      const rigid::FreeBodyExact motion(r.moments, rigid::launch_omega(1, 10.0, p));
      const double T2 = 2 * motion.energy(), L = motion.angular_momentum_magnitude();
      const double closed = std::sqrt(I1 * (T2 * I3 - L * L) / (I3 - I1)) / L;
      const rigid::CosineRange range = rigid::direction_cosine_range(motion, 0, motion.period());
      // Brent's refinement leaves ~eps in the value (sqrt(eps) in t at a smooth maximum).
      CHECK_THAT(range.max, WithinRel(closed, 1e-9));
      CHECK_THAT(-range.min, WithinRel(closed, 1e-9));
    }
    // Near the separatrix of a lamina this is I1 / I2.
    const rigid::FreeBodyExact near(r.moments, rigid::launch_omega(1, 10.0, 1e-9));
    CHECK_THAT(rigid::direction_cosine_range(near, 0, near.period()).max,
               WithinRel(I1 / r.moments.I2, 1e-6));
  }
}

TEST_CASE("racquet: the cosine range holds every sampled value, the span's ends included") {
  // Spans that end anywhere in the motion, most of them with the cosine still rising or
  // falling there, so the extreme is the span's own end: the range must reach it (to
  // roundoff) and contain every value of a dense grid of its own, the ends included.
  constexpr double kEps = 2.220446049250313e-16;
  const rigid::Racquet r = rigid::make_racquet(kOther);
  const rigid::FreeBodyExact motion(r.moments, rigid::launch_omega(1, 10.0, 0.01));
  const double L = motion.angular_momentum_magnitude();
  for (int axis = 0; axis < 3; ++axis) {
    const auto cosine = [&](double t) {
      return r.moments.vector()(axis) * motion.omega_body(t)(axis) / L;
    };
    for (const double share : {0.13, 0.37, 0.61, 0.77, 0.93, 1.21}) {
      INFO("axis " << axis << ", span " << share << " periods");
      const double span = share * motion.period();
      const rigid::CosineRange range = rigid::direction_cosine_range(motion, axis, span);
      // how far any value lies outside the range (0 if inside)
      double outside = 0.0;
      for (int k = 0; k <= 4000; ++k) {
        const double c = cosine(span * k / 4000);
        outside = std::max({outside, c - range.max, range.min - c});
      }
      CHECK(outside <= 4 * kEps);
      CHECK(cosine(span) <= range.max + 4 * kEps);
      CHECK(cosine(span) >= range.min - 4 * kEps);
    }
  }
}

TEST_CASE("racquet: the growth rate is the least-squares rate over the whole window") {
  // The fit's definition, written out here: omega's two transverse components at
  // `samples` times spread evenly over [0, t_end], ends included, each fitted by
  // A e^{rate t} + B e^{-rate t} with one shared rate. The rate reported minimises that
  // sum of squares: one part in 1e6 either side of it (well beyond Brent's sqrt(eps)
  // in the rate) the sum is larger; a window or grid other than the whole one moves the
  // minimum by more than that (a window short by one sample in 400: about 1e-5).
  for (const auto& model : {kText, kOther}) {
    const rigid::Racquet r = rigid::make_racquet(model);
    for (const double p : {1e-2, 1e-4}) {
      INFO("perturbation " << p);
      const rigid::FreeBodyExact motion(r.moments, rigid::launch_omega(1, 10.0, p));
      const rigid::GrowthFit fit = rigid::measure_growth_rate(motion, 1, 0.1);
      const auto n = static_cast<Eigen::Index>(fit.samples);
      Eigen::VectorXd t(n);
      Eigen::MatrixXd y(n, 2);
      for (Eigen::Index i = 0; i < n; ++i) {
        t(i) = fit.t_end * static_cast<double>(i) / static_cast<double>(n - 1);
        const Eigen::Vector3d w = motion.omega_body(t(i));
        y(i, 0) = w(2);
        y(i, 1) = w(0);
      }
      const auto sum_of_squares = [&](double rate) {
        Eigen::MatrixXd basis(n, 2);
        basis.col(0) = (rate * t.array()).exp();
        basis.col(1) = (-rate * t.array()).exp();
        // the normal equations, solved by a complete orthogonal decomposition
        const Eigen::MatrixXd a = basis.completeOrthogonalDecomposition().solve(y);
        return (basis * a - y).squaredNorm();
      };
      const double at = sum_of_squares(fit.rate);
      CHECK(sum_of_squares(fit.rate * (1 + 1e-6)) > at);
      CHECK(sum_of_squares(fit.rate * (1 - 1e-6)) > at);
    }
  }
}
