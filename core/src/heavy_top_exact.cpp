// The heavy symmetric top's exact motion (heavy_top.h, HeavyTopExact): the start's
// constants, the turning circles as roots of the cubic f(u) (polished about a pole
// they are near), the phase of theta in Jacobi's elliptic functions, the mean
// precession over a nutation period, and the regime of the axis's path (eqs. 176-195).
#include <algorithm>
#include <boost/math/special_functions/ellint_rc.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "rigid/format.h"
#include "rigid/heavy_top.h"
#include "rigid/periodic_mean.h"
#include "rigid/quad.h"
#include "rigid/rotation.h"
#include "rigid/units.h"

namespace rigid {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Newton's method on the cubic ((c3 v + c2) v + c1) v + c0 from v, to a step of a few
// ulps of v (or 50 steps, or a step that is not finite).
double cubic_root_near(double c3, double c2, double c1, double c0, double v) {
  for (int it = 0; it < 50; ++it) {
    const double step = (((c3 * v + c2) * v + c1) * v + c0) / ((3.0 * c3 * v + 2.0 * c2) * v + c1);
    if (!std::isfinite(step)) break;
    v -= step;
    if (std::abs(step) <= 4 * kEps * std::abs(v)) break;
  }
  return v;
}

// The start's own rules: finite, theta0 in [0, 180) deg, and not at rest upright.
void check_start(const TopStart& s) {
  if (!std::isfinite(s.theta) || !std::isfinite(s.theta_dot) || !std::isfinite(s.phi_dot) ||
      !std::isfinite(s.spin) || !std::isfinite(s.phi) || !std::isfinite(s.psi)) {
    throw std::invalid_argument("the start (angles and rates) must be finite");
  }
  if (!(s.theta >= 0.0 && s.theta < kPi)) {
    throw std::invalid_argument("theta0 must lie in [0, 180) deg, got " +
                                format_number(rad_to_deg(s.theta)) + " deg");
  }
  if (s.theta == 0.0 && s.theta_dot == 0.0 && s.spin == 0.0) {
    throw std::invalid_argument(
        "a top upright at rest (theta0 = 0, no spin, no theta_dot) does not move");
  }
}

// Boost.Math computes a double's integral in long double by default: on x86 the
// x87's 64-bit significand, in hardware, a few bits more kept. Where long double is
// binary128 in software (WebAssembly, AArch64) that costs some fifty times a double's
// (the web page's heavy top spent 94 % of an input's wait in it), so there the
// integrals are computed in double, as free_body_exact.cpp's are everywhere.
#if LDBL_MANT_DIG == 64
using Precision = boost::math::policies::policy<>;
#else
using Precision = boost::math::policies::policy<boost::math::policies::promote_double<false> >;
#endif

double rf(double x, double y, double z) {
  return boost::math::ellint_rf(x, y, z, Precision());
}
double rj(double x, double y, double z, double p) {
  return boost::math::ellint_rj(x, y, z, p, Precision());
}
double rc(double x, double y) {
  return boost::math::ellint_rc(x, y, Precision());
}

}  // namespace

// The start's terms that decide the motion (heavy_top.h's header comment): formed in
// 113-bit arithmetic from the double inputs and each rounded once. In doubles, b - a =
// phi_dot0 sin^2 - a (1 - cos) kept only eps of its two terms (a top started to reach
// upright, b - a = 3.5e-16, came out 0: its theta_min of 1.6e-11 deg read 0, and its
// period 3 % short), and 1 + cos(theta0) rounded to 0 within 1e-8 rad of the bottom.
struct HeavyTopExact::StartTerms {
  double st, s2, u0, omu0, opu0;  // sin, sin^2, cos, 1 - cos, 1 + cos of theta0
  double a, beta, d0, c0;         // p_psi / I, 2 mgl / I, phi_dot0 sin^2, theta_dot0^2 + ...
  double A, B, C;                 // f(u0 + w) = beta w^3 + A w^2 + B w + C
  double b_minus_a, b_plus_a;     // b - a u at u = 1 and at u = -1
  // the cubic about u = 1 (v = u - 1) and about u = -1 (v = 1 + u), g(v) = beta v^3 + ...,
  // with P = c0 - beta (1 - u0) and c0 + beta (1 + u0), the energy's margin over each pole
  double north2, north1, north0;  // 2 beta - P - a^2, 2 (a Q - P), -Q^2 with Q = b - a
  double south2, south1, south0;  // -(2 beta + P + a^2), 2 (P + a Q), -Q^2 with Q = b + a
  double w3;                      // the largest root, u3 - u0 (+inf where it overflows)
};

