// The free symmetric top in closed form (symmetric_top.h).
#include "rigid/symmetric_top.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "rigid/format.h"
#include "rigid/free_body.h"
#include "rigid/free_body_integrate.h"
#include "rigid/inertia.h"
#include "rigid/units.h"

namespace rigid {

std::string to_string(ConeContact contact) {
  switch (contact) {
    case ConeContact::kOutside:
      return "outside";
    case ConeContact::kInside:
      return "inside";
    case ConeContact::kNone:
      break;
  }
  return "none";
}

void validate_symmetric(double I, double Is) {
  // The symmetry axis is 3; the triangle inequality I + I >= Is is the one that can fail.
  validate(PrincipalMoments{I, I, Is});
}

SymmetricPrecession free_symmetric_precession(double I, double Is, double omega, double alpha) {
  validate_symmetric(I, Is);
  if (!std::isfinite(omega) || !(omega > 0.0)) {
    throw std::invalid_argument("|omega| must be positive and finite, got " + format_number(omega));
  }
  if (!(alpha >= 0.0 && alpha < kPi / 2)) {
    throw std::invalid_argument("alpha must be at least 0 and below 90 deg, got " +
                                format_number(rad_to_deg(alpha)) + " deg");
  }
  const double s = std::sin(alpha), c = std::cos(alpha);
  SymmetricPrecession p;
  p.body_rate = omega * c * ((Is - I) / I);  // eq. 109; exactly omega cos alpha when Is = 2I
  p.L = omega * std::hypot(I * s, Is * c);   // eq. 143
  p.space_rate = p.L / I;                    // eqs. 146-147
  p.theta = std::atan2(I * s, Is * c);       // eq. 144
  p.spin_rate = -p.body_rate;                // omega_3 - phi_dot cos theta
  p.body_cone = alpha;
  const double lead = std::atan2((I - Is) * s * c, Is * c * c + I * s * s);  // theta - alpha
  p.space_cone = std::abs(lead);
  p.contact = lead > 0   ? ConeContact::kOutside
              : lead < 0 ? ConeContact::kInside
                         : ConeContact::kNone;
  p.body_period = p.body_rate == 0.0 ? std::numeric_limits<double>::infinity()
                                     : 2 * kPi / std::abs(p.body_rate);
  p.space_period = 2 * kPi / p.space_rate;
  return p;
}

PrecessionCheck integrated_precession(double I, double Is, double omega, double alpha, double tol,
                                      std::size_t max_steps) {
  const SymmetricPrecession p = free_symmetric_precession(I, Is, omega, alpha);
  if (alpha == 0.0) {
    throw std::invalid_argument("at alpha = 0 the axis 3 lies along L: it has no turn to measure");
  }
  const double period = p.space_period * omega;  // dimensionless: time in units of 1/omega
  const PrincipalMoments moments{1.0, 1.0, Is / I};
  const RotationState x0 =
      make_state(Vec3(std::sin(alpha), 0.0, std::cos(alpha)), Eigen::Quaterniond::Identity());
  OdeOptions options;
  options.abs_tol = options.rel_tol = tol;
  options.max_steps = max_steps;
  const FreeBodyRun run =
      integrate(FreeBodyProblem(moments), x0, {0.0, period / 4, period}, options);
  const Vec3 L = Vec3(std::sin(alpha), 0.0, (Is / I) * std::cos(alpha)).normalized();
  const Vec3 axis0 = Vec3::UnitZ();
  const Vec3 quarter = attitude(run.samples[1].x) * Vec3::UnitZ();
  const Vec3 end = attitude(run.samples[2].x) * Vec3::UnitZ();
  // The turn of 3 about L between t = 0 and a quarter period (about 90 degrees); the
  // parts across L scaled to unit length first, since at alpha ~ 1e-200 their cross
  // product (~1e-400) underflowed to 0 and the turn read 0
  const Vec3 u = (axis0 - axis0.dot(L) * L).stableNormalized();
  const Vec3 v = (quarter - quarter.dot(L) * L).stableNormalized();
  const double turn = std::atan2(u.cross(v).dot(L), u.dot(v));
  PrecessionCheck check;
  check.space_rate = turn / (period / 4) * omega;
  check.axis_return = angle_between(axis0, end);
  check.L_space_drift_rel = run.max_invariant_error[FreeBodyProblem::kLSpace];
  check.energy_drift_rel = run.max_invariant_error[FreeBodyProblem::kEnergy];
  check.steps = run.steps;
  return check;
}

}  // namespace rigid
