// The heavy symmetric top: its rules, its steady motions (the sleeping top, steady
// precession, the fast top's estimates), the Euler angles of its attitude, and what
// decides its exact motion's path: the regime, a pole's undecided side and the
// condition of the nutation period (heavy_top.h). The exact motion itself, its
// turning circles, phase and mean precession: heavy_top_exact.cpp.
#include "rigid/heavy_top.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "rigid/format.h"
#include "rigid/free_body_exact.h"
#include "rigid/rotation.h"
#include "rigid/units.h"

namespace rigid {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

void require_positive(double value, const char* what) {
  if (!std::isfinite(value) || !(value > 0.0)) {
    throw std::invalid_argument(std::string(what) + " must be positive and finite, got " +
                                format_number(value));
  }
}

}  // namespace

void validate(const HeavyTop& top) {
  require_positive(top.I, "the transverse moment I");
  require_positive(top.Is, "the moment Is about the symmetry axis");
  require_positive(top.mgl, "m g l");
}

void validate_top_body(double I, double Is, double m, double arm) {
  require_positive(I, "the transverse moment I");
  require_positive(Is, "the moment Is about the symmetry axis");
  require_positive(m, "the mass");
  require_positive(arm, "the arm");
  // About the centre of mass: I_cm = I - m arm^2 >= Is / 2, to a few ulps of I so
  // that a thin disk (I_cm = Is / 2 exactly, up to rounding) passes.
  const double I_cm = I - m * arm * arm;
  if (I_cm < 0.5 * Is - 8 * kEps * I) {
    throw std::invalid_argument(
        "no body has these moments: about the centre of mass I - m arm^2 = " + format_number(I_cm) +
        " kg m^2 must be at least Is/2 = " + format_number(0.5 * Is));
  }
}

double sleeping_min_spin(const HeavyTop& top) {
  validate(top);
  return std::sqrt(4.0 * top.mgl * top.I) / top.Is;  // eq. 189
}

double horizontal_precession_rate(const HeavyTop& top, double spin) {
  validate(top);
  return top.mgl / (top.Is * spin);  // eq. 185
}

SteadyPrecession steady_precession_rates(const HeavyTop& top, double spin, double theta) {
  validate(top);
  // A theta within the rounding of its own conversion from degrees (2 ulps: 90 *
  // (pi / 180) lands one ulp from the double nearest pi/2) of 90 deg is horizontal:
  // those doubles have |cos| below 3e-16, which would make the fast rate 1e17 rad/s
  // where the angle meant, and all the input can tell, has it infinite.
  const double c_raw = std::cos(theta);
  const double ulp = std::nextafter(std::abs(theta), HUGE_VAL) - std::abs(theta);
  const double c = std::abs(c_raw) <= 2.0 * ulp ? 0.0 : c_raw;
  const double L3 = top.Is * spin;
  const double D = L3 * L3 - 4.0 * top.mgl * top.I * c;  // eq. 188
  SteadyPrecession p;
  if (!(D >= 0.0)) return p;
  p.exists = true;
  const double root = std::sqrt(D);
  // I c phi_dot^2 - Is S phi_dot + mgl = 0; the root without cancellation first.
  const double big = L3 >= 0 ? L3 + root : L3 - root;
  // Horizontal with no spin (big = 0): eq. 187 asks m g l = 0, no rate balances gravity
  if (big == 0.0) {
    p.exists = false;
    return p;
  }
  p.slow = 2.0 * top.mgl / big;
  p.fast = c == 0.0 ? std::copysign(std::numeric_limits<double>::infinity(), big)
                    : big / (2.0 * top.I * c);
  return p;
}

FastTopNutation fast_top_nutation(const HeavyTop& top, const TopStart& start) {
  validate(top);
  if (!(start.spin > 0.0)) throw std::invalid_argument("fast_top_nutation: the spin must be > 0");
  FastTopNutation n;
  const double L3 = top.Is * start.spin;
  n.order = 2.0 * top.mgl * top.I / (L3 * L3);
  n.frequency = L3 / top.I;
  const double slow = top.mgl / L3;  // the fast top's slow precession (eq. 185)
  n.range = 2.0 / n.frequency *
            std::hypot(start.theta_dot, std::sin(start.theta) * (start.phi_dot - slow));
  return n;
}

std::string to_string(TopRegime regime) {
  switch (regime) {
    case TopRegime::kSleeping:
      return "sleeping";
    case TopRegime::kWavy:
      return "wavy";
    case TopRegime::kLooping:
      return "looping";
    case TopRegime::kCusped:
      return "cusped";
    case TopRegime::kThroughPole:
      return "through the pole";
    case TopRegime::kPlanar:
      return "planar";
    case TopRegime::kSteady:
      break;
  }
  return "steady";
}

Eigen::Quaterniond euler_attitude(double phi, double theta, double psi) {
  return Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitX()) *
         Eigen::AngleAxisd(psi, Eigen::Vector3d::UnitZ());
}

Eigen::Vector3d euler_omega_body(const TopAngles& a) {
  return omega_in_body({a.phi, a.theta, a.psi}, {a.phi_dot, a.theta_dot, a.psi_dot}, a.sin_theta);
}