HeavyTopExact::StartTerms HeavyTopExact::start_terms(const HeavyTop& top, const TopStart& s) {
  const Quad theta = quad_angle(s.theta, s.theta_deg);
  const Quad st = sin(theta), u0 = cos(theta), half = sin(theta / 2), half_c = cos(theta / 2);
  const Quad s2 = st * st, omu0 = 2 * half * half, opu0 = 2 * half_c * half_c;
  const Quad I = top.I, a = Quad(top.Is) * s.spin / I, beta = 2 * Quad(top.mgl) / I;
  const Quad thd = s.theta_dot, phd = s.phi_dot;
  const Quad d0 = phd * s2, c0 = thd * thd + phd * phd * s2;
  const Quad A = -c0 + 2 * beta * u0 - a * a, B = -2 * c0 * u0 - beta * s2 + 2 * a * d0;
  const Quad C = thd * thd * s2;
  // The largest root lies right of the cubic's inflection point, where f is convex:
  // Newton's method from an upper bound (Cauchy's) falls to it monotonically. In
  // 113-bit numbers w^3 cannot overflow (at rates of 1e60 rad/s w3 ~ 1e117: in
  // doubles f(w) was inf from rates of 3e52 on, and the roots wrong).
  const auto f = [&](const Quad& w) { return ((beta * w + A) * w + B) * w + C; };
  const auto df = [&](const Quad& w) { return (3 * beta * w + 2 * A) * w + B; };
  Quad w = 1 + std::max({Quad(abs(A)), Quad(abs(B)), Quad(abs(C))}) / beta;
  if (w < omu0) w = omu0;
  for (int it = 0; it < 2000; ++it) {
    const Quad next = w - f(w) / df(w);
    if (!(next < w)) break;
    w = next;
  }
  if (w < omu0) w = omu0;  // u3 >= 1: f(1) = -(b - a)^2 <= 0
  const Quad Qn = d0 - a * omu0, Qs = d0 + a * opu0;
  const Quad Pn = c0 - beta * omu0, Ps = c0 + beta * opu0;
  const auto d = [](const Quad& x) { return static_cast<double>(x); };
  StartTerms t;
  t.st = d(st), t.s2 = d(s2), t.u0 = d(u0), t.omu0 = d(omu0), t.opu0 = d(opu0);
  t.a = d(a), t.beta = d(beta), t.d0 = d(d0), t.c0 = d(c0);
  t.A = d(A), t.B = d(B), t.C = d(C);
  t.b_minus_a = d(Qn), t.b_plus_a = d(Qs);
  // 2 beta - P - a^2 cancels to 1 % at the text's top spun near S_min: formed here, it
  // keeps its digits, where in doubles it held 1e-14 and u1 came out 3 ulps off
  t.north2 = d(2 * beta - Pn - a * a), t.north1 = d(2 * (a * Qn - Pn)), t.north0 = d(-Qn * Qn);
  t.south2 = d(-(2 * beta + Ps + a * a)), t.south1 = d(2 * (Ps + a * Qs)), t.south0 = d(-Qs * Qs);
  t.w3 = d(w);
  return t;
}

HeavyTopExact::HeavyTopExact(const HeavyTop& top, const TopStart& start)
    : top_(top), start_(start) {
  validate(top);
  check_start(start);
  const StartTerms terms = start_terms(top, start);
  take_constants(terms);
  // An upright top with no theta_dot stays upright: it sleeps (stably or not).
  if (start.theta == 0.0 && start.theta_dot == 0.0) {
    regime_ = TopRegime::kSleeping;
    period_ = std::numeric_limits<double>::infinity();
    mean_phi_dot_ = 0.0;
    return;
  }

  find_turning_circles(terms);
  refine_near_south_pole(terms);
  const double u3_minus_1 = refine_near_north_pole(terms);
  take_poles_within_underflow();
  set_phase(u3_minus_1);
  set_mean_precession();
  classify_regime();
}

// The start's constants: u0, a = p_psi / I, beta = 2 mgl / I, p_psi, p_phi and the energy.
void HeavyTopExact::take_constants(const StartTerms& t) {
  const double I = top_.I, Is = top_.Is;
  const double st = t.st, s2 = t.s2;
  u0_ = t.u0;
  one_minus_u0_ = t.omu0;
  one_plus_u0_ = t.opu0;
  a_ = t.a;
  beta_ = t.beta;
  d0_ = t.d0;
  p_psi_ = Is * start_.spin;                        // eq. 176
  p_phi_ = I * start_.phi_dot * s2 + p_psi_ * u0_;  // eq. 177
  const double c0 = t.c0;
  energy_ = 0.5 * I * c0 + top_.mgl * u0_ + 0.5 * Is * start_.spin * start_.spin;  // eqs. 191-193
  if (!std::isfinite(energy_) || !std::isfinite(p_phi_) || !std::isfinite(t.A) ||
      !std::isfinite(t.B) || !std::isfinite(t.w3) || !std::isfinite(st)) {
    throw std::invalid_argument(
        "the rates are too large against gravity: the energy or the cubic's third root u3 "
        "overflows a double (1.8e308); slow the rates or strengthen gravity");
  }
}

