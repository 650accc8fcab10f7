// top_nutation: sections 8, 8.1 and 9 of the chapter, the heavy symmetric top, as a library.
// A top spins on a fixed tip; gravity's torque turns its axis about the
// vertical (precession) while the axis nods between two circles (nutation).
// The spin S and p_phi = L_z are conserved, and with the energy they reduce the
// motion to one coordinate in the effective potential V(theta) (eq. 195); the
// nodding follows exactly from a cubic and Jacobi's elliptic functions, and
// every integrator is measured against it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "common/figures.h"
#include "common/inputs.h"
#include "common/integrated_motion.h"
#include "common/integrated_run.h"
#include "common/program.h"
#include "common/report.h"
#include "rigid/heavy_top.h"
#include "rigid/heavy_top_integrate.h"

namespace rigid::lab::top_nutation {

/// The lab's inputs, with the text's top (section 8.1): a 2.00 kg disk of radius
/// 5.0 cm, 4.0 cm above the tip, spinning at 500 rpm, released at 30 deg.
struct Inputs {
  double mass = 2.0;
  double arm = 0.04;
  double disk_radius = 0.05;
  std::optional<Eigen::Vector2d> inertia;  ///< (I, Is) about the tip; else the disk's
  double g = 9.8;
  std::optional<double> spin;  ///< rad/s; else spin_rpm
  double spin_rpm = 500.0;
  double theta0_deg = 30.0;
  double thetadot0 = 0.0;
  double phidot0 = 0.0;
  std::optional<double> t_end;    ///< s; else three nutation periods
  std::optional<double> periods;  ///< t_end as a number of nutation periods
  IntegrationInputs integration;  ///< "exact" by default; step: nutation period / 2000
};

/// What the lab reports, and what its figures and its motion draw.
struct Report : lab::Report {
  using lab::Report::Report;
  HeavyTop top;
  /// The exact motion from the inputs' start (always set by compute()).
  std::optional<HeavyTopExact> motion;
  double arm = 0.0, disk_radius = 0.0;  ///< for drawing the top, m
  /// Where the disk's rim would touch a table under the tip, l cos theta = r sin theta
  /// (rad); none for moments given without a disk.
  std::optional<double> table_theta;
  std::string method;  ///< "exact" or the integrator's name
  OdeOptions options;  ///< the chosen method's settings
  bool fixed = false;  ///< the method takes a fixed step
  HeavyTopRun run;     ///< the lab's run: exact, or the chosen integrator
  /// Every integrator at the lab's settings and at the same cost, kEqualCostEvaluations
  /// a nutation period (none at equal cost for a top with no nutation to count by).
  MethodComparisons comparisons;
  double t_end = 0.0;  ///< s
  double scale = 0.0;  ///< the nutation period (or a turn of the spin), s
};

/// The inputs' rules: options, widgets and compute()'s checks.
const InputTable<Inputs>& input_table();
/// Everything the lab reports. Throws InputError naming a broken input.
Report compute(const Inputs& in);
/// The effective potential with E' and the turning points, the axis's path on the
/// sphere in three regimes, theta(t) and phi_dot(t) exact beside integrated (an
/// extra splitting4 run when the method is exact), the top, and every integrator.
void figures(const Report& report, FigureSink& sink);

/// The top moving: its disk (with spokes, so its spin shows), L, the gravity torque,
/// omega, the centre of mass's circle at the current tilt, and the path of the
/// symmetry axis's end.
class Motion {
 public:
  /// `sample_times`: times at which an integrated motion is sampled ahead in one run from
  /// the start (the animation's frame times; IntegratedMotion), so each frame is what
  /// that one run gives there, never a step of another. Exact: the closed form at any t.
  /// The same t gives the same scene in any order (the exact path's points, kept as they
  /// are made, are the same whenever made).
  explicit Motion(const Report& report, const std::vector<double>& sample_times = {});
  /// The span of the motion shown: the lab's t_end, s.
  double seconds() const { return seconds_; }
  /// The top at time t >= 0 (s), with the path of its axis since t = 0, the last 10
  /// nutation periods of it: integrated, through sample_times (else the run's samples)
  /// up to t; exact, 400 points a nutation period. scene(0) is the "top" figure.
  render::Scene3D scene(double t) const;
  /// The top at time t >= 0: the closed form, or the integrated run's state.
  BodyState state(double t) const;

 private:
  HeavyTopExact exact_;
  double arm_, disk_radius_, seconds_;
  std::optional<IntegratedMotion<HeavyTopProblem>> integrated_;  ///< none: the closed form
  std::vector<double> path_times_;  ///< integrated: the times the axis's path runs through
  // The exact axis's end at the path's grid times k T / 400 (T the nutation period),
  // each computed once: a live view fitting its camera to sixteen frames, and frames
  // played in turn, share most of their paths' points (each an elliptic integral).
  Eigen::Vector3d exact_axis(std::int64_t k) const;
  // The axis's end (a unit vector) through [from, t]: the run's own samples, or the
  // closed form on its grid (exact_axis), and at t.
  std::vector<Eigen::Vector3d> axis_path(double from, double t) const;
  mutable std::mutex axis_mutex_;
  mutable std::unordered_map<std::int64_t, Eigen::Vector3d> axis_;
};

/// The top precessing and nodding, the path of its axis on the sphere; its frames
/// at `frame_times` come from the integrator sampled there (never at its steps).
Animation animation(const Report& report, const FrameTimes& frame_times);

/// The lab as one program.
LabProgram<Inputs, Report> program();

}  // namespace rigid::lab::top_nutation
