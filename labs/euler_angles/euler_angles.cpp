#include "euler_angles/euler_angles.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
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

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

constexpr char kName[] = "euler_angles";
constexpr char kTitle[] =
    "Euler angles: the three rotations, omega in three frames, Lagrange's equations (sections 6-7)";
constexpr double kEps = std::numeric_limits<double>::epsilon();

// The passive turn by `angle` about `axis` (eq. 121's lambda_phi, lambda_theta,
// lambda_psi): the transpose of the active rotation Eigen makes.
Matrix3d passive(const Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis).toRotationMatrix().transpose();
}

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
  const auto at = [&motion, e](double t) {
    return euler_state(motion.attitude(t), motion.omega_body(t), e);
  };
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
  // psi's two terms, defined at a pole too (the rates are not needed: eqs. 154-156 make
  // d omega / d psi = (omega_2, -omega_1, 0))
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
          : "no differences here: " + no_differences_reason(!start)));
  report.result_json("lagrange_psi_force_error", psi.force.error, "N m");
  const Vector3d w = motion.omega_body(0.0);
  report.result("euler_psi_rate", "  Euler: I3 omega_3_dot = (I1 - I2) omega_1 omega_2 (eq. 158)",
                (I.I1 - I.I2) * w(0) * w(1), "N m");
  // --csv: the angles, their rates and omega in the three frames along this motion, over
  // its time scale (a polhode period), 200 samples
  TimeSeries series{{"t_s", "phi_rad", "theta_rad", "psi_rad", "phi_dot_rad_s", "theta_dot_rad_s",
                     "psi_dot_rad_s", "omega_x", "omega_y", "omega_z", "omega_xp", "omega_yp",
                     "omega_zp", "omega_1", "omega_2", "omega_3"},
                    {},
                    {"euler_angles: the free motion of the body of section 7 from the angles "
                     "and rates given, over one polhode period (or one turn)",
                     "phi_rad, theta_rad, psi_rad: the z-x-z Euler angles of section 6, phi and "
                     "psi continuous from the start (not wrapped); their rates in rad/s (at a "
                     "pole, where they are undefined, 0)",
                     "omega_x, omega_y, omega_z: omega in the fixed frame; omega_xp, omega_yp, "
                     "omega_zp: in the intermediate frame x'y'z' (x' the line of nodes); omega_1, "
                     "omega_2, omega_3: in the body; all rad/s"}};
  EulerAngles previous = e;
  for (int n = 0; n <= 200; ++n) {
    const double t = scale * n / 200.0;
    // continuous: phi and psi by whole turns nearest the previous sample's
    EulerState s = at(t).value_or(EulerState{euler_zxz(motion.attitude(t)), EulerRates{}});
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
  std::map<double, RotationState> run;
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
                        [&](const RotationState& x, double t) { run[t] = x; });
    } catch (const std::exception& error) {
      failed = error.what();
    }
  }
  const auto at = [&](double t) -> std::optional<EulerState> {
    const auto found = run.find(t);
    if (found == run.end()) return std::nullopt;
    const RotationState& x = found->second;
    return euler_state(Eigen::Quaterniond(x[3], x[4], x[5], x[6]).normalized(),
                       Vector3d(x[0], x[1], x[2]), center->angles);
  };
  const std::optional<LagrangeTerms> differences =
      steps && !failed ? lagrange_terms(I, at, t1, *steps, N) : std::nullopt;
  // the terms exact but for rounding at the run's state at t1
  const std::optional<LagrangeTerms> exact =
      failed ? std::nullopt : lagrange_terms_exact(I, euler_zxz(q1.normalized()), w1, N);
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
  const Vector3d w1_body(at_t1[0], at_t1[1], at_t1[2]);
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
  // eq. 166, (I_i - I_j) w_i w_j - (I_k w_k_dot - N_k) = 0 for i j k = 1 2 3, 2 3 1, 3 1 2;
  // 1 2 3 is eq. 164, N_3 = L_3_dot + w_1 L_2 - w_2 L_1
  const double moments[3] = {I.I1, I.I2, I.I3};
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const std::string key = fmt::format("euler_torque_residual_{}", k + 1);
    const std::string label =
        fmt::format("(I{0} - I{1}) w{0} w{1} - (I{2} w{2}_dot - N{2}) at t1 (eq. 166{3})", i + 1,
                    j + 1, k + 1, k == 2 ? ", 164" : "");
    if (!differences) {
      report.result_none(
          key, label, "N m",
          failed ? "the integration failed" : no_differences_reason(!center || !exact));
      report.result_json_none(key + "_error", "N m");
      continue;
    }
    const Vector3d w = Vector3d(run[t1][0], run[t1][1], run[t1][2]);
    const Measured w_dot = central_derivative([&](double dt) { return run.at(t1 + dt)[k]; },
                                              steps->time, 64 * kEps * w.norm());
    report.result(key, label,
                  (moments[i] - moments[j]) * w(i) * w(j) - (moments[k] * w_dot.value - N(k)),
                  "N m");
    report.remark(
        fmt::format("(+- {:.2g} N m: the differences' own error)", moments[k] * w_dot.error));
    report.result_json(key + "_error", moments[k] * w_dot.error, "N m");
  }
  // eq. 165's epsilon_ijk is the permutation symbol of eqs. 159-162, which the text then
  // calls by another name
  report.erratum(
      {"section 7.2, after eq. 165",
       "the sign of the last terms depends on the perturbation symbol",
       "it is the permutation symbol epsilon_ijk of eqs. 159-162 (+1 for an even permutation "
       "of 123, -1 for an odd one, 0 where two subscripts are equal); eq. 166's rows here take "
       "i j k = 2 3 1, 3 1 2 and 1 2 3, each an even permutation, epsilon_ijk = +1."});
}

}  // namespace

