// tire_balancing's figures: the wheel on its crooked axle with the cone L
// sweeps; the balancing mass against the tilt, exact and small-angle.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "rigid/units.h"
#include "tire_balancing/tire_balancing.h"

namespace rigid::lab::tire_balancing {
namespace {

// The wheel, its crooked axle, the balancing masses and the cone L sweeps
// before balancing. Angles of a degree would be invisible, so the scene
// magnifies every angle about the symmetry axis by the same factor and says so.
render::Scene3D scene_of(const CrookedWheel& wheel, double m0, double omega) {
  const double a = wheel.radius, b = wheel.offset;
  // A straight axle (tilt 0) has no angle to magnify.
  const double magnify = wheel.tilt > 0.0 ? std::max(1.0, deg_to_rad(12.0) / wheel.tilt) : 1.0;
  const auto shown = [&](const Vec3& v) -> Vec3 {
    // Magnify the angle of v from the x axis (within the plane of v and x).
    const double angle = std::atan2(std::hypot(v.y(), v.z()), v.x());
    const Vec3 side = Vec3(0, v.y(), v.z()).normalized();
    return v.norm() *
           (std::cos(magnify * angle) * Vec3::UnitX() + std::sin(magnify * angle) * side);
  };
  const Vec3 axle = shown(axle_direction(wheel));
  const Vec3 L0 = angular_momentum_at(wheel, 0.0, omega, 0.0);
  const double cone_angle = magnify * angle_between(L0, axle_direction(wheel));

  render::Scene3D scene;
  if (magnify > 1) scene.title = fmt::format("angles drawn \\times{:.0f}", magnify);
  scene.camera.eye = Vec3(1.9, -3.0, 1.5) * a * 1.6;
  scene.camera.target = Vec3(0.05 * a, 0, 0);
  scene.camera.fov_y_deg = 34;

  scene.add_cylinder(Vec3(-0.012 * a, 0, 0), Vec3(0.012 * a, 0, 0), a,
                     flat_body(colors::kBody, 0.35f), "disk (symmetry axis x)");
  scene.add_cylinder(-1.9 * a * axle, 1.9 * a * axle, 0.035 * a, {colors::kFixedAxis},
                     "crooked axle");
  // A balanced wheel (a straight axle) needs no masses, and L sweeps no cone.
  if (m0 > 0.0) {
    const double r0 = 0.07 * a * std::cbrt(std::max(m0, 1e-6) / (0.01 * wheel.mass));
    scene.add_marker(Vec3(-b, a, 0), std::min(r0, 0.15 * a), {colors::kMarker},
                     fmt::format("balancing masses m_0 = {:.1f} g", 1e3 * m0));
    scene.add_marker(Vec3(b, -a, 0), std::min(r0, 0.15 * a), {colors::kMarker});
    // One on each face, opposite: the camera sees the +x face, the other mass through
    // the translucent disk, tinted by it.
    scene.add_label(Vec3(b, -1.3 * a, 0), "m_0 on the front face");
    scene.add_label(Vec3(-b, 1.4 * a, 0), "m_0 on the back face");
  }
  // The cone swept by L about the axle when unbalanced, with L at t = 0.
  const double length = 1.6 * a;
  if (cone_angle > 0.0) {
    scene.add_cone(Vec3::Zero(), length * std::cos(cone_angle) * axle,
                   length * std::sin(cone_angle), {colors::kL, 0.25f},
                   "cone swept by L (unbalanced)");
  }
  const Vec3 L_shown = shown(L0).normalized();
  scene.add_arrow(Vec3::Zero(), length * L_shown, 0.03 * a, {colors::kL}, "L before balancing");
  scene.add_arrow(Vec3::Zero(), length * 1.12 * axle, 0.03 * a, {colors::kOmega},
                  "\\omega along the axle");
  scene.add_label(length * 1.05 * L_shown, "L", colors::kL);
  scene.add_label(length * 1.15 * axle, "\\omega", colors::kOmega);
  // The frame's axes beside the wheel: at its centre x would lie under L and the cone.
  scene.add_axes(Vec3(0, -0.5 * a, -1.45 * a), Mat3::Identity(), 0.45 * a, {"x", "y", "z"},
                 0.015 * a);
  return scene;
}

// The balancing mass against the tilt: exact (eq. 60) against small-angle (eq. 61).
render::Plot2D mass_plot(const CrookedWheel& wheel, double m0) {
  std::vector<double> tilt_deg, exact_g, small_g;
  const double top = std::min(44.0, std::max(5.0, 4.0 * rad_to_deg(wheel.tilt)));
  CrookedWheel w = wheel;
  for (int k = 1; k <= 200; ++k) {
    w.tilt = deg_to_rad(top * k / 200.0);
    try {
      exact_g.push_back(1e3 * balance_mass_exact(w));
    } catch (const std::invalid_argument&) {
      break;  // no mass reaches steeper tilts
    }
    tilt_deg.push_back(rad_to_deg(w.tilt));
    small_g.push_back(1e3 * balance_mass_small_angle(w));
  }
  render::Plot2D plot;
  plot.title = "balancing mass against axle tilt";
  render::Panel& panel = plot.panel();
  panel.x = {"axle tilt \\theta (\\deg)", render::Scale::kLinear, 0, top};
  panel.y = {"balancing mass m_0 (g)", render::Scale::kLinear, 0};
  panel.add_line(tilt_deg, exact_g, "exact, tan 2\\theta (eq. 60)").color = render::kBlue;
  auto& small =
      panel.add_line(tilt_deg, small_g, "small angle, \\theta \\approx 8bm_0/(am) (eq. 61)");
  small.color = render::kOrange;
  small.dash = render::Dash::kDashed;
  panel
      .add_points({rad_to_deg(wheel.tilt)}, {1e3 * m0},
                  fmt::format("this wheel: {:.1f} g", 1e3 * m0))
      .color = colors::kMarker;  // as the masses are drawn in the scene
  return plot;
}

}  // namespace

void figures(const Report& report, FigureSink& sink) {
  sink.add("scene", "the crooked axle and the cone L sweeps",
           [&] { return scene_of(report.wheel, report.m0, report.omega); });
  sink.add("mass", "balancing mass, exact against small-angle",
           [&] { return mass_plot(report.wheel, report.m0); });
}

}  // namespace rigid::lab::tire_balancing
