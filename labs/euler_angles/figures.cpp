// euler_angles' figures: the three rotations as the text's Figure 9.6.2 draws them
// (the fixed axes, the line of nodes, the body's axes, the angles as arcs) with omega
// and its three parts.
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "euler_angles/euler_angles.h"
#include "rigid/units.h"

namespace rigid::lab::euler_angles {

using Eigen::Vector3d;

namespace {

// An arc of radius `radius` about `axis` from direction `from` through `angle` (rad),
// with its label at the middle, a little outside.
void add_arc(render::Scene3D& scene, const Vector3d& axis, const Vector3d& from, double angle,
             double radius, render::Color color, const std::string& text) {
  std::vector<Vector3d> points;
  const int n = 48;
  for (int k = 0; k <= n; ++k) {
    points.push_back(radius * (Eigen::AngleAxisd(angle * k / n, axis) * from));
  }
  scene.add_polyline(points, color, 4.0);
  scene.add_label(1.18 * radius * (Eigen::AngleAxisd(0.5 * angle, axis) * from), text, color);
}

render::Scene3D rotations_scene(const Report& report) {
  const EulerAngles& e = report.angles;
  const Vector3d z = Vector3d::UnitZ(), x = Vector3d::UnitX();
  // body-to-space: Rz(phi) Rx(theta) Rz(psi); the line of nodes Rz(phi) x; 3 = Rz(phi) Rx(theta) z
  const Eigen::Matrix3d to_space = quaternion_from_euler_zxz(e).toRotationMatrix();
  const Vector3d nodes = Eigen::AngleAxisd(e.phi, z) * x;
  const Vector3d three = to_space.col(2);
  render::Scene3D scene;
  scene.title = "the three rotations and omega's three parts";
  // The fixed axes grey (the triad's own colour), the body's one green, the line of
  // nodes black, each labelled at its tip; each angle and its rate one colour of its own.
  scene.add_axes(Vector3d::Zero(), Eigen::Matrix3d::Identity(), 1.0, {"x", "y", "z"});
  for (int i = 0; i < 3; ++i) {
    scene.add_arrow(Vector3d::Zero(), 0.95 * to_space.col(i), 0.014, {render::kBluishGreen},
                    i == 0 ? "body axes 1, 2, 3" : "");
    scene.add_label(1.04 * to_space.col(i), std::to_string(i + 1), render::kBluishGreen);
  }
  scene.add_arrow(Vector3d::Zero(), 0.9 * nodes, 0.014, {colors::kMarker}, "line of nodes x'");
  scene.add_label(0.98 * nodes, "x'", colors::kMarker);
  add_arc(scene, z, x, e.phi, 0.45, colors::kL, "\\phi");
  add_arc(scene, nodes, z, e.theta, 0.55, render::kOrange, "\\theta");
  add_arc(scene, three, nodes, e.psi, 0.65, render::kReddishPurple, "\\psi");
  if (report.rates_defined) {
    // omega and its parts, thicker than the axes they lie on: phi_dot along z,
    // theta_dot along x', psi_dot along 3 (eq. 124); a part (or omega) that is zero
    // has no arrow
    const EulerRates& r = report.rates;
    const double scale = 0.8 / std::max(report.omega_space.norm(), 1e-300);
    const auto arrow = [&](const Vector3d& to, double radius, render::Color color,
                           const std::string& label) {
      if (to.norm() > 1e-6) scene.add_arrow(Vector3d::Zero(), to, radius, {color}, label);
    };
    arrow(scale * report.omega_space, 0.022, colors::kOmega,
          "\\omega = \\phi-dot z + \\theta-dot x' + \\psi-dot 3");
    arrow(scale * r.phi_dot * z, 0.018, colors::kL, "\\phi-dot z");
    arrow(scale * r.theta_dot * nodes, 0.018, render::kOrange, "\\theta-dot x'");
    arrow(scale * r.psi_dot * three, 0.018, render::kReddishPurple, "\\psi-dot 3");
  }
  // Seen from 45 deg of azimuth before the line of nodes (halfway to 3's, 90 deg before
  // it) and 25 deg above the xy plane: z up, x' and 3 slanting across the picture (from
  // along either, its arrow and angle would be points).
  const double azimuth = e.phi - deg_to_rad(45.0), elevation = deg_to_rad(25.0);
  scene.camera.eye = 3.2 * Vector3d(std::cos(elevation) * std::cos(azimuth),
                                    std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
  scene.camera.target = Vector3d(0, 0, 0.3);
  scene.camera.fov_y_deg = 30;
  return scene;
}

}  // namespace

void figures(const Report& report, FigureSink& sink) {
  sink.add("rotations", "the three rotations phi, theta, psi and omega's three parts",
           rotations_scene(report));
}

}  // namespace rigid::lab::euler_angles
