// top_nutation's figures and motion: the effective potential with E' and the
// turning points, the axis's path on the unit sphere in three regimes, theta(t)
// and phi_dot(t) exact beside integrated, the top in 3D (the first frame of its
// motion), and every integrator.
#include <fmt/format.h>

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "common/integrator_plot.h"
#include "rigid/units.h"
#include "top_nutation/top_nutation.h"

namespace rigid::lab::top_nutation {
using Eigen::Vector3d;
namespace {

// The animation's path of the symmetry axis: this many nutation periods behind the top.
constexpr int kPathPeriods = 10;

// The symmetry axis in space, R e3, from Euler angles.
Vector3d axis_of(double theta, double phi) {
  return {std::sin(theta) * std::sin(phi), -std::sin(theta) * std::cos(phi), std::cos(theta)};
}

// A circle of colatitude theta on the sphere of `radius` about centre c.
std::vector<Vector3d> circle(double theta, const Vector3d& c, double radius) {
  std::vector<Vector3d> points;
  for (int k = 0; k <= 180; ++k) points.push_back(c + radius * axis_of(theta, 2 * kPi * k / 180));
  return points;
}

// V(theta) of eq. 195 for the motion's p_phi and p_psi.
double effective_potential(const HeavyTopExact& m, double theta) {
  const HeavyTop& top = m.top();
  const double s = std::sin(theta), num = m.p_phi() - m.p_psi() * std::cos(theta);
  return num * num / (2 * top.I * s * s) + top.mgl * std::cos(theta);
}

// Where a table under the tip would catch the disk's rim, as a legend entry rather than a
// line label: the legend keeps clear of it and of the data, where a label had sat on the
// curve.
void add_table_line(render::Panel& panel, std::vector<double> x, std::vector<double> y,
                    double table) {
  render::Series& rim = panel.add_line(
      std::move(x), std::move(y), fmt::format("rim on a table, {:.4g}\\deg", rad_to_deg(table)));
  // dotted and dark: the turning angles' lines beside it are grey dashes
  rim.color = render::kBlack;
  rim.width = 3;
  rim.dash = render::Dash::kDotted;
}

// V(theta) with E' = E - Is S^2 / 2, the turning points where they meet, and the
// minimum: steady precession (the text's Figure 9.8.2, for this top).
render::Plot2D potential_plot(const HeavyTopExact& m, std::optional<double> table) {
  const HeavyTop& top = m.top();
  const double S = m.start().spin;
  const double E_prime = m.energy() - 0.5 * top.Is * S * S;
  const double lo = m.theta_min(), hi = m.theta_max();
  const double span = std::max(hi - lo, deg_to_rad(6.0));
  const double a = std::max(lo - 0.8 * span, deg_to_rad(0.2));
  const double b = std::min(hi + 0.8 * span, deg_to_rad(179.8));
  // The minimum of V: steady precession at that tilt.
  const auto [theta_steady, V_min] = boost::math::tools::brent_find_minima(
      [&](double th) { return effective_potential(m, th); }, a, b, 40);
  const double depth = std::max(E_prime - V_min, 1e-12 * (std::abs(E_prime) + top.mgl));
  const double y_top = E_prime + 1.2 * depth, y_bottom = V_min - 0.25 * depth;
  std::vector<double> x, y;
  for (int k = 0; k <= 600; ++k) {
    const double th = a + (b - a) * k / 600;
    const double v = effective_potential(m, th);
    if (v > y_top) continue;  // V climbs steeply off the drawn range
    x.push_back(rad_to_deg(th));
    y.push_back(v);
  }
  render::Plot2D plot;
  plot.title = "the effective potential V(\\theta) (eq. 195)";
  render::Panel& panel = plot.panel();
  panel.x = {"\\theta (\\deg)", render::Scale::kLinear, rad_to_deg(a), rad_to_deg(b)};
  panel.y = {"V(\\theta) and E' (J)", render::Scale::kLinear, y_bottom, y_top};
  panel.add_line(x, y, "V(\\theta)").color = render::kBlue;
  panel.add_ref_line(E_prime, false, fmt::format("E' = {:.5g} J", E_prime)).color =
      render::kVermillion;
  panel
      .add_points(
          {rad_to_deg(lo), rad_to_deg(hi)}, {E_prime, E_prime},
          fmt::format("turning points {:.4g}\\deg, {:.4g}\\deg", rad_to_deg(lo), rad_to_deg(hi)))
      .marker_size = 18;
  panel.series.back().color = render::kVermillion;
  panel
      .add_points(
          {rad_to_deg(theta_steady)}, {V_min},
          fmt::format("minimum: steady precession at {:.4g}\\deg", rad_to_deg(theta_steady)),
          render::Marker::kSquare)
      .marker_size = 18;
  panel.series.back().color = render::kBlack;
  // where a table under the tip would catch the disk's rim, if in view
  if (table && *table > a && *table < b) {
    add_table_line(panel, {rad_to_deg(*table), rad_to_deg(*table)}, {y_bottom, y_top}, *table);
  }
  return plot;
}

// The axis's path on the unit sphere: this run's (its own start), then starts of the same
// top that differ only in phi_dot0 (theta_dot0 = 0) in the regimes this run is not, each
// labelled with the regime the exact motion reports.
// This run's start beside starts of the same top in the regimes it is not in (wavy,
// cusped, looping: theta_dot0 = 0 and phi_dot0 = +-1/2 the slow steady rate, or 0),
// and the phi_dot0 of those.
struct RegimePaths {
  struct Path {
    TopStart start;
    std::string name;
  };
  std::vector<Path> paths;
  std::vector<double> contrasts;
};

RegimePaths regime_paths(const HeavyTopExact& m) {
  const HeavyTop& top = m.top();
  const TopStart& s0 = m.start();
  const SteadyPrecession steady = steady_precession_rates(top, s0.spin, s0.theta);
  const double reference = steady.exists && std::isfinite(steady.slow) && steady.slow != 0
                               ? std::abs(steady.slow)
                               : (s0.spin > 0 ? top.mgl / (top.Is * s0.spin) : 1.0);
  RegimePaths out;
  out.paths = {{s0, "this run"}};
  for (const double phi_dot0 : {0.5 * reference, 0.0, -0.5 * reference}) {
    TopStart start = s0;
    start.theta_dot = 0.0;
    start.phi_dot = phi_dot0;
    if (start.theta == 0.0) start.theta = 1e-3;  // upright: a hair off, so there is a path
    if (out.paths.size() < 3 && HeavyTopExact(top, start).regime() != m.regime()) {
      out.paths.push_back({start, fmt::format("\\phi-dot_0 = {:.3g} rad/s", phi_dot0)});
      out.contrasts.push_back(phi_dot0);
    }
  }
  // a top sleeping upright has no path: this run drawn a hair off (one through the pole
  // from upright, theta_dot0 != 0, has one, and keeps its start and its name)
  if (m.regime() == TopRegime::kSleeping) {
    out.paths.front().start.theta = 1e-3;
    out.paths.front().name =
        fmt::format("this run sleeps; {:.3g}\\deg off upright", rad_to_deg(1e-3));
  }
  return out;
}

// Over how many nutation periods the paths are drawn: enough to show the pattern repeat.
constexpr double kPathFigurePeriods = 3;

render::Scene3D paths_scene(const HeavyTopExact& m) {
  const HeavyTop& top = m.top();
  const RegimePaths regimes = regime_paths(m);
  const auto& paths = regimes.paths;
  render::Scene3D scene;
  std::string others;
  for (const double c : regimes.contrasts)
    others += fmt::format("{}{:.3g}", others.empty() ? "" : ", ", c);
  scene.title =
      fmt::format("the symmetry axis on the unit sphere: this run{}",
                  others.empty() ? std::string() : ", and \\phi-dot_0 = " + others + " rad/s");
  // Three spheres in an L, seen from above: this run's above the first other, the second
  // beside that, the legend in the free corner (in a row they left the lower part of a
  // 4:3 frame empty); fewer in a row.
  const double gap = 4.6, rise = 3.6;
  const std::vector<Vector3d> centres =
      paths.size() == 3
          ? std::vector<Vector3d>{Vector3d(0, rise, 0), Vector3d::Zero(), Vector3d(gap, 0, 0)}
          : std::vector<Vector3d>{Vector3d::Zero(), Vector3d(gap, 0, 0), Vector3d(2 * gap, 0, 0)};
  int index = 0;
  for (const RegimePaths::Path& p : paths) {
    const HeavyTopExact motion(top, p.start);
    const Vector3d c = centres[static_cast<std::size_t>(index)];
    const double period = std::isfinite(motion.nutation_period()) ? motion.nutation_period() : 1.0;
    std::vector<Vector3d> path;
    for (int k = 0; k <= 900; ++k) {
      const TopAngles a = motion.angles(kPathFigurePeriods * period * k / 900);
      path.push_back(c + 1.02 * axis_of(a.theta, a.phi));
    }
    const bool first = index == 0;
    scene.add_sphere(c, 1.0, {render::kLightGray, 0.35f, 0.1f}, first ? "unit sphere" : "");
    scene.add_tube(path, 0.022, {colors::kSymmetryAxis}, first ? "path of the symmetry axis" : "");
    // Paths and circles just outside the translucent sphere, so it does not veil them.
    scene.add_polyline(circle(motion.theta_min(), c, 1.02), render::kBlack, 2.5,
                       first ? "turning circles \\theta_{min}, \\theta_{max}" : "");
    scene.add_polyline(circle(motion.theta_max(), c, 1.02), render::kBlack, 2.5);
    scene.add_arrow(c, c + 1.25 * Vector3d::UnitZ(), 0.02, {colors::kFixedAxis},
                    first ? "vertical z" : "");
    scene.add_label(c + Vector3d(0, -1.35, 0),
                    fmt::format("{}: {}", p.name, to_string(motion.regime())));
    ++index;
  }
  // From above, 15 deg off the vertical, far off with a narrow view: the caps the axes
  // sweep face the camera, so that waves, cusps (touching the outer circle) and loops
  // differ at a glance (from the side, 35 deg above the horizon, the three looked alike),
  // and the tilt keeps the spheres round bodies with z standing out of them.
  Vector3d middle = Vector3d::Zero();
  for (std::size_t k = 0; k < paths.size(); ++k) middle += centres[k] / paths.size();
  const double tilt = deg_to_rad(15.0), distance = 26.0;
  scene.camera.eye = middle + Vector3d(0, -distance * std::sin(tilt), distance * std::cos(tilt));
  scene.camera.target = middle;
  scene.camera.up = Vector3d::UnitY();
  scene.camera.fov_y_deg = 12;
  return scene;
}

// The same paths as theta against phi, each in its own panel: the band between the turning
// circles filled, so that a fast top's waves, cusps or loops, a fraction of a degree tall
// on the sphere, show as plainly as a slow top's.
render::Plot2D band_plot(const HeavyTopExact& m) {
  const RegimePaths regimes = regime_paths(m);
  const int n = static_cast<int>(regimes.paths.size());
  render::Plot2D plot(n, 1);  // wide panels: the pattern runs along phi
  plot.title = fmt::format("the band between the turning circles, {:g} nutation periods",
                           kPathFigurePeriods);
  for (int i = 0; i < n; ++i) {
    const RegimePaths::Path& p = regimes.paths[static_cast<std::size_t>(i)];
    const HeavyTopExact motion(m.top(), p.start);
    const double period = std::isfinite(motion.nutation_period()) ? motion.nutation_period() : 1.0;
    std::vector<double> phi, theta;
    for (int k = 0; k <= 1200; ++k) {
      const TopAngles a = motion.angles(kPathFigurePeriods * period * k / 1200);
      phi.push_back(rad_to_deg(a.phi));
      theta.push_back(rad_to_deg(a.theta));
    }
    render::Panel& panel = plot.panel(i, 0);
    panel.title = fmt::format("{}: {}", p.name, to_string(motion.regime()));
    if (i == n - 1) panel.x.label = "\\phi (\\deg)";
    panel.y.label = "\\theta (\\deg)";
    panel.add_line(phi, theta, i == 0 ? "path of the symmetry axis" : "").color =
        colors::kSymmetryAxis;
    panel.add_ref_line(rad_to_deg(motion.theta_min()), false, i == 0 ? "\\theta_{min}" : "").color =
        render::kBlack;
    panel.add_ref_line(rad_to_deg(motion.theta_max()), false, i == 0 ? "\\theta_{max}" : "").color =
        render::kBlack;
    panel.legend = render::LegendPlace::kNone;
  }
  return plot;
}

// phi_dot from a state: omega_z = phi_dot + psi_dot cos(theta), omega_3 = phi_dot cos(theta) +
// psi_dot.
double phi_dot_of(const RotationState& x) {
  const Eigen::Quaterniond q = attitude(x);
  const Vector3d w = omega_body(x);
  const Vector3d axis = q * Vector3d::UnitZ();
  const double omega_z = (q * w).z(), c = axis.z();
  const double sin2 = axis.x() * axis.x() + axis.y() * axis.y();
  return sin2 > 0 ? (omega_z - w.z() * c) / sin2 : 0.0;
}

// theta(t) and phi_dot(t): the exact motion beside an integrated run, this run's or, for
// an exact run (`exact_run`), one integrated as a check on it.
// `integrated_run` null: none beside it (`why_none` goes in the title).
render::Plot2D theta_plot(const HeavyTopExact& motion, const HeavyTopRun* integrated_run,
                          bool exact_run, double t_end, const std::string& why_none,
                          std::optional<double> table) {
  std::vector<double> t, theta, phi_dot, ti, thetai, tpi, phi_doti;
  for (int k = 0; k <= 1200; ++k) {
    t.push_back(t_end * k / 1200);
    const TopAngles a = motion.angles(t.back());
    theta.push_back(rad_to_deg(a.theta));
    phi_dot.push_back(a.phi_dot);
  }
  const std::vector<HeavyTopRun::Sample> none;
  const auto& samples = integrated_run ? integrated_run->samples : none;
  const std::size_t stride = std::max<std::size_t>(1, samples.size() / 60);
  // phi_dot read from an integrated state is (omega's part across the axis) / sin(theta):
  // at a sample a hair from a pole the axis goes through, its rounding over that sine is
  // all there is (-2e12 rad/s beside the exact 14.7). Such samples show theta, not phi_dot.
  double sin_max = 0.0;
  for (std::size_t i = 0; i < samples.size(); i += stride) {
    sin_max = std::max(sin_max, std::sin(tilt_of(attitude(samples[i].x))));
  }
  for (std::size_t i = 0; i < samples.size(); i += stride) {
    const HeavyTopRun::Sample& s = samples[i];
    const double tilt = tilt_of(attitude(s.x));
    ti.push_back(s.t);
    thetai.push_back(rad_to_deg(tilt));
    if (std::sin(tilt) < 1e-3 * sin_max) continue;
    tpi.push_back(s.t);
    phi_doti.push_back(phi_dot_of(s.x));
  }
  // an exact run's figure integrates beside it as a check, and says so
  const std::string integrated =
      !integrated_run ? ""
      : exact_run     ? std::string(method_name(integrated_run->method)) + ", a check on it"
                      : std::string(method_name(integrated_run->method)) + ", this run";
  render::Plot2D plot(2, 1);
  plot.title = integrated_run ? "nutation and precession"
                              : "nutation and precession, exact (" + why_none + ")";
  render::Panel& top = plot.panel(0, 0);
  top.y.label = "\\theta (\\deg)";
  top.add_line(t, theta, "exact").color = render::kBlue;
  if (integrated_run) top.add_points(ti, thetai, integrated).color = render::kVermillion;
  top.add_ref_line(rad_to_deg(motion.theta_min()), false, "\\theta_{min}");
  top.add_ref_line(rad_to_deg(motion.theta_max()), false, "\\theta_{max}");
  // the tilt where a table under the tip would catch the rim, where the axis goes past it
  if (table && *table > motion.theta_min() && *table < motion.theta_max()) {
    add_table_line(top, {0.0, t_end}, {rad_to_deg(*table), rad_to_deg(*table)}, *table);
  }
  render::Panel& bottom = plot.panel(1, 0);
  bottom.x.label = "t (s)";
  top.x.motion_time = bottom.x.motion_time = true;
  bottom.y.label = "\\phi-dot (rad/s)";
  bottom.add_line(t, phi_dot, "exact").color = render::kBlue;
  if (integrated_run) bottom.add_points(tpi, phi_doti, integrated).color = render::kVermillion;
  // the unit is the axis's: a short label finds a gap between the curve's crossings
  // only a mean there is: none through a pole (two limits), none below its roundoff
  if (motion.mean_precession_defined() &&
      std::abs(motion.mean_precession_rate()) > motion.mean_precession_error()) {
    bottom.add_ref_line(motion.mean_precession_rate(), false,
                        fmt::format("mean {:.4g}", motion.mean_precession_rate()));
  }
  bottom.legend = render::LegendPlace::kNone;
  return plot;
}

}  // namespace

void figures(const Report& report, FigureSink& sink) {
  const HeavyTopExact& motion = *report.motion;
  sink.add("potential", "the effective potential, E' and the turning points",
           [&] { return potential_plot(motion, report.table_theta); });
  sink.add("paths", "the axis's path on the sphere: this run's beside the other regimes",
           [&] { return paths_scene(motion); });
  sink.add("band", "the same paths as theta against phi: waves, cusps or loops at any spin",
           [&] { return band_plot(motion); });
  sink.add("theta", "theta(t) and phi_dot(t), exact beside integrated", [&] {
    // Beside the exact motion, an integrated one: the lab's own, or splitting4 at the
    // run's step, unless that would take more work than a run may (--periods 1e8, --step
    // 1e-20: the exact run is valid, and the figure says why it stands alone).
    HeavyTopRun splitting4;
    const HeavyTopRun* integrated = &report.run;
    std::string why_none;
    if (report.method == "exact") {
      OdeOptions o = report.options;
      o.method = Method::kSplitting4;
      o.max_evaluations = max_run_evaluations(o.method);
      o.max_steps = o.max_evaluations / static_cast<std::size_t>(evaluations_per_step(o.method));
      const double steps = std::ceil(report.t_end / o.step);
      if (steps <= static_cast<double>(o.max_steps)) {
        splitting4 = integrate(HeavyTopProblem(report.top), heavy_top_state(motion.angles(0.0)),
                               sample_times(report.t_end, report.scale, o.step), o);
        integrated = &splitting4;
      } else {
        integrated = nullptr;
        why_none =
            fmt::format("splitting4 at step {:.3g} s would need {:.3g} steps", o.step, steps);
      }
    }
    return theta_plot(motion, integrated, report.method == "exact", report.t_end, why_none,
                      report.table_theta);
  });
  sink.add("top", "the top, L, the gravity torque and the precession circle",
           [&] { return Motion(report).scene(0.0); });
  // A sleeping top has no comparison at equal cost: the one at the lab's settings.
  const MethodComparisons& compared = report.comparisons;
  const bool equal_cost = !compared.at_cost.empty();
  // (a live view's first look at new inputs has not compared the methods yet)
  if (compared.at_settings.empty() && !equal_cost) return;
  const double evaluations = kEqualCostEvaluations;
  sink.add("integrators",
           equal_cost ? fmt::format("every integrator at the same cost ({:g} evaluations a "
                                    "nutation period) over {:g} periods against the exact theta",
                                    evaluations, compared.at_cost_periods)
                      : "every integrator against the exact theta",
           [&] {
             return integrators_plot(
                 method_curves(equal_cost ? compared.at_cost : compared.at_settings, rad_to_deg),
                 equal_cost ? fmt::format("at equal cost, {:g} evaluations a period", evaluations)
                            : "integrators against the exact solution",
                 equal_cost ? TimeAxis{motion.nutation_period(), "nutation periods"} : TimeAxis{},
                 "error in \\theta", "|\\theta - \\theta_{exact}| (\\deg)",
                 "|E - E_0| / (T_0 + mgl)",
                 // theta's roundoff: kRoundoffFloor of a radian, in degrees
                 rad_to_deg(kRoundoffFloor),
                 // a run half a nutation out of step is off by the band's whole width
                 {rad_to_deg(motion.theta_max() - motion.theta_min()),
                  "\\theta_{max} - \\theta_{min}: half a nutation out of step"});
           });
}

// ---- The motion --------------------------------------------------------------

Motion::Motion(const Report& report, const std::vector<double>& sample_times)
    : exact_(*report.motion),
      arm_(report.arm),
      disk_radius_(report.disk_radius),
      seconds_(report.t_end) {
  if (report.method == "exact") return;
  // held to every invariant, as the lab's own run is
  integrated_.emplace(HeavyTopProblem(exact_.top()), heavy_top_state(exact_.angles(0.0)),
                      report.options, HeavyTopProblem::kInvariantCount, report.run.samples,
                      sample_times);
  path_times_ = sample_times.empty() ? report.run.times() : integrated_->sampled_times();
}

std::vector<Vector3d> Motion::axis_path(double from, double t) const {
  const double T = exact_.nutation_period();
  std::vector<Vector3d> path;
  const auto axis_at = [&](double s) { return Vector3d(state(s).attitude * Vector3d::UnitZ()); };
  if (!path_times_.empty() || !std::isfinite(T)) {
    std::vector<double> when;
    for (const double s : path_times_) {
      if (s >= from && s < t) when.push_back(s);
    }
    // (no nutation to count by: the run's span in two points)
    if (path_times_.empty()) when.push_back(from);
    for (const double s : when) path.push_back(axis_at(s));
  } else {
    // the closed form on one grid, 400 points a nutation period, whatever t is
    const double h = T / 400;
    for (auto k = static_cast<std::int64_t>(std::ceil(from / h)); k * h < t; ++k) {
      path.push_back(exact_axis(k));
    }
  }
  path.push_back(axis_at(t));
  return path;
}

Vector3d Motion::exact_axis(std::int64_t k) const {
  const std::lock_guard<std::mutex> hold(axis_mutex_);
  // a long run's older loops are not drawn again: forgotten past a few paths' worth
  if (axis_.size() > 16 * 400 * kPathPeriods) axis_.clear();
  const auto [at, made] = axis_.try_emplace(k);
  if (made) {
    const TopAngles a = exact_.angles(static_cast<double>(k) * (exact_.nutation_period() / 400));
    at->second = euler_attitude(a.phi, a.theta, a.psi) * Vector3d::UnitZ();
  }
  return at->second;
}

BodyState Motion::state(double t) const {
  if (!integrated_) {
    if (!(t >= 0.0)) refuse_before_start(t);
    const TopAngles a = exact_.angles(t);
    return {euler_attitude(a.phi, a.theta, a.psi), exact_.omega_body(a)};
  }
  const RotationState x = integrated_->state(t);
  return {attitude(x), omega_body(x)};
}

render::Scene3D Motion::scene(double t) const {
  const BodyState now = state(t);
  const Eigen::Quaterniond q = now.attitude;
  const Vector3d e3 = q * Vector3d::UnitZ();
  const double l = arm_, size = std::max(l + disk_radius_, 2 * disk_radius_);
  // A disk below 2% of the picture (--disk-radius 1e-20, --arm 1e20) is drawn at 2%: it
  // would not show, nor would l +- its thickness differ in doubles. The title says so.
  const double r = std::max(disk_radius_, 0.02 * size);
  const Vector3d omega = q * now.omega_body;
  const HeavyTop& top = exact_.top();
  const Vector3d L_body = Vector3d(top.I, top.I, top.Is).cwiseProduct(now.omega_body);
  const Vector3d L = q * L_body;
  const Vector3d torque = -top.mgl * e3.cross(Vector3d::UnitZ());
  render::Scene3D scene;
  scene.title = t > 0 ? fmt::format("the top at t = {:.3f} s; arrows show directions", t)
                      : "the top at t = 0; arrows show directions";
  if (r > disk_radius_) scene.title += " (disk enlarged to be seen)";
  scene.add_marker(Vector3d::Zero(), 0.06 * size, {render::kGray}, "tip (pivot)");
  scene.add_cylinder(Vector3d::Zero(), (l + 0.5 * r) * e3, 0.03 * size, {render::kGray});
  // The disk translucent, so the tip, the spindle and the circle below stay in view.
  scene.add_cylinder(l * e3 - 0.05 * r * e3, l * e3 + 0.05 * r * e3, r, {colors::kBody, 0.5f},
                     "disk");
  // two spokes fixed in the disk, so its spin shows as it turns
  for (const Vector3d& spoke : {Vector3d(q * Vector3d::UnitX()), Vector3d(q * Vector3d::UnitY())}) {
    scene.add_polyline({l * e3 - 0.95 * r * spoke, l * e3 + 0.95 * r * spoke}, render::kBlack, 2.5);
  }
  // the symmetry axis drawn on past the disk, and the path of its end on a sphere
  // clear of the disk so far (none at t = 0): the nodding and the precession
  const double reach = 1.3 * size;
  scene.add_polyline({(l + 0.5 * r) * e3, reach * e3}, colors::kSymmetryAxis, 2.0);
  if (t > 0) {
    // the last kPathPeriods nutation periods of it: over a long run the older loops only
    // fill the band between the turning circles, and a frame's cost stays bounded
    const double T = exact_.nutation_period();
    const double from = std::isfinite(T) ? std::max(0.0, t - kPathPeriods * T) : 0.0;
    std::vector<Vector3d> path = axis_path(from, t);
    for (Vector3d& p : path) p *= reach;
    // one short name for the whole film (its frames share one legend, and a long entry
    // would narrow the scene of a small one)
    scene.add_polyline(std::move(path), colors::kSymmetryAxis, 3.0, "path of the symmetry axis");
  }
  const double arrow = 1.6 * size;
  if (L.norm() > 0) {
    scene.add_arrow(Vector3d::Zero(), arrow * L.normalized(), 0.025 * size, {colors::kL}, "L");
  }
  if (torque.norm() > 0) {
    scene.add_arrow(l * e3, l * e3 + 0.8 * arrow * torque.normalized(), 0.025 * size,
                    {colors::kTorque}, "gravity torque");
  }
  if (omega.norm() > 0) {
    scene.add_arrow(Vector3d::Zero(), 1.2 * arrow * omega.normalized(), 0.018 * size,
                    {colors::kOmega}, "\\omega");
  }
  // A fast top's L and omega lie almost along one line: each head named, beside it.
  const Vector3d side = Vector3d::UnitZ().cross(e3).normalized().isZero()
                            ? Vector3d::UnitX()
                            : Vector3d::UnitZ().cross(e3).normalized();
  if (L.norm() > 0) scene.add_label(arrow * L.normalized() + 0.12 * size * side, "L", colors::kL);
  if (omega.norm() > 0) {
    scene.add_label(1.2 * arrow * omega.normalized() + 0.12 * size * side, "\\omega",
                    colors::kOmega);
  }
  // The circle the axis's end goes round at this tilt: out there, clear of the disk that
  // hides the centre of mass's own (smaller than the disk), and black beside its path.
  scene.add_polyline(circle(std::acos(std::clamp(e3.z(), -1.0, 1.0)), Vector3d::Zero(), reach),
                     render::kBlack, 2.5, "precession circle at this \\theta");
  scene.add_axes(Vector3d::Zero(), Eigen::Matrix3d::Identity(), 1.4 * size, {"x", "y", "z"});
  scene.camera.eye = size * Vector3d(4.0, -6.5, 1.2);
  scene.camera.target = Vector3d(0, 0, 0.4 * size);
  return scene;
}

Animation animation(const Report& report, const FrameTimes& frame_times) {
  // Shared, not copied, by every copy of the scene function.
  const auto motion = std::make_shared<const Motion>(
      report, report.method == "exact" ? std::vector<double>{} : frame_times(report.t_end));
  return play(motion, "the top precessing and nodding; the path of its axis on the sphere", "top");
}

}  // namespace rigid::lab::top_nutation
