// lamina_tensor's figures: the lamina with its rotation axis, omega, L and the
// principal axes; the moment about an in-plane axis against its angle.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "lamina_tensor/lamina_tensor.h"
#include "rigid/units.h"

namespace rigid::lab::lamina_tensor {
namespace {

// The principal axes' colours: the shared ones, but axis 2 olive. A plate's L leans
// toward its largest in-plane moment's axis, and in the shared orange that axis and L
// in vermillion read as one hue and one direction; olive is yellow dark enough for
// text on white.
constexpr render::Color kAxisColors[3] = {colors::kPrincipal[0], render::kOlive,
                                          colors::kPrincipal[2]};

// The lamina with its rotation axis, omega, L and the principal axes.
render::Scene3D scene_of(const Report& report) {
  const Vec3& n = report.n;
  const Mat3& I = report.I;
  const PrincipalAxes& principal = report.principal;
  const double a = report.a, b = report.b;
  const Vec3 L_dir = (I * n).stableNormalized();  // scaled: |I n|^2 may overflow
  const double size = std::max(a, b);
  const Vec3 centre = report.corner ? Vec3(a / 2, b / 2, 0) : Vec3::Zero();

  render::Scene3D scene;
  scene.title = fmt::format("angle(L, \\omega) = {:.1f}\\deg", rad_to_deg(angle_between(I * n, n)));
  scene.camera.eye = centre + size * Vec3(1.2, -2.2, 2.6);
  scene.camera.target = centre + Vec3(0, 0, 0.1 * size);
  scene.camera.fov_y_deg = 38;

  scene.add_box(centre, Vec3(a / 2, b / 2, 0.01 * size), Mat3::Identity(),
                flat_body(colors::kBody, 0.35f), "lamina");
  // The fixed rotation axis runs through the origin both ways.
  scene.add_cylinder(-0.4 * size * n, 1.15 * size * n, 0.006 * size, {colors::kFixedAxis},
                     "rotation axis n");
  const double arrow = 0.9 * size;
  scene.add_arrow(Vec3::Zero(), arrow * n, 0.018 * size, {colors::kOmega}, "\\omega");
  scene.add_arrow(Vec3::Zero(), arrow * L_dir, 0.018 * size, {colors::kL},
                  "L = I\\omega (direction)");
  scene.add_label(arrow * 1.08 * n, "\\omega", colors::kOmega);
  scene.add_label(arrow * 1.08 * L_dir, "L", colors::kL);
  // The angle between omega and L, as an arc in their plane (section 1.1).
  const double angle = angle_between(L_dir, n);
  if (angle > 1e-6) {
    const Vec3 across = (L_dir - n * n.dot(L_dir)).stableNormalized();
    std::vector<Vec3> arc;
    for (int k = 0; k <= 48; ++k) {
      const double t = angle * k / 48.0;
      arc.push_back(0.45 * size * (std::cos(t) * n + std::sin(t) * across));
    }
    scene.add_polyline(arc, render::kBlack, 3.0);
    const Vec3 middle = std::cos(angle / 2) * n + std::sin(angle / 2) * across;
    scene.add_label(0.53 * size * middle, fmt::format("{:.1f}\\deg", rad_to_deg(angle)),
                    render::kBlack);
  }
  // Principal axes through the origin, both directions, labelled by moment.
  const render::Color* axis_colors = kAxisColors;
  for (int i = 0; i < 3; ++i) {
    const Vec3 e = principal.axes.row(i).transpose();
    const double reach = (i == 2 ? 0.6 : 0.75) * size;
    scene.add_cylinder(
        -reach * e, reach * e, 0.009 * size, {axis_colors[i]},
        fmt::format("principal axis {}: I_{} = {:.4g} kg m^2", i + 1, i + 1, principal.moments(i)));
    scene.add_label(reach * 1.1 * e, std::to_string(i + 1), axis_colors[i]);
  }
  // The x, y, z triad as thick as the principal axes, so it reads at 800x600 too.
  scene.add_axes(Vec3::Zero(), Mat3::Identity(), 0.45 * size, {"x", "y", "z"}, 0.009 * size);
  return scene;
}

// The moment n.I.n about an in-plane axis at angle alpha from x: the principal
// axes are its extremes (section 2.3).
render::Plot2D moment_plot(const Report& report) {
  const Mat3& I = report.I;
  const Vec3& n = report.n;
  // the sweep --csv writes (moment_sweep)
  std::vector<double> alpha_deg, moment;
  for (const std::vector<double>& row : report.time_series().rows) {
    alpha_deg.push_back(row[0]);
    moment.push_back(row[1]);
  }
  render::Plot2D plot;
  plot.title = "moment about an axis in the x-y plane";
  render::Panel& panel = plot.panel();
  panel.x = {"axis angle \\alpha from x (\\deg)", render::Scale::kLinear, -90, 90};
  panel.y = {"moment n\u00b7I\u00b7n (kg m^2)", render::Scale::kLinear, 0.0};
  panel.add_line(alpha_deg, moment, "I(\\alpha) = n\u00b7I\u00b7n").color = render::kBlue;

  const InPlaneAxes axes = in_plane_principal_axes(I);
  for (const auto& [theta, value] :
       {std::pair{axes.theta, axes.moment}, std::pair{axes.theta_other, axes.moment_other}}) {
    double deg = rad_to_deg(theta);
    if (deg > 90) deg -= 180;
    // In the plane the smaller moment is axis 1's and the larger axis 2's (I3 is normal).
    const int index = value < std::max(axes.moment, axes.moment_other) ? 0 : 1;
    panel.add_ref_line(deg, true, fmt::format("principal axis {} at {:.1f}\\deg", index + 1, deg))
        .color = kAxisColors[index];
    panel.annotate(deg, value, fmt::format("{:.4g} kg m^2", value));
  }
  if (std::abs(n.z()) < 1e-12) {
    double deg = rad_to_deg(std::atan2(n.y(), n.x()));
    if (deg > 90) deg -= 180;
    if (deg < -90) deg += 180;
    panel.add_points({deg}, {moment_about_axis(I, n)}, "chosen axis n", render::Marker::kCircle)
        .color = colors::kMarker;
  }
  return plot;
}

}  // namespace

void figures(const Report& report, FigureSink& sink) {
  sink.add("scene", "L is not along omega; the principal axes", [&] { return scene_of(report); });
  sink.add("moment", "the moment n.I.n is extreme on the principal axes",
           [&] { return moment_plot(report); });
}

}  // namespace rigid::lab::lamina_tensor
