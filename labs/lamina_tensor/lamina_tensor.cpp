#include "lamina_tensor/lamina_tensor.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "rigid/units.h"

namespace rigid::lab::lamina_tensor {
namespace {
constexpr const char* kName = "lamina_tensor";
constexpr const char* kTitle = "inertia tensor of a rectangular lamina (sections 1-3.1)";

// The moment n.I.n about an axis in the x-y plane at alpha = -90, -89.5, .., 90 deg
// from x, as the moment figure draws it and --csv writes it.
TimeSeries moment_sweep(const Mat3& I) {
  TimeSeries sweep(
      "lamina_tensor: the moment about an axis in the plate's plane against its angle (a "
      "sweep: the lab has no time series), as its moment figure draws it");
  sweep.add({"alpha_deg"}, "deg", "the axis's angle from x toward y")
      .add({"moment_kg_m2"}, "kg m^2",
           "n.I.n about that axis through the origin (extreme on the principal axes)");
  for (int k = 0; k <= 360; ++k) {
    const double alpha = deg_to_rad(-90.0 + 0.5 * k);
    sweep.rows.push_back(
        {rad_to_deg(alpha), moment_about_axis(I, Vec3(std::cos(alpha), std::sin(alpha), 0))});
  }
  return sweep;
}

// The rotation axis, unit: by its components, the plate's diagonal, or an angle in the plane.
Vec3 axis_of(Report& report, const Inputs& in) {
  Vec3 axis = in.axis_word == "diagonal" ? Vec3(in.a, in.b, 0.0) : in.axis;
  if (in.axis_deg) {
    const double t = deg_to_rad(*in.axis_deg);
    axis = Vec3(std::cos(t), std::sin(t), 0.0);
    report.drop_input("axis");
  }
  return axis.stableNormalized();
}

// Section 1: the tensor about the origin, and the moment about n.
void report_tensor(Report& report, const Inputs& in) {
  const Vec3& n = report.n;
  report.section("1. inertia tensor about the " + in.origin +
                 " (eqs. 6-11, 20, 70): x along a, y along b, z normal; " +
                 (report.corner ? "the plate fills 0 <= x <= a, 0 <= y <= b"
                                : "the plate's centre at the origin"));
  report.result("axis_unit", "rotation axis n (unit)", n, "");
  report.result("axis_angle_from_x_deg", "  its angle from x toward y",
                rad_to_deg(std::atan2(n.y(), n.x())), "deg", report.textbook("37 (3-4-5)"));
  const Mat3& I = report.I = rigid::lamina_tensor({in.mass, in.a, in.b, report.corner});
  report.series(moment_sweep(I));
  report.result("inertia_tensor", "inertia tensor I", I, "kg m^2",
                report.textbook("(4/3, -1/2, 0; -1/2, 1/3, 0; 0, 0, 5/3) ma^2"));
  report.result("scalar_moment", "moment about n, n.I.n (eq. 21)", moment_about_axis(I, n),
                "kg m^2", report.textbook("0.493 ma^2"));
}

// Section 1.1: L = I omega, off omega unless n is principal.
Vec3 report_angular_momentum(Report& report, const Inputs& in, const Vec3& omega) {
  report.section("1.1 angular momentum (eq. 28)");
  const Vec3 L = angular_momentum(report.I, omega);
  report.result("angular_momentum", "L = I omega", L, "kg m^2/s",
                report.textbook("(0.767, -0.20, 0) ma^2 omega"));
  report.result("angular_momentum_magnitude", "|L|", L.stableNorm(), "kg m^2/s",
                report.textbook("0.793 ma^2 omega"));
  report.result("angle_L_omega_deg", "angle between L and omega",
                rad_to_deg(angle_between(L, omega)), "deg", report.textbook("51"));
  if (report.textbook_inputs()) {
    // The text's |L| from its printed components: L_x to three digits, L_y to two.
    const Vec3 unit_L = L / (in.mass * in.a * in.a * in.omega);
    const double Lx_printed = std::round(1e3 * unit_L.x()) / 1e3;
    const double Ly_printed = std::round(1e2 * unit_L.y()) / 1e2;
    report.erratum({"section 1.1, after eq. 28", "The magnitude of this (L) is 0.793ma^2 omega",
                    fmt::format("|L| = {:.4f} ma^2 omega exactly; 0.793 comes from rounding L_x "
                                "to {:.3f} before taking the norm (|({:.3f}, {:.2f}, 0)| = {:.4f})",
                                unit_L.stableNorm(), Lx_printed, Lx_printed, Ly_printed,
                                std::hypot(Lx_printed, Ly_printed))});
  }
  return L;
}

// Section 2.1's examples do not depend on the plate's orientation: shown with the
// textbook's inputs, or when asked for, by --examples or by a block side c of one's
// own (which nothing else uses: never silently ignored).
void report_examples(Report& report, const Inputs& in) {
  if (!report.textbook_inputs() && !in.examples && in.c == Inputs{}.c) return;
  const double m = in.mass, a = in.a;
  report.section("2.1 symmetric bodies about their centre of mass, built from primitives");
  const Body paddle = model_paddle(m, a);
  report.result("paddle_principal_moments", "model paddle I1, I2, I3 (eqs. 41-43)",
                Vec3(paddle.I_com.diagonal()), "kg m^2", printed("(1/8, 31/24, 17/12) ma^2"));
  report.result("block_principal_moments", "block a x b x c (eq. 40)",
                Vec3(solid_box(m, a, in.b, in.c).I_com.diagonal()), "kg m^2",
                printed("m/12 (b^2+c^2, a^2+c^2, a^2+b^2)"));
  const Mat3 cube = solid_box(m, a, a, a).I_com;
  report.result("cube_moment_about_axis", "cube of side a, moment about n",
                moment_about_axis(cube, report.n), "kg m^2", printed("ma^2/6"));
  report.result("cube_moment_about_diagonal", "cube, moment about its body diagonal",
                moment_about_axis(cube, Vec3(1, 1, 1)), "kg m^2", printed("ma^2/6"));
}

// Section 2.3: the principal axes in the plate's plane from tan 2 theta.
InPlaneAxes report_in_plane_axes(Report& report, const Inputs& in) {
  report.section("2.3 principal axes in the x-y plane from tan 2 theta (eqs. 53-56)");
  const InPlaneAxes plane = in_plane_principal_axes(report.I);
  report.result("two_theta_deg", "2 theta, tan 2 theta = 2 Ixy / (Ixx - Iyy)",
                rad_to_deg(plane.two_theta), "deg", report.textbook("-45 (tan 2 theta = -1)"));
  report.result("principal_angle_deg", "axis angle from x", rad_to_deg(plane.theta), "deg",
                report.textbook("-22.5"));
  report.result("principal_angle_moment", "  moment about that axis (eq. 50)", plane.moment,
                "kg m^2");
  report.result("principal_angle_other_deg", "other in-plane axis", rad_to_deg(plane.theta_other),
                "deg", report.textbook("67.5"));
  report.result("principal_angle_other_moment", "  moment about that axis", plane.moment_other,
                "kg m^2");
  report.result("body_diagonal_deg", "body diagonal, for contrast",
                rad_to_deg(std::atan2(in.b, in.a)), "deg", report.textbook("63.4"));
  if (report.textbook_inputs()) {
    const double ma2 = in.mass * in.a * in.a;
    report.erratum(
        {"section 2.3, after eq. 56",
         "So the 1-axis is at -22 deg and the 2-axis is at 67.5 deg relative to the original "
         "x-axis",
         fmt::format("the axis at {:.1f} deg has the moment {:.3f} ma^2, I2 when moments ascend "
                     "(as in the text's own section 2.4); the axis at {:.1f} deg carries "
                     "I1 = {:.3f} ma^2",
                     rad_to_deg(plane.theta), plane.moment / ma2, rad_to_deg(plane.theta_other),
                     plane.moment_other / ma2)});
  }
  return plane;
}

// Section 2.4: the principal moments and axes by diagonalising I.
void report_principal(Report& report) {
  report.section("2.4 principal moments and axes by diagonalisation (eqs. 62-69)");
  const PrincipalAxes& principal = report.principal = principal_axes(report.I);
  report.result("principal_moments", "principal moments I1, I2, I3", principal.moments, "kg m^2",
                report.textbook("(0.126, 1.540, 1.667) ma^2"));
  report.result("principal_axes", "principal axes e1; e2; e3 (rows)", principal.axes, "",
                report.textbook("(-0.3827, -0.9239, 0); (0.9239, -0.3827, 0); (0, 0, 1)"));
}

// Section 3.1: the torque that holds the axis while the plate turns at constant omega.
Vec3 report_torque(Report& report, const Inputs& in, const Vec3& omega) {
  const Mat3& I = report.I;
  const PrincipalAxes& principal = report.principal;
  report.section("3.1 torque to turn about a fixed axis at constant omega (eqs. 74-76)");
  const Vec3 N = fixed_axis_torque(I, omega);
  report.result("fixed_axis_torque", "N = omega x (I omega) about n, x-y-z frame", N, "N m");
  report.result("fixed_axis_torque_principal", "  the same in the principal frame",
                Vec3(principal.axes * N), "N m");
  // The section's own example turns the lamina about x, whatever --axis says.
  const Vec3 N_x = principal.axes * fixed_axis_torque(I, in.omega * Vec3::UnitX());
  report.result("fixed_axis_torque_x_principal", "N1, N2, N3 for rotation about x", N_x, "N m",
                report.textbook("(0, 0, 0.500) ma^2 omega^2"));
  if (report.textbook_inputs()) {
    report.erratum({"section 3.1, after eq. 77", "we find N1 = N2 = 0, N3 = 0.500 ma^2 omega^2",
                    fmt::format("for rotation about +x, N3 = omega1 omega2 (I2 - I1) = {:.3f} "
                                "ma^2 omega^2: the right size with the wrong sign; the axle "
                                "pushes along -z",
                                N_x(2) / (in.mass * in.a * in.a * in.omega * in.omega))});
  }
  return N;
}

}  // namespace

const InputTable<Inputs>& input_table() {
  static const InputTable<Inputs> table = [] {
    InputTable<Inputs> t;
    t.number("--mass", &Inputs::mass, "mass m of the lamina").unit("kg").positive().symbol("m");
    t.number("--a", &Inputs::a, "side a along x").unit("m").positive().symbol("a");
    t.number("--b", &Inputs::b, "side b along y").unit("m").positive().symbol("b");
    t.number("--c", &Inputs::c,
             "third side c of the section 2.1 block (a x b x c); giving it shows section 2.1")
        .unit("m")
        .positive();
    t.choice("--origin", &Inputs::origin, {"corner", "center"},
             "origin of the axes: x along side a, y along side b, z normal to the plate; "
             "corner: the plate spans 0 <= x <= a, 0 <= y <= b; center: its middle")
        .symbol("origin");
    t.vector_or_word("--axis", &Inputs::axis, &Inputs::axis_word,
                     "rotation axis n through the origin (normalised)")
        .nonzero()
        .words({"diagonal"}, "diagonal: along the plate's diagonal, (a, b, 0)");
    t.angle_deg("--axis-deg", &Inputs::axis_deg,
                "rotation axis in the plate's plane, at this angle from x toward y (instead of "
                "--axis)")
        .lab_default("--axis's")
        .excludes("--axis", "give --axis or --axis-deg, not both");
    t.number("--omega", &Inputs::omega, "angular speed about the axis").unit("rad/s").positive();
    t.flag("--examples", &Inputs::examples,
           "also section 2.1's paddle, block and cube, with these inputs (the textbook's "
           "inputs show them anyway)")
        .numerical();
    return t;
  }();
  return table;
}

Report compute(const Inputs& in) {
  Report report(kName, kTitle);
  report.start(input_table(), in);
  report.a = in.a;
  report.b = in.b;
  report.corner = in.origin == "corner";
  const Vec3 n = report.n = axis_of(report, in);
  const Vec3 omega = in.omega * n;

  report_tensor(report, in);
  const Vec3 L = report_angular_momentum(report, in, omega);
  report.section("1.2 kinetic energy (eqs. 33-34)");
  report.result("kinetic_energy", "T = omega.I omega / 2", kinetic_energy(report.I, omega), "J",
                report.textbook("(1/2)(0.493) ma^2 omega^2"));
  report_examples(report, in);
  const InPlaneAxes plane = report_in_plane_axes(report, in);
  report_principal(report);
  const Vec3 N = report_torque(report, in, omega);

  const double L_omega = rad_to_deg(angle_between(L, omega));
  report.answer(
      L_omega < 1e-6
          ? fmt::format("L is along omega: n is a principal axis, and the plate turns about it "
                        "steadily with no torque")
          : fmt::format("L is {:.3g} deg from omega: n is not a principal axis, so turning "
                        "steadily about it takes a torque |N| = {:.4g} N m; in the plate's plane "
                        "the principal axes lie at {:.4g} and {:.4g} deg from x",
                        L_omega, N.stableNorm(),
                        rad_to_deg(std::min(plane.theta, plane.theta_other)),
                        rad_to_deg(std::max(plane.theta, plane.theta_other))));
  return report;
}

LabProgram<Inputs, Report> program() {
  return {kName, kTitle, input_table(), compute, figures, nullptr,
          /*csv=*/
          "the moment n.I.n about an axis in the plate's plane at each angle alpha "
          "from x, -90 to 90 deg (a sweep, as the moment figure draws it; no time series)"};
}

}  // namespace rigid::lab::lamina_tensor
