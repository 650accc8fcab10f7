// poinsot's figures: the energy and momentum ellipsoids with their polhode, a
// family of polhodes with the separatrix, omega(t) with its phase plot, and
// every integrator's error against the exact solution.
#include "figures.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/free_body_scenes.h"
#include "common/integrator_plot.h"
#include "rigid/poinsot.h"

namespace rigid::lab::poinsot {
using Eigen::Vector3d;
namespace {

// The energy and momentum ellipsoids and the polhode where they meet (section 4).
render::Scene3D ellipsoids_scene(const FreeBodyExact& motion, const Vector3d& omega0,
                                 const std::vector<std::vector<Vector3d>>& polhode) {
  const PoinsotEllipsoids e = poinsot_ellipsoids(motion.moments(), omega0);
  const double size = std::max(e.energy_semi_axes.maxCoeff(), e.momentum_semi_axes.maxCoeff());
  render::Scene3D scene;
  scene.title = "energy and momentum ellipsoids";
  frame_camera(scene, size);
  // The energy ellipsoid a light surface, the momentum one a mesh of lines in L's
  // colour: two translucent surfaces would blend into a colour neither swatch shows.
  scene.add_ellipsoid(Vector3d::Zero(), e.energy_semi_axes, Eigen::Matrix3d::Identity(),
                      {render::kLightGray, 1.0f, 0.15f},
                      "energy ellipsoid \\Sigma I_i\\omega_i^2 = 2T");
  add_ellipsoid_mesh(scene, e.momentum_semi_axes, colors::kL,
                     "momentum ellipsoid \\Sigma I_i^2\\omega_i^2 = L^2");
  // A steady spin has no curve: its polhode is the point omega0 itself.
  for (std::size_t k = 0; k < polhode.size(); ++k) {
    scene.add_tube(polhode[k], 0.012 * size, {colors::kPolhode}, k == 0 ? "polhode" : "");
  }
  scene.add_sphere(omega0, 0.03 * size, {colors::kMarker}, "\\omega_0");
  scene.add_axes(Vector3d::Zero(), Eigen::Matrix3d::Identity(), 1.25 * size,
                 {"\\omega_1", "\\omega_2", "\\omega_3"});
  return scene;
}

// omega_1, omega_2, omega_3 against t and the phase plot of section 5.1.
render::Plot2D omega_plot(const Vector3d& omega0, const std::vector<FreeBodySample>& samples) {
  std::vector<double> t, w[3];
  for (const auto& s : samples) {
    t.push_back(s.t);
    for (int i = 0; i < 3; ++i) w[i].push_back(s.omega_body(i));
  }
  render::Plot2D plot(1, 2);
  render::Panel& left = plot.panel(0, 0);
  left.title = "angular velocity in body axes";
  left.x.label = "t (s)";
  left.y.label = "\\omega_i (rad/s)";
  for (int i = 0; i < 3; ++i) {
    left.add_line(t, w[i], fmt::format("\\omega_{}", i + 1)).color = colors::kPrincipal[i];
  }
  render::Panel& right = plot.panel(0, 1);
  right.title = "phase plot";
  right.x.label = "\\omega_1 (rad/s)";
  right.y.label = "\\omega_j (rad/s)";
  right.add_line(w[0], w[1], "\\omega_2 against \\omega_1").color = colors::kPrincipal[1];
  right.add_line(w[0], w[2], "\\omega_3 against \\omega_1").color = colors::kPrincipal[2];
  right.add_points({omega0(0), omega0(0)}, {omega0(1), omega0(2)}, "t = 0").color = colors::kMarker;
  right.equal_aspect = true;
  return plot;
}

}  // namespace

void draw(FigureSet& set, const Run& run) {
  const auto curve = polhode(run.motion.moments(), run.omega0, 400);
  set.add("ellipsoids", "energy and momentum ellipsoids meet on the polhode",
          ellipsoids_scene(run.motion, run.omega0, curve));
  set.add("polhodes", "polhodes about the largest and smallest axes, the separatrix",
          polhodes_scene(run.motion, run.omega0, curve));
  set.add("omega", "omega(t) of the text's ellipsoid and its phase plot",
          omega_plot(run.omega0, run.samples));
  std::vector<MethodCurve> curves;
  for (const MethodComparison& m : run.methods) {
    curves.push_back({m.options.method, method_label(m.options),
                      m.completed && std::isfinite(m.max_omega_error), m.t, m.omega_error,
                      m.energy_error});
  }
  set.add("integrators",
          fmt::format("every integrator at the same cost ({:g} evaluations a period) over {:g} "
                      "{} against the exact solution",
                      run.evaluations_per_period, run.periods, run.period_name),
          integrators_plot(
              curves,
              fmt::format("at equal cost: {:g} evaluations a period", run.evaluations_per_period),
              {run.period, run.period_name}, "error in \\omega",
              "|\\omega - \\omega_{exact}| / |\\omega_0|", "|T - T_0| / T_0"));
}

Animation::Animation(const FreeBodyExact& motion, const Vector3d& half_extents, bool box,
                     double t_end, StateAt state_at, const std::vector<double>& path_times)
    : motion_(motion),
      half_extents_(half_extents),
      box_(box),
      state_at_(state_at ? std::move(state_at)
                         : StateAt([&motion](double t) { return motion.state(t); })) {
  const PrincipalMoments& I = motion.moments();
  const Vector3d w0 = motion.omega_body(0.0);
  const Vector3d L0 = Vector3d(I.I1, I.I2, I.I3).cwiseProduct(w0);
  // the space frame turned so that L, fixed in space, points straight down: the energy
  // ellipsoid then rests on the invariable plane like a ball on a table
  const Eigen::Matrix3d attitude0 = motion.attitude(0.0).toRotationMatrix();
  space_ =
      Eigen::Quaterniond::FromTwoVectors(attitude0 * L0, -Vector3d::UnitZ()).toRotationMatrix();
  size_ = half_extents.maxCoeff();
  const PoinsotEllipsoids e = poinsot_ellipsoids(I, w0);
  construction_scale_ = size_ / e.energy_semi_axes.maxCoeff();
  omega_scale_ = 1.7 * size_ / e.energy_semi_axes.maxCoeff();
  // omega . L / |L| = 2T / |L|: the plane's distance from the fixed point
  plane_depth_ = construction_scale_ * 2.0 * motion.energy() / motion.angular_momentum_magnitude();
  offset_ = Vector3d(3.0 * size_, 0.0, 0.0);
  polhode_ = polhode(I, w0, 240);
  // the herpolhode: the contact point over the whole motion, at `path_times` or else
  // 240 samples a polhode period
  std::vector<double> times = path_times;
  if (times.empty()) {
    const double period = std::isfinite(motion.period()) ? motion.period() : t_end;
    const int n = std::clamp(static_cast<int>(240.0 * t_end / period), 240, 20000);
    for (int k = 0; k <= n; ++k) times.push_back(t_end * k / n);
  }
  double reach = 0.0;
  for (const double t : times) {
    const FreeBodyState x = state_at_(t);
    const Eigen::Matrix3d a = space_ * attitude(x).toRotationMatrix();
    herpolhode_t_.push_back(t);
    herpolhode_.push_back(to_construction(a, omega_body(x)));
    reach = std::max(reach, (herpolhode_.back() - offset_).head<2>().norm());
  }
  plane_radius_ = std::max(1.2 * reach, 0.6 * size_);
}

Vector3d Animation::to_construction(const Eigen::Matrix3d& attitude, const Vector3d& w) const {
  return offset_ + construction_scale_ * (attitude * w);
}

render::Scene3D Animation::frame(double t) const {
  const FreeBodyState x = state_at_(t);
  const Eigen::Matrix3d a = space_ * attitude(x).toRotationMatrix();
  const Vector3d w = omega_body(x);
  render::Scene3D scene;
  scene.title = fmt::format(
      "the body turning, L fixed; its energy ellipsoid rolls on the "
      "invariable plane: t = {:.2f} s",
      t);
  // from the side and above: the plane and the herpolhode on it show, and the body
  scene.camera.eye = Vector3d(1.5 * size_, -8.0 * size_, 6.0 * size_);
  scene.camera.target = Vector3d(1.5 * size_, 0.0, -0.5 * size_);
  scene.camera.fov_y_deg = 27;
  // the body, its principal axes, L and omega
  render::Material body{colors::kBody};
  if (box_) {
    scene.add_box(Vector3d::Zero(), half_extents_, a, body, "the body");
  } else {
    scene.add_ellipsoid(Vector3d::Zero(), half_extents_, a, body, "the body");
  }
  scene.add_arrow(Vector3d::Zero(), -1.9 * size_ * Vector3d::UnitZ(), 0.035 * size_, {colors::kL},
                  "L, fixed in space");
  scene.add_arrow(Vector3d::Zero(), omega_scale_ * (a * w), 0.035 * size_, {colors::kOmega},
                  "\\omega");
  // Poinsot's construction: the energy ellipsoid turning with the body, touching the
  // invariable plane at omega, the polhode on it, the herpolhode on the plane
  const PoinsotEllipsoids e = poinsot_ellipsoids(motion_.moments(), motion_.omega_body(0.0));
  // translucent, so the polhode behind it and the herpolhode beneath it show
  scene.add_ellipsoid(offset_, construction_scale_ * e.energy_semi_axes, a,
                      {render::kLightGray, 0.55f, 0.15f}, "energy ellipsoid");
  for (std::size_t k = 0; k < polhode_.size(); ++k) {
    std::vector<Vector3d> curve;
    for (const Vector3d& p : polhode_[k]) curve.push_back(to_construction(a, 1.004 * p));
    scene.add_tube(std::move(curve), 0.012 * size_, {colors::kPolhode}, k == 0 ? "polhode" : "");
  }
  scene.add_disk(offset_ - plane_depth_ * Vector3d::UnitZ(), Vector3d::UnitZ(), plane_radius_,
                 flat_body(render::kLightGray, 0.55f), "invariable plane");
  std::vector<Vector3d> trace;
  for (std::size_t k = 0; k < herpolhode_t_.size() && herpolhode_t_[k] < t; ++k) {
    trace.push_back(herpolhode_[k]);
  }
  const Vector3d contact = to_construction(a, w);
  trace.push_back(contact);
  if (trace.size() >= 2)
    scene.add_tube(std::move(trace), 0.012 * size_, {render::kBlack}, "herpolhode");
  scene.add_arrow(offset_, contact, 0.025 * size_, {colors::kOmega});
  scene.add_sphere(contact, 0.035 * size_, {colors::kOmega});
  return scene;
}

render::Scene3D Animation::herpolhode_scene(double periods) const {
  const double T = motion_.period();
  const auto contact = [&](double t) {
    const FreeBodyState x = motion_.state(t);
    return to_construction(space_ * attitude(x).toRotationMatrix(), omega_body(x));
  };
  render::Scene3D scene;
  scene.title =
      fmt::format("the herpolhode over {:g} polhode periods on the invariable plane", periods);
  // the plane face on, from its free side (the ellipsoid rests on the other), a little
  // aslant so the ellipsoid shows as a body behind it
  scene.camera.eye = offset_ + Vector3d(0.0, -3.0 * size_, -12.0 * size_);
  scene.camera.target = offset_ - plane_depth_ * Vector3d::UnitZ();
  scene.camera.up = Vector3d::UnitY();
  scene.camera.fov_y_deg = 27;
  const int n = static_cast<int>(std::ceil(periods * 480));
  std::vector<Vector3d> trace;
  double reach = 0.0;
  for (int k = 0; k <= n; ++k) {
    trace.push_back(contact(periods * T * k / n));
    reach = std::max(reach, (trace.back() - offset_).head<2>().norm());
  }
  scene.add_disk(offset_ - plane_depth_ * Vector3d::UnitZ(), Vector3d::UnitZ(),
                 std::max(1.15 * reach, 0.6 * size_), flat_body(render::kLightGray, 0.55f),
                 "invariable plane");
  // a thin line: many loops over a few periods
  scene.add_polyline(std::move(trace), render::kBlack, 2.0, "herpolhode");
  for (int k = 0; k <= static_cast<int>(periods); ++k) {
    const Vector3d p = contact(k * T);
    scene.add_sphere(p, 0.03 * size_, {colors::kOmega},
                     k == 0 ? "the contact point at t = 0, T, 2T, .." : "");
    scene.add_label(p, k == 0 ? "0" : k == 1 ? "T" : fmt::format("{}T", k));
  }
  // the energy ellipsoid at t = 0, touching the plane at the first contact point
  const FreeBodyState x0 = motion_.state(0.0);
  const Eigen::Matrix3d a0 = space_ * attitude(x0).toRotationMatrix();
  const PoinsotEllipsoids e = poinsot_ellipsoids(motion_.moments(), motion_.omega_body(0.0));
  scene.add_ellipsoid(offset_, construction_scale_ * e.energy_semi_axes, a0,
                      {render::kLightGray, 1.0f, 0.15f},
                      "energy ellipsoid at t = 0, behind the plane");
  return scene;
}

}  // namespace rigid::lab::poinsot