// The turning circles u1 <= u2 (and u3 >= 1), the roots of f, about u0.
void HeavyTopExact::find_turning_circles(const StartTerms& t) {
  // f(u0 + w) = beta w^3 + A w^2 + B w + C (header comment).
  const double A = t.A, B = t.B, C = t.C;
  w3_ = t.w3;
  // The other two roots from Vieta's relations with w3: w1 w2 = -C / (beta w3) <= 0,
  // so they are real with w1 <= 0 <= w2 (f(0) = C >= 0), and w1 + w2 = (B/beta -
  // w1 w2) / w3, which (unlike -A/beta - w3) has no cancellation when w3 >> |w1|,
  // |w2|: a fast top's nutation is a tiny difference of roots of size 1.
  const double product = w3_ > 0.0 ? -C / (beta_ * w3_) : 0.0;
  const double sum = w3_ > 0.0 ? (B / beta_ - product) / w3_ : -A / beta_;
  const double disc = std::max(sum * sum - 4.0 * product, 0.0);
  const double r = 0.5 * (sum + std::copysign(std::sqrt(disc), sum));
  const double other = r != 0.0 ? product / r : 0.0;
  w1_ = std::min(std::min(r, other), 0.0);
  w2_ = std::max(std::max(r, other), 0.0);
  w1_ = std::max(w1_, -one_plus_u0_);
  w2_ = std::min(w2_, one_minus_u0_);
  if (w2_ > w3_) std::swap(w2_, w3_);
  // b - a u at the poles. Where it is exactly zero, f(+-1) = 0: the pole is a
  // root, so the axis goes through it (a start upright with theta_dot, or no spin
  // and no p_phi); set that root exactly, not to within roundoff.
  b_minus_a_ = t.b_minus_a;  // at u = 1
  b_plus_a_ = t.b_plus_a;    // at u = -1
  // u = -1 can only be u1; u = +1 is u2 (the axis reaches upright) or u3 (it does
  // not): whichever computed root lies nearer.
  through_south_ = b_plus_a_ == 0.0;
  if (through_south_) w1_ = -one_plus_u0_;
  if (b_minus_a_ == 0.0) {
    through_north_ = std::abs(w2_ - one_minus_u0_) < std::abs(w3_ - one_minus_u0_);
    (through_north_ ? w2_ : w3_) = one_minus_u0_;
  }
}

void HeavyTopExact::refine_near_south_pole(const StartTerms& t) {
  // 1 + u1 to its own relative accuracy. Near the south pole u0 + w1 holds it only to
  // roundoff of 1 (a top that barely spins swings through the bottom: 1 + u1 ~ 1e-14
  // came out wrong by its whole size, and phi_dot = (b + a)/(2 (1 + u)) there by
  // orders of magnitude: the energy off by 1e16). About u = -1, v = 1 + u, the cubic
  // is g(v) = v (2 - v)(P - beta v) - (Q - a v)^2 with P = c0 + beta (1 + u0) and
  // Q = b + a, both formed without cancellation: its small root by Newton's method
  // from Q^2 / g'(0) (g(0) = -Q^2 <= 0 < g'(0) = 2 (P + a Q)).
  // Released with theta_dot0 = 0 at u0 = u1 (the axis rises from it), 1 + u1 is 1 + u0
  // exactly: the small root below would land within rounding on either side of it, and
  // above it (u1 > u0) left no phase to start from (v0 NaN a hair from the bottom).
  const bool u0_is_u1 = t.C == 0.0 && w1_ == 0.0;
  opu1_ = u0_is_u1 ? one_plus_u0_ : one_plus_u0_ + w1_;
  if (!through_south_ && !u0_is_u1 && opu1_ < 1e-3) {
    const double c2 = t.south2, c1 = t.south1, Q2 = -t.south0;
    const double v = cubic_root_near(beta_, c2, c1, -Q2, c1 > 0.0 ? Q2 / c1 : opu1_);
    if (v > 0.0 && v < 2e-3) {
      opu1_ = std::min(v, one_plus_u0_);  // u1 <= u0
      w1_ = opu1_ - one_plus_u0_;
    }
  }
}

