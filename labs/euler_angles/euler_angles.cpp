#include "euler_angles/euler_angles.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <string>

#include "common/free_motion.h"
#include "euler_angles/lagrange.h"
#include "rigid/units.h"

namespace rigid::lab::euler_angles {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

constexpr char kName[] = "euler_angles";
constexpr char kTitle[] =
    "Euler angles: the three rotations, omega in three frames, Lagrange's equations (sections 6-7)";
constexpr double kEps = std::numeric_limits<double>::epsilon();

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
    // --from-omega sets all three rates: a rate given beside it would be dropped
    const struct {
      const char *flag, *help, *symbol;
      double Inputs::*field;
    } rates[] = {{"--phi-dot", "phi's rate", "\\phi-dot", &Inputs::phi_dot},
                 {"--theta-dot", "theta's rate", "\\theta-dot", &Inputs::theta_dot},
                 {"--psi-dot", "psi's rate", "\\psi-dot", &Inputs::psi_dot}};
    for (const auto& rate : rates) {
      t.number(rate.flag, rate.field, rate.help)
          .unit("rad/s")
          .symbol(rate.symbol)
          .excludes("--from-omega", "give the rates or --from-omega, not both");
    }
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

namespace {

// Section 6: lambda of eq. 122, checked against the three turns of eq. 121 composed.
void report_lambda(Report& report, const EulerAngles& e) {
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
}

// The rates: as given, or from omega in the body (eqs. 134-136 inverted).
void report_rates(Report& report, const Inputs& in, const EulerAngles& e, double sin_theta) {
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
}

// The size of omega's parts, the scale of its roundoff.
double omega_size(const Report& report) {
  const EulerRates& r = report.rates;
  const bool pole = !report.rates_defined;
  const Vector3d& w_body = report.omega_body;
  return pole ? 2 * w_body.lpNorm<1>()
              : std::abs(r.phi_dot) + std::abs(r.theta_dot) + std::abs(r.psi_dot);
}

// omega in the three frames from the rates (eqs. 128-139), each checked against another's
// turned by lambda.
void report_omega(Report& report, const Inputs& in, const EulerAngles& e, double sin_theta) {
  const EulerRates& r = report.rates;
  const bool pole = !report.rates_defined;
  const Matrix3d lambda = space_to_body_matrix(e);
  const Vector3d z = Vector3d::UnitZ(), x = Vector3d::UnitX();
  // omega by eqs. 128-139 from the rates; the omega given, where it was, is shown as given
  // (its frames by lambda), and the formulas are checked against it
  const Vector3d f_int = omega_intermediate(e, r, sin_theta),
                 f_body = omega_in_body(e, r, sin_theta), f_space = omega_in_space(e, r, sin_theta);
  const Vector3d w_space = in.from_omega ? Vector3d(lambda.transpose() * *in.from_omega) : f_space;
  const Vector3d w_body = in.from_omega ? *in.from_omega : f_body;
  const Vector3d w_int =
      in.from_omega ? Vector3d(passive(x, e.theta) * passive(z, e.phi) * w_space) : f_int;
  report.omega_body = w_body, report.omega_space = w_space;
  const double size = omega_size(report);
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
}

// Eqs. 137-139 as the text prints them, against omega in space; returns them.
Vector3d report_printed_omega(Report& report, const EulerAngles& e, double sin_theta) {
  const EulerRates& r = report.rates;
  const bool pole = !report.rates_defined;
  const bool north = std::cos(e.theta) > 0;
  const Vector3d &w_body = report.omega_body, &w_space = report.omega_space;
  const double size = omega_size(report);
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
  return as_printed;
}

// In short: omega in space and in the body, and the rates where omega was given.
void report_answer(Report& report, const Inputs& in, const Vector3d& as_printed) {
  const EulerRates& r = report.rates;
  const bool pole = !report.rates_defined;
  const bool north = std::cos(report.angles.theta) > 0;
  const Vector3d &w_body = report.omega_body, &w_space = report.omega_space;
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
}

// With a body's moments: L = I omega in the body and in space, and T (eq. 150).
void report_body(Report& report, const Inputs& in) {
  const Vector3d& w_body = report.omega_body;
  const Matrix3d lambda = space_to_body_matrix(report.angles);
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
}

}  // namespace

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
  report_lambda(report, e);
  report_rates(report, in, e, sin_theta);
  report_omega(report, in, e, sin_theta);
  const Vector3d as_printed = report_printed_omega(report, e, sin_theta);
  report_answer(report, in, as_printed);
  const double scale = report_section_7(report, in, e, sin_theta);
  const Vector3d moments = in.moments.value_or(Vector3d(1, 2, 3));
  report_torque(report, in, {moments(0), moments(1), moments(2)}, e, scale);
  report_body(report, in);
  return report;
}

LabProgram<Inputs, Report> program() {
  return {kName, kTitle, input_table(), compute, figures, animation,
          /*csv=*/
          "the free motion against time: the Euler angles, their rates and omega in "
          "the fixed, intermediate and body frames",
          /*preview=*/nullptr,
          /*textbook_example=*/false, [](const Report& report) {
            return report.free_motion ? free_body_motion(*report.free_motion, std::nullopt, {})
                                      : BodyMotion{};
          }};
}

}  // namespace rigid::lab::euler_angles
