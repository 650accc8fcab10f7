// football's figures and motion: the body cone rolling on the space cone, with
// omega along their line of contact, L and the symmetry axis; the rates against alpha.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "football/football.h"
#include "rigid/inertia.h"
#include "rigid/units.h"

namespace rigid::lab::football {
namespace {

const char* const kSpaceRateLabel = "\\phi-dot / \\omega, 3 about L in space (eq. 147)";
const char* const kBodyRateLabel = "|\\Omega| / \\omega, \\omega about 3 in the body (eq. 109)";

// A circle of `radius` about the z axis at height z.
std::vector<Vec3> circle_about_z(double radius, double z) {
  std::vector<Vec3> points;
  for (int k = 0; k <= 120; ++k) {
    const double a = 2 * kPi * k / 120;
    points.emplace_back(radius * std::cos(a), radius * std::sin(a), z);
  }
  return points;
}

// Both scenes seen alike: L up, the cones' apex low in the view.
render::Camera cones_camera() {
  render::Camera camera;
  camera.eye = Vec3(0.9, -3.6, 1.5);
  camera.target = Vec3(0.15, 0, 0.55);
  camera.fov_y_deg = 32;
  return camera;
}

// A spin along 3 (alpha = 0): omega, L and 3 on one line, both cones lines. The three
// arrows are nested, the shortest the thickest, so each shows its own colour; lines
// fixed in the body turn about 3 at omega.
render::Scene3D aligned_scene(double ratio, double omega, const std::string& prefix, double t) {
  render::Scene3D scene;
  scene.title = prefix + fmt::format(
                             "Is/I = {:.6g}: \\omega, L and 3 on one line; "
                             "nothing precesses",
                             ratio);
  scene.camera = cones_camera();
  const double r = 0.016;
  scene.add_arrow(Vec3::Zero(), 1.45 * Vec3::UnitZ(), r, {colors::kL}, "L (fixed in space)");
  scene.add_arrow(Vec3::Zero(), 1.3 * Vec3::UnitZ(), 1.5 * r, {colors::kSymmetryAxis},
                  "symmetry axis 3");
  scene.add_arrow(Vec3::Zero(), 1.15 * Vec3::UnitZ(), 2 * r, {colors::kOmega}, "\\omega");
  // The body's turn about 3, seen on a disk of lines fixed in it.
  const double turn = omega * t;
  for (int k = 0; k < 8; ++k) {
    const double beta = turn + 2 * kPi * k / 8;
    scene.add_polyline({Vec3(0, 0, 0.6), Vec3(0.5 * std::cos(beta), 0.5 * std::sin(beta), 0.6)},
                       colors::kSymmetryAxis, 2.5);
  }
  scene.add_polyline(circle_about_z(0.5, 0.6), colors::kSymmetryAxis, 3.0,
                     "lines fixed in the body, turning about 3");
  scene.add_label(1.55 * Vec3::UnitZ(), "L, 3, \\omega");
  scene.add_label(Vec3(0, 0, -0.1), "centre of mass");
  return scene;
}

// L along z; the symmetry axis 3 and omega in the x-z plane at t = 0. The body
// cone (half-angle alpha about 3) touches the space cone (half-angle |theta - alpha|
// about L) along omega. Small angles are magnified by one factor, said in the title.
// At time t the plane of L, 3 and omega has turned about L by phi_dot t, and the body
// cone has rolled on the space cone: lines drawn on it, fixed in the body, show it.
render::Scene3D rolling_cones_scene(double ratio, double alpha_deg, const SymmetricPrecession& p,
                                    const std::string& prefix, double t) {
  const double widest = std::max(p.theta, p.body_cone);
  const double magnify =
      std::max(1.0, std::min(deg_to_rad(22.0) / p.body_cone, deg_to_rad(70.0) / widest));
  const double theta = magnify * p.theta, alpha = magnify * p.body_cone;
  const double space = magnify * p.space_cone;
  const double lead = theta - alpha;  // omega's angle from L, towards 3 when > 0
  const Vec3 L = Vec3::UnitZ();
  // the plane of L, 3 and omega turns about L at phi_dot
  const Eigen::Matrix3d turn(Eigen::AngleAxisd(p.space_rate * t, Vec3::UnitZ()));
  const Vec3 axis3 = turn * Vec3(std::sin(theta), 0, std::cos(theta));
  const Vec3 omega = turn * Vec3(std::sin(lead), 0, std::cos(lead));

  render::Scene3D scene;
  scene.title =
      prefix +
      fmt::format("Is/I = {:.6g}, \\alpha = {:.3g}\\deg, body cone rolls {} the space cone", ratio,
                  alpha_deg, p.contact == ConeContact::kInside ? "round" : "outside");
  if (magnify > 1) scene.title += fmt::format("; angles \\times{:.3g}", magnify);
  scene.camera = cones_camera();

  const double slant = 1.0;  // both cones end on the circle omega's tip sweeps
  const char* space_name = "space cone (fixed, about L)";
  const char* body_name = "body cone (about 3, rolls)";
  // too narrow to see: omega all but along L, its path about L a point; say so
  const bool narrow = space < deg_to_rad(1.0);
  if (narrow) {
    scene.title += fmt::format("; space cone {:.3g}\\deg and \\omega's path in it, not drawn",
                               rad_to_deg(p.space_cone));
  } else {
    // The space cone as lines in L's colour: inside the body cone (an oblate body) two
    // translucent cones would blend into a colour neither swatch shows.
    const std::vector<Vec3> rim = circle_about_z(slant * std::sin(space), slant * std::cos(space));
    // Seen through the body cone (an oblate body's rolls round it), they are drawn
    // thicker and the body cone fainter.
    const bool inside = p.contact == ConeContact::kInside;
    scene.add_polyline(rim, colors::kL, inside ? 3.5 : 3.0, space_name);
    for (std::size_t k = 0; k + 1 < rim.size(); k += 10) {
      scene.add_polyline({Vec3::Zero(), rim[k]}, colors::kL, inside ? 3.0 : 2.0);
    }
  }
  scene.add_cone(Vec3::Zero(), slant * std::cos(alpha) * axis3, slant * std::sin(alpha),
                 {colors::kSymmetryAxis, p.contact == ConeContact::kInside ? 0.22f : 0.35f},
                 body_name);
  // Lines fixed in the body cone, so its rolling shows: in the turning plane the body
  // turns about 3 by -Omega' t, where Omega' sin(alpha) = phi_dot sin(space) makes the
  // drawn (magnified) cones roll without slipping; the line at pi from the plane's x
  // side lies along omega. Unmagnified, Omega' is the body's own Omega.
  const double roll = std::sin(alpha) > 0 ? p.space_rate * std::sin(space) / std::sin(alpha) : 0.0;
  const double spin = (p.body_rate >= 0 ? 1.0 : -1.0) * roll * t;
  const Eigen::Matrix3d tilt(Eigen::AngleAxisd(theta, Vec3::UnitY()));
  for (int k = 0; k < 8; ++k) {
    const double beta = kPi + 2 * kPi * k / 8 - spin;
    const Vec3 line =
        turn * tilt *
        Vec3(std::sin(alpha) * std::cos(beta), std::sin(alpha) * std::sin(beta), std::cos(alpha));
    scene.add_polyline({0.15 * slant * line, slant * line}, colors::kSymmetryAxis, 2.5);
  }
  const double r = 0.016;
  scene.add_arrow(Vec3::Zero(), 1.45 * L, r, {colors::kL}, "L (fixed in space)");
  scene.add_arrow(Vec3::Zero(), 1.45 * axis3, r, {colors::kSymmetryAxis}, "symmetry axis 3");
  scene.add_arrow(Vec3::Zero(), 1.3 * omega, r, {colors::kOmega}, "\\omega, the line of contact");
  scene.add_polyline(circle_about_z(1.45 * std::sin(theta), 1.45 * std::cos(theta)),
                     colors::kSymmetryAxis, 3.0, "path of 3 about L");
  // omega's tip goes round L on the space cone's rim, once per precession period.
  if (!narrow) {
    scene.add_polyline(circle_about_z(1.3 * std::sin(std::abs(lead)), 1.3 * std::cos(lead)),
                       colors::kOmega, 3.0, "path of \\omega about L");
  }
  scene.add_label(1.5 * L, "L", colors::kL);
  scene.add_label(1.5 * axis3, "3", colors::kSymmetryAxis);
  scene.add_label(1.35 * omega, "\\omega", colors::kOmega);
  // the cones' common apex named: the fit keeps its label in view, and so the apex off
  // the image's bottom edge
  scene.add_label(Vec3(0, 0, -0.1), "centre of mass");
  return scene;
}

// The cones of a precession, or, spun along 3, the one line of omega, L and 3.
render::Scene3D cones_scene(double ratio, double alpha_deg, const SymmetricPrecession& p,
                            const std::string& prefix, double t) {
  // there phi_dot = |L| / I = omega Is / I
  if (p.body_cone == 0.0) return aligned_scene(ratio, p.space_rate / ratio, prefix, t);
  return rolling_cones_scene(ratio, alpha_deg, p, prefix, t);
}

// Where alpha is tiny the rates do not change with it (the Earth's two flat lines): beside
// them, the rates at this alpha against the flattening |Is/I - 1| of a body of the same I,
// on log axes: |Omega| grows with it, so that the nearly round Earth wobbles once in 305
// days while it turns daily. Same lines, same legend.
void flattening_panel(render::Panel& panel, const Report& report) {
  const double sign = report.Is >= report.I ? 1.0 : -1.0;
  const double alpha = deg_to_rad(report.alpha_deg);
  std::vector<double> flattening, body, space;
  for (int k = 0; k <= 160; ++k) {
    const double e = std::pow(10.0, -5.0 + 5.0 * k / 160) * 0.99;
    const SymmetricPrecession p =
        free_symmetric_precession(report.I, report.I * (1 + sign * e), report.omega, alpha);
    flattening.push_back(e);
    body.push_back(std::abs(p.body_rate) / report.omega);
    space.push_back(p.space_rate / report.omega);
  }
  panel.x = {"flattening |Is/I - 1| at this \\alpha, log scale", render::Scale::kLog10,
             flattening.front(), flattening.back()};
  panel.y = {"rate / \\omega, log scale", render::Scale::kLog10};
  panel.add_line(flattening, space, kSpaceRateLabel).color = colors::kL;
  panel.add_line(flattening, body, kBodyRateLabel).color = colors::kSymmetryAxis;
  const double e = std::abs(report.Is / report.I - 1);
  const SymmetricPrecession& p = report.precession;
  panel
      .add_points({e, e}, {p.space_rate / report.omega, std::abs(p.body_rate) / report.omega},
                  fmt::format("this run, \\alpha = {:.3g}\\deg", report.alpha_deg))
      .color = colors::kMarker;
}

// Omega / omega and phi_dot / omega against alpha for this body. Where the two rates differ
// by more than 20 times (the Earth's 0.00327 and 1.00327), they are drawn on a log scale as
// |Omega| / omega, and where alpha is tiny (the Earth's 0.2 arcsec) against log alpha: the run's
// two points then carry their periods, which a linear plot could not show apart.
render::Plot2D rates_plot(const Report& report) {
  const SymmetricPrecession& p = report.precession;
  const double body_rate = p.body_rate / report.omega, space_rate = p.space_rate / report.omega;
  const bool log_rates = body_rate != 0.0 && (std::abs(body_rate) < space_rate / 20.0 ||
                                              std::abs(body_rate) > space_rate * 20.0);
  const bool log_alpha = report.alpha_deg > 0 && report.alpha_deg < 0.5;
  // the sweep --csv writes (rate_sweep): alpha, Omega / omega, phi_dot / omega
  std::vector<double> alpha_deg, body, space;
  for (const std::vector<double>& row : report.time_series().rows) {
    alpha_deg.push_back(row[0]);
    body.push_back(log_rates ? std::abs(row[1]) : row[1]);
    space.push_back(row[2]);
  }
  const bool flattening = log_alpha && log_rates;
  render::Plot2D plot(1, flattening ? 2 : 1);
  plot.title = fmt::format("rates against \\alpha{}, Is/I = {:.4g}",
                           flattening ? " and against the flattening" : "", report.Is / report.I);
  if (flattening) {
    flattening_panel(plot.panel(0, 1), report);
    plot.shared_legend = true;
  }
  render::Panel& panel = plot.panel();
  if (log_alpha) {
    panel.x = {"angle \\alpha between \\omega and 3 (\\deg), log scale", render::Scale::kLog10,
               alpha_deg.front(), 90};
  } else {
    panel.x = {"angle \\alpha between \\omega and 3 (\\deg)", render::Scale::kLinear, 0, 90};
  }
  panel.y = {log_rates ? "rate / \\omega, log scale" : "rate / \\omega"};
  if (log_rates) panel.y.scale = render::Scale::kLog10;
  // In the colours of the cones' axes: the turn about L (the space cone's), the turn
  // about 3 (the body cone's).
  panel.add_line(alpha_deg, space, kSpaceRateLabel).color = colors::kL;
  panel
      .add_line(
          alpha_deg, body,
          log_rates ? kBodyRateLabel : "\\Omega / \\omega, \\omega about 3 in the body (eq. 109)")
      .color = colors::kSymmetryAxis;
  const double body_point = log_rates ? std::abs(body_rate) : body_rate;
  panel
      .add_points({report.alpha_deg, report.alpha_deg}, {space_rate, body_point},
                  fmt::format("this run, \\alpha = {:.3g}\\deg", report.alpha_deg))
      .color = colors::kMarker;
  if (log_rates || log_alpha) {
    panel.annotate(report.alpha_deg, space_rate,
                   "2\\pi / \\phi-dot = " + readable_period(p.space_period));
    if (body_rate != 0.0) {
      panel.annotate(report.alpha_deg, body_point,
                     "2\\pi / |\\Omega| = " + readable_period(p.body_period));
    }
  }
  return plot;
}

}  // namespace

Motion::Motion(const Report& report)
    : ratio_(report.Is / report.I), alpha_deg_(report.alpha_deg), precession_(report.precession) {}

// Two turns of 3 about L: a precession period in each half of the animation.
double Motion::seconds() const {
  return 2.0 * precession_.space_period;
}

render::Scene3D Motion::scene(double t) const {
  return cones_scene(ratio_, alpha_deg_, precession_, "", t);
}

// The motion is exact at any time: it needs no frame times to sample.
Animation animation(const Report& report, const FrameTimes& /*frame_times*/) {
  return play(std::make_shared<const Motion>(report),
              "the body cone rolling on the space cone, omega along their line of contact",
              "cones");
}

void figures(const Report& report, FigureSink& sink) {
  const Contrast& other = report.contrast;
  // the still of the motion: the cones at t = 0
  sink.add("cones", "the body cone rolls on the space cone along omega",
           [&] { return Motion(report).scene(0.0); });
  sink.add("cones_contrast", other.caption, [&] {
    return cones_scene(other.ratio, report.alpha_deg, other.precession, other.title + ": ", 0.0);
  });
  sink.add("rates", "the precession rates against alpha (and the flattening, where alpha is tiny)",
           [&] { return rates_plot(report); });
}

}  // namespace rigid::lab::football