double HeavyTopExact::refine_near_north_pole(const StartTerms& t) {
  const double B = t.B, C = t.C;
  // u2 and u3 near the north pole likewise, from the cubic about u = 1, v = u - 1:
  // g(v) = beta v^3 + (2 beta - P - a^2) v^2 + 2 (a Q - P) v - Q^2 with P = c0 - beta (1 -
  // u0) and Q = b - a. Its two small roots (v2 <= 0 <= v3) by the quadratic's stable
  // formula, polished by Newton's method on g. A top released near upright (theta0 =
  // 1e-6 deg: 1 - u0 = 1.5e-16) has u3 - u2 ~ 1 - u0, which the roots about u0 held
  // only to roundoff of 1: k'^2 off by its size, the period by 8 %.
  // Where the axis goes through the pole (b - a = 0: v2 = 0 is a root), u3 still
  // needs this form: a top started to just reach upright has u3 - 1 = 7.7e-9, which
  // the roots about u0 held to its size (1.5e-8).
  // Released with theta_dot0 = 0, u0 is a root: u2 itself (kept exact) where the axis
  // falls from it, or u1 where it rises (a start faster than steady a hair from upright:
  // then u2 is this form's small root, where taking u2 = u0 had theta_min 6 % off).
  const bool u0_is_u2 = C == 0.0 && w2_ == 0.0;
  double u3_minus_1 = std::numeric_limits<double>::quiet_NaN();  // where found about the pole
  omu2_ = one_minus_u0_ - w2_;
  if (omu2_ < 1e-3 || w3_ - one_minus_u0_ < 1e-3) {
    const double A2 = t.north2, B2 = t.north1, C2 = t.north0;
    const auto polish = [&](double v) { return cubic_root_near(beta_, A2, B2, C2, v); };
    const double disc = B2 * B2 - 4.0 * A2 * C2;
    const double q = -0.5 * (B2 + std::copysign(std::sqrt(std::max(disc, 0.0)), B2));
    if (q != 0.0) {
      // C2/q is the small root. q/A2 is the other only where A2 > 0: for A2 <= 0 the
      // two have one sign (a spinning top nodding just off upright with u3 far above
      // 1), the cubic's v^3 term decides the second, and 1 - u2 = -C2/q alone (its
      // roots about u0 held it to 2e-10 at 1 - u2 = 1e-14).
      const double r2 = polish(C2 / q), r1 = A2 > 0.0 ? polish(q / A2) : r2;
      const double v3 = std::max(r1, r2), v2 = std::min(r1, r2);
      const bool v3_small = through_north_ ? A2 > 0.0 && v3 > 0.0 : v3 >= 0.0;
      if (v3_small && v3 < 1e-3 && !through_south_ && opu1_ >= 1e-3) {
        // and u1 again from Vieta's relations with this w3 (they held its roundoff)
        w3_ = one_minus_u0_ + v3;
        u3_minus_1 = v3;
        const double product = -C / (beta_ * w3_), sum = (B / beta_ - product) / w3_;
        const double w2_here = !u0_is_u2 && v2 <= 0.0 && v2 > -1e-3 ? one_minus_u0_ + v2 : w2_;
        w1_ = std::max(w2_here != 0.0 ? product / w2_here : sum - w2_here, -one_plus_u0_);
        opu1_ = one_plus_u0_ + w1_;
      }
      // u2 = u0 exactly when released with theta_dot = 0 (f(u0) = 0): kept
      if (!through_north_ && !u0_is_u2 && v2 <= 0.0 && v2 > -1e-3) w2_ = one_minus_u0_ + v2;
      if (!through_north_ && v2 <= 0.0 && v2 > -1e-3) omu2_ = !u0_is_u2 ? -v2 : one_minus_u0_;
    }
  }
  return u3_minus_1;
}

void HeavyTopExact::take_poles_within_underflow() {
  // A turning circle whose distance from a pole underflows is the pole: the passage,
  // a turn of phi by pi within a vanishing time, is then exact, where the integral of
  // the spike would overflow. Above that the passage is resolved: 1 - u2 and 1 + u1
  // are known to their own accuracy, and the complete and incomplete integrals keep
  // theirs (taking a circle within 16 eps of a pole as the pole missed the mean
  // precession by ~sqrt of that distance: 2e-8 at 1 + u1 = 8e-16).
  if (!through_south_ && !(opu1_ >= std::numeric_limits<double>::min())) {
    through_south_ = true;
    w1_ = -one_plus_u0_;
    opu1_ = 0.0;
  }
  // (North: only where phi_dot's spike there, (b - a)/(2 (1 - u2)), is far beyond the
  // motion's own rates; a top released from rest near upright has phi_dot -a/2 at the
  // top, no spike, and keeps its 1 - u2.)
  if (!through_north_ && omu2_ < std::numeric_limits<double>::min() &&
      std::abs(b_minus_a_) > 1e6 * omu2_ * (std::abs(a_) + std::sqrt(beta_))) {
    through_north_ = true;
    w2_ = one_minus_u0_;
    omu2_ = 0.0;
  }
}

