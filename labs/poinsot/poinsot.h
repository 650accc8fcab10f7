// poinsot: sections 4, 4.1 and 5.1 of the chapter, as a library. A free body
// turns with no torque: omega moves on the energy and the momentum ellipsoids at
// once, along their intersection, the polhode. For the text's solid ellipsoid
// x^2/9 + y^2/4 + z^2 = 1 (I = pi, 2 pi, 8.168) started at omega = (1, 1, 1),
// omega(t) follows in closed form from Jacobi's elliptic functions; every
// integrator is measured against it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/figures.h"
#include "common/free_motion.h"
#include "common/inputs.h"
#include "common/integrated_motion.h"
#include "common/integrated_run.h"
#include "common/program.h"
#include "common/report.h"
#include "rigid/free_body_exact.h"
#include "rigid/free_body_integrate.h"
#include "rigid/units.h"

namespace rigid::lab::poinsot {

/// The lab's inputs, with the text's defaults (section 5.1: the solid ellipsoid
/// x^2/9 + y^2/4 + z^2 = 1 of mass pi, started at omega = (1, 1, 1)).
struct Inputs {
  std::optional<Eigen::Vector3d> inertia;  ///< principal moments, instead of a body
  Eigen::Vector3d ellipsoid{3, 2, 1};      ///< semi-axes A, B, C
  std::optional<Eigen::Vector3d> box;      ///< side lengths, instead of the ellipsoid
  double mass = kPi;
  Eigen::Vector3d omega0{1, 1, 1};
  std::optional<double> t_end;    ///< s; neither this nor periods: three polhode periods
  std::optional<double> periods;  ///< t_end as a number of polhode periods
  IntegrationInputs integration;  ///< "exact" by default; step: period / 2000
};

/// The herpolhode figure: enough polhode periods for its failure to close to show.
inline constexpr double kHerpolhodePeriods = 6.0;

/// What the lab reports, and what its figures and its motion draw.
struct Report : lab::Report {
  using lab::Report::Report;
  /// The closed form from omega0 (compute() replaces this placeholder).
  FreeBodyExact exact{PrincipalMoments{}, Eigen::Vector3d::UnitZ()};
  Eigen::Vector3d omega0 = Eigen::Vector3d::Zero();
  /// The body as drawn: a solid ellipsoid's semi-axes, or a box's half sides if `box`.
  Eigen::Vector3d extents = Eigen::Vector3d::Ones();
  bool box = false;
  double scale = 0.0;  ///< the time scale: the polhode period, or one turn, s
  double t_end = 0.0;  ///< s
  std::string method = "exact";
  OdeOptions options;  ///< the chosen method's, as the run used them
  FreeBodyRun run;     ///< the lab's own run (the closed form sampled, for "exact")
  /// Every method at the lab's settings and at kEqualCostEvaluations a polhode period.
  MethodComparisons comparisons;
};

/// The inputs' rules: options, widgets and compute()'s checks.
const InputTable<Inputs>& input_table();
/// Everything the lab reports. Throws InputError naming a broken input.
Report compute(const Inputs& in);
/// The energy and momentum ellipsoids with their polhode, a family of polhodes with
/// the separatrix, omega(t) with its phase plot, every integrator's error against the
/// exact solution, and the herpolhode that does not close.
void figures(const Report& report, FigureSink& sink);

/// The body's motion: the scene at any time t, in any order, cheaply. The body
/// turning in space with L fixed (drawn pointing down), and beside it Poinsot's
/// construction: the body's energy ellipsoid rolling without slipping on the
/// invariable plane, the polhode on the ellipsoid and the herpolhode traced on the
/// plane so far. Lengths of the construction (rad/s) are scaled to the body's size.
class Motion {
 public:
  /// `sample_times`: times at which an integrated motion is sampled ahead in one run (the
  /// animation's frame times; IntegratedMotion), so those frames come from one run from
  /// t = 0, not from restarts. Exact method: the closed form at any t. Nothing mutable:
  /// the same t gives the same scene in any order.
  explicit Motion(const Report& report, const std::vector<double>& sample_times = {});
  /// The span of the motion, t_end.
  double seconds() const { return t_end_; }
  /// The scene at time t >= 0 of the motion.
  render::Scene3D scene(double t) const;
  /// The construction alone, seen from above: the herpolhode over `periods` polhode
  /// periods on the invariable plane with the contact point at each whole period
  /// (they do not coincide), and the energy ellipsoid touching the plane at t = 0.
  render::Scene3D herpolhode_scene(double periods) const;

 private:
  /// The state at t: the closed form's, or the integrated motion's.
  RotationState state(double t) const;
  Eigen::Vector3d to_construction(const Eigen::Matrix3d& attitude, const Eigen::Vector3d& w) const;
  FreeBodyExact exact_;
  Eigen::Vector3d half_extents_;
  bool box_;
  double t_end_;
  std::optional<IntegratedMotion<FreeBodyProblem>> integrated_;  ///< none: the closed form
  Eigen::Matrix3d space_;  ///< the motion's space frame turned so that L points down
  double size_, omega_scale_, construction_scale_, plane_depth_, plane_radius_;
  Eigen::Vector3d offset_;                             ///< where the construction stands
  std::vector<std::vector<Eigen::Vector3d>> polhode_;  ///< in body axes, rad/s
  std::vector<double> herpolhode_t_;
  std::vector<Eigen::Vector3d> herpolhode_;  ///< the contact point at those times, drawn
};

/// The motion as --animate and a live view show it; an integrated method is sampled at
/// exactly `frame_times`.
Animation animation(const Report& report, const FrameTimes& frame_times);

/// The lab as one program.
LabProgram<Inputs, Report> program();

}  // namespace rigid::lab::poinsot