const InputTable<Inputs>& input_table() {
  static const InputTable<Inputs> table = [] {
    InputTable<Inputs> t;
    t.number("--phi-deg", &Inputs::phi_deg, "phi: the first turn, about the fixed z axis")
        .unit("deg")
        .symbol("\\phi");
    t.number("--theta-deg", &Inputs::theta_deg,
             "theta: the second, about the line of nodes x', from z to the body's 3 axis")
        .unit("deg")
        .symbol("\\theta");
    t.number("--psi-deg", &Inputs::psi_deg, "psi: the third, about the body's 3 axis")
        .unit("deg")
        .symbol("\\psi");
    t.number("--phi-dot", &Inputs::phi_dot, "phi's rate").unit("rad/s").symbol("\\phi-dot");
    t.number("--theta-dot", &Inputs::theta_dot, "theta's rate").unit("rad/s").symbol("\\theta-dot");
    t.number("--psi-dot", &Inputs::psi_dot, "psi's rate").unit("rad/s").symbol("\\psi-dot");
    t.vector("--moments", &Inputs::moments, "a body's principal moments I1, I2, I3: L and T")
        .unit("kg m^2")
        .positive()
        .lab_default("none");
    t.vector("--torque", &Inputs::torque,
             "a constant torque N1, N2, N3 in the body: section 7.2's Lagrange equations with "
             "torque against an integration")
        .unit("N m");
    t.vector("--from-omega", &Inputs::from_omega,
             "omega in the body frame: the rates from it (eqs. 134-136 inverted), instead of "
             "the rates given")
        .unit("rad/s")
        .lab_default("the rates given");
    return t;
  }();
  return table;
}

