// The heavy symmetric top on a fixed pivot (sections 8, 8.1 and 9, eqs. 167-195;
// Goldstein, Classical Mechanics, section 5.7).
//
// Conventions. I is the moment about any transverse axis through the pivot, Is
// the moment about the symmetry axis 3, and mgl = m g l with l the distance from
// the pivot to the centre of mass along 3. Euler angles are Goldstein's z-x-z:
// the body-to-space rotation is Rz(phi) Rx(theta) Rz(psi), theta is the tilt
// of 3 from the upward vertical z, phi its azimuth (precession) and psi the turn
// about 3; omega_body = (phi_dot sin(theta) sin(psi) + theta_dot cos(psi),
// phi_dot sin(theta) cos(psi) - theta_dot sin(psi), phi_dot cos(theta) + psi_dot).
// The spin S = omega_3 = phi_dot cos(theta) + psi_dot (eq. 170); p_psi = Is S and
// p_phi = I phi_dot sin^2(theta) + Is S cos(theta) (eqs. 176-177) are conserved,
// with E' = I (theta_dot^2 + phi_dot^2 sin^2 theta) / 2 + mgl cos(theta) (eq. 193).
//
// The exact motion. With u = cos(theta), a = p_psi / I, b = p_phi / I and
// beta = 2 mgl / I, the energy equation is u_dot^2 = f(u) = (2E'/I - beta u)(1 - u^2)
// - (b - a u)^2, a cubic with roots u1 <= u2 <= 1 <= u3; the axis nods between
// theta_max = acos(u1) and theta_min = acos(u2) as
//   u(t) = u1 + (u2 - u1) sn^2(lambda t + v0, k),  k^2 = (u2 - u1)/(u3 - u1),
//   lambda = sqrt(beta (u3 - u1)) / 2,  nutation period 2 K(k) / lambda,
// and phi(t), psi(t) follow from phi_dot = (b - a u)/(1 - u^2) and
// psi_dot = S - u phi_dot by partial fractions in 1 - u and 1 + u, each an
// elliptic integral of the third kind (Carlson's R_J, as the free body uses).
// The cubic is formed about u0 = cos(theta0), in w = u - u0, so its
// coefficients carry no cancellation: f(0) = theta_dot0^2 sin^2 theta0 exactly.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "rigid/free_body_exact.h"

