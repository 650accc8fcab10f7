// The heavy symmetric top (heavy_top.h, heavy_top_integrate.h): the exact
// motion against mpmath's 30-digit integration of the Euler-angle equations
// (make_reference.py, which knows nothing of the cubic or the elliptic
// functions), its conserved quantities, turning points, regimes and limits,
// the steady rates of section 8.1, and the integrators' orders and invariants.
#include "rigid/heavy_top.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>

#include "reference_heavy_top.inc"
#include "rigid/heavy_top_integrate.h"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

// The text's top (section 8.1): a 2.00 kg disk of radius 0.05 m, 0.04 m above the tip.
const rigid::HeavyTop kText{0.25 * 2.0 * 0.05 * 0.05 + 2.0 * 0.04 * 0.04, 0.5 * 2.0 * 0.05 * 0.05,
                            2.0 * 9.8 * 0.04};
const double kS500 = 500.0 * 2 * M_PI / 60.0;
const double k30 = M_PI / 6;

rigid::HeavyTopExact exact_of(const TopReference& r) {
  return rigid::HeavyTopExact({r.I, r.Is, r.mgl}, {r.theta0, r.theta_dot0, r.phi_dot0, r.spin});
}

// The conserved quantities of eqs. 176, 177 and 191 from a sample's angles and rates.
struct Invariants {
  double E, p_phi, p_psi;
};
Invariants invariants(const rigid::HeavyTop& top, const rigid::TopAngles& a) {
  const double s = std::sin(a.theta), c = std::cos(a.theta);
  const double S = a.phi_dot * c + a.psi_dot;
  return {0.5 * top.I * (a.phi_dot * a.phi_dot * s * s + a.theta_dot * a.theta_dot) +
              0.5 * top.Is * S * S + top.mgl * c,
          top.I * a.phi_dot * s * s + top.Is * S * c, top.Is * S};
}

}  // namespace

TEST_CASE("heavy top: the exact theta, phi, psi match mpmath's 30-digit integration") {
  for (const TopReference& r : kTopReference) {
    INFO(r.name);
    const rigid::HeavyTopExact exact = exact_of(r);
    for (const auto& row : r.rows) {
      const rigid::TopAngles a = exact.angles(row[0]);
      // The closed form carries eps relative error in its phase lambda t (lambda t
      // up to ~30 here) and in the roots; phi and psi grow to ~70 rad. Measured over
      // the references: 1.9e-15 rad in theta, 7.1e-15 in phi, 2.1e-14 in psi; the
      // bounds are 4-5x those.
      CHECK_THAT(a.theta, WithinAbs(row[1], 1e-14));
      CHECK_THAT(a.phi, WithinAbs(row[2], 1e-14 + 1e-15 * std::abs(row[2])));
      CHECK_THAT(a.psi, WithinAbs(row[3], 1e-14 + 1e-15 * std::abs(row[3])));
    }
  }
}

TEST_CASE("heavy top: the nutation period and mean precession match mpmath's quadrature") {
  for (const TopReference& r : kTopReference) {
    INFO(r.name);
    const rigid::HeavyTopExact exact = exact_of(r);
    // K and Pi by Carlson's R_F and R_J carry a few ulps; the mean is a sum of two
    // such terms that may nearly cancel (a top close to a pole): 1e-12 relative.
    CHECK_THAT(exact.nutation_period(), WithinRel(r.period, 1e-13));
    CHECK_THAT(exact.mean_precession_rate(), WithinRel(r.mean_phi_dot, 1e-12));
  }
}

