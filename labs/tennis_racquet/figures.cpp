// tennis_racquet's figures: omega against t for a spin about each principal
// axis, the growth of the disturbance on a log scale, the racquet turning over
// during one flip, and its polhodes with the separatrix.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/free_body_scenes.h"
#include "rigid/poinsot.h"
#include "rigid/units.h"
#include "tennis_racquet/tennis_racquet.h"

namespace rigid::lab::tennis_racquet {
using Eigen::Vector3d;
namespace {

const char* const kAxisWords[] = {"the handle", "in the plane", "the face's normal"};

// omega_1, omega_2, omega_3 against t for the launch about each axis (sections 4.1.1-4.1.2).
render::Plot2D omega_plot(const Report& f) {
  render::Plot2D plot(3, 1);
  plot.title =
      "\\omega in body axes for a spin about each principal axis; a stable spin's own "
      "\\omega_i less its start, to show its change";
  const int samples = 1500;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> t(samples), w[3];
    for (int n = 0; n < samples; ++n) {
      t[n] = f.t_end * n / (samples - 1);
      const Vector3d omega = f.launches[axis].omega_body(t[n]);
      for (int i = 0; i < 3; ++i) w[i].push_back(omega(i));
    }
    render::Panel& panel = plot.panel(axis, 0);
    const SpinStability& p = f.predicted[axis];
    // A stable spin keeps its axis's omega near the launch's: drawn less that, the wobble
    // of the other two (a share epsilon of it) fills the panel instead of a flat line at
    // 0 under one at omega.
    const double spin = p.unstable ? 0.0 : w[axis].front();
    // Launched exactly along its axis (no disturbance), a spin has no polhode to go
    // round: it neither flips nor wobbles, and the rate is the one a disturbance would have.
    const double period = f.launches[axis].period();
    const bool still = f.launches[axis].regime() == FreeMotionRegime::kSteady;
    std::string does;
    if (p.unstable) {
      does = still ? fmt::format("unstable, would grow at {:.4g}/s; undisturbed, it stays", p.rate)
                   : fmt::format("unstable, grows at {:.4g}/s, flips every {:.3g} s", p.rate,
                                 0.5 * period);
    } else {
      does =
          still ? fmt::format("stable, would wobble at {:.4g} rad/s; undisturbed, it stays", p.rate)
                : fmt::format("stable, wobbles at {:.4g} rad/s", p.rate);
    }
    panel.title = fmt::format("about {} ({}): {}", axis + 1, kAxisWords[axis], does);
    panel.x = {axis == 2 ? "t (s)" : "", render::Scale::kLinear, 0, f.t_end};
    panel.y.label = "\\omega_i (rad/s)";
    for (int i = 0; i < 3; ++i) {
      std::vector<double> y = w[i];
      if (i == axis) {
        for (double& v : y) v -= spin;
      }
      panel.add_line(t, y, fmt::format("\\omega_{}", i + 1)).color = colors::kPrincipal[i];
    }
    // no legend (a short panel has no room for one): each omega named at its extreme in
    // its colour, the spin's deviation at its middle
    panel.legend = render::LegendPlace::kNone;
    for (int i = 0; i < 3; ++i) {
      const std::vector<double>& y = panel.series[i].y;
      std::size_t n = y.size() / 2;
      if (i != axis || p.unstable) {
        n = static_cast<std::size_t>(
            std::max_element(y.begin(), y.end(),
                             [](double a, double b) { return std::abs(a) < std::abs(b); }) -
            y.begin());
      }
      // the spin's omega says what is taken off it (its start; the title says why)
      const std::string name = i == axis && spin != 0.0
                                   ? fmt::format("\\omega_{} \u2212 {:.6g}", i + 1, spin)
                                   : fmt::format("\\omega_{}", i + 1);
      render::Annotation& label = panel.annotate(t[n], y[n], name);
      label.color = colors::kPrincipal[i];
      label.arrow = false;
    }
  }
  return plot;
}

// The transverse share of omega about axis 2 on a log scale, with lines of the
// predicted, the measured and the text's slope through the end of the fit.
render::Plot2D growth_plot(const Report& f) {
  const FreeBodyExact& motion = f.launches[1];
  const double flip = first_sign_change(motion, 1);
  const int samples = 800;
  std::vector<double> t, share;
  for (int n = 0; n < samples; ++n) {
    t.push_back(flip * n / (samples - 1));
    share.push_back(transverse_share(motion.omega_body(t.back()), 1));
  }
  const double top = 1.6;
  // A line of slope `rate` on the log scale through (t_end, share_end) of the fit.
  const auto slope_line = [&](double rate) {
    std::vector<double> x, y;
    for (double ti : t) {
      const double v = f.growth->share_end * std::exp(rate * (ti - f.growth->t_end));
      if (v > top) break;
      x.push_back(ti);
      y.push_back(v);
    }
    return std::pair{x, y};
  };
  render::Plot2D plot;
  plot.title = "the disturbance of a spin about 2 grows exponentially";
  render::Panel& panel = plot.panel();
  panel.x = {"t (s)", render::Scale::kLinear, 0, flip};
  panel.y = {
      "transverse share |\\omega_\\perp| / |\\omega| = \\sqrt(\\omega_1^2 + \\omega_3^2) / "
      "|\\omega|",
      render::Scale::kLog10,
      0.3 * std::min(share.front(), slope_line(f.textbook_rate).second.front()), top};
  panel.add_span(f.growth->t_begin, f.growth->t_end, true, "fitted interval").color = render::kGray;
  panel.add_line(t, share, "exact motion").color = render::kBlack;
  const auto [xp, yp] = slope_line(f.predicted[1].rate);
  auto& predicted =
      panel.add_line(xp, yp, fmt::format("predicted, eqs. 86-88: {:.4g}/s", f.predicted[1].rate));
  predicted.color = render::kBlue;
  predicted.dash = render::Dash::kDashed;
  const auto [xm, ym] = slope_line(f.growth->rate);
  auto& measured = panel.add_line(xm, ym, fmt::format("measured: {:.4g}/s", f.growth->rate));
  measured.color = render::kVermillion;
  measured.dash = render::Dash::kDotted;
  measured.width = 5;
  const auto [xt, yt] = slope_line(f.textbook_rate);
  auto& text = panel.add_line(xt, yt, fmt::format("eq. 92 (\\omega_2): {:.4g}/s", f.textbook_rate));
  text.color = render::kOrange;
  text.dash = render::Dash::kDashDot;
  panel.add_ref_line(1.0, false, "\\omega all transverse: the flip");
  return plot;
}

// The racquet (ring, strings, handle) at instants of one flip, in a frame that
// keeps L vertical and turns with the handle about L, so only the turning over
// is left; body axis 2 goes from along L to against it.
render::Scene3D flip_scene(const Report& f) {
  const FreeBodyExact& motion = f.launches[1];
  const double flip = first_sign_change(motion, 1);
  const double quarter = 0.25 * motion.period();
  const double L = motion.angular_momentum_magnitude(), I2 = motion.moments().I2;
  // The angle between body axis 2 and L falls monotonically through the flip.
  const auto angle2 = [&](double t) {
    return std::acos(std::clamp(I2 * motion.omega_body(t)(1) / L, -1.0, 1.0));
  };
  const double lo = angle2(flip - quarter), hi = angle2(flip + quarter);
  const Eigen::Quaterniond to_display =
      Eigen::Quaterniond::FromTwoVectors(motion.L_space(), Vector3d::UnitZ());
  const double a = f.body.radius(), length = f.body.length();
  const double spacing_x = 1.15 * length, spacing_z = 1.35 * a * 2 + 0.6 * length;

  render::Scene3D scene;
  scene.title = fmt::format("one flip: axis 2 turns from L to -L (seen turning with {} about L)",
                            f.body.box ? "axis 1" : "the handle");
  const int columns = 3, instants = 6;
  for (int k = 0; k < instants; ++k) {
    // The instant where axis 2 makes the k-th of six angles with L.
    const double target = lo + (hi - lo) * (0.03 + 0.94 * k / (instants - 1));
    double t0 = flip - quarter, t1 = flip + quarter;
    for (int it = 0; it < 100; ++it) {
      const double mid = 0.5 * (t0 + t1);
      (angle2(mid) < target ? t0 : t1) = mid;
    }
    const double t = 0.5 * (t0 + t1);
    Eigen::Matrix3d R = (to_display * motion.attitude(t)).toRotationMatrix();
    const Vector3d handle = R.col(0);
    // Turn about L (display z) so the handle points the same way in every instant.
    const double turn = -std::atan2(handle.y(), handle.x()) + deg_to_rad(-25.0);
    R = Eigen::AngleAxisd(turn, Vector3d::UnitZ()).toRotationMatrix() * R;
    const Vector3d c((k % columns) * spacing_x, 0, -(k / columns) * spacing_z);
    const bool first = k == 0;
    add_body(scene, f.body, R, c, first);
    scene.add_arrow(c, c + 0.55 * length * Vector3d::UnitZ(), 0.03 * a, {colors::kL},
                    first ? "L, fixed in space" : "");
    scene.add_arrow(c, c + 0.4 * length * R.col(1), 0.03 * a, {colors::kPrincipal[1]},
                    first ? "body axis 2" : "");
    // the time over L's arrow, which always points up: under the racquet, axis 2 turned
    // down (late in the flip) pushed it aside, onto its neighbour's
    scene.add_label(c + 0.68 * length * Vector3d::UnitZ(), fmt::format("t = {:.3f} s", t));
    scene.add_label(c + 0.45 * length * R.col(1), fmt::format("{:.0f}\\deg", rad_to_deg(angle2(t))),
                    colors::kPrincipal[1]);
  }
  scene.camera.eye = Vector3d(0.9 * spacing_x, -4.0 * length * 3, 0.8 * length * 3);
  scene.camera.target = Vector3d(spacing_x, 0, -0.5 * spacing_z);
  scene.camera.fov_y_deg = 30;
  return scene;
}

}  // namespace