void HeavyTopExact::set_phase(double u3_minus_1) {
  // sn^2 of the phase, its modulus and rate.
  const double span = w3_ - w1_;  // u3 - u1 > 0
  k2_ = (w2_ - w1_) / span;
  // u3 - u2 from the pole where both are near it: (1 - u0 + v3) - (1 - u0 - (1 - u2))
  // kept only eps (1 - u0) of a difference of 1e-9 (the period 1e-8 off by it)
  kp2_ = (std::isnan(u3_minus_1) ? w3_ - w2_ : u3_minus_1 + omu2_) / span;
  lambda_ = 0.5 * std::sqrt(beta_ * span);
  jacobi_ = JacobiElliptic(kp2_);
  // K(k) = R_F(0, k'^2, 1); infinite on the separatrix (k' = 0).
  K_ = kp2_ > 0.0 ? rf(0.0, kp2_, 1.0) : std::numeric_limits<double>::infinity();
  period_ = kp2_ > 0.0 ? 2.0 * K_ / lambda_ : std::numeric_limits<double>::infinity();
  // The phase at t = 0: sn^2(v0) = (u0 - u1)/(u2 - u1), v0 = F(asin(sqrt(r)), k) by
  // Carlson's R_F with 1 - r = w2/(w2 - w1) and 1 - k^2 r = w3/(w3 - w1) formed exactly;
  // v0 < 0 while u falls (theta_dot0 > 0).
  if (w2_ > w1_) {
    const double ratio = -w1_ / (w2_ - w1_);
    v0_ = std::sqrt(ratio) * rf(w2_ / (w2_ - w1_), w3_ / span, 1.0);
    if (start_.theta_dot > 0.0) v0_ = -v0_;
  }
  // Started upright (the turning circle u2 = 1 itself): exactly at v0 = -K, leaving.
  if (start_.theta == 0.0) v0_ = -K_;
  const double amplitude = w2_ - w1_;
  const double one_minus_u1 = one_minus_u0_ - w1_;
  const double one_plus_u2 = one_plus_u0_ + w2_;
  // Steady: no nodding beyond roundoff, measured against the distance of the
  // circles from the poles (near upright, u moves by theta^2 only).
  regime_ = amplitude <= 64 * kEps * std::min(one_minus_u1, one_plus_u2) ? TopRegime::kSteady
                                                                         : TopRegime::kWavy;
}