TEST_CASE("heavy top: theta stays between the turning angles and E, p_phi, p_psi are constant") {
  for (const TopReference& r : kTopReference) {
    INFO(r.name);
    const rigid::HeavyTopExact exact = exact_of(r);
    const rigid::HeavyTop top{r.I, r.Is, r.mgl};
    const Invariants start = invariants(top, exact.angles(0.0));
    CHECK_THAT(start.p_psi, WithinRel(exact.p_psi(), 1e-15));
    CHECK_THAT(start.E, WithinRel(exact.energy(), 1e-14));
    const double L = std::hypot(start.p_phi, start.p_psi) + top.I * std::abs(r.theta_dot0);
    // eq. 177, the start's p_phi = I phi_dot sin^2(theta) + Is S cos(theta), as the top reports it:
    // two products and a sum, ~3 roundings of L (an a-priori bound; measured 2.2e-16 L)
    CHECK_THAT(exact.p_phi(), WithinAbs(start.p_phi, 4 * DBL_EPSILON * L));
    double lowest = M_PI, highest = 0;
    for (int n = 0; n <= 2000; ++n) {
      const double t = 3.0 * exact.nutation_period() * n / 2000;
      const rigid::TopAngles a = exact.angles(t);
      // Turning angles from the cubic's roots; theta from sn^2 between them: a few ulps.
      CHECK(a.theta >= exact.theta_min() - 1e-13);
      CHECK(a.theta <= exact.theta_max() + 1e-13);
      lowest = std::min(lowest, a.theta);
      highest = std::max(highest, a.theta);
      const Invariants now = invariants(top, a);
      // Rates from the closed form carry ~eps / sin(theta) of rounding (measured: p_phi
      // 1.4e-14, p_psi 7.1e-15, of L ~ 0.1-1): bounds 5-8x those.
      CHECK_THAT(now.E, WithinAbs(start.E, 1e-11 * (std::abs(start.E) + top.mgl)));
      CHECK_THAT(now.p_phi, WithinAbs(start.p_phi, 1e-14 * L));
      CHECK_THAT(now.p_psi, WithinAbs(start.p_psi, 5e-15 * L));
    }
    // Three nutation periods sampled 2000 times reach both turning circles (to the
    // sampling's second order: (pi / 667)^2 of the amplitude). That bound is for the
    // worst phase of the samples against the turning points; these references' samples
    // land closer (2e-8 rad), which is luck of phase, not a tighter bound.
    const double amplitude = exact.theta_max() - exact.theta_min();
    CHECK(lowest - exact.theta_min() <= 3e-5 * amplitude + 1e-15);
    CHECK(exact.theta_max() - highest <= 3e-5 * amplitude + 1e-15);
  }
}

TEST_CASE("heavy top: the regime follows phi_dot at the turning circles") {
  const double slow = rigid::steady_precession_rates(kText, kS500, k30).slow;
  const struct {
    double theta_dot, phi_dot;
    rigid::TopRegime regime;
  } cases[] = {
      {0.0, 0.0, rigid::TopRegime::kCusped},    // released: phi_dot = 0 at the top circle
      {0.0, -4.0, rigid::TopRegime::kLooping},  // pushed back: phi_dot changes sign
      {0.0, 20.0, rigid::TopRegime::kWavy},     // pushed forward beyond the steady rate
      {0.5, 3.0, rigid::TopRegime::kWavy},
      {0.0, slow, rigid::TopRegime::kSteady},  // the slow steady rate of eq. 187
  };
  for (const auto& c : cases) {
    INFO("theta_dot0 " << c.theta_dot << ", phi_dot0 " << c.phi_dot);
    const rigid::HeavyTopExact exact(kText, {k30, c.theta_dot, c.phi_dot, kS500});
    CHECK(exact.regime() == c.regime);
    const double a = exact.phi_dot_at_u1(), b = exact.phi_dot_at_u2();
    if (c.regime == rigid::TopRegime::kLooping) CHECK(a * b < 0);
    if (c.regime == rigid::TopRegime::kWavy) CHECK(a * b > 0);
  }
  // At steady precession both roots coincide at theta0 to roundoff. A double root moved
  // by a rounding eps splits by ~sqrt(eps) = 1.5e-8 in general (the discriminant), so
  // 1e-7 is the method's bound, although these inputs split by 1.1e-16 only.
  const rigid::HeavyTopExact steady(kText, {k30, 0.0, slow, kS500});
  CHECK(steady.theta_max() - steady.theta_min() < 1e-7);
  CHECK_THAT(steady.mean_precession_rate(), WithinRel(slow, 1e-7));
}

