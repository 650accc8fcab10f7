// euler_angles' section 7: Lagrange's equations in the Euler angles, their terms exact but
// for rounding and checked by differences along a motion: the exact free motion (eqs.
// 150-159), and an integration under a constant torque in the body (eqs. 163-166).
#include "euler_angles/lagrange.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "common/free_motion.h"
#include "rigid/euler_lagrange.h"
#include "rigid/free_body_exact.h"
#include "rigid/ode.h"
#include "rigid/units.h"

namespace rigid::lab::euler_angles {

using Eigen::Vector3d;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Why Lagrange's equations in the Euler angles are undefined at these angles.
std::string pole_reason(double theta_deg) {
  return fmt::format(
      "theta = {:g} deg: at a pole phi and psi turn about one axis, their rates are undefined "
      "(only phi_dot {} psi_dot is) and so are the angles' Lagrange equations",
      theta_deg, theta_deg < 90 ? "+" : "-");
}

// Why there are no differences along the motion at a time: at a pole (`pole`), or so near
// one that the angles read from an attitude keep fewer than 6 digits.
std::string no_differences_reason(bool pole) {
  return pole ? "at a pole the motion's attitude gives only phi_dot +- psi_dot, not each rate"
              : "within 1.4e-8 rad of a pole the angles an attitude gives keep fewer than 6 digits";
}

// Each angle's residual d/dt dT/dq_dot - dT/dq (- Q) as one row: its exact terms' value
// with their rounding bound (remark, JSON _error), and beside it as a check the value
// the differences along the motion give (JSON _differences and _differences_error, null
// where there are none). None, saying why, where there are no exact terms (`why_none`)
// or their bound exceeds 1e-3 of the motion's size `size` (T, or |Q| where larger; named
// in `size_name`), which would check nothing.
void report_residuals(Report& report, const std::optional<LagrangeTerms>& exact,
                      const std::optional<LagrangeTerms>& differences,
                      const std::string& key_prefix, const std::string& at, bool with_force,
                      double size, const std::string& size_name, const std::string& why_none,
                      const std::string& why_no_differences) {
  const char* names[3] = {"phi", "theta", "psi"};
  for (int k = 0; k < 3; ++k) {
    const std::string key = fmt::format("{}{}", key_prefix, names[k]);
    const std::string label = fmt::format("d/dt dT/d{0}_dot - dT/d{0}{1} at {2}", names[k],
                                          with_force ? fmt::format(" - Q_{}", names[k]) : "", at);
    const std::string check =
        differences
            ? fmt::format(
                  "by differences along the motion {:.3g} +- {:.2g}{}",
                  differences->residual[k].value, differences->residual[k].error,
                  differences->residual[k].error > 1e-3 * size ? ", too coarse to tell" : "")
            : "no differences here: " + why_no_differences;
    if (!exact) {
      report.result_none(key, label, "N m", why_none);
      report.result_json_none(key + "_error", "N m");
    } else if (exact->residual[k].error > 1e-3 * size) {
      const double terms =
          std::max(std::abs(exact->momentum_rate[k].value), std::abs(exact->dT_dq[k].value));
      report.result_none(
          key, label, "N m",
          fmt::format("its exact terms' rounding, {:.2g} N m, exceeds 1e-3 of {}: the terms are "
                      "{:.3g} N m here, and near a pole theta's grow as 1 / sin theta and cancel",
                      exact->residual[k].error, size_name, terms));
      report.result_json_none(key + "_error", "N m");
    } else {
      report.result(key, label, exact->residual[k].value, "N m");
      report.remark(fmt::format("(+- {:.2g} N m: the exact terms' rounding; {})",
                                exact->residual[k].error, check));
      report.result_json(key + "_error", exact->residual[k].error, "N m");
    }
    if (differences) {
      report.result_json(key + "_differences", differences->residual[k].value, "N m");
      report.result_json(key + "_differences_error", differences->residual[k].error, "N m");
    } else {
      report.result_json_none(key + "_differences", "N m");
      report.result_json_none(key + "_differences_error", "N m");
    }
  }
}

// The free motion's state in the angles at t, phi and psi nearest e's (none at a pole).
std::optional<EulerState> free_state(const FreeBodyExact& motion, const EulerAngles& e, double t) {
  return euler_state(motion.attitude(t), motion.omega_body(t), e);
}

// psi's two terms, defined at a pole too (the rates are not needed: eqs. 154-156 make
// d omega / d psi = (omega_2, -omega_1, 0)), and Euler's equation they make (eq. 158).
void report_psi(Report& report, const PrincipalMoments& I, const FreeBodyExact& motion,
                const std::optional<LagrangeTerms>& differences, double T,
                const std::string& why_no_differences) {
  const PsiTerms psi = psi_terms(I, report.omega_body);
  report.result("lagrange_psi_momentum", "  dT/dpsi_dot = I3 omega_3 (eqs. 153-156)",
                psi.momentum.value, "kg m^2/s");
  report.remark(fmt::format("(+- {:.2g} kg m^2/s: rounding)", psi.momentum.error));
  report.result_json("lagrange_psi_momentum_error", psi.momentum.error, "kg m^2/s");
  report.result("lagrange_psi_force",
                "  dT/dpsi = I1 omega_1 omega_2 + I2 omega_2 (-omega_1) (eqs. 154-155, 157)",
                psi.force.value, "N m");
  report.remark(fmt::format(
      "(+- {:.2g} N m: rounding; {})", psi.force.error,
      differences
          ? fmt::format("by differences in psi, the rates held: {:.9g} +- {:.2g}{}",
                        differences->dT_dq[2].value, differences->dT_dq[2].error,
                        differences->dT_dq[2].error > 1e-3 * std::max(T, std::abs(psi.force.value))
                            ? ", too coarse to tell"
                            : "")
          : "no differences here: " + why_no_differences));
  report.result_json("lagrange_psi_force_error", psi.force.error, "N m");
  const Vector3d w = motion.omega_body(0.0);
  report.result("euler_psi_rate", "  Euler: I3 omega_3_dot = (I1 - I2) omega_1 omega_2 (eq. 158)",
                (I.I1 - I.I2) * w(0) * w(1), "N m");
}

// --csv: the angles, their rates and omega in the three frames along the free motion, over
// its time scale (a polhode period), 200 samples
void add_free_series(Report& report, const FreeBodyExact& motion, const EulerAngles& e,
                     double scale) {
  TimeSeries series(
      "euler_angles: the free motion of the body of section 7 from the angles and rates "
      "given, over one polhode period (or one turn)");
  series.add({"t_s"}, "s", "time")
      .add({"phi_rad", "theta_rad", "psi_rad"}, "rad",
           "the z-x-z Euler angles of section 6, phi and psi continuous from the start (not "
           "wrapped)")
      .add({"phi_dot_rad_s", "theta_dot_rad_s", "psi_dot_rad_s"}, "rad/s",
           "the angles' rates (at a pole, where they are undefined, 0)")
      .add({"omega_x", "omega_y", "omega_z"}, "rad/s", "omega in the fixed frame")
      .add({"omega_xp", "omega_yp", "omega_zp"}, "rad/s",
           "omega in the intermediate frame x'y'z' (x' the line of nodes)")
      .add({"omega_1", "omega_2", "omega_3"}, "rad/s", "omega in the body's principal axes");
  EulerAngles previous = e;
  for (int n = 0; n <= 200; ++n) {
    const double t = scale * n / 200.0;
    // continuous: phi and psi by whole turns nearest the previous sample's
    EulerState s =
        free_state(motion, e, t).value_or(EulerState{euler_zxz(motion.attitude(t)), EulerRates{}});
    s.angles.phi = previous.phi + std::remainder(s.angles.phi - previous.phi, 2 * kPi);
    s.angles.psi = previous.psi + std::remainder(s.angles.psi - previous.psi, 2 * kPi);
    previous = s.angles;
    const Vector3d w_body = motion.omega_body(t), w_space = motion.attitude(t) * w_body;
    const Vector3d w_int = passive(Vector3d::UnitX(), s.angles.theta) *
                           passive(Vector3d::UnitZ(), s.angles.phi) * w_space;
    series.rows.push_back({t, s.angles.phi, s.angles.theta, s.angles.psi, s.rates.phi_dot,
                           s.rates.theta_dot, s.rates.psi_dot, w_space(0), w_space(1), w_space(2),
                           w_int(0), w_int(1), w_int(2), w_body(0), w_body(1), w_body(2)});
  }
  report.series(std::move(series));
}

// The print's slips in section 7, with this body's numbers.
void report_section_7_errata(Report& report, const Inputs& in, const PrincipalMoments& I,
                             const EulerAngles& e, double T) {
  // eqs. 154-156 list d omega_2 / d psi_dot twice: the missing one is d omega_1 / d psi_dot,
  // 0 as eq. 134 says (d omega / d psi_dot is the body's 3 axis whatever the angles)
  const Vector3d d_psi_dot = rate_axes_in_body(e).col(2);
  report.erratum({"eqs. 154-156", "d omega_2 / d psi_dot = 0 ... d omega_2 / d psi_dot = 0",
                  fmt::format("they list d omega_2 / d psi_dot twice; one of them is d omega_1 / d "
                              "psi_dot, also 0 (eq. 134 has no psi_dot; d omega / d psi_dot = "
                              "({:g}, {:g}, {:g}) here, the body's 3 axis).",
                              d_psi_dot(0), d_psi_dot(1), d_psi_dot(2))});
  // eq. 150 lacks its 1/2 whatever the body: shown for this one
  report.erratum(
      {"eq. 150", "T = sum_{i=1}^{3} I_i omega_i^2",
       fmt::format("T = 1/2 sum I_i omega_i^2 = omega.L / 2 (eq. 81 has sum I_i omega_i^2 = 2T). "
                   "For {} I = ({:g}, {:g}, {:g}) kg m^2 the print gives {:.6g} J here, twice "
                   "the kinetic energy T = {:.6g} J.",
                   in.moments ? "this body," : "the body of section 7,", I.I1, I.I2, I.I3, 2 * T,
                   T)});
}

// The run under the torque to t1, and the Lagrange terms there: exact at its state, and by
// differences along one run through the differences' times. None where it failed or t1 is
// at a pole.
struct TorqueRun {
  double t1 = 0.0;                          ///< s
  Eigen::Quaterniond q1;                    ///< the attitude at t1 (rkf78 at 1e-13)
  Vector3d w1;                              ///< omega in the body at t1, rad/s
  RotationState reference_t1{};             ///< the state at t1 by vern9 a hundred times tighter
  std::optional<std::string> failed;        ///< why an integration failed
  std::optional<EulerState> center;         ///< the state at t1 in the angles
  std::optional<LagrangeSteps> steps;       ///< the differences' steps at t1
  std::map<double, RotationState> samples;  ///< the run at the differences' times
  std::optional<LagrangeTerms> differences, exact;
};

// The integrations (Euler's equations and the quaternion, rkf78 at 1e-13, and vern9 as
// the reference) from the report's omega and the attitude e to t1, a quarter of the
// motion's time scale.
TorqueRun integrate_torque(const Report& report, const PrincipalMoments& I, const Vector3d& N,
                           const EulerAngles& e, double free_scale) {
  // The motion's time scale: the free motion's, or less where the torque turns the body
  // by a radian from rest sooner (in 2 pi sqrt(I / |N|))
  const double I_max = std::max({I.I1, I.I2, I.I3}), I_min = std::min({I.I1, I.I2, I.I3});
  const double torque_scale = 2 * kPi * std::sqrt(I_max / N.norm());
  double scale = std::min(free_scale, torque_scale);
  if (!std::isfinite(scale)) scale = 1.0;  // at rest, and no torque: nothing moves
  const double t1 = 0.25 * scale;
  const Vector3d w0 = report.omega_body;
  const RotationState x0 = make_state(w0, quaternion_from_euler_zxz(e));
  // the tolerance: 1e-13 of omega's largest size over [0, t1] (and of q's, 1)
  OdeOptions options;
  options.method = Method::kRkf78;
  options.rel_tol = 1e-13;
  options.abs_tol = 1e-13 * std::min(1.0, w0.norm() + N.norm() * t1 / I_min + 1e-300);
  options.max_evaluations = 2'000'000;
  const EulerRhs rhs{I, N};
  RotationState at_t1{};
  std::map<double, RotationState> samples;
  std::optional<std::string> failed;
  // the reference: vern9 a hundred times tighter
  OdeOptions reference = options;
  reference.method = Method::kVern9;
  reference.rel_tol /= 100, reference.abs_tol /= 100;
  RotationState reference_t1{};
  try {
    integrate_sampled(rhs, x0, {0.0, t1}, options,
                      [&](const RotationState& x, double) { at_t1 = x; });
    integrate_sampled(rhs, x0, {0.0, t1}, reference,
                      [&](const RotationState& x, double) { reference_t1 = x; });
  } catch (const std::exception& error) {
    failed = error.what();
  }
  const Eigen::Quaterniond q1 = Eigen::Quaterniond(at_t1[3], at_t1[4], at_t1[5], at_t1[6]);
  const Vector3d w1(at_t1[0], at_t1[1], at_t1[2]);
  const std::optional<EulerState> center =
      failed ? std::nullopt : euler_state(q1.normalized(), w1, e);
  const std::optional<LagrangeSteps> steps = center ? lagrange_steps(*center, scale) : std::nullopt;
  std::vector<double> times;
  if (steps) {
    // one run through the differences' times: its error is smooth between them and
    // cancels, leaving roundoff (steps.noise, 64 eps)
    times = lagrange_times(t1, steps->time);
    times.insert(times.begin(), 0.0);
    try {
      integrate_sampled(rhs, x0, times, options,
                        [&](const RotationState& x, double t) { samples[t] = x; });
    } catch (const std::exception& error) {
      failed = error.what();
    }
  }
  const auto at = [&](double t) -> std::optional<EulerState> {
    const auto found = samples.find(t);
    if (found == samples.end()) return std::nullopt;
    const RotationState& x = found->second;
    return euler_state(Eigen::Quaterniond(x[3], x[4], x[5], x[6]).normalized(),
                       Vector3d(x[0], x[1], x[2]), center->angles);
  };
  const std::optional<LagrangeTerms> differences =
      steps && !failed ? lagrange_terms(I, at, t1, *steps, N) : std::nullopt;
  // the terms exact but for rounding at the run's state at t1
  const std::optional<LagrangeTerms> exact =
      failed ? std::nullopt : lagrange_terms_exact(I, euler_zxz(q1.normalized()), w1, N);
  return {t1, q1, w1, reference_t1, failed, center, steps, std::move(samples), differences, exact};
}

// t1 and how far the run is from its reference there.
void report_torque_accuracy(Report& report, const TorqueRun& torque) {
  const double t1 = torque.t1;
  const std::optional<std::string>& failed = torque.failed;
  const Eigen::Quaterniond& q1 = torque.q1;
  const Vector3d& w1 = torque.w1;
  const RotationState& reference_t1 = torque.reference_t1;
  report.result("torque_check_time_s", "t1, a quarter of the motion's time scale", t1, "s");
  const char omega_label[] = "  |omega_rkf78 - omega_vern9| / |omega| at t1 (1e-13; 1e-15)";
  const char attitude_label[] = "  the angle between their attitudes at t1";
  if (failed) {
    report.result_none("torque_integration_error", omega_label, "", *failed);
    report.result_none("torque_attitude_error", attitude_label, "rad", *failed);
  } else {
    const Vector3d w_ref(reference_t1[0], reference_t1[1], reference_t1[2]);
    const Eigen::Quaterniond q_ref(reference_t1[3], reference_t1[4], reference_t1[5],
                                   reference_t1[6]);
    report.result("torque_integration_error", omega_label,
                  (w1 - w_ref).norm() / std::max(w_ref.norm(), 1e-300), "");
    report.result("torque_attitude_error", attitude_label, attitude_distance(q1, q_ref), "rad");
    report.remark("(phi and psi carry it divided by sin theta)");
  }
}

// Each angle's equation with the torque's generalized force Q, and psi's without it.
void report_torque_lagrange(Report& report, const PrincipalMoments& I, const Vector3d& N,
                            const TorqueRun& torque) {
  const std::optional<std::string>& failed = torque.failed;
  const std::optional<LagrangeTerms>& exact = torque.exact;
  const std::optional<LagrangeTerms>& differences = torque.differences;
  const std::optional<EulerState>& center = torque.center;
  const std::string why_none =
      failed ? "the integration failed" : "t1 is at a pole, where the rates are undefined";
  double Q_size = 0.0;
  if (exact) {
    const Vector3d Q(exact->force[0].value, exact->force[1].value, exact->force[2].value);
    Q_size = Q.cwiseAbs().maxCoeff();
    report.result("generalized_force", "Q = (N.z, N.x', N_3) at t1, the torque's virtual work", Q,
                  "N m");
  } else {
    report.result_none("generalized_force", "Q = (N.z, N.x', N_3) at t1", "N m", why_none);
  }
  const Vector3d& w1_body = torque.w1;
  const double T1 = 0.5 * w1_body.dot(I.vector().cwiseProduct(w1_body));
  report_residuals(report, exact, differences, "torque_lagrange_residual_", "t1", true,
                   std::max(T1, Q_size), fmt::format("max(T, |Q_k|), {:.3g}", std::max(T1, Q_size)),
                   why_none, failed ? *failed : no_differences_reason(!center || !exact));
  // Without Q psi's equation misses by the torque's N_3: the check can tell where N_3 is
  // well above the exact terms' rounding
  const char free_label[] = "  d/dt dT/dpsi_dot - dT/dpsi without Q_psi";
  if (exact) {
    const double value = exact->residual[2].value + exact->force[2].value;
    const double error = exact->residual[2].error + exact->force[2].error;
    report.result("torque_free_residual_psi", free_label, value, "N m");
    report.remark(std::abs(N(2)) > 10 * error
                      ? fmt::format("(misses by N_3 = {:g} N m: without the torque's Q it does "
                                    "not hold; +- {:.2g} N m)",
                                    N(2), error)
                      : fmt::format("(N_3 = {:g} N m is within 10 times the rounding, {:.2g} N m, "
                                    "here: this cannot tell)",
                                    N(2), error));
    report.result_json("torque_free_residual_psi_error", error, "N m");
  } else {
    report.result_none("torque_free_residual_psi", free_label, "N m", why_none);
    report.result_json_none("torque_free_residual_psi_error", "N m");
  }
}

// eq. 166, (I_i - I_j) w_i w_j - (I_k w_k_dot - N_k) = 0 for i j k = 1 2 3, 2 3 1, 3 1 2;
// 1 2 3 is eq. 164, N_3 = L_3_dot + w_1 L_2 - w_2 L_1; omega_dot by differences along the
// run
void report_euler_torque(Report& report, const PrincipalMoments& I, const Vector3d& N,
                         const TorqueRun& torque) {
  const double t1 = torque.t1;
  const std::map<double, RotationState>& run = torque.samples;
  const double moments[3] = {I.I1, I.I2, I.I3};
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const std::string key = fmt::format("euler_torque_residual_{}", k + 1);
    const std::string label =
        fmt::format("(I{0} - I{1}) w{0} w{1} - (I{2} w{2}_dot - N{2}) at t1 (eq. 166{3})", i + 1,
                    j + 1, k + 1, k == 2 ? ", 164" : "");
    if (!torque.differences) {
      report.result_none(key, label, "N m",
                         torque.failed ? "the integration failed"
                                       : no_differences_reason(!torque.center || !torque.exact));
      report.result_json_none(key + "_error", "N m");
      continue;
    }
    const RotationState& x1 = run.at(t1);
    const Vector3d w = Vector3d(x1[0], x1[1], x1[2]);
    const Measured w_dot = central_derivative([&](double dt) { return run.at(t1 + dt)[k]; },
                                              torque.steps->time, 64 * kEps * w.norm());
    report.result(key, label,
                  (moments[i] - moments[j]) * w(i) * w(j) - (moments[k] * w_dot.value - N(k)),
                  "N m");
    report.remark(
        fmt::format("(+- {:.2g} N m: the differences' own error)", moments[k] * w_dot.error));
    report.result_json(key + "_error", moments[k] * w_dot.error, "N m");
  }
}

}  // namespace

