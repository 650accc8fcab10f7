// poinsot's figures: the energy and momentum ellipsoids with their polhode, a
// family of polhodes with the separatrix, omega(t) with its phase plot, every
// integrator's error against the exact solution, and the herpolhode.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/free_body_scenes.h"
#include "common/integrator_plot.h"
#include "poinsot/poinsot.h"
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
  // The energy ellipsoid opaque and light, the momentum one translucent in L's colour
  // around it: the energy ellipsoid shows where it comes out of the momentum one, and
  // that edge is the polhode (a mesh of lines for the second reads as a tangle where
  // the first hides half of each line).
  scene.add_ellipsoid(Vector3d::Zero(), e.energy_semi_axes, Eigen::Matrix3d::Identity(),
                      {render::kLightGray, 1.0f, 0.15f},
                      "energy ellipsoid \\Sigma I_i\\omega_i^2 = 2T");
  scene.add_ellipsoid(Vector3d::Zero(), e.momentum_semi_axes, Eigen::Matrix3d::Identity(),
                      {colors::kL, 0.3f, 0.1f},
                      "momentum ellipsoid \\Sigma I_i^2\\omega_i^2 = L^2");
  // A steady spin has no curve: its polhode is the point omega0 itself.
  for (std::size_t k = 0; k < polhode.size(); ++k) {
    scene.add_tube(polhode[k], 0.012 * size, {colors::kPolhode}, k == 0 ? "polhode" : "");
  }
  scene.add_marker(omega0, 0.03 * size, {colors::kMarker}, "\\omega_0");
  scene.add_axes(Vector3d::Zero(), Eigen::Matrix3d::Identity(), 1.25 * size,
                 {"\\omega_1", "\\omega_2", "\\omega_3"});
  return scene;
}

// omega_1, omega_2, omega_3 against t and the phase plot of section 5.1.
render::Plot2D omega_plot(const Vector3d& omega0, const std::vector<FreeBodyRun::Sample>& samples) {
  std::vector<double> t, w[3];
  for (const auto& s : samples) {
    t.push_back(s.t);
    for (int i = 0; i < 3; ++i) w[i].push_back(s.x[i]);
  }
  render::Plot2D plot(1, 2);
  render::Panel& left = plot.panel(0, 0);
  left.title = "angular velocity in body axes";
  left.x.label = "t (s)";
  left.x.motion_time = true;
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

void figures(const Report& report, FigureSink& sink) {
  const FreeBodyExact& exact = report.exact;
  const auto curve = polhode(exact.moments(), report.omega0, 400);
  sink.add("ellipsoids", "energy and momentum ellipsoids meet on the polhode",
           [&] { return ellipsoids_scene(exact, report.omega0, curve); });
  sink.add("polhodes",
           "polhodes about the axes of the largest and smallest moments, the separatrix",
           [&] { return polhodes_scene(exact, report.omega0, curve); });
  sink.add("omega", "omega(t) of the text's ellipsoid and its phase plot",
           [&] { return omega_plot(report.omega0, report.run.samples); });
  const bool periodic = std::isfinite(exact.period());
  const std::string period_name = periodic ? "polhode periods" : "turns";
  // (a live view's first look at new inputs has not compared the methods yet)
  if (!report.comparisons.at_cost.empty()) {
    // A run that keeps T and |L| is at most omega reversed off: 2 |omega| at its largest
    // on the polhode (|omega| is not conserved; T and |L| are), over |omega0|; one that
    // drifts may pass it.
    double largest = report.omega0.norm();
    for (const auto& piece : curve)
      for (const Vector3d& w : piece) largest = std::max(largest, w.norm());
    sink.add("integrators",
             fmt::format("every integrator at the same cost ({:g} evaluations a period) over {:g} "
                         "{} against the exact solution",
                         kEqualCostEvaluations, report.comparisons.at_cost_periods, period_name),
             [&] {
               return integrators_plot(
                   method_curves(report.comparisons.at_cost),
                   fmt::format("at equal cost, {:g} evaluations a period", kEqualCostEvaluations),
                   {report.scale, period_name}, "error in \\omega",
                   "|\\omega - \\omega_{exact}| / |\\omega_0|", "|T - T_0| / T_0", kRoundoffFloor,
                   {2 * largest / report.omega0.norm(), "\\omega reversed"});
             });
  }
  if (periodic) {
    sink.add("herpolhode",
             fmt::format("Poinsot's construction seen from above: the herpolhode over {:g} "
                         "polhode periods does not close",
                         kHerpolhodePeriods),
             [&] { return Motion(report).herpolhode_scene(kHerpolhodePeriods); });
  }
}

}  // namespace rigid::lab::poinsot