TEST_CASE("heavy top: a cusp at the far circle is told from a wave or a loop a hair away") {
  // Released from rest at 30 deg the top cusps at its upper circle. Started instead at
  // its lower circle with that motion's phi_dot there, the cusp is the far circle, where
  // phi_dot's numerator b - a u2 is zero only to the roundoff of the start's phi_dot
  // (a few eps of its terms): still cusped. phi_dot there changed by 1e-9 of itself moves
  // that numerator by ~1e-9 of its terms, far beyond roundoff: more phi_dot lifts the top
  // past where phi_dot is zero, a loop; less, a wave (b - a u at the far circle -7.5e-9
  // and +7.5e-9 by mpmath's roots at 50 digits).
  const rigid::HeavyTopExact released(kText, {k30, 0.0, 0.0, kS500});
  const rigid::TopAngles low = released.angles(0.5 * released.nutation_period());
  REQUIRE(std::abs(low.theta_dot) < 8e-15);  // measured 8.7e-16
  const auto regime = [&](double factor) {
    return rigid::HeavyTopExact(kText, {low.theta, 0.0, low.phi_dot * factor, kS500}).regime();
  };
  CHECK(regime(1.0) == rigid::TopRegime::kCusped);
  CHECK(regime(1 + 1e-9) == rigid::TopRegime::kLooping);
  CHECK(regime(1 - 1e-9) == rigid::TopRegime::kWavy);
}

TEST_CASE("heavy top: eq. 187's steady rates solve eq. 184 with theta_ddot = 0") {
  for (const double theta : {0.1, k30, 1.2, M_PI / 2, 2.0}) {
    INFO("theta " << theta);
    const rigid::SteadyPrecession p = rigid::steady_precession_rates(kText, kS500, theta);
    REQUIRE(p.exists);
    const auto residual = [&](double phi_dot) {  // mgl - Is S phi_dot + I phi_dot^2 cos theta
      return kText.mgl - kText.Is * kS500 * phi_dot + kText.I * phi_dot * phi_dot * std::cos(theta);
    };
    // Each term is at most ~mgl (or Is S phi_dot); their sum vanishes to a few ulps of it.
    CHECK(std::abs(residual(p.slow)) <=
          4 * DBL_EPSILON * (kText.mgl + kText.Is * kS500 * std::abs(p.slow)));
    if (std::isfinite(p.fast)) {
      CHECK(std::abs(residual(p.fast)) <=
            1e-13 * (kText.mgl + kText.Is * kS500 * std::abs(p.fast)));
    }
    // Started at either rate with theta_dot = 0, the exact motion does not nod.
    for (const double rate : {p.slow, p.fast}) {
      if (!std::isfinite(rate)) continue;
      const rigid::HeavyTopExact exact(kText, {theta, 0.0, rate, kS500});
      CHECK(exact.theta_max() - exact.theta_min() < 1e-7);  // ~sqrt(eps): a double root
    }
  }
  // Horizontal: the slow rate is eq. 185's and the fast one is infinite.
  const rigid::SteadyPrecession h = rigid::steady_precession_rates(kText, kS500, M_PI / 2);
  CHECK_THAT(h.slow, WithinRel(rigid::horizontal_precession_rate(kText, kS500), 1e-15));
  // Below the minimum spin (eq. 188) there is no steady precession near upright.
  const double S_min = rigid::sleeping_min_spin(kText);
  CHECK(rigid::steady_precession_rates(kText, 0.99 * S_min, 1e-3).exists == false);
  CHECK(rigid::steady_precession_rates(kText, 1.01 * S_min, 1e-3).exists);
}