namespace rigid {

/// A symmetric top on a fixed pivot: moments about the pivot and the gravity torque scale.
struct HeavyTop {
  double I = 1.0;    ///< about a transverse axis through the pivot, kg m^2
  double Is = 1.0;   ///< about the symmetry axis, kg m^2
  double mgl = 1.0;  ///< m g l, N m (l: pivot to centre of mass)
};

/// Throws std::invalid_argument unless I, Is and mgl are positive and finite.
void validate(const HeavyTop& top);

/// Throws std::invalid_argument unless a body of mass m with its centre of mass
/// at `arm` from the pivot can have the pivot moments I, Is: about the centre of
/// mass the transverse moment I - m arm^2 must be at least Is/2 (the triangle
/// inequality of a symmetric body; a thin disk sits on the bound and passes).
void validate_top_body(double I, double Is, double m, double arm);

/// The smallest spin of a sleeping top, S = sqrt(4 mgl I) / Is, rad/s (eqs. 188-189).
double sleeping_min_spin(const HeavyTop& top);

/// The precession rate of a horizontal top, mgl / (Is S), rad/s (eq. 185).
double horizontal_precession_rate(const HeavyTop& top, double spin);

/// The two steady precession rates at tilt theta (eq. 187, from eq. 184 with
/// theta_ddot = 0: mgl = Is S phi_dot - I phi_dot^2 cos(theta)).
struct SteadyPrecession {
  bool exists = false;  ///< false when Is^2 S^2 < 4 mgl I cos(theta) (eq. 188), or horizontal
                        ///< with no spin (eq. 187 would need m g l = 0)
  double slow = 0.0;    ///< (Is S - sqrt(D)) / (2 I cos theta), formed as 2 mgl / (Is S + sqrt(D))
  double fast = 0.0;    ///< (Is S + sqrt(D)) / (2 I cos theta); +inf at theta = 90 deg
                        ///< (any theta within 2 ulps of it)
};
SteadyPrecession steady_precession_rates(const HeavyTop& top, double spin, double theta);

/// The start of a motion: Euler angles and rates at t = 0.
struct TopStart {
  double theta = 0.0;      ///< rad, in [0, pi)
  double theta_dot = 0.0;  ///< rad/s
  double phi_dot = 0.0;    ///< rad/s
  double spin = 0.0;       ///< S = omega_3, rad/s
  double phi = 0.0;        ///< rad
  double psi = 0.0;        ///< rad
  /// theta as given in degrees, where it was: sin and cos of theta, and 1 - cos and
  /// 1 + cos near a pole, are then those of the angle meant, where the radians keep
  /// it only to ulp(pi) (at 179.9999999 deg, 1 + cos theta to 1e-7 of itself). Taken
  /// only while theta is deg_to_rad of it (quad_angle): change theta, and theta rules.
  std::optional<double> theta_deg = std::nullopt;
};

/// The fast top (Goldstein 5.7, Is S much more than sqrt(m g l I)): its nodding, to
/// relative order `order`.
struct FastTopNutation {
  /// 2 m g l I / (Is S)^2 = (S_min / S)^2 / 2: the relative order of the estimates.
  double order = 0.0;
  /// The nutation frequency, a = Is S / I, rad/s.
  double frequency = 0.0;
  /// theta_max - theta_min, rad: relative to the slow precession mgl / (Is S), the
  /// axis starts with the velocity (theta_dot0, sin(theta0) (phi_dot0 - mgl / (Is S)))
  /// on the sphere, which turns at the rate a, so the axis circles with radius
  /// |velocity| / a; from rest, 2 m g l I sin(theta0) / (Is S)^2.
  double range = 0.0;
};
/// The fast-top estimates for a start (any theta_dot0, phi_dot0) with spin S > 0.
FastTopNutation fast_top_nutation(const HeavyTop& top, const TopStart& start);

/// The figure the symmetry axis traces on the unit sphere.
enum class TopRegime {
  kSleeping,     ///< upright and not nodding: theta = 0 for all t
  kSteady,       ///< u1 = u2: steady precession at one tilt
  kWavy,         ///< phi_dot keeps one sign at both turning circles
  kLooping,      ///< phi_dot changes sign: the axis loops back
  kCusped,       ///< phi_dot = 0 at a turning circle (a top released with phi_dot = theta_dot = 0)
  kThroughPole,  ///< a turning circle is a pole (b -+ a = 0): the axis passes the vertical
  kPlanar,       ///< no spin and no p_phi: the axis swings in one vertical plane
};
/// "sleeping", "steady", "wavy", "looping", "cusped", "through the pole" or "planar".
std::string to_string(TopRegime regime);

/// Euler angles and their rates at one time.
struct TopAngles {
  double theta = 0.0, phi = 0.0, psi = 0.0;
  double theta_dot = 0.0, phi_dot = 0.0, psi_dot = 0.0;
  /// sin(theta) to full relative accuracy, where known (the exact motion has it from
  /// (1 - u)(1 + u)). Near a pole sin of the rounded theta is not: theta = pi - 2e-11
  /// holds it to ulp(pi) / 2e-11 = 2e-5, and phi_dot sin(theta) in omega with it.
  std::optional<double> sin_theta;
};

/// The body-to-space rotation Rz(phi) Rx(theta) Rz(psi).
Eigen::Quaterniond euler_attitude(double phi, double theta, double psi);
/// omega in body axes from the Euler angles and rates (header comment).
Eigen::Vector3d euler_omega_body(const TopAngles& a);
/// The Euler angles of an attitude (euler_zxz) and their rates from omega in body
/// axes, euler_omega_body inverted: theta_dot = w1 cos(psi) - w2 sin(psi), phi_dot =
/// (w1 sin(psi) + w2 cos(psi)) / sin(theta), psi_dot = w3 - phi_dot cos(theta). At
/// theta = 0 or pi only phi + psi (phi - psi) is defined: psi is 0 there
/// (euler_zxz), so phi_dot takes the whole turn, w3 (or -w3), and psi_dot is 0.
TopAngles euler_angles_and_rates(const Eigen::Quaterniond& q, const Eigen::Vector3d& omega_body);

class HeavyTopExact;

/// The nutation period's condition number: the largest |d ln T / d ln x| over the start's
/// theta0 and rates x, by central differences of the exact motion (infinite on the
/// separatrix). Near it it grows as 1 / k'^2: a top started to just reach upright (u3 - 1 =
/// 7.7e-9) has 4.6e6, where the text's top has 1.6.
double nutation_period_condition(const HeavyTopExact& motion);

/// The exact motion of the heavy symmetric top from a start.
///
/// The quantities that decide the motion near a pole or the separatrix (1 -+ cos theta0,
/// b -+ a, the energy's margin over the poles, and the cubic's coefficients and largest
/// root) are formed in 113-bit arithmetic from the double inputs and rounded once, so
/// a turning circle a hair from a pole, or a root a hair from another, keeps its digits.
class HeavyTopExact {
 public:
  /// Throws std::invalid_argument for an invalid top, a non-finite start, theta
  /// outside [0, pi), a top at rest upright (theta = 0, no spin, no theta_dot), or rates
  /// so large against gravity that the energy, or the cubic's third root u3, overflows a
  /// double (|rate| beyond ~1e150 rad/s; at the text's top u3 ~ (rate / 6)^2).
  HeavyTopExact(const HeavyTop& top, const TopStart& start);