void HeavyTopExact::set_mean_precession() {
  const double amplitude = w2_ - w1_;
  const double one_minus_u1 = one_minus_u0_ - w1_, one_plus_u1 = opu1_;
  // phi_dot = (b - a u)/(1 - u^2) = [(b - a)/(1 - u) + (b + a)/(1 + u)] / 2, and
  // 1 - u = (1 - u1)(1 - n+ sn^2), 1 + u = (1 + u1)(1 + n- sn^2). A term whose
  // coefficient is zero is left out (its n may be infinite: the pole is a root).
  n_plus_ = !through_north_ && one_minus_u1 > 0.0 ? amplitude / one_minus_u1 : 0.0;
  n_minus_ = !through_south_ ? -amplitude / one_plus_u1 : 0.0;
  // 1 - n+ = (1 - u2)/(1 - u1) as such: near upright 1 - n+ rounded to 0
  one_minus_n_plus_ = n_plus_ != 0.0 ? omu2_ / one_minus_u1 : 1.0;
  // Complete integrals of 1/(1 - n sn^2) over a half period: Pi(n, k) = K + n/3 R_J(0, k'^2, 1,
  // 1 - n); for n < -1 the form third_kind takes there, at sn = 1.
  const auto complete = [&](double n, double one_minus_n) {
    if (n < -1.0) {
      const double w = k2_ / n;
      return -w / 3.0 * rj(0.0, kp2_, 1.0, 1.0 - w) + rc(0.0, one_minus_n * (1.0 - w));
    }
    return n == 0.0 ? K_ : K_ + n / 3.0 * rj(0.0, kp2_, 1.0, one_minus_n);
  };
  // A term with a zero coefficient is left out, whatever its n.
  use_plus_ = !through_north_ && b_minus_a_ != 0.0;
  use_minus_ = !through_south_ && b_plus_a_ != 0.0;
  pi_plus_ = use_plus_ ? complete(n_plus_, one_minus_n_plus_) : 0.0;
  pi_minus_ = use_minus_ ? complete(n_minus_, 1.0 - n_minus_) : 0.0;
  G_plus_0_ = use_plus_ ? third_kind(v0_, n_plus_, one_minus_n_plus_, pi_plus_) : 0.0;
  G_minus_0_ = use_minus_ ? third_kind(v0_, n_minus_, 1.0 - n_minus_, pi_minus_) : 0.0;
  // Over a nutation period (2K in v, 2K / lambda in t): the two integrals, and pi for
  // each pole the axis goes through (phi jumps by pi there, the Euler angles' way
  // of crossing it).
  mean_phi_dot_ = 0.0;
  const double term_plus = use_plus_ ? b_minus_a_ / one_minus_u1 * pi_plus_ / (2.0 * K_) : 0.0;
  const double term_minus = use_minus_ ? b_plus_a_ / one_plus_u1 * pi_minus_ / (2.0 * K_) : 0.0;
  mean_phi_dot_ = term_plus + term_minus;
  // Each complete integral to a few ulps: their difference to 32 eps of their sizes (a
  // looping top at rates of 1e60 has terms of 1e60 and a mean of 6e-59: roundoff, said so)
  mean_error_ = 32 * kEps * (std::abs(term_plus) + std::abs(term_minus));
  // A fast top's two terms are ~a each and cancel to ~mgl/(Is S) (at S = 1e8 rad/s to
  // 3e-3 of it; at 1e10 to 0): then the mean of phi_dot = (d0 - a w)/((1 - u)(1 + u)),
  // free of that cancellation pointwise, over a nutation period (periodic_mean).
  // Only where phi_dot is smooth: a turning circle nearer a pole than the nod is wide
  // puts a spike of phi_dot there (a turn by nearly pi in a sliver of the period) that
  // sampling misses, where the terms hold it (a pass 4e-21 deg from upright: the mean
  // 6.78 rad/s for 0.0091).
  if (!through_north_ && !through_south_ && std::isfinite(K_) && K_ > 0.0 &&
      std::min(omu2_, opu1_) > w2_ - w1_ &&
      std::abs(term_plus) + std::abs(term_minus) > 1e3 * std::abs(mean_phi_dot_)) {
    mean_phi_dot_ = periodic_mean(
        [&](double t) {
          const Phase p = phase(t);
          return at(p.sn * p.sn, p.cn * p.cn).phi_dot;
        },
        period_);
    mean_error_ = 64 * kEps * std::abs(mean_phi_dot_);  // pointwise free of cancellation
  }
  if (std::isfinite(period_)) {
    if (through_north_) mean_phi_dot_ += std::copysign(kPi, b_minus_a_) / period_;
    if (through_south_) mean_phi_dot_ += std::copysign(kPi, b_plus_a_) / period_;
  }

  // A pole that is a root of f (b -+ a = 0, not a circle within underflow of it): the
  // axis goes through the vertical, phi is undefined there and turns by pi at once, and
  // which way is the limit of a path a hair to either side. The motion takes the way of
  // the sign of zero; the mean precession has both limits, pi / period apart a pole.
  const int root_poles = this->root_poles();
  const double spread = std::isfinite(period_) ? root_poles * kPi / period_ : 0.0;
  const double base =
      mean_phi_dot_ -
      (through_north_ && b_minus_a_ == 0.0 ? std::copysign(spread / root_poles, b_minus_a_) : 0.0) -
      (through_south_ && b_plus_a_ == 0.0 ? std::copysign(spread / root_poles, b_plus_a_) : 0.0);
  mean_limits_ = {base - spread, base + spread};
}

int HeavyTopExact::root_poles() const {
  return (through_north_ && b_minus_a_ == 0.0) + (through_south_ && b_plus_a_ == 0.0);
}

HeavyTopExact::Phase HeavyTopExact::phase(double t) const {
  Phase p;
  p.v = lambda_ * t + v0_;
  if (kp2_ == 1.0 || k2_ == 0.0) {  // k = 0: sn = sin
    p.sn = std::sin(p.v);
    p.cn = std::cos(p.v);
    p.dn = 1.0;
  } else {
    jacobi_(p.v, p.sn, p.cn, p.dn);
  }
  return p;
}

