// euler_angles' figures: the three rotations as the text's Figure 9.6.2 draws them
// (the fixed axes, the line of nodes, the body's axes, the angles as arcs) with omega
// as the sum of its three parts; the three turns applied in turn as an animation; and
// gimbal lock, where the axes of phi and psi line up.
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "euler_angles/euler_angles.h"
#include "rigid/units.h"

namespace rigid::lab::euler_angles {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

// Each angle and its rate keep one colour in every figure.
constexpr render::Color kPhiColor = colors::kL;
constexpr render::Color kThetaColor = render::kOrange;
constexpr render::Color kPsiColor = render::kReddishPurple;
constexpr render::Color kBodyColor = render::kBluishGreen;

// An arc of radius `radius` about `axis` from direction `from` through `angle` (rad),
// with its label (if any) at the middle, a little outside; none for a zero angle.
void add_arc(render::Scene3D& scene, const Vector3d& axis, const Vector3d& from, double angle,
             double radius, render::Color color, const std::string& text) {
  angle = std::remainder(angle, 2 * kPi);  // phi and psi of any size: the same turn
  if (!(std::abs(angle) > 1e-9)) return;
  std::vector<Vector3d> points;
  const int n = 48;
  for (int k = 0; k <= n; ++k) {
    points.push_back(radius * (Eigen::AngleAxisd(angle * k / n, axis) * from));
  }
  scene.add_polyline(points, color, 5.0);
  if (!text.empty())
    scene.add_label(1.18 * radius * (Eigen::AngleAxisd(0.5 * angle, axis) * from), text, color);
}

// Seen from 45 deg of azimuth before the line of nodes of `phi` (halfway to 3's, 90 deg
// before it) and 25 deg above the xy plane: z up, x' and 3 slanting across the picture
// (from along either, its arrow and angle would be points).
render::Camera camera_before_nodes(double phi) {
  render::Camera camera;
  const double azimuth = phi - deg_to_rad(45.0), elevation = deg_to_rad(25.0);
  camera.eye = 3.2 * Vector3d(std::cos(elevation) * std::cos(azimuth),
                              std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
  camera.target = Vector3d(0, 0, 0.3);
  camera.fov_y_deg = 30;
  return camera;
}

// The fixed axes, the body's after the turns `e` (partial ones in the animation), the line
// of nodes and the angles as arcs.
render::Scene3D turns_scene(const EulerAngles& e) {
  const Vector3d z = Vector3d::UnitZ(), x = Vector3d::UnitX();
  // body-to-space: Rz(phi) Rx(theta) Rz(psi); the line of nodes Rz(phi) x; 3 = its third column
  const Matrix3d to_space = quaternion_from_euler_zxz(e).toRotationMatrix();
  const Vector3d nodes = Eigen::AngleAxisd(e.phi, z) * x;
  render::Scene3D scene;
  // The fixed axes grey (the triad's own colour), the body's one green, the line of
  // nodes black, each labelled at its tip; each angle and its rate one colour of its own.
  scene.add_axes(Vector3d::Zero(), Matrix3d::Identity(), 1.0, {"x", "y", "z"});
  for (int i = 0; i < 3; ++i) {
    scene.add_arrow(Vector3d::Zero(), 0.95 * to_space.col(i), 0.014, {kBodyColor},
                    i == 0 ? "body axes 1, 2, 3" : "");
    scene.add_label(1.04 * to_space.col(i), std::to_string(i + 1), kBodyColor);
  }
  scene.add_arrow(Vector3d::Zero(), 0.9 * nodes, 0.014, {colors::kMarker}, "line of nodes x'");
  scene.add_label(0.98 * nodes, "x'", colors::kMarker);
  add_arc(scene, z, x, e.phi, 0.45, kPhiColor, "\\phi");
  add_arc(scene, nodes, z, e.theta, 0.55, kThetaColor, "\\theta");
  add_arc(scene, to_space.col(2), nodes, e.psi, 0.65, kPsiColor, "\\psi");
  return scene;
}

render::Scene3D rotations_scene(const Report& report) {
  const EulerAngles& e = report.angles;
  render::Scene3D scene = turns_scene(e);
  scene.title = report.rates_defined
                    ? "the three rotations and omega as the sum of its three parts"
                    : "the three rotations and omega, whose parts a pole leaves undefined";
  if (report.rates_defined) {
    // omega = phi_dot z + theta_dot x' + psi_dot 3 (eq. 124) drawn as that sum: each part
    // from the last one's tip, to scale, and omega from the origin to the chain's end; a
    // part that is zero has no arrow
    const EulerRates& r = report.rates;
    const Vector3d z = Vector3d::UnitZ();
    const Vector3d nodes = Eigen::AngleAxisd(e.phi, z) * Vector3d::UnitX();
    const Vector3d three = quaternion_from_euler_zxz(e) * z;
    // omega half again as long as the axes: its head and the parts' clear of the axes'
    // tips and labels, and the shortest part (theta_dot x', a sixth of omega here) long
    // enough to show as an arrow
    const double scale = 1.5 / std::max(report.omega_space.norm(), 1e-300);
    Vector3d tip = Vector3d::Zero();
    const auto part = [&](const Vector3d& along, render::Color color, const std::string& label) {
      const Vector3d next = tip + scale * along;
      if ((next - tip).norm() > 1e-6) scene.add_arrow(tip, next, 0.02, {color}, label);
      tip = next;
    };
    part(r.phi_dot * z, kPhiColor, "\\phi-dot z");
    part(r.theta_dot * nodes, kThetaColor, "\\theta-dot x'");
    part(r.psi_dot * three, kPsiColor, "\\psi-dot 3");
    if (tip.norm() > 1e-6) {
      scene.add_arrow(Vector3d::Zero(), tip, 0.022, {colors::kOmega},
                      "\\omega = \\phi-dot z + \\theta-dot x' + \\psi-dot 3");
    }
  } else if (report.omega_space.norm() > 0) {
    // at a pole omega is defined, its split between phi_dot and psi_dot is not: omega
    // alone, at unit length
    scene.add_arrow(Vector3d::Zero(), report.omega_space.normalized(), 0.016, {colors::kOmega},
                    "\\omega (at the pole its \\phi-dot and \\psi-dot are undefined)");
  }
  scene.camera = camera_before_nodes(e.phi);
  return scene;
}

// The three turns one after another, each in a second of the animation's own time (not
// the body's: the turns are a construction), eased in and out, then a second at rest.
class Turns {
 public:
  // phi and psi of any size turn the body as their remainders in (-180, 180] deg do
  explicit Turns(const Report& report)
      : angles_{std::remainder(report.angles.phi, 2 * kPi), report.angles.theta,
                std::remainder(report.angles.psi, 2 * kPi)} {}
  double seconds() const { return 4.0; }
  render::Scene3D scene(double t) const {
    const auto eased = [](double s) {
      s = std::clamp(s, 0.0, 1.0);
      return s * s * (3 - 2 * s);
    };
    const EulerAngles e{angles_.phi * eased(t), angles_.theta * eased(t - 1),
                        angles_.psi * eased(t - 2)};
    render::Scene3D scene = turns_scene(e);
    const int stage = t < 1 ? 0 : t < 2 ? 1 : 2;
    const char* turn[3] = {"first turn: \\phi about z",
                           "second: \\theta about the line of nodes x'",
                           "third: \\psi about the body's 3"};
    scene.title =
        t >= 3
            ? "the three turns done: \\lambda = \\lambda_\\psi \\lambda_\\theta \\lambda_\\phi"
            : fmt::format("{}: \\phi = {:.0f}\u00b0, \\theta = {:.0f}\u00b0, \\psi = {:.0f}\u00b0",
                          turn[stage], rad_to_deg(e.phi), rad_to_deg(e.theta), rad_to_deg(e.psi));
    scene.camera = camera_before_nodes(angles_.phi);
    return scene;
  }

 private:
  EulerAngles angles_;
};

// Gimbal lock: near theta = 0 the axes of phi (z) and psi (3) nearly line up, and with
// the line of nodes they span little more than a plane; a turn about n = z x x', the
// plane's normal, needs phi_dot = cot(theta) and psi_dot = -1 / sin(theta) (eqs. 134-136
// inverted). (n is not the text's y', which theta tilts out of the xy plane.)
render::Scene3D gimbal_scene(const Report& report) {
  const double theta = deg_to_rad(8.0);
  const EulerAngles e{report.angles.phi, theta, report.angles.psi};
  const Vector3d z = Vector3d::UnitZ();
  const Vector3d nodes = Eigen::AngleAxisd(e.phi, z) * Vector3d::UnitX();
  const Vector3d three = quaternion_from_euler_zxz(e) * z;
  const Vector3d normal = z.cross(nodes);  // n
  // the rates that turn the body at 1 rad/s about n: from omega in the body
  const Vector3d omega_body = quaternion_from_euler_zxz(e).conjugate() * normal;
  const std::optional<EulerRates> rates = rates_from_body_omega(e, omega_body);
  render::Scene3D scene;
  scene.title = fmt::format(
      "gimbal lock: at \\theta = {:g}\u00b0 the axes of \\phi and \\psi "
      "nearly line up",
      rad_to_deg(theta));
  scene.add_disk(Vector3d::Zero(), normal, 0.85, flat_body(render::kSkyBlue, 0.18f),
                 "the plane of z and x'");
  const auto axis = [&](const Vector3d& along, render::Color color, const std::string& legend,
                        const std::string& name) {
    scene.add_arrow(Vector3d::Zero(), along, 0.018, {color}, legend);
    scene.add_label(1.07 * along, name, color);
  };
  axis(z, kPhiColor, "\\phi turns about z", "z");
  axis(nodes, kThetaColor, "\\theta about the line of nodes x'", "x'");
  axis(three, kPsiColor, "\\psi about the body's 3", "3");
  // the arc halfway up, its label beside it on 3's side, pinned there: between the two
  // shafts there is no room, and at 0.75 up it sat on z's arrowhead
  add_arc(scene, nodes, z, theta, 0.5, kThetaColor, "");
  render::Label3D theta_label{0.5 * (z + three).normalized() + 0.14 * (three - z).normalized(),
                              "\\theta", kThetaColor};
  theta_label.pinned = true;
  scene.add_label(std::move(theta_label));
  if (rates) {
    axis(0.8 * normal, colors::kOmega,
         fmt::format("1 rad/s about n = z \u00d7 x' needs \\phi-dot = {:.3g}, \\psi-dot = "
                     "{:.3g} rad/s",
                     rates->phi_dot, rates->psi_dot),
         "n");
  }
  // from the side of the plane, a little above, so the three axes fan out in it
  const double azimuth = e.phi - deg_to_rad(60.0), elevation = deg_to_rad(20.0);
  scene.camera.eye = 3.4 * Vector3d(std::cos(elevation) * std::cos(azimuth),
                                    std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
  scene.camera.target = Vector3d(0, 0, 0.35);
  scene.camera.fov_y_deg = 30;
  return scene;
}

}  // namespace

void figures(const Report& report, FigureSink& sink) {
  sink.add("rotations", "the three rotations phi, theta, psi and omega as the sum of its parts",
           [&] { return rotations_scene(report); });
  sink.add("gimbal_lock", "gimbal lock: near theta = 0 the axes of phi and psi line up",
           [&] { return gimbal_scene(report); });
}

Animation animation(const Report& report, const FrameTimes& /*frame_times*/) {
  return play(std::make_shared<const Turns>(report),
              "the three turns in turn: phi about z, theta about the line of nodes, psi about 3");
}

}  // namespace rigid::lab::euler_angles