// Section 7 at these angles and rates (or this omega), for a body (its moments, or I = 1,
// 2, 3 kg m^2): each angle's Lagrange equation exact but for rounding, checked by
// differences along the exact torque-free motion started there; psi's is Euler's (eqs.
// 150-159).
double report_section_7(Report& report, const Inputs& in, const EulerAngles& e, double sin_theta) {
  const Vector3d moments = in.moments.value_or(Vector3d(1, 2, 3));
  const PrincipalMoments I{moments(0), moments(1), moments(2)};
  report.section(
      fmt::format("7 Lagrange's equations along the free motion of I = ({:g}, {:g}, "
                  "{:g}) kg m^2{} (eqs. 150-159)",
                  I.I1, I.I2, I.I3, in.moments ? "" : ", a body of the lab's"));
  const FreeBodyExact motion = for_input(in.moments ? "--moments" : "--theta-deg", [&] {
    return FreeBodyExact(I, report.omega_body, quaternion_from_euler_zxz(e));
  });
  const auto at = [&motion, e](double t) { return free_state(motion, e, t); };
  const double scale = time_scale(motion);
  // the terms exact but for rounding at the state given, by the rates or by omega (sin
  // theta from its degrees)
  const std::optional<LagrangeTerms> exact =
      in.from_omega ? lagrange_terms_exact(I, e, report.omega_body, Vector3d::Zero(), sin_theta)
                    : lagrange_terms_exact(I, e, report.rates, Vector3d::Zero(), sin_theta);
  // the check: differences along the closed-form motion
  const std::optional<EulerState> start = at(0.0);
  const std::optional<LagrangeSteps> steps = start ? lagrange_steps(*start, scale) : std::nullopt;
  const std::optional<LagrangeTerms> differences =
      steps ? lagrange_terms(I, at, 0.0, *steps) : std::nullopt;
  const Vector3d L = moments.cwiseProduct(report.omega_body);
  const double T = 0.5 * report.omega_body.dot(L);
  report_residuals(report, exact, differences, "lagrange_residual_", "t = 0", false, T,
                   fmt::format("T, {:.3g} J", T), pole_reason(in.theta_deg),
                   no_differences_reason(!start));
  report_psi(report, I, motion, differences, T, no_differences_reason(!start));
  add_free_series(report, motion, e, scale);
  report.free_motion = motion;
  report_section_7_errata(report, in, I, e, T);
  return scale;
}

