// poinsot's inputs and figures: the energy and momentum ellipsoids with their
// polhode, a family of polhodes with the separatrix, omega(t) with its phase
// plot, and every integrator's error against the exact solution.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "common/figures.h"
#include "common/free_body_run.h"
#include "rigid/free_body_exact.h"
#include "rigid/integrate.h"
#include "rigid/units.h"

namespace rigid::lab::poinsot {

/// The lab's inputs, with the text's defaults (section 5.1: the solid ellipsoid
/// x^2/9 + y^2/4 + z^2 = 1 of mass pi, started at omega = (1, 1, 1)).
struct Inputs {
  Eigen::Vector3d inertia{1, 1, 1};      ///< used only when --inertia is given
  Eigen::Vector3d ellipsoid{3, 2, 1};    ///< semi-axes A, B, C
  Eigen::Vector3d box{0.2, 0.15, 0.03};  ///< side lengths, used only when --box is given
  double mass = kPi;
  Eigen::Vector3d omega0{1, 1, 1};
  double t_end = 0.0;             ///< 0: three polhode periods
  double periods = 0.0;           ///< --periods: t_end as a number of polhode periods
  IntegrationInputs integration;  ///< "exact" by default; step 0: period / 2000
};

/// What the figures show of a run.
struct Run {
  const FreeBodyExact& motion;
  Eigen::Vector3d omega0;
  const std::vector<FreeBodySample>& samples;    ///< the lab's own run (exact or integrated)
  const std::vector<MethodComparison>& methods;  ///< every integrator at the same cost
  double evaluations_per_period = 0.0;           ///< that cost
  double periods = 0.0;                          ///< over this many periods
  double period = 0.0;                           ///< of this length: the time scale, s
  std::string period_name;                       ///< "polhode periods"
};

/// Hands the lab's figures to the set.
void draw(FigureSet& set, const Run& run);

/// The animation of the motion: the body turning in space with L fixed (drawn
/// pointing down), and beside it Poinsot's construction, the body's energy
/// ellipsoid rolling without slipping on the invariable plane, the polhode on the
/// ellipsoid and the herpolhode traced on the plane so far. Lengths of the
/// construction (rad/s) are scaled to the body's size.
class Animation {
 public:
  /// The state (omega_body, attitude) at a time: the exact solution's, or an integrator's.
  using StateAt = std::function<FreeBodyState(double)>;
  /// `half_extents`: the semi-axes of the solid ellipsoid drawn (a box's half sides
  /// if `box`); the herpolhode is sampled over [0, t_end] (240 times a polhode period),
  /// or at `path_times`. States come from `state_at`, the exact solution if empty.
  Animation(const FreeBodyExact& motion, const Eigen::Vector3d& half_extents, bool box,
            double t_end, StateAt state_at = {}, const std::vector<double>& path_times = {});
  /// The scene at time t of the motion.
  render::Scene3D frame(double t) const;
  /// The construction alone, seen from above: the herpolhode over `periods` polhode
  /// periods on the invariable plane with the contact point at each whole period
  /// (they do not coincide), and the energy ellipsoid touching the plane at t = 0.
  render::Scene3D herpolhode_scene(double periods) const;

 private:
  Eigen::Vector3d to_construction(const Eigen::Matrix3d& attitude, const Eigen::Vector3d& w) const;
  const FreeBodyExact& motion_;
  Eigen::Vector3d half_extents_;
  bool box_;
  StateAt state_at_;
  Eigen::Matrix3d space_;  ///< the motion's space frame turned so that L points down
  double size_, omega_scale_, construction_scale_, plane_depth_, plane_radius_;
  Eigen::Vector3d offset_;                             ///< where the construction stands
  std::vector<std::vector<Eigen::Vector3d>> polhode_;  ///< in body axes, rad/s
  std::vector<double> herpolhode_t_;
  std::vector<Eigen::Vector3d> herpolhode_;  ///< the contact point at those times, drawn
};

}  // namespace rigid::lab::poinsot