double DrawnBody::radius() const {
  if (box) return 0.5 * box->maxCoeff();
  return racquet.cm_offset > 0 ? (racquet.handle_start - racquet.head_centre).norm() : 0.0;
}

double DrawnBody::length() const {
  // a box's arrows (a share of its length) must reach out of it along any axis
  if (box) return 3.0 * box->maxCoeff();
  return (racquet.handle_end - racquet.head_centre).norm() + radius();
}

// The racquet turned by R (body to display) about its centre of mass at c: the head
// (a ring), its two faces in their colours (unshaded: each keeps its swatch's colour
// however it is turned), the handle; named in the legend if `named`. A box of given
// moments: the box, its +3 face marked in the racquet's +3 face colour.
void add_body(render::Scene3D& scene, const DrawnBody& body, const Eigen::Matrix3d& R,
              const Vector3d& c, bool named) {
  if (body.box) {
    const Vector3d h = *body.box, n3 = R.col(2);
    scene.add_box(c, h, R, {render::kGray}, named ? "the body, a box of these moments" : "");
    const double face = 0.8 * std::min(h(0), h(1));
    scene.add_disk(c + (h(2) * 1.01) * n3, n3, face, flat_body(colors::kBody, 1.0f),
                   named ? "face toward +3" : "");
    scene.add_disk(c - (h(2) * 1.01) * n3, -n3, face, flat_body(render::kYellow, 1.0f),
                   named ? "face toward -3" : "");
    return;
  }
  const Racquet& r = body.racquet;
  const double a = body.radius();
  const Vector3d head = c + R * r.head_centre, n3 = R.col(2);
  scene.add_torus(head, n3, a, 0.06 * a, {render::kGray}, named ? "the head, a ring" : "");
  scene.add_disk(head + 0.004 * a * n3, n3, 0.96 * a, flat_body(colors::kBody, 1.0f),
                 named ? "face toward +3" : "");
  scene.add_disk(head - 0.004 * a * n3, -n3, 0.96 * a, flat_body(render::kYellow, 1.0f),
                 named ? "face toward -3" : "");
  // The handle runs along body axis 1 from the rim. One shorter than a tenth of the head's
  // radius (--handle-length 1e-20) is drawn at that tenth, so it shows; its length is in
  // the table.
  const double handle = std::max((r.handle_end - r.handle_start).norm(), 0.1 * a);
  const Vector3d start = c + R * r.handle_start;
  scene.add_cylinder(start, start + handle * R.col(0), 0.05 * a, {render::kBlack},
                     named ? "the handle, axis 1" : "");
}

void figures(const Report& f, FigureSink& sink) {
  sink.add("omega", "omega(t) for a spin about each axis: only axis 2 flips",
           [&] { return omega_plot(f); });
  // A racquet that does not flip (moments equal to double precision) has neither.
  if (f.growth) {
    sink.add("growth", "the disturbance grows at the predicted rate until the flip",
             [&] { return growth_plot(f); });
    sink.add("flip", "the racquet turns over about its handle", [&] { return flip_scene(f); });
  }
  const FreeBodyExact& motion = f.launches[f.spin_axis];
  const Vector3d omega0 = motion.omega_body(0.0);
  sink.add("polhodes", "this racquet's polhode beside the separatrix",
           [&] { return polhodes_scene(motion, omega0, polhode(motion.moments(), omega0, 400)); });
}

}  // namespace rigid::lab::tennis_racquet