TEST_CASE("heavy top: a sleeping top nods a little above the minimum spin and falls below it") {
  const double S_min = rigid::sleeping_min_spin(kText);
  const double hair = 1e-4;
  const rigid::HeavyTopExact above(kText, {hair, 0.0, 0.0, 1.05 * S_min});
  const rigid::HeavyTopExact below(kText, {hair, 0.0, 0.0, 0.95 * S_min});
  // Above: the axis stays within a few times its start; below it falls far.
  CHECK(above.theta_max() < 10 * hair);
  CHECK(below.theta_max() > 0.3);
  // Exactly upright with no theta_dot it sleeps, whatever the spin.
  const rigid::HeavyTopExact upright(kText, {0.0, 0.0, 0.0, 0.5 * S_min});
  CHECK(upright.regime() == rigid::TopRegime::kSleeping);
  CHECK(upright.theta(1.0) == 0.0);
  CHECK_THROWS_AS(rigid::HeavyTopExact(kText, {0.0, 0.0, 0.0, 0.0}), std::invalid_argument);
  CHECK_THROWS_AS(rigid::HeavyTopExact(kText, {M_PI, 0.0, 0.0, 1.0}), std::invalid_argument);
  CHECK_THROWS_AS(rigid::HeavyTopExact(kText, {-0.1, 0.0, 0.0, 1.0}), std::invalid_argument);
}

TEST_CASE("heavy top: a fast top nods at Is S / I with amplitude 2 mgl I sin(theta0)/(Is S)^2") {
  // Released from rest (Goldstein 5.7): frequency -> a = Is S / I and amplitude in
  // theta -> beta sin(theta0)/a^2, each with relative error O(beta / a^2): tenfold
  // spin, a hundredfold smaller error.
  const rigid::HeavyTop top{5.0, 1.0, 20.0};
  double previous_f = 0, previous_a = 0;
  for (const double S : {500.0, 5000.0, 50000.0}) {
    const rigid::HeavyTopExact exact(top, {0.05, 0.0, 0.0, S});
    const double a = top.Is * S / top.I;
    const double f_err = std::abs(2 * M_PI / exact.nutation_period() / a - 1);
    const double amp = exact.theta_max() - exact.theta_min();
    const double a_err =
        std::abs(amp / (2 * top.mgl * top.I * std::sin(0.05) / std::pow(top.Is * S, 2)) - 1);
    if (previous_f > 0) {
      CHECK(f_err / previous_f == Approx(0.01).epsilon(0.2));
      CHECK(a_err / previous_a == Approx(0.01).epsilon(0.2));
    }
    previous_f = f_err;
    previous_a = a_err;
  }
}

TEST_CASE("heavy top: integrators agree with the exact theta, splittings keep p_phi, p_psi") {
  const rigid::HeavyTopExact exact(kText, {k30, 0.5, 3.0, kS500});
  const rigid::RotationState x0 = rigid::heavy_top_state(exact.angles(0.0));
  const std::vector<double> times = rigid::uniform_times(0.0, 3 * exact.nutation_period(), 301);
  const auto error = [&](const rigid::HeavyTopRun& run) {
    double e = 0;
    for (const auto& s : run.samples) {
      e = std::max(e, std::abs(rigid::tilt_of(rigid::attitude(s.x)) - exact.theta(s.t)));
    }
    return e;
  };
  for (const rigid::Method m : rigid::kAllMethods) {
    INFO(rigid::method_name(m));
    rigid::OdeOptions o;
    o.method = m;
    o.abs_tol = o.rel_tol = 1e-10;
    o.step = 1e-3;
    const rigid::HeavyTopRun run = rigid::integrate(rigid::HeavyTopProblem(kText), x0, times, o);
    // Tolerance 1e-10 over ~3 nutation periods; the fixed steps at 1e-3 s
    // (lambda h ~ 0.02): rk4 ~ (lambda h)^4, the splitting ~ (lambda h)^2.
    const double bound = m == rigid::Method::kSplitting ? 1e-4 : 1e-7;
    CHECK(error(run) < bound);
    CHECK(run.max_invariant_error[rigid::HeavyTopProblem::kEnergy] < bound);
    if (m == rigid::Method::kSplitting || m == rigid::Method::kSplitting4) {
      // Every sub-step is a rotation or a torque normal to z and 3: roundoff only, a
      // random walk of ~eps sqrt(30 n) ~ 4e-14 over n ~ 1300 steps (measured 4.1e-15).
      CHECK(run.max_invariant_error[rigid::HeavyTopProblem::kPPhi] < 3e-14);
      CHECK(run.max_invariant_error[rigid::HeavyTopProblem::kPPsi] < 3e-14);
    }
  }
}

