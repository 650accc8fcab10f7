#include "euler_angles/euler_angles.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "common/free_motion.h"
#include "rigid/euler_lagrange.h"
#include "rigid/free_body_exact.h"
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

// Section 7 along the exact torque-free motion of the body (its moments, or I = 1, 2, 3
// kg m^2) started at these angles with this omega: each angle's Lagrange equation holds
// to the error its differences state, and psi's is Euler's (eqs. 151-159).
void report_section_7(Report& report, const Inputs& in, const EulerAngles& e, const EulerRates& r) {
  const Vector3d moments = in.moments.value_or(Vector3d(1, 2, 3));
  const PrincipalMoments I{moments(0), moments(1), moments(2)};
  report.section(
      fmt::format("7 Lagrange's equations along the free motion of I = ({:g}, {:g}, "
                  "{:g}) kg m^2{} (eqs. 150-159)",
                  I.I1, I.I2, I.I3, in.moments ? "" : ", a body of the lab's"));
  const FreeBodyExact motion = for_input(in.moments ? "--moments" : "--theta-deg", [&] {
    return FreeBodyExact(I, omega_in_body(e, r), quaternion_from_euler_zxz(e));
  });
  // The angles continuous in time from the start (phi and psi by whole turns nearest it).
  const auto at = [&motion, e](double t) {
    EulerState s;
    s.angles = euler_zxz(motion.attitude(t));
    const auto near = [](double a, double to) { return to + std::remainder(a - to, 2 * kPi); };
    s.angles.phi = near(s.angles.phi, e.phi);
    s.angles.psi = near(s.angles.psi, e.psi);
    s.rates = rates_from_body_omega(s.angles, motion.omega_body(t)).value_or(EulerRates{});
    return s;
  };
  // steps: 1e-3 rad in the angles, 1e-4 of the motion's time scale in t
  const double scale = time_scale(motion);
  const LagrangeTerms terms = lagrange_terms(I, at, 0.0, 1e-3, 1e-4 * scale);
  const char* names[3] = {"phi", "theta", "psi"};
  for (int k = 0; k < 3; ++k) {
    report.result(fmt::format("lagrange_residual_{}", names[k]),
                  fmt::format("d/dt dT/d{0}_dot - dT/d{0} at t = 0", names[k]),
                  terms.residual[k].value, "J");
    report.remark(
        fmt::format("(+- {:.2g} J: the differences' own error)", terms.residual[k].error));
  }
  const Vector3d w = motion.omega_body(0.0);
  report.result("lagrange_psi_momentum", "  dT/dpsi_dot = I3 omega_3 (eqs. 153-156)",
                terms.momentum[2], "kg m^2/s");
  report.result("lagrange_psi_force", "  dT/dpsi = (I1 - I2) omega_1 omega_2 (eq. 157)",
                terms.dT_dq[2].value, "J");
  report.result("euler_psi_rate", "  Euler: I3 omega_3_dot = (I1 - I2) omega_1 omega_2 (eq. 158)",
                (I.I1 - I.I2) * w(0) * w(1), "J");
  // eqs. 154-156 list dw2/dpsi_dot twice: the missing one is dw1/dpsi_dot, 0 as eq. 134 says
  const double d = 1e-3;
  const double dw1 = (omega_in_body(e, {r.phi_dot, r.theta_dot, r.psi_dot + d})(0) -
                      omega_in_body(e, {r.phi_dot, r.theta_dot, r.psi_dot - d})(0)) /
                     (2 * d);
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
    EulerState s = at(t);
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
  report.note(fmt::format(
      "errata: eqs. 154-156 list d omega_2 / d psi_dot = 0 twice; one of them is d omega_1 / d "
      "psi_dot, also 0 (eq. 134 has no psi_dot; by differences here: {:.3g}).",
      dw1));
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
    throw InputError("--theta-deg", fmt::format("must lie in [0, 180] (got {:g})", in.theta_deg));
  }
  const EulerAngles e{deg_to_rad(in.phi_deg), deg_to_rad(in.theta_deg), deg_to_rad(in.psi_deg)};
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
  if (in.from_omega) {
    report.drop_input("phi_dot"), report.drop_input("theta_dot"), report.drop_input("psi_dot");
    const std::optional<EulerRates> back = rates_from_body_omega(e, *in.from_omega);
    if (!back) {
      // At a pole phi and psi turn about one axis: only their sum (or difference) is defined.
      report.rates_defined = false;
      const bool north = std::cos(e.theta) > 0;
      const std::string why = fmt::format(
          "theta = {:g} deg: phi and psi turn about one axis, only phi_dot {} psi_dot "
          "= {}omega_3 is defined",
          in.theta_deg, north ? "+" : "-", north ? "" : "-");
      report.result_none("rates_rad_s", "phi_dot, theta_dot, psi_dot from omega", "rad/s", why);
      report.result("rates_sum_rad_s",
                    north ? "  phi_dot + psi_dot = omega_3" : "  phi_dot - psi_dot = -omega_3",
                    north ? (*in.from_omega)(2) : -(*in.from_omega)(2), "rad/s");
      report.omega_body = *in.from_omega;
      report.omega_space = lambda.transpose() * *in.from_omega;
      report.answer(
          fmt::format("at theta = {:g} deg the rates cannot be had from omega: {}; "
                      "omega is ({:.4g}, {:.4g}, {:.4g}) rad/s in space",
                      in.theta_deg, why.substr(why.find(": ") + 2), report.omega_space(0),
                      report.omega_space(1), report.omega_space(2)));
      return report;
    }
    r = *back;
    report.result("rates_rad_s", "phi_dot, theta_dot, psi_dot from omega (134-136 inverted)",
                  Vector3d(r.phi_dot, r.theta_dot, r.psi_dot), "rad/s");
  }
  report.rates = r;
  const Vector3d w_int = omega_intermediate(e, r), w_body = omega_in_body(e, r),
                 w_space = omega_in_space(e, r);
  report.omega_body = w_body, report.omega_space = w_space;
  const double size = std::abs(r.phi_dot) + std::abs(r.theta_dot) + std::abs(r.psi_dot);
  report.result("omega_intermediate_rad_s", "in x'y'z' (eqs. 128-130)", w_int, "rad/s",
                printed("(theta_dot, phi_dot sin theta, phi_dot cos theta + psi_dot)"));
  report.result("omega_body_rad_s", "in 123 (eqs. 134-136)", w_body, "rad/s",
                printed("(phi_dot sin theta sin psi + theta_dot cos psi, phi_dot sin theta cos "
                        "psi - theta_dot sin psi, phi_dot cos theta + psi_dot)"));
  report.result("omega_space_rad_s", "in xyz (eq. 139, eqs. 137-138 corrected)", w_space, "rad/s");
  // Each frame's omega again as lambda of another's: the formulas agree to roundoff.
  report.result_roundoff("omega_body_vs_lambda", "  |omega_123 - lambda omega_xyz|",
                         (w_body - lambda * w_space).norm(), 16 * kEps * size, "rad/s");
  report.result_roundoff("omega_intermediate_vs_lambda",
                         "  |omega_x'y'z' - lambda_theta lambda_phi omega_xyz|",
                         (w_int - passive(x, e.theta) * passive(z, e.phi) * w_space).norm(),
                         16 * kEps * size, "rad/s");
  if (in.from_omega) {
    report.result_roundoff("omega_round_trip", "  |omega from the rates - omega given|",
                           (w_body - *in.from_omega).norm(), 64 * kEps * size, "rad/s");
  }
  const Vector3d as_printed = omega_in_space_as_printed(e, r);
  report.result("omega_space_printed_rad_s", "  eqs. 137-139 as the text prints them", as_printed,
                "rad/s",
                printed("(theta_dot cos psi - psi_dot sin theta cos phi, theta_dot sin psi - "
                        "psi_dot sin theta sin phi, phi_dot + psi_dot cos theta)"));
  if ((as_printed - w_space).norm() > 16 * kEps * size) {
    report.note(fmt::format(
        "errata: eqs. 137-138 print omega_x = theta_dot cos psi - psi_dot sin theta cos phi and "
        "omega_y = theta_dot sin psi - psi_dot sin theta sin phi; omega in space is phi_dot z + "
        "theta_dot x' + psi_dot 3 with x' = (cos phi, sin phi, 0) and 3 = (sin theta sin phi, "
        "-sin theta cos phi, cos theta) (eq. 122's third row), so omega_x = theta_dot cos phi + "
        "psi_dot sin theta sin phi = {:.6g} and omega_y = theta_dot sin phi - psi_dot sin theta "
        "cos phi = {:.6g} rad/s here, where the print gives {:.6g} and {:.6g}; lambda^T omega_123 "
        "agrees with the corrected form to roundoff. Eq. 139 is right.",
        w_space(0), w_space(1), as_printed(0), as_printed(1)));
  }
  report.answer(fmt::format(
      "omega = phi_dot z + theta_dot x' + psi_dot 3 is ({:.4g}, {:.4g}, {:.4g}) rad/s in space and "
      "({:.4g}, {:.4g}, {:.4g}) in the body, |omega| = {:.4g} rad/s; the text's eqs. 137-138 "
      "would give ({:.4g}, {:.4g}) for its x and y",
      w_space(0), w_space(1), w_space(2), w_body(0), w_body(1), w_body(2), w_space.norm(),
      as_printed(0), as_printed(1)));
  report_section_7(report, in, e, r);
  if (in.moments) {
    const Vector3d I = *in.moments;
    report.section("the body: L = I omega and T (eq. 150)");
    const Vector3d L = I.cwiseProduct(w_body);
    report.result("angular_momentum_body", "L in 123", L, "kg m^2/s");
    report.result("angular_momentum_space", "L in xyz (lambda^T L_123)",
                  Vector3d(lambda.transpose() * L), "kg m^2/s");
    const double T = 0.5 * L.dot(w_body);
    report.result("kinetic_energy_j", "T = 1/2 sum I_i omega_i^2", T, "J");
    report.note(fmt::format(
        "errata: eq. 150 writes T = sum I_i omega_i^2 without the 1/2: that is {:.6g} J here, "
        "twice the kinetic energy T = 1/2 sum I_i omega_i^2 = omega.L / 2 = {:.6g} J (eq. 81).",
        2 * T, T));
  }
  return report;
}

LabProgram<Inputs, Report> program() {
  return {kName, kTitle, input_table(), compute, figures, nullptr, /*csv=*/true};
}

}  // namespace rigid::lab::euler_angles
