// tennis_racquet's motion: the racquet of the run turning in space with L fixed
// and drawn up, omega's components in a strip below; from the closed form, or from
// the integrator that --method names.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "rigid/units.h"
#include "tennis_racquet/tennis_racquet.h"

namespace rigid::lab::tennis_racquet {
using Eigen::Vector3d;
namespace {

// The racquet in state x at time t of `motion`, L turned to display z: spun about axis 2
// it turns over and back, launched exactly along an axis it stays.
render::Scene3D spin_scene(const DrawnBody& body, const FreeBodyExact& motion, int axis, double t,
                           const RotationState& x) {
  const Eigen::Quaterniond to_display =
      Eigen::Quaterniond::FromTwoVectors(motion.L_space(), Vector3d::UnitZ());
  const Eigen::Matrix3d R = (to_display * attitude(x).normalized()).toRotationMatrix();
  const double a = body.radius(), length = body.length();
  const double I2 = motion.moments().I2, L = motion.angular_momentum_magnitude();
  const double angle2 = std::acos(std::clamp(I2 * omega_body(x)(1) / L, -1.0, 1.0));
  render::Scene3D scene;
  // launched exactly along its axis (--perturbation 0), it neither turns over nor wobbles
  const char* does = motion.regime() == FreeMotionRegime::kSteady ? "it stays"
                     : axis == 1                                  ? "it turns over and back"
                                                                  : "it wobbles";
  scene.title = fmt::format("spun about axis {}, {}: t = {:.3f} s, axis 2 at {:.0f}\\deg from L",
                            axis + 1, does, t, rad_to_deg(angle2));
  add_body(scene, body, R, Vector3d::Zero(), true);
  scene.add_arrow(Vector3d::Zero(), 0.55 * length * Vector3d::UnitZ(), 0.03 * a, {colors::kL},
                  "L, fixed in space");
  scene.add_arrow(Vector3d::Zero(), 0.45 * length * R.col(1), 0.03 * a, {colors::kPrincipal[1]},
                  "body axis 2");
  scene.camera.eye = Vector3d(2.5 * length, -3.0 * length, 1.6 * length);
  scene.camera.target = Vector3d::Zero();
  scene.camera.fov_y_deg = 30;
  return scene;
}

}  // namespace

Motion::Motion(const Report& report, const std::vector<double>& sample_times)
    : body_(report.body),
      motion_(report.launches.at(report.spin_axis)),
      axis_(report.spin_axis),
      t_end_(report.t_end) {
  // The strip's lines are the same in every frame: sampled once.
  constexpr int kSamples = 600;
  for (int n = 0; n < kSamples; ++n) {
    strip_t_.push_back(t_end_ * n / (kSamples - 1));
    const Vector3d omega = motion_.omega_body(strip_t_.back());
    for (int i = 0; i < 3; ++i) strip_omega_[i].push_back(omega(i));
  }
  if (!report.drawn_integrator) return;
  integrated_.emplace(FreeBodyProblem(motion_.moments()), motion_.state(0.0),
                      *report.drawn_integrator, free_body_words().runaway_invariants, report.run,
                      sample_times);
}

RotationState Motion::state(double t) const {
  return integrated_ ? integrated_->state(t) : motion_.state(t);
}

render::Scene3D Motion::scene(double t) const {
  return spin_scene(body_, motion_, axis_, t, state(t));
}

render::Plot2D Motion::strip(double t) const {
  render::Plot2D plot;
  render::Panel& panel = plot.panel();
  panel.x = {"t (s)", render::Scale::kLinear, 0, t_end_};
  panel.x.motion_time = true;
  panel.y.label = "\\omega_i (rad/s)";
  for (int i = 0; i < 3; ++i) {
    panel.add_line(strip_t_, strip_omega_[i], fmt::format("\\omega_{}", i + 1)).color =
        colors::kPrincipal[i];
  }
  if (!std::isnan(t)) panel.add_ref_line(t, true).color = colors::kMarker;
  // no legend: in a strip this short its box sat on the curves; each omega named in its
  // colour beside its largest swing instead, placed clear of the curves
  panel.legend = render::LegendPlace::kNone;
  for (int i = 0; i < 3; ++i) {
    const std::vector<double>& y = strip_omega_[i];
    const auto n = static_cast<std::size_t>(
        std::max_element(y.begin(), y.end(),
                         [](double a, double b) { return std::abs(a) < std::abs(b); }) -
        y.begin());
    render::Annotation& label = panel.annotate(strip_t_[n], y[n], fmt::format("\\omega_{}", i + 1));
    label.color = colors::kPrincipal[i];
    label.arrow = false;
  }
  return plot;
}

Animation animation(const Report& report, const FrameTimes& frame_times) {
  const auto motion = std::make_shared<const Motion>(
      report, report.drawn_integrator ? frame_times(report.t_end) : std::vector<double>{});
  Animation a = play(motion, "the racquet turning in space, omega's components below");
  a.strip = [motion](double t) { return motion->strip(t); };
  a.strip_share = 0.3;
  return a;
}

}  // namespace rigid::lab::tennis_racquet