TEST_CASE("heavy top: the splittings' observed orders are 2 and 4 by step halving") {
  const rigid::HeavyTopExact exact(kText, {k30, 0.5, 3.0, kS500});
  const rigid::RotationState x0 = rigid::heavy_top_state(exact.angles(0.0));
  // Samples on a grid every step divides, so each run takes whole steps only;
  // steps from lambda h ~ 0.08 down, where every method is in its asymptotic range.
  const double T = 0.512;
  const std::vector<double> times = rigid::uniform_times(0.0, T, 9);
  for (const auto& [m, order] :
       {std::pair{rigid::Method::kSplitting, 2}, std::pair{rigid::Method::kSplitting4, 4},
        std::pair{rigid::Method::kRk4, 4}}) {
    INFO(rigid::method_name(m));
    double previous = 0;
    for (const double h : {4e-3, 2e-3, 1e-3}) {
      rigid::OdeOptions o;
      o.method = m;
      o.step = h;
      const rigid::HeavyTopRun run = rigid::integrate(rigid::HeavyTopProblem(kText), x0, times, o);
      double e = 0;  // the largest angle between the run's attitude and the exact one
      for (const auto& s : run.samples) {
        const Eigen::Quaterniond d = rigid::attitude(s.x).conjugate() * exact.attitude(s.t);
        e = std::max(e, 2 * std::atan2(d.vec().norm(), std::abs(d.w())));
      }
      if (previous > 0) {
        const double observed = std::log2(previous / e);
        CHECK(observed == Approx(order).margin(0.3));
      }
      previous = e;
    }
  }
}

TEST_CASE("heavy top: through a pole the Euler angles jump and the attitude goes on smoothly") {
  // Upright with theta_dot (through the north pole each period), a pendulum with no
  // spin through the bottom (south), and a spinning top started upright with theta_dot.
  const struct {
    const char* name;
    rigid::HeavyTop top;
    rigid::TopStart start;
  } cases[] = {
      {"upright, theta_dot0 = 1", kText, {0.0, 1.0, 0.0, kS500}},
      {"no spin: a pendulum through the bottom", kText, {k30, 0.0, 0.0, 0.0}},
      {"no spin, from below", kText, {2.0, 2.0, 0.0, 0.0}},
      {"slow spin, upright, theta_dot0 = 3", kText, {0.0, 3.0, 0.0, 100.0 * 2 * M_PI / 60}},
  };
  for (const auto& c : cases) {
    INFO(c.name);
    const rigid::HeavyTopExact exact(c.top, c.start);
    REQUIRE(std::isfinite(exact.nutation_period()));
    CHECK(std::isfinite(exact.mean_precession_rate()));
    // dopri5 is not used: rkf78 at 1e-13 on the quaternion, which knows no poles.
    rigid::OdeOptions o;
    o.method = rigid::Method::kRkf78;
    o.abs_tol = o.rel_tol = 1e-13;
    const std::vector<double> times = rigid::uniform_times(0.0, 3 * exact.nutation_period(), 601);
    const rigid::HeavyTopRun run = rigid::integrate(
        rigid::HeavyTopProblem(c.top), rigid::heavy_top_state(exact.angles(0.0)), times, o);
    double worst = 0;
    for (const rigid::HeavyTopRun::Sample& s : run.samples) {
      const Eigen::Quaterniond d = rigid::attitude(s.x).conjugate() * exact.attitude(s.t);
      worst = std::max(worst, 2 * std::atan2(d.vec().norm(), std::abs(d.w())));
      // omega from the exact angles and rates, against the integrated one.
      const Eigen::Vector3d w = rigid::euler_omega_body(exact.angles(s.t));
      const Eigen::Vector3d omega = rigid::omega_body(s.x);
      CHECK((w - omega).norm() <=
            1e-12 * (1 + omega.norm()));  // measured 2.3e-12 at 1 + abs omega = 9.6
    }
    // rkf78 at 1e-13 over three periods: the attitudes agree to 1.6e-13 rad.
    CHECK(worst < 1e-12);
  }
}