double HeavyTopExact::third_kind(double v, double n, double one_minus_n, double complete) const {
  // Reduce v to [-K, K] by whole half-periods 2K: each adds 2 Pi(n, k).
  if (!(K_ > 0.0)) return v;
  const double m = std::isfinite(K_) ? std::round(v / (2.0 * K_)) : 0.0;
  const double vr = m == 0.0 ? v : v - 2.0 * K_ * m;
  double sn, cn, dn;
  if (k2_ == 0.0) {
    sn = std::sin(vr);
    cn = std::cos(vr);
    dn = 1.0;
  } else {
    jacobi_(vr, sn, cn, dn);
  }
  // Pi(n; am v, k) = v + n/3 sn^3 R_J(cn^2, dn^2, 1, 1 - n sn^2) for |v| <= K, its last
  // argument as cn^2 + (1 - n) sn^2 (no cancellation where n is near 1). For n < -1 (a
  // turning circle near the south pole: n = -(u2 - u1)/(1 + u1)) Pi ~ 1/sqrt(-n) is what
  // is left of v minus a term as large as v: it kept only eps sqrt(-n) of itself (1e-9
  // at 1 + u1 = 1e-13). The transformation to w = k^2/n (DLMF 19.7.9 in Carlson's form)
  //   Pi(n; am v) = -w/3 sn^3 R_J(cn^2, dn^2, 1, 1 - w sn^2)
  //                 + sn R_C(cn^2 dn^2, (1 - n sn^2)(1 - w sn^2))
  // adds two terms of one sign.
  const double one_minus_n_sn2 = cn * cn + one_minus_n * sn * sn;
  double part = vr;
  if (n < -1.0) {
    const double w = k2_ / n;
    const double one_minus_w_sn2 = 1.0 - w * sn * sn;
    part = -w / 3.0 * sn * sn * sn * rj(cn * cn, dn * dn, 1.0, one_minus_w_sn2) +
           sn * rc(cn * cn * dn * dn, one_minus_n_sn2 * one_minus_w_sn2);
  } else if (n != 0.0) {
    part = vr + n / 3.0 * sn * sn * sn * rj(cn * cn, dn * dn, 1.0, one_minus_n_sn2);
  }
  return m == 0.0 ? part : part + 2.0 * m * complete;
}

HeavyTopExact::Where HeavyTopExact::at(double sn2, double cn2) const {
  // u = u1 + (u2 - u1) sn^2 = u2 - (u2 - u1) cn^2: each form from the nearer turning
  // circle, so 1 - u, 1 + u and b - a u keep their digits there (near a pole too).
  const double delta = w2_ - w1_;
  Where x;
  if (sn2 <= 0.5) {
    x.w = w1_ + delta * sn2;
    x.omu = (one_minus_u0_ - w1_) - delta * sn2;
    x.opu = opu1_ + delta * sn2;
    // b - a u: near the south pole as (b + a) - a (1 + u), both parts exact there; where
    // the pole is taken as the turning circle, b + a is roundoff (phi's turn by pi
    // there stands for its term), and left out
    x.numerator = through_south_ ? -a_ * x.opu
                  : opu1_ < 1e-3 ? b_plus_a_ - a_ * x.opu
                                 : (d0_ - a_ * w1_) - a_ * delta * sn2;
  } else {
    x.w = w2_ - delta * cn2;
    x.omu = omu2_ + delta * cn2;
    x.opu = (one_plus_u0_ + w2_) - delta * cn2;
    // likewise b - a u = (b - a) + a (1 - u) near the north pole, without b - a where
    // the pole is taken as the turning circle
    x.numerator = through_north_ ? a_ * x.omu
                  : omu2_ < 1e-3 ? b_minus_a_ + a_ * x.omu
                                 : (d0_ - a_ * w2_) + a_ * delta * cn2;
  }
  x.omu = std::max(x.omu, 0.0);
  x.opu = std::max(x.opu, 0.0);
  x.theta = std::atan2(std::sqrt(x.omu * x.opu), u0_ + x.w);
  // phi_dot = (b - a u)/((1 - u)(1 + u)); at a pole the axis goes through, its limit
  // [(b - a)/(1 - u) + (b + a)/(1 + u)]/2 keeps only the other pole's term.
  if (x.omu * x.opu > 0.0) {
    x.phi_dot = x.numerator / (x.omu * x.opu);
  } else if (x.omu == 0.0) {
    x.phi_dot = x.opu > 0.0 ? 0.5 * b_plus_a_ / x.opu : 0.0;
  } else {
    x.phi_dot = 0.5 * b_minus_a_ / x.omu;
  }
  return x;
}

double HeavyTopExact::theta_from(const Phase& p) const {
  return at(p.sn * p.sn, p.cn * p.cn).theta;
}

double HeavyTopExact::theta(double t) const {
  if (regime_ == TopRegime::kSleeping) return 0.0;
  return theta_from(phase(t));
}

