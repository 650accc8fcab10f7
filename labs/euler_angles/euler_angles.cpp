#include "euler_angles/euler_angles.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "rigid/units.h"

namespace rigid::lab::euler_angles {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

constexpr char kName[] = "euler_angles";
constexpr char kTitle[] = "Euler angles: the three rotations and omega in three frames (section 6)";
constexpr double kEps = std::numeric_limits<double>::epsilon();

// The passive turn by `angle` about `axis` (eq. 121's lambda_phi, lambda_theta,
// lambda_psi): the transpose of the active rotation Eigen makes.
Matrix3d passive(const Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis).toRotationMatrix().transpose();
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
  report.result("omega_intermediate_rad_s",
                "in x'y'z': (theta_dot, phi_dot sin theta, ..) "
                "(eqs. 128-130)",
                w_int, "rad/s");
  report.result("omega_body_rad_s", "in 123 (eqs. 134-136)", w_body, "rad/s");
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
  const Vector3d printed = omega_in_space_as_printed(e, r);
  report.result("omega_space_printed_rad_s", "  eqs. 137-139 as the text prints them", printed,
                "rad/s");
  if ((printed - w_space).norm() > 16 * kEps * size) {
    report.note(fmt::format(
        "errata: eqs. 137-138 print omega_x = theta_dot cos psi - psi_dot sin theta cos phi and "
        "omega_y = theta_dot sin psi - psi_dot sin theta sin phi; omega in space is phi_dot z + "
        "theta_dot x' + psi_dot 3 with x' = (cos phi, sin phi, 0) and 3 = (sin theta sin phi, "
        "-sin theta cos phi, cos theta) (eq. 122's third row), so omega_x = theta_dot cos phi + "
        "psi_dot sin theta sin phi = {:.6g} and omega_y = theta_dot sin phi - psi_dot sin theta "
        "cos phi = {:.6g} rad/s here, where the print gives {:.6g} and {:.6g}; lambda^T omega_123 "
        "agrees with the corrected form to roundoff. Eq. 139 is right.",
        w_space(0), w_space(1), printed(0), printed(1)));
  }
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
  return {kName, kTitle, input_table(), compute, figures, nullptr, /*csv=*/false};
}

}  // namespace rigid::lab::euler_angles