TEST_CASE("heavy top: a top that barely spins swings through the bottom with its energy kept") {
  // Released at 30 deg with S from 1e-3 down to 1e-200 rad/s: the axis swings to within
  // 1 + u1 ~ (b + a)^2 / (2 beta (1 + u0)) of straight down (1e-10 .. below underflow).
  // 1 + u1 was formed as (1 + u0) + w1 and held only roundoff of 1, so phi_dot =
  // (b + a)/(2 (1 + u)) near the bottom came out orders of magnitude off: the energy
  // error was 3e16 at S = 1e-6. The Euler angles themselves are ill-conditioned there:
  // theta holds pi - theta only to eps pi, and E's sensitivity to it, I phi_dot^2 sin
  // cos, is 2e10 at the bottom at S = 1e-9. Bound: each sample's energy within what
  // rounding its angles and rates to doubles moves E (first order, each to eps of
  // itself, 4x for their sum), plus 1e-14 of (T0 + mgl) for the evaluation (measured:
  // at most 0.16 of that bound).
  for (const double spin : {1e-3, 1e-4, 1e-5, 1e-6, 1e-9, 1e-30, 1e-200}) {
    const rigid::HeavyTopExact exact(kText, {k30, 0.0, 0.0, spin});
    const Invariants start = invariants(kText, exact.angles(0.0));
    const double scale = 0.5 * kText.Is * spin * spin + kText.mgl;
    double worst = 0.0;  // the largest error in units of its bound
    for (int k = 0; k <= 4000; ++k) {
      const double t = 3.0 * exact.nutation_period() * k / 4000.0;
      const rigid::TopAngles a = exact.angles(t);
      const double sn = std::sin(a.theta), cs = std::cos(a.theta);
      const double S = a.phi_dot * cs + a.psi_dot;
      const double dE_dtheta = kText.I * a.phi_dot * a.phi_dot * sn * cs -
                               kText.Is * S * a.phi_dot * sn - kText.mgl * sn;
      const double rounding =
          DBL_EPSILON * (std::abs(dE_dtheta * a.theta) +
                         std::abs((kText.I * a.phi_dot * sn * sn + kText.Is * S * cs) * a.phi_dot) +
                         std::abs(kText.Is * S) * (std::abs(a.phi_dot * cs) + std::abs(a.psi_dot)) +
                         kText.I * a.theta_dot * a.theta_dot);
      const double bound = 4 * rounding + 1e-14 * scale;
      worst = std::max(worst, std::abs(invariants(kText, a).E - start.E) / bound);
    }
    INFO("S = " << spin << " rad/s: theta_max " << exact.theta_max() * 180.0 / M_PI
                << " deg, energy error " << worst << " of its bound");
    CHECK(worst <= 1.0);
    CHECK(exact.theta_max() <= M_PI);
  }
}

// Released from rest a hair from upright (make_edge_cases.py: 60 digits, u0 divided out).
struct NearUpright {
  double theta0_deg, spin, period;
};
const NearUpright kNearUpright[] = {
#include "reference_near_upright.inc"
};

TEST_CASE("heavy top: released a hair from upright, the period keeps 1 - u0 below roundoff of 1") {
  // 1 - u0 = theta0^2 / 2 from 1.5e-14 down to 1.5e-20: u3 - u2 is of that size, and the
  // roots about u0 held it only to roundoff of 1 (theta0 = 1e-6 deg, S = 10: 3.3070 s for
  // 3.0676; and the top was taken as passing through upright). About the north pole its
  // relative accuracy is kept: the period to ~1e-14 (K ~ ln(4/k') and lambda, a few ulps).
  for (const NearUpright& c : kNearUpright) {
    const rigid::HeavyTopExact exact(kText, {c.theta0_deg * M_PI / 180.0, 0.0, 0.0, c.spin});
    INFO("theta0 " << c.theta0_deg << " deg, S " << c.spin << ": period " << exact.nutation_period()
                   << " s, reference " << c.period);
    // Measured: the period to 6.9e-16 relative, theta_min to 1.7e-18 of theta0.
    CHECK(std::abs(exact.nutation_period() - c.period) < 4e-15 * c.period);
    CHECK(std::abs(exact.theta_min() - c.theta0_deg * M_PI / 180.0) <
          4 * DBL_EPSILON * c.theta0_deg * M_PI / 180.0);
  }
}