Report compute(const Inputs& in) {
  Report report(kName, kTitle);
  report.start(input_table(), in);
  if (!(in.theta_deg >= 0.0 && in.theta_deg <= 180.0)) {
    throw InputError("--theta-deg", fmt::format("must lie in [0, 180] (got {})", in.theta_deg));
  }
  // phi and psi by whole turns in degrees (exact) before radians: 1e15 deg in radians would
  // keep no digit of its turn; sin(theta) from the nearer pole's side in degrees (180 -
  // theta exact), which theta in radians loses near 180 deg
  const EulerAngles e{deg_to_rad(std::remainder(in.phi_deg, 360.0)), deg_to_rad(in.theta_deg),
                      deg_to_rad(std::remainder(in.psi_deg, 360.0))};
  const double sin_theta =
      std::sin(deg_to_rad(in.theta_deg <= 90.0 ? in.theta_deg : 180.0 - in.theta_deg));
  report.angles = e;

  report.section(
      "6 the three rotations: lambda = lambda_psi lambda_theta lambda_phi (eqs. 121-122)");
  const Matrix3d lambda = space_to_body_matrix(e);
  report.result("lambda", "lambda (eq. 122), space to body", lambda, "");
  const Vector3d z = Vector3d::UnitZ(), x = Vector3d::UnitX();
  const Matrix3d composed = passive(z, e.psi) * passive(x, e.theta) * passive(z, e.phi);
  // eq. 122 against the three turns of eq. 121 composed (Eigen's rotations): roundoff
  report.result_roundoff("lambda_vs_composed", "  |lambda - lambda_psi lambda_theta lambda_phi|",
                         (lambda - composed).norm(), 16 * kEps, "");
  report.result_roundoff("lambda_orthogonality", "  |lambda lambda^T - 1|",
                         (lambda * lambda.transpose() - Matrix3d::Identity()).norm(), 16 * kEps,
                         "");
  report.result("lambda_determinant", "  det lambda", lambda.determinant(), "");

  report.section("6 omega = phi_dot z + theta_dot x' + psi_dot 3 (eqs. 123-139)");
  EulerRates r{in.phi_dot, in.theta_dot, in.psi_dot};
  // At a pole omega gives only phi_dot + psi_dot (or phi_dot - psi_dot: the two turn
  // about one axis) and theta_dot, omega along the line of nodes; everything else stands
  const bool pole = in.from_omega && !rates_from_body_omega(e, *in.from_omega, sin_theta);
  const bool north = std::cos(e.theta) > 0;
  if (in.from_omega) {
    report.drop_input("phi_dot"), report.drop_input("theta_dot"), report.drop_input("psi_dot");
    const Vector3d& w = *in.from_omega;
    if (!pole) {
      r = *rates_from_body_omega(e, w, sin_theta);
      report.result("rates_rad_s", "phi_dot, theta_dot, psi_dot from omega (134-136 inverted)",
                    Vector3d(r.phi_dot, r.theta_dot, r.psi_dot), "rad/s");
    } else {
      r = {0.0, w(0) * std::cos(e.psi) - w(1) * std::sin(e.psi), 0.0};
      report.result_none(
          "rates_rad_s", "phi_dot, theta_dot, psi_dot from omega", "rad/s",
          fmt::format("theta = {:g} deg: phi and psi turn about one axis, only phi_dot {} "
                      "psi_dot = {}omega_3 is defined, and theta_dot",
                      in.theta_deg, north ? "+" : "-", north ? "" : "-"));
      report.result("rates_sum_rad_s",
                    north ? "  phi_dot + psi_dot = omega_3" : "  phi_dot - psi_dot = -omega_3",
                    north ? w(2) : -w(2), "rad/s");
      report.result("theta_dot_rad_s", "  theta_dot = omega_1 cos psi - omega_2 sin psi",
                    r.theta_dot, "rad/s");
    }
  }
  report.rates = r;
  report.rates_defined = !pole;
  // omega by eqs. 128-139 from the rates; the omega given, where it was, is shown as given
  // (its frames by lambda), and the formulas are checked against it
  const Vector3d f_int = omega_intermediate(e, r, sin_theta),
                 f_body = omega_in_body(e, r, sin_theta), f_space = omega_in_space(e, r, sin_theta);
  const Vector3d w_space = in.from_omega ? Vector3d(lambda.transpose() * *in.from_omega) : f_space;
  const Vector3d w_body = in.from_omega ? *in.from_omega : f_body;
  const Vector3d w_int =
      in.from_omega ? Vector3d(passive(x, e.theta) * passive(z, e.phi) * w_space) : f_int;
  report.omega_body = w_body, report.omega_space = w_space;
  const double size = pole ? 2 * w_body.lpNorm<1>()
                           : std::abs(r.phi_dot) + std::abs(r.theta_dot) + std::abs(r.psi_dot);
  report.result("omega_intermediate_rad_s", "in x'y'z' (eqs. 128-130)", w_int, "rad/s",
                printed("(theta_dot, phi_dot sin theta, phi_dot cos theta + psi_dot)"));
  report.result("omega_body_rad_s", "in 123 (eqs. 134-136)", w_body, "rad/s",
                printed("(phi_dot sin theta sin psi + theta_dot cos psi, phi_dot sin theta cos "
                        "psi - theta_dot sin psi, phi_dot cos theta + psi_dot)"));
  report.result("omega_space_rad_s", "in xyz (eq. 139, eqs. 137-138 corrected)", w_space, "rad/s");
  // Each frame's omega again as lambda of another's: the formulas agree to roundoff.
  const char body_label[] = "  |omega_123 - lambda omega_xyz|";
  const char intermediate_label[] = "  |omega_x'y'z' - lambda_theta lambda_phi omega_xyz|";
  const char round_trip_label[] = "  |omega from the rates - omega given|";
  if (pole) {
    const char why[] = "the rates are undefined at a pole: omega is as given, its frames by lambda";
    report.result_none("omega_body_vs_lambda", body_label, "rad/s", why);
    report.result_none("omega_intermediate_vs_lambda", intermediate_label, "rad/s", why);
    report.result_none("omega_round_trip", round_trip_label, "rad/s", why);
  } else {
    report.result_roundoff("omega_body_vs_lambda", body_label, (f_body - lambda * f_space).norm(),
                           16 * kEps * size, "rad/s");
    report.result_roundoff("omega_intermediate_vs_lambda", intermediate_label,
                           (f_int - passive(x, e.theta) * passive(z, e.phi) * f_space).norm(),
                           16 * kEps * size, "rad/s");
    if (in.from_omega) {
      report.result_roundoff("omega_round_trip", round_trip_label, (f_body - *in.from_omega).norm(),
                             64 * kEps * size, "rad/s");
    }
  }
  // The print's psi_dot sin theta at a pole is its limit there, omega_3 sin theta -
  // (omega_1 sin psi + omega_2 cos psi) cos theta (eqs. 134-136 inverted, times sin theta)
  Vector3d as_printed = omega_in_space_as_printed(e, r, sin_theta);
  double psi_dot_sin_theta = 0.0;
  if (pole) {
    const Vector3d& w = w_body;
    psi_dot_sin_theta =
        w(2) * sin_theta - (w(0) * std::sin(e.psi) + w(1) * std::cos(e.psi)) * std::cos(e.theta);
    as_printed = {r.theta_dot * std::cos(e.psi) - psi_dot_sin_theta * std::cos(e.phi),
                  r.theta_dot * std::sin(e.psi) - psi_dot_sin_theta * std::sin(e.phi),
                  north ? w(2) : -w(2)};
  }
  report.result("omega_space_printed_rad_s", "  eqs. 137-139 as the text prints them", as_printed,
                "rad/s",
                printed("(theta_dot cos psi - psi_dot sin theta cos phi, theta_dot sin psi - "
                        "psi_dot sin theta sin phi, phi_dot + psi_dot cos theta)"));
  if (pole) {
    report.remark(fmt::format("(psi_dot sin theta at its limit at the pole, {:.6g} rad/s)",
                              psi_dot_sin_theta));
  }
  if ((as_printed - w_space).norm() > 16 * kEps * size) {
    report.erratum(
        {"eqs. 137-138",
         "omega_x = theta_dot cos psi - psi_dot sin theta cos phi, omega_y = theta_dot sin psi - "
         "psi_dot sin theta sin phi",
         fmt::format(
             "omega in space is phi_dot z + theta_dot x' + psi_dot 3 with x' = (cos phi, sin phi, "
             "0) and 3 = (sin theta sin phi, -sin theta cos phi, cos theta) (eq. 122's third "
             "row), so omega_x = theta_dot cos phi + psi_dot sin theta sin phi = {:.6g} and "
             "omega_y = theta_dot sin phi - psi_dot sin theta cos phi = {:.6g} rad/s here, where "
             "the print gives {:.6g} and {:.6g}{}; lambda^T omega_123 agrees with the corrected "
             "form to roundoff. Eq. 139 is right.",
             w_space(0), w_space(1), as_printed(0), as_printed(1),
             pole ? fmt::format(" (at the pole psi_dot sin theta taken at its limit, {:.6g} rad/s)",
                                psi_dot_sin_theta)
                  : "")});
  }
  const std::string in_space = fmt::format(
      "({:.4g}, {:.4g}, {:.4g}) rad/s in space and ({:.4g}, {:.4g}, {:.4g}) in the body, |omega| "
      "= {:.4g} rad/s; the text's eqs. 137-138 would give ({:.4g}, {:.4g}) for its x and y",
      w_space(0), w_space(1), w_space(2), w_body(0), w_body(1), w_body(2), w_space.norm(),
      as_printed(0), as_printed(1));
  if (pole) {
    report.answer(fmt::format(
        "at theta = {:g} deg omega cannot be split into phi_dot and psi_dot: only phi_dot {} "
        "psi_dot = {:.4g} rad/s is defined, with theta_dot = {:.4g} rad/s; omega is {}",
        in.theta_deg, north ? "+" : "-", north ? w_body(2) : -w_body(2), r.theta_dot, in_space));
  } else if (in.from_omega) {
    report.answer(fmt::format(
        "omega given in the body gives phi_dot, theta_dot, psi_dot = ({:.4g}, {:.4g}, {:.4g}) "
        "rad/s (eqs. 134-136 inverted); omega is {}",
        r.phi_dot, r.theta_dot, r.psi_dot, in_space));
  } else {
    report.answer("omega = phi_dot z + theta_dot x' + psi_dot 3 is " + in_space);
  }
  const double scale = report_section_7(report, in, e, sin_theta);
  const Vector3d moments = in.moments.value_or(Vector3d(1, 2, 3));
  report_torque(report, in, {moments(0), moments(1), moments(2)}, e, scale);
  if (in.moments) {
    const Vector3d I = *in.moments;
    report.section("the body: L = I omega and T (eq. 150)");
    const Vector3d L = I.cwiseProduct(w_body);
    report.result("angular_momentum_body", "L in 123", L, "kg m^2/s");
    report.result("angular_momentum_space", "L in xyz (lambda^T L_123)",
                  Vector3d(lambda.transpose() * L), "kg m^2/s");
    report.result("kinetic_energy_j", "T = 1/2 sum I_i omega_i^2 (eq. 150's 1/2: errata below)",
                  0.5 * L.dot(w_body), "J");
  }
  return report;
}

LabProgram<Inputs, Report> program() {
  return {kName,
          kTitle,
          input_table(),
          compute,
          figures,
          animation,
          /*csv=*/true,
          /*preview=*/nullptr,
          /*textbook_example=*/false};
}

}  // namespace rigid::lab::euler_angles
