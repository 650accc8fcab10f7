// poinsot's motion: the body turning with L fixed beside Poinsot's construction,
// at any time, from the closed form or from the lab's integrator.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "poinsot/poinsot.h"
#include "rigid/poinsot.h"

namespace rigid::lab::poinsot {
using Eigen::Vector3d;

Motion::Motion(const Report& report, const std::vector<double>& sample_times)
    : exact_(report.exact), half_extents_(report.extents), box_(report.box), t_end_(report.t_end) {
  const PrincipalMoments& I = exact_.moments();
  const Vector3d w0 = exact_.omega_body(0.0);
  const Vector3d L0 = Vector3d(I.I1, I.I2, I.I3).cwiseProduct(w0);
  // the space frame turned so that L, fixed in space, points straight down: the energy
  // ellipsoid then rests on the invariable plane like a ball on a table
  const Eigen::Matrix3d attitude0 = exact_.attitude(0.0).toRotationMatrix();
  space_ =
      Eigen::Quaterniond::FromTwoVectors(attitude0 * L0, -Vector3d::UnitZ()).toRotationMatrix();
  size_ = half_extents_.maxCoeff();
  const PoinsotEllipsoids e = poinsot_ellipsoids(I, w0);
  construction_scale_ = size_ / e.energy_semi_axes.maxCoeff();
  omega_scale_ = 1.7 * size_ / e.energy_semi_axes.maxCoeff();
  // omega . L / |L| = 2T / |L|: the plane's distance from the fixed point
  plane_depth_ = construction_scale_ * 2.0 * exact_.energy() / exact_.angular_momentum_magnitude();
  offset_ = Vector3d(3.0 * size_, 0.0, 0.0);
  polhode_ = polhode(I, w0, 240);
  // the herpolhode: the contact point over the whole motion, at the integrator's own
  // times, or else 240 samples a polhode period of the closed form
  std::vector<double> times;
  if (report.method != "exact") {
    integrated_.emplace(FreeBodyProblem(I), exact_.state(0.0), report.options,
                        free_body_words().runaway_invariants, report.run.samples, sample_times);
    times = sample_times.empty() ? report.run.times() : integrated_->sampled_times();
  } else {
    const double period = std::isfinite(exact_.period()) ? exact_.period() : t_end_;
    const int n = std::clamp(static_cast<int>(240.0 * t_end_ / period), 240, 20000);
    for (int k = 0; k <= n; ++k) times.push_back(t_end_ * k / n);
  }
  double reach = 0.0;
  for (const double t : times) {
    const RotationState x = state(t);
    const Eigen::Matrix3d a = space_ * attitude(x).toRotationMatrix();
    herpolhode_t_.push_back(t);
    herpolhode_.push_back(to_construction(a, omega_body(x)));
    reach = std::max(reach, (herpolhode_.back() - offset_).head<2>().norm());
  }
  plane_radius_ = std::max(1.2 * reach, 0.6 * size_);
}

RotationState Motion::state(double t) const {
  return integrated_ ? integrated_->state(t) : exact_.state(t);
}

Vector3d Motion::to_construction(const Eigen::Matrix3d& attitude, const Vector3d& w) const {
  return offset_ + construction_scale_ * (attitude * w);
}

render::Scene3D Motion::scene(double t) const {
  const RotationState x = state(t);
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
  // omega and the polhode it traces share a colour, so they share one legend entry
  const char* omega_name = "\\omega, and its path in the body: the polhode";
  scene.add_arrow(Vector3d::Zero(), omega_scale_ * (a * w), 0.035 * size_, {colors::kOmega},
                  omega_name);
  // Poinsot's construction: the energy ellipsoid turning with the body, touching the
  // invariable plane at omega, the polhode on it, the herpolhode on the plane
  const PoinsotEllipsoids e = poinsot_ellipsoids(exact_.moments(), exact_.omega_body(0.0));
  // translucent, so the polhode behind it and the herpolhode beneath it show
  scene.add_ellipsoid(offset_, construction_scale_ * e.energy_semi_axes, a,
                      {render::kLightGray, 0.55f, 0.15f}, "energy ellipsoid");
  for (std::size_t k = 0; k < polhode_.size(); ++k) {
    std::vector<Vector3d> curve;
    for (const Vector3d& p : polhode_[k]) curve.push_back(to_construction(a, 1.004 * p));
    scene.add_tube(std::move(curve), 0.012 * size_, {colors::kPolhode}, k == 0 ? omega_name : "");
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
  scene.add_marker(contact, 0.035 * size_, {colors::kOmega});
  return scene;
}

namespace {

// The contact points at t = 0, tau, 2 tau, .. (tau the polhode period: T is the kinetic
// energy), each with its time outside the herpolhode's ring of radius `ring` about
// `centre`, along the ray from the centre through the point: clear of the loops, and in
// the order the points go round; the label at its leader's end, a ray near an earlier
// one's taking its label farther out.
void add_contact_points(render::Scene3D& scene, const std::vector<Vector3d>& points,
                        const Vector3d& centre, double ring, double size) {
  // markers no larger than two fifths of the nearest two's distance, so that points close
  // together (a book spun near its middle axis) stay apart, and not below a third of
  // their usual size, so that they show
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      nearest = std::min(nearest, (points[i] - points[j]).norm());
  const double marker = std::clamp(nearest / 2.5, 0.01 * size, 0.03 * size);
  std::vector<Vector3d> rays;
  std::vector<int> levels;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vector3d& p = points[k];
    scene.add_marker(p, marker, {colors::kOmega},
                     k == 0 ? "the contact point at t = 0, \\tau, 2\\tau, .. (\\tau: the polhode "
                              "period)"
                            : "");
    Vector3d out = p - centre;
    out.z() = 0;
    out = out.norm() > 1e-6 * ring ? out.normalized() : Vector3d::UnitX();
    // the first level no ray within 40 degrees holds
    int level = 0;
    for (bool clash = true; clash; ++level) {
      clash = false;
      for (std::size_t j = 0; j < rays.size(); ++j)
        clash = clash || (levels[j] == level && out.dot(rays[j]) > std::cos(0.7));
      if (!clash) break;
    }
    rays.push_back(out);
    levels.push_back(level);
    const double reach = ring + (0.1 + 0.15 * level) * size;
    const Vector3d lift(0, 0, p.z() - centre.z());
    render::Label3D label{centre + (reach + 0.05 * size) * out + lift,
                          k == 0   ? "0"
                          : k == 1 ? "\\tau"
                                   : fmt::format("{}\\tau", k)};
    label.pinned = true;
    scene.add_label(std::move(label));
    scene.add_polyline({p, centre + reach * out + lift}, colors::kOmega, 1.5);
  }
}

}  // namespace

render::Scene3D Motion::herpolhode_scene(double periods) const {
  const double T = exact_.period();
  const auto contact = [&](double t) {
    const RotationState x = exact_.state(t);
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
  const int count = static_cast<int>(periods) + 1;
  std::vector<Vector3d> points;
  for (int k = 0; k < count; ++k) points.push_back(contact(k * T));
  add_contact_points(scene, points, offset_, std::max(reach, 1e-9 * size_), size_);
  // the energy ellipsoid at t = 0, touching the plane at the first contact point
  const RotationState x0 = exact_.state(0.0);
  const Eigen::Matrix3d a0 = space_ * attitude(x0).toRotationMatrix();
  const PoinsotEllipsoids e = poinsot_ellipsoids(exact_.moments(), exact_.omega_body(0.0));
  scene.add_ellipsoid(offset_, construction_scale_ * e.energy_semi_axes, a0,
                      {render::kLightGray, 1.0f, 0.15f},
                      "energy ellipsoid at t = 0, behind the plane");
  return scene;
}

Animation animation(const Report& report, const FrameTimes& frame_times) {
  // The closed form needs no samples ahead; an integrator is sampled at exactly the
  // frames' times, in one run.
  const auto motion = std::make_shared<const Motion>(
      report, report.method == "exact" ? std::vector<double>{} : frame_times(report.t_end));
  return play(motion,
              "the body turning with L fixed, and its energy ellipsoid rolling on the invariable "
              "plane: polhode and herpolhode");
}

}  // namespace rigid::lab::poinsot