// Fast tops released from rest at 30 deg (make_edge_cases.py: 60 digits).
struct FastTop {
  double spin, mean_phi_dot;
};
const FastTop kFastTop[] = {
#include "reference_fast_top.inc"
};
// Axes passing a hair from a pole, up and down, with spin (make_edge_cases.py: quad at
// 140 digits, split about each spike).
struct Passage {
  double theta0, theta_dot0, phi_dot0, spin, period, mean_phi_dot;
  struct {
    double t, phi, psi;
  } rows[2];
};
const Passage kPassages[] = {
#include "reference_passages.inc"
};

TEST_CASE("heavy top: a hair from a pole phi turns by nearly pi, the way b - a or b + a says") {
  // Through the pole phi_dot ~ (b -+ a)/(2 (1 -+ u)) turns phi by nearly pi within a time
  // ~sqrt(1 -+ u); that distance, 1 - u2 from 1e-6 to 1e-34 and 1 + u1 from 8e-10 to
  // 1e-62, is known to its own accuracy and the passage is resolved (the pole itself is
  // taken only where it underflows). Before: 1 - u2 held to 2e-10 of itself where u3 is
  // far above 1 (the small roots about u = 1 needed two), the complete and incomplete
  // integrals for n < -1 kept eps sqrt(-n) (7.7e-10 of the mean at 1 + u1 = 8e-14), and a
  // circle within 16 eps of a pole was the pole (2.3e-8). Bounds: the period and mean to
  // 16 eps of themselves (a few Carlson integrals; measured 3.5e-16), phi and psi to
  // 4 eps of (1 + |angle| + |S t|) (their terms' roundoff; measured 7e-16 at phi = 6.3).
  for (const Passage& c : kPassages) {
    const rigid::HeavyTopExact exact(kText, {c.theta0, c.theta_dot0, c.phi_dot0, c.spin});
    INFO("theta0 " << c.theta0 << ", theta_dot0 " << c.theta_dot0 << ", phi_dot0 " << c.phi_dot0
                   << ", S " << c.spin << ": 1 - u2 " << 1 - exact.u2() << ", mean "
                   << exact.mean_precession_rate() << ", relative error "
                   << (exact.mean_precession_rate() - c.mean_phi_dot) / c.mean_phi_dot);
    CHECK(std::abs(exact.nutation_period() - c.period) <= 8 * DBL_EPSILON * c.period);
    CHECK(std::abs(exact.mean_precession_rate() - c.mean_phi_dot) <=
          16 * DBL_EPSILON * std::abs(c.mean_phi_dot));
    for (const auto& row : c.rows) {
      const rigid::TopAngles a = exact.angles(row.t);
      INFO("t " << row.t << ": phi " << a.phi - row.phi << ", psi " << a.psi - row.psi << " off");
      CHECK(std::abs(a.phi - row.phi) <= 4 * DBL_EPSILON * (1 + std::abs(row.phi)));
      CHECK(std::abs(a.psi - row.psi) <=
            4 * DBL_EPSILON * (1 + std::abs(row.psi) + std::abs(c.spin * row.t)));
    }
  }
}

TEST_CASE("heavy top: below S = 1e-30 the mean precession is its limit, past 1 + u1 underflowing") {
  // The mean differs from its S -> 0 limit by O(S) (the smooth part ~a, the passage's
  // miss of pi ~sqrt(1 + u1) ~ a): the S = 1e-30 reference holds to 1e-30, on both
  // sides of 1 + u1 underflowing (S ~ 1e-154), where the pole is taken as such.
  const auto limit = std::find_if(std::begin(kPassages), std::end(kPassages),
                                  [](const Passage& c) { return c.spin == 1e-30; });
  REQUIRE(limit != std::end(kPassages));
  for (const double spin : {1e-60, -1e-100, 1e-150, -1e-160, 1e-200, -1e-300}) {
    const rigid::HeavyTopExact exact(kText, {limit->theta0, 0.0, 0.0, spin});
    INFO("S " << spin << ": mean " << exact.mean_precession_rate());
    CHECK(std::abs(exact.mean_precession_rate() - std::copysign(limit->mean_phi_dot, spin)) <=
          16 * DBL_EPSILON * limit->mean_phi_dot);
  }
}