  /// The Euler angles and rates at time t.
  TopAngles angles(double t) const;
  /// omega in body axes from angles(t): euler_omega_body, but omega_3 the spin S the
  /// motion holds constant. phi_dot cos(theta) + psi_dot returns S only to eps |phi_dot|,
  /// which near a pole (phi_dot ~ 1 / (1 - u^2)) outweighs a slow spin.
  Eigen::Vector3d omega_body(const TopAngles& angles) const;
  /// theta(t) alone, rad (one sn evaluation).
  double theta(double t) const;
  /// The body-to-space attitude at time t.
  Eigen::Quaterniond attitude(double t) const;

  /// The roots of f(u): u1 <= u2 bound the motion, u3 >= 1.
  double u1() const { return u0_ + w1_; }
  double u2() const { return u0_ + w2_; }
  double u3() const { return u0_ + w3_; }
  /// The turning angles acos(u2) and acos(u1), rad.
  double theta_min() const;
  double theta_max() const;
  /// The nutation period 2 K(k) / lambda, s (pi / lambda in the steady limit; +inf for a
  /// top on the separatrix, u2 = u3, which takes forever to leave the vertical).
  double nutation_period() const { return period_; }
  /// The mean of phi_dot over a nutation period, rad/s: the one this motion's phi(t)
  /// takes where the axis goes through a pole (see mean_precession_defined).
  double mean_precession_rate() const { return mean_phi_dot_; }
  /// A bound on the mean's rounding error, rad/s: where it exceeds the mean, the mean is
  /// a difference of two turns (about the two poles) below their roundoff.
  double mean_precession_error() const { return mean_error_; }
  /// False where the axis goes through a pole (kThroughPole, kPlanar): phi turns by pi
  /// there at once, either way, and the mean is either of mean_precession_limits().
  bool mean_precession_defined() const { return mean_limits_[0] == mean_limits_[1]; }
  /// The least and the greatest mean phi_dot a path a hair beside this one takes (equal
  /// where the mean is defined), rad/s.
  const std::array<double, 2>& mean_precession_limits() const { return mean_limits_; }
  /// The regime of the symmetry axis's path.
  TopRegime regime() const { return regime_; }
  /// A turning circle a hair from a pole, on the side of the vertical the sign of b -+ a
  /// (phi_dot's numerator b - a u at u = +-1) decides, where b -+ a is within 1e3 ulps of
  /// the terms it is formed from: an input's last digits decide the side, and with it the
  /// path's name and its mean precession, which moves by 2 pi / period between the sides.
  struct UndecidedSide {
    bool upright = true;      ///< the pole passed: upright (b - a), or the bottom (b + a)
    double distance = 0.0;    ///< the turning circle's angle from that pole, rad
    double terms = 0.0;       ///< the size of the terms b -+ a is formed from, rad/s
    double other_mean = 0.0;  ///< the mean precession on the other side, rad/s
  };
  /// Each pole whose side is undecided so (none where the period is infinite).
  std::vector<UndecidedSide> undecided_sides() const;
  /// |S| plus the axis's greatest speed on the sphere, sqrt(2 (E' + m g l) / I), rad/s: the
  /// motion's fastest rate, which a step must resolve whatever the nutation period.
  double fastest_rate() const;
  /// phi_dot at the turning circles theta_max (u1) and theta_min (u2), rad/s.
  double phi_dot_at_u1() const { return phi_dot_u1_; }
  double phi_dot_at_u2() const { return phi_dot_u2_; }

