// lamina_tensor: sections 1, 1.1, 1.2, 2, 2.1, 2.3, 2.4 and 3.1 of the chapter.
// A rectangular lamina of mass m, side a along x and b along y, turns about an
// axis n through the origin (its corner or its centre). We find its inertia
// tensor, the moment about n, L and the angle between L and omega, the kinetic
// energy, the principal axes two ways, and the torque that holds the axis fixed.
#include <fmt/format.h>

#include <cmath>

#include "common/lab.h"
#include "figures.h"
#include "rigid/inertia.h"
#include "rigid/units.h"

using rigid::Mat3;
using rigid::Vec3;
using rigid::lab::Lab;
using rigid::lab::printed;

int main(int argc, char** argv) {
  Lab lab("lamina_tensor", "inertia tensor of a rectangular lamina (sections 1-3.1)");
  rigid::lab::lamina_tensor::Inputs in;
  lab.number("--mass", in.mass, "mass m of the lamina").unit("kg").positive().symbol("m");
  lab.number("--a", in.a, "side a along x").unit("m").positive().symbol("a");
  lab.number("--b", in.b, "side b along y").unit("m").positive().symbol("b");
  lab.number("--c", in.c, "third side c of the section 2.1 block (a x b x c)").unit("m").positive();
  lab.choice("--origin", in.origin, {"corner", "center"},
             "origin of the axes: x along side a, y along side b, z normal to the plate; "
             "corner: the plate spans 0 <= x <= a, 0 <= y <= b; center: its middle")
      .symbol("origin");
  auto& axis = lab.vector("--axis", in.axis, "rotation axis n through the origin (normalised)")
                   .nonzero()
                   .words({"diagonal"}, "diagonal: along the plate's diagonal, (a, b, 0)");
  lab.angle_deg("--axis-deg", in.axis_deg,
                "rotation axis in the plate's plane, at this angle from x toward y (instead of "
                "--axis)")
      .lab_default("--axis's");
  lab.number("--omega", in.omega, "angular speed about the axis").unit("rad/s").positive();
  lab.flag("--examples", in.examples,
           "also section 2.1's paddle, block and cube (always with the textbook's inputs)")
      .numerical();

  return lab.run(argc, argv, [&](Lab& lab) {
    const double m = in.mass, a = in.a, ma2 = m * a * a;
    if (lab.given("--axis") && lab.given("--axis-deg")) {
      throw rigid::lab::UsageError("--axis-deg", "give --axis or --axis-deg, not both");
    }
    // The axis: by its components, the plate's diagonal, or an angle in the plane.
    if (axis.word() == "diagonal") in.axis = Vec3(a, in.b, 0.0);
    if (lab.given("--axis-deg")) {
      const double t = rigid::deg_to_rad(in.axis_deg);
      in.axis = Vec3(std::cos(t), std::sin(t), 0.0);
      lab.drop_input("axis");
    }
    const Vec3 n = in.axis.stableNormalized();
    const Vec3 omega = in.omega * n;

    lab.section("1. inertia tensor about the " + in.origin + " (eqs. 6-11, 20, 70): x along a, " +
                "y along b, z normal; " +
                (in.origin == "corner" ? "the plate fills 0 <= x <= a, 0 <= y <= b"
                                       : "the plate's centre at the origin"));
    lab.result("axis_unit", "rotation axis n (unit)", n, "");
    lab.result("axis_angle_from_x_deg", "  its angle from x toward y",
               rigid::rad_to_deg(std::atan2(n.y(), n.x())), "deg", lab.textbook("37 (3-4-5)"));
    const Mat3 I = rigid::lamina_tensor({in.mass, a, in.b, in.origin == "corner"});
    lab.result("inertia_tensor", "inertia tensor I", I, "kg m^2",
               lab.textbook("(4/3, -1/2, 0; -1/2, 1/3, 0; 0, 0, 5/3) ma^2"));
    lab.result("scalar_moment", "moment about n, n.I.n (eq. 21)", rigid::moment_about_axis(I, n),
               "kg m^2", lab.textbook("0.493 ma^2"));

    lab.section("1.1 angular momentum (eq. 28)");
    const Vec3 L = rigid::angular_momentum(I, omega);
    lab.result("angular_momentum", "L = I omega", L, "kg m^2/s",
               lab.textbook("(0.767, -0.20, 0) ma^2 omega"));
    lab.result("angular_momentum_magnitude", "|L|", L.stableNorm(), "kg m^2/s",
               lab.textbook("0.793 ma^2 omega"));
    lab.result("angle_L_omega_deg", "angle between L and omega",
               rigid::rad_to_deg(rigid::angle_between(L, omega)), "deg", lab.textbook("51"));
    if (lab.textbook_inputs()) {
      lab.note(fmt::format(
          "errata: |L| = {:.4f} ma^2 omega exactly; the text's 0.793 comes from rounding L_x "
          "to 0.767 before taking the norm",
          L.stableNorm() / (ma2 * in.omega)));
    }

    lab.section("1.2 kinetic energy (eqs. 33-34)");
    lab.result("kinetic_energy", "T = omega.I omega / 2", rigid::kinetic_energy(I, omega), "J",
               lab.textbook("(1/2)(0.493) ma^2 omega^2"));

    // Section 2.1's examples do not depend on the plate's orientation: shown with the
    // textbook's inputs, or when asked for.
    if (lab.textbook_inputs() || in.examples) {
      lab.section("2.1 symmetric bodies about their centre of mass, built from primitives");
      const rigid::Body paddle = rigid::model_paddle(m, a);
      lab.result("paddle_principal_moments", "model paddle I1, I2, I3 (eqs. 41-43)",
                 Vec3(paddle.I_com.diagonal()), "kg m^2", printed("(1/8, 31/24, 17/12) ma^2"));
      lab.result("block_principal_moments", "block a x b x c (eq. 40)",
                 Vec3(rigid::solid_box(m, a, in.b, in.c).I_com.diagonal()), "kg m^2",
                 printed("m/12 (b^2+c^2, a^2+c^2, a^2+b^2)"));
      const Mat3 cube = rigid::solid_box(m, a, a, a).I_com;
      lab.result("cube_moment_about_axis", "cube of side a, moment about n",
                 rigid::moment_about_axis(cube, n), "kg m^2", printed("ma^2/6"));
      lab.result("cube_moment_about_diagonal", "cube, moment about its body diagonal",
                 rigid::moment_about_axis(cube, Vec3(1, 1, 1)), "kg m^2", printed("ma^2/6"));
    }

    lab.section("2.3 principal axes in the x-y plane from tan 2 theta (eqs. 53-56)");
    const rigid::InPlaneAxes plane = rigid::in_plane_principal_axes(I);
    lab.result("two_theta_deg", "2 theta, tan 2 theta = 2 Ixy / (Ixx - Iyy)",
               rigid::rad_to_deg(plane.two_theta), "deg", lab.textbook("-45 (tan 2 theta = -1)"));
    lab.result("principal_angle_deg", "axis angle from x", rigid::rad_to_deg(plane.theta), "deg",
               lab.textbook("-22.5"));
    lab.result("principal_angle_moment", "  moment about that axis (eq. 50)", plane.moment,
               "kg m^2");
    lab.result("principal_angle_other_deg", "other in-plane axis",
               rigid::rad_to_deg(plane.theta_other), "deg", lab.textbook("67.5"));
    lab.result("principal_angle_other_moment", "  moment about that axis", plane.moment_other,
               "kg m^2");
    lab.result("body_diagonal_deg", "body diagonal, for contrast",
               rigid::rad_to_deg(std::atan2(in.b, a)), "deg", lab.textbook("63.4"));
    if (lab.textbook_inputs()) {
      lab.note(fmt::format(
          "errata: the text calls the axis at {:.1f} deg 'the 1-axis', but its moment is "
          "{:.3f} ma^2 (I2 when moments ascend, as in its section 2.4); the axis at {:.1f} deg "
          "carries I1 = {:.3f} ma^2",
          rigid::rad_to_deg(plane.theta), plane.moment / ma2, rigid::rad_to_deg(plane.theta_other),
          plane.moment_other / ma2));
    }

    lab.section("2.4 principal moments and axes by diagonalisation (eqs. 62-69)");
    const rigid::PrincipalAxes principal = rigid::principal_axes(I);
    lab.result("principal_moments", "principal moments I1, I2, I3", principal.moments, "kg m^2",
               lab.textbook("(0.126, 1.540, 1.667) ma^2"));
    lab.result("principal_axes", "principal axes e1; e2; e3 (rows)", principal.axes, "",
               lab.textbook("(-0.3827, -0.9239, 0); (0.9239, -0.3827, 0); (0, 0, 1)"));

    lab.section("3.1 torque to turn about a fixed axis at constant omega (eqs. 74-76)");
    const Vec3 N = rigid::fixed_axis_torque(I, omega);
    lab.result("fixed_axis_torque", "N = omega x (I omega) about n, x-y-z frame", N, "N m");
    lab.result("fixed_axis_torque_principal", "  the same in the principal frame",
               Vec3(principal.axes * N), "N m");
    // The section's own example turns the lamina about x, whatever --axis says.
    const Vec3 N_x = principal.axes * rigid::fixed_axis_torque(I, in.omega * Vec3::UnitX());
    lab.result("fixed_axis_torque_x_principal", "N1, N2, N3 for rotation about x", N_x, "N m",
               lab.textbook("(0, 0, 0.500) ma^2 omega^2"));
    if (lab.textbook_inputs()) {
      lab.note(fmt::format(
          "errata: for rotation about +x, N3 = omega1 omega2 (I2 - I1) = {:.3f} ma^2 omega^2; "
          "the text prints +0.500 (right size, wrong sign): the axle pushes along -z",
          N_x(2) / (ma2 * in.omega * in.omega)));
    }

    lab.figures([&](rigid::lab::FigureSet& set) {
      rigid::lab::lamina_tensor::draw(set, in, I, principal);
    });
  });
}