TopAngles euler_angles_and_rates(const Eigen::Quaterniond& q, const Eigen::Vector3d& w) {
  const EulerAngles e = euler_zxz(q);
  TopAngles a;
  a.theta = e.theta, a.phi = e.phi, a.psi = e.psi;
  if (const std::optional<EulerRates> r = rates_from_body_omega(e, w)) {
    a.phi_dot = r->phi_dot, a.theta_dot = r->theta_dot, a.psi_dot = r->psi_dot;
  } else {
    // at a pole psi is 0 (euler_zxz): phi takes the whole turn about 3 = +-z
    a.theta_dot = w(0) * std::cos(e.psi) - w(1) * std::sin(e.psi);
    a.phi_dot = std::cos(e.theta) > 0 ? w(2) : -w(2);
    a.psi_dot = 0.0;
  }
  return a;
}

void HeavyTopExact::classify_regime() {
  const int root_poles = this->root_poles();
  // phi_dot at the turning circles.
  const Where at_u1 = at(0.0, 1.0), at_u2 = at(1.0, 0.0);
  phi_dot_u1_ = at_u1.phi_dot;
  phi_dot_u2_ = at_u2.phi_dot;
  if (regime_ == TopRegime::kWavy) {
    if (a_ == 0.0 && d0_ == 0.0) {
      // no spin and no p_phi: phi_dot = 0 but at the poles, the axis swings in a plane
      regime_ = TopRegime::kPlanar;
    } else if (root_poles > 0) {
      regime_ = TopRegime::kThroughPole;
    } else {
      // b - a u at each turning circle as at() forms it (from the nearer pole's b -+ a
      // near a pole, each term to its own accuracy); within the roundoff of its terms
      // it is a cusp (released with phi_dot = theta_dot = 0), as is a circle taken as
      // the pole itself (within underflow of it).
      const auto numerator = [&](const Where& x, double w, double pole_term, double to_pole,
                                 bool pole) {
        const double bound = to_pole < 1e-3
                                 ? 16 * kEps * (std::abs(pole_term) + std::abs(a_ * to_pole))
                                 : 16 * kEps * (std::abs(d0_) + std::abs(a_ * w));
        return pole || std::abs(x.numerator) <= bound ? 0.0 : x.numerator;
      };
      const double n1 = numerator(at_u1, w1_, b_plus_a_, opu1_, through_south_);
      const double n2 = numerator(at_u2, w2_, b_minus_a_, omu2_, through_north_);
      if (n1 == 0.0 || n2 == 0.0) {
        regime_ = TopRegime::kCusped;
      } else if ((n1 > 0) != (n2 > 0)) {
        regime_ = TopRegime::kLooping;
      }
    }
  }
}

std::vector<HeavyTopExact::UndecidedSide> HeavyTopExact::undecided_sides() const {
  std::vector<UndecidedSide> sides;
  if (!std::isfinite(period_)) return sides;
  for (const bool upright : {true, false}) {
    const double value = upright ? b_minus_a_ : b_plus_a_;
    const double terms = std::abs(d0_) + std::abs(a_) * (upright ? one_minus_u0_ : one_plus_u0_);
    if (std::abs(value) > 1e3 * kEps * terms) continue;
    sides.push_back({upright, upright ? theta_min() : kPi - theta_max(), terms,
                     mean_phi_dot_ - std::copysign(2 * kPi, value) / period_});
  }
  return sides;
}

double nutation_period_condition(const HeavyTopExact& motion) {
  const double T = motion.nutation_period();
  if (!std::isfinite(T)) return std::numeric_limits<double>::infinity();
  // A relative step of 1e-7, or 1e-3 of k'^2 near the separatrix, so that no step carries
  // the start across it (T to ~1e-15: the number to ~1e-15 / h, read where it is large).
  const double kp2 = (motion.u3() - motion.u2()) / (motion.u3() - motion.u1());
  const double h = std::min(1e-7, 1e-3 * std::max(kp2, 1e-12));
  double worst = 0.0;
  for (int k = 0; k < 4; ++k) {
    const auto input = [k](TopStart& s) -> double& {
      return k == 0 ? s.theta : k == 1 ? s.theta_dot : k == 2 ? s.phi_dot : s.spin;
    };
    TopStart s = motion.start();
    if (input(s) == 0.0) continue;
    double T_at[2];
    for (const int side : {0, 1}) {
      const double scale = side ? 1 + h : 1 - h;
      TopStart t = s;
      input(t) *= scale;
      if (k == 0 && s.theta_deg) t.theta_deg = *s.theta_deg * scale;
      try {
        T_at[side] = HeavyTopExact(motion.top(), t).nutation_period();
      } catch (const std::exception&) {
        T_at[side] = T;  // a step past a rule (theta0 at 180): that side left out
      }
    }
    worst = std::max(worst, std::abs(T_at[1] - T_at[0]) / (2 * h * T));
  }
  return std::isfinite(worst) ? worst : std::numeric_limits<double>::infinity();
}

}  // namespace rigid