// Section 7.2: the same body under a constant torque N in the body (eqs. 163-166),
// integrated (Euler's equations and the quaternion, rkf78 at 1e-13), checked at a time t1
// well into the motion. Each angle's equation gains the torque's generalized force, its
// virtual work N . (z dphi + x' dtheta + 3 dpsi): Q = (N.z, N.x', N_3), exact at the
// run's state and by differences along it; eq. 166 for each axis with omega_dot by
// differences along the run.
void report_torque(Report& report, const Inputs& in, const PrincipalMoments& I,
                   const EulerAngles& e, double free_scale) {
  const Vector3d N = in.torque;
  report.section(fmt::format(
      "7.2 with a constant torque N = ({:g}, {:g}, {:g}) N m in the body, integrated (eqs. "
      "163-166)",
      N(0), N(1), N(2)));
  const TorqueRun torque = integrate_torque(report, I, N, e, free_scale);
  report_torque_accuracy(report, torque);
  report_torque_lagrange(report, I, N, torque);
  report_euler_torque(report, I, N, torque);
  // eq. 165's epsilon_ijk is the permutation symbol of eqs. 159-162, which the text then
  // calls by another name
  report.erratum(
      {"section 7.2, after eq. 165",
       "the sign of the last terms depends on the perturbation symbol",
       "it is the permutation symbol epsilon_ijk of eqs. 159-162 (+1 for an even permutation "
       "of 123, -1 for an odd one, 0 where two subscripts are equal); eq. 166's rows here take "
       "i j k = 2 3 1, 3 1 2 and 1 2 3, each an even permutation, epsilon_ijk = +1."});
}

}  // namespace rigid::lab::euler_angles