TEST_CASE("heavy top: a fast top's mean precession, a tiny difference of two terms, is kept") {
  // mean phi_dot ~ mgl/(Is S) where the partial fractions' terms are ~a = Is S / I each:
  // summed, they kept it to 3e-3 at S = 1e8 and lost it at 1e10 (0). The trapezoidal
  // mean of phi_dot over the phase is free of the cancellation: to 1e-12. The lab switches
  // to it where the terms cancel by more than 1e3 (here S of about 1e3); the spins 3e3 to
  // 3e4 cancel by 1e4 to 2e6, where the summed terms would keep only eps times that
  // (up to 4e-10): a switch moved higher fails here.
  for (const FastTop& c : kFastTop) {
    const rigid::HeavyTopExact exact(kText, {k30, 0.0, 0.0, c.spin});
    INFO("S " << c.spin << ": mean " << exact.mean_precession_rate() << ", reference "
              << c.mean_phi_dot);
    CHECK(std::abs(exact.mean_precession_rate() - c.mean_phi_dot) < 1e-14 * c.mean_phi_dot);
  }
}

TEST_CASE(
    "heavy top: at 90 deg, to the precision the angle is given in, the fast rate is infinite") {
  // cos(double(pi/2)) = 6e-17 is below half an ulp of the angle (1.1e-16): the input
  // cannot tell horizontal from a hair either side, where the fast rate is +-1e17 or
  // more. A degree off, it is finite and solves eq. 187.
  for (const double theta : {M_PI / 2, 90.0 * (M_PI / 180.0), 3 * M_PI / 2}) {
    const rigid::SteadyPrecession p = rigid::steady_precession_rates(kText, kS500, theta);
    CHECK(p.exists);
    CHECK(p.fast == HUGE_VAL);
    CHECK(p.slow == Approx(kText.mgl / (kText.Is * kS500)).epsilon(4 * DBL_EPSILON));
  }
  const double off = M_PI / 2 - 1e-9;
  const rigid::SteadyPrecession p = rigid::steady_precession_rates(kText, kS500, off);
  CHECK(std::isfinite(p.fast));
  CHECK(
      std::abs(kText.I * std::cos(off) * p.fast * p.fast - kText.Is * kS500 * p.fast + kText.mgl) <=
      16 * DBL_EPSILON * kText.Is * kS500 * p.fast);  // roundoff of its largest terms
}

TEST_CASE("heavy top: the Euler rates at either pole take that pole's sign") {
  // At the north pole 3 = z and omega_3 = phi_dot + psi_dot; at the south pole 3 = -z and
  // omega_3 = -(phi_dot - psi_dot). psi is 0 there (euler_zxz), so phi_dot = +omega_3 up,
  // -omega_3 down: the top's CSV reads its phi_dot from this.
  const Eigen::Vector3d w(0.0, 0.0, 2.5);
  const auto up = rigid::euler_angles_and_rates(rigid::euler_attitude(0.3, 0.0, 0.0), w);
  CHECK(up.phi_dot == 2.5);
  const auto down = rigid::euler_angles_and_rates(rigid::euler_attitude(0.3, M_PI, 0.0), w);
  CHECK(down.phi_dot == -2.5);
  CHECK(down.psi_dot == 0.0);
}

TEST_CASE("heavy top: a theta changed after theta_deg was set is the theta taken") {
  // As the paths figure does for an upright start: a hair off, in radians.
  rigid::TopStart upright{0.0, 0.0, 0.0, 52.36};
  upright.theta_deg = 0.0;
  rigid::TopStart off = upright;
  off.theta = 1e-3;
  const rigid::HeavyTopExact moved(kText, off), plain(kText, {1e-3, 0.0, 0.0, 52.36});
  CHECK(moved.regime() == plain.regime());
  CHECK(moved.theta_max() == plain.theta_max());
  CHECK(rigid::HeavyTopExact(kText, upright).regime() == rigid::TopRegime::kSleeping);
}