  /// Conserved: the total energy E = E' + Is S^2 / 2 (J), p_phi = L_z and p_psi = Is S (kg m^2/s).
  double energy() const { return energy_; }
  double p_phi() const { return p_phi_; }
  double p_psi() const { return p_psi_; }
  const HeavyTop& top() const { return top_; }
  const TopStart& start() const { return start_; }

 private:
  struct Phase {
    double sn, cn, dn;
    double v;  ///< lambda t + v0
  };
  Phase phase(double t) const;
  // Where the axis is at sn^2, cn^2 of the phase: u - u0, 1 - u, 1 + u, b - a u, theta, phi_dot.
  struct Where {
    double w, omu, opu, numerator, theta, phi_dot;
  };
  Where at(double sn2, double cn2) const;
  double theta_from(const Phase& p) const;
  // The integral of 1/(1 - n sn^2) from 0 to v (v reduced by 2K inside).
  double third_kind(double v, double n, double one_minus_n, double complete) const;

  // The constructor's steps, in the book's order (heavy_top_exact.cpp).
  struct StartTerms;  // the start's terms, formed in 113-bit arithmetic
  static StartTerms start_terms(const HeavyTop& top, const TopStart& start);
  // The conserved p_psi, p_phi and E (eqs. 176, 177, 191-193); throws where they overflow.
  void take_constants(const StartTerms& terms);
  // The turning circles u1 <= u2 and u3 >= 1, the roots of the energy equation's f(u), about u0.
  void find_turning_circles(const StartTerms& terms);
  // 1 + u1 to its own accuracy where u1 is near the bottom, from f about u = -1.
  void refine_near_south_pole(const StartTerms& terms);
  // 1 - u2 and u3 - 1 where near upright, from f about u = 1; returns u3 - 1 (NaN: not).
  double refine_near_north_pole(const StartTerms& terms);
  // A turning circle within underflow of a pole taken as the pole.
  void take_poles_within_underflow();
  // The phase: k^2, lambda, K, the nutation period, v0; steady or wavy.
  void set_phase(double u3_minus_1);
  // The mean precession, phi_dot's mean over a nutation period, and its limits.
  void set_mean_precession();
  // phi_dot at the turning circles, and the regime its signs there decide.
  void classify_regime();
  // The poles the axis goes through as roots of f (b -+ a = 0): 0, 1 or 2.
  int root_poles() const;

  HeavyTop top_;
  TopStart start_;
  TopRegime regime_ = TopRegime::kSteady;
  double u0_ = 1.0, one_minus_u0_ = 0.0, one_plus_u0_ = 2.0;
  double a_ = 0.0, beta_ = 0.0, d0_ = 0.0;  // p_psi/I, 2 mgl/I, phi_dot0 sin^2(theta0)
  double w1_ = 0.0, w2_ = 0.0, w3_ = 0.0;   // the roots, u_i - u0
  double opu1_ = 0.0;                       // 1 + u1, to its own relative accuracy
  double omu2_ = 0.0;                       // 1 - u2, likewise
  double lambda_ = 0.0, v0_ = 0.0, kp2_ = 1.0, k2_ = 0.0, K_ = 0.0, period_ = 0.0;
  double n_plus_ = 0.0, n_minus_ = 0.0, pi_plus_ = 0.0, pi_minus_ = 0.0;
  double one_minus_n_plus_ = 1.0;  // (1 - u2)/(1 - u1), not 1 - n+ rounded (0 near upright)
  double b_minus_a_ = 0.0, b_plus_a_ = 0.0;
  bool through_north_ = false, through_south_ = false;  // a pole is a turning circle
  bool use_plus_ = false, use_minus_ = false;           // the J+ and J- terms of phi, psi
  double G_plus_0_ = 0.0, G_minus_0_ = 0.0;
  double mean_phi_dot_ = 0.0, phi_dot_u1_ = 0.0, phi_dot_u2_ = 0.0;
  std::array<double, 2> mean_limits_{0.0, 0.0};
  double mean_error_ = 0.0;
  double energy_ = 0.0, p_phi_ = 0.0, p_psi_ = 0.0;
  JacobiElliptic jacobi_{1.0};
};

}  // namespace rigid