TopAngles HeavyTopExact::angles(double t) const {
  TopAngles out;
  const double S = start_.spin;
  if (regime_ == TopRegime::kSleeping) {
    out.phi = start_.phi;
    out.psi = start_.psi + S * t;
    out.psi_dot = S;
    return out;
  }
  const Phase p = phase(t);
  const Where x = at(p.sn * p.sn, p.cn * p.cn);
  out.theta = x.theta;
  out.sin_theta = std::sqrt(x.omu) * std::sqrt(x.opu);  // each root apart: no underflow
  // theta_dot = -u_dot / sin(theta), u_dot = 2 (u2 - u1) lambda sn cn dn. Where a pole
  // is a turning circle, 1 - u = (u2 - u1) cn^2 (north) or 1 + u = (u2 - u1) sn^2
  // (south) exactly, and that factor cancels: the axis goes through the pole at
  // its full speed instead of 0/0 (leaving it, at the instant itself).
  const double delta = w2_ - w1_;
  const double cn_part = through_north_ ? 1.0 : p.cn;
  const double sn_part = through_south_ ? 1.0 : p.sn;
  const double rest = (through_north_ ? delta : x.omu) * (through_south_ ? delta : x.opu);
  out.theta_dot =
      rest > 0.0 ? -2.0 * delta * lambda_ * sn_part * cn_part * p.dn / std::sqrt(rest) : 0.0;
  if (through_north_ || through_south_) {
    // The sign of the cancelled factor is roundoff at the pole itself: take it from
    // where v is in the period instead. theta grows for half a period after the axis
    // leaves the north pole (v = K + 2Kj), and falls after it leaves the south pole.
    const double from = through_north_ ? p.v - K_ : p.v;
    const double r = from - 2 * K_ * std::floor(from / (2 * K_));  // in [0, 2K)
    const bool after_pass = r < K_;
    out.theta_dot = std::abs(out.theta_dot) * ((after_pass == through_north_) ? 1.0 : -1.0);
  }
  out.phi_dot = x.phi_dot;
  out.psi_dot = S - (u0_ + x.w) * out.phi_dot;
  // J+ = int dt/(1 - u), J- = int dt/(1 + u), each an integral of the third kind.
  const double one_minus_u1 = one_minus_u0_ - w1_, one_plus_u1 = opu1_;
  const double J_plus = !use_plus_
                            ? 0.0
                            : (third_kind(p.v, n_plus_, one_minus_n_plus_, pi_plus_) - G_plus_0_) /
                                  (one_minus_u1 * lambda_);
  const double J_minus = !use_minus_
                             ? 0.0
                             : (third_kind(p.v, n_minus_, 1.0 - n_minus_, pi_minus_) - G_minus_0_) /
                                   (one_plus_u1 * lambda_);
  // Through a pole, phi turns by pi at once and psi by -pi (north: phi + psi is the
  // turn about z there) or +pi (south: phi - psi is); passages at v = K + 2Kj (north,
  // sn^2 = 1) and v = 2Kj (south, sn = 0) after v0.
  double north = 0.0, south = 0.0;
  if (through_north_ && std::isfinite(K_)) {  // on the separatrix it never arrives
    north = std::copysign(kPi, b_minus_a_) *
            (std::floor((p.v - K_) / (2 * K_)) - std::floor((v0_ - K_) / (2 * K_)));
  }
  if (through_south_ && std::isfinite(K_)) {
    south =
        std::copysign(kPi, b_plus_a_) * (std::floor(p.v / (2 * K_)) - std::floor(v0_ / (2 * K_)));
  }
  out.phi = start_.phi + 0.5 * (b_minus_a_ * J_plus + b_plus_a_ * J_minus) + north + south;
  out.psi =
      start_.psi + (S - a_) * t - 0.5 * (b_minus_a_ * J_plus - b_plus_a_ * J_minus) - north + south;
  return out;
}

Eigen::Vector3d HeavyTopExact::omega_body(const TopAngles& angles) const {
  Eigen::Vector3d w = euler_omega_body(angles);
  w.z() = start_.spin;
  return w;
}

Eigen::Quaterniond HeavyTopExact::attitude(double t) const {
  const TopAngles a = angles(t);
  return euler_attitude(a.phi, a.theta, a.psi);
}

double HeavyTopExact::theta_min() const {
  return regime_ == TopRegime::kSleeping ? 0.0 : at(1.0, 0.0).theta;
}

double HeavyTopExact::theta_max() const {
  return regime_ == TopRegime::kSleeping ? 0.0 : at(0.0, 1.0).theta;
}

double HeavyTopExact::fastest_rate() const {
  const double E_prime = energy_ - 0.5 * top_.Is * start_.spin * start_.spin;
  return std::abs(start_.spin) + std::sqrt(2 * std::max(E_prime + top_.mgl, 0.0) / top_.I);
}

}  // namespace rigid
