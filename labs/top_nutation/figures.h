// top_nutation's inputs and figures: the effective potential V(theta) with E'
// and the turning points, the path of the symmetry axis on the unit sphere in
// three regimes, theta(t) and phi_dot(t) exact beside integrated, the top in 3D,
// and every integrator's error against the exact motion.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "common/figures.h"
#include "common/free_body_run.h"
#include "rigid/heavy_top.h"
#include "rigid/heavy_top_integrate.h"

namespace rigid::lab::top_nutation {

/// The lab's inputs, with the text's top (section 8.1): a 2.00 kg disk of radius
/// 5.0 cm, 4.0 cm above the tip, spinning at 500 rpm, released at 30 deg.
struct Inputs {
  double mass = 2.0;
  double arm = 0.04;
  double disk_radius = 0.05;
  Eigen::Vector2d inertia{0.0, 0.0};  ///< (I, Is) about the pivot, used only when given
  double g = 9.8;
  double spin = 0.0;  ///< rad/s, used only when given
  double spin_rpm = 500.0;
  double theta0_deg = 30.0;
  double thetadot0 = 0.0;
  double phidot0 = 0.0;
  double t_end = 0.0;             ///< 0: three nutation periods
  double periods = 0.0;           ///< --periods: t_end as a number of nutation periods
  IntegrationInputs integration;  ///< "exact" by default; step 0: nutation period / 2000
};

/// What the figures show.
struct Figures {
  const HeavyTopExact& motion;
  const TopRun& run;                          ///< the lab's run (exact or integrated)
  const TopRun& integrated;                   ///< an integrated run beside the exact one
  const std::vector<TopComparison>& methods;  ///< every integrator, at the same cost if
                                              ///< evaluations_per_period > 0
  double arm = 0.04, disk_radius = 0.05;      ///< for drawing the top, m
  double t_end = 0.0;
  double evaluations_per_period = 0.0;  ///< the comparison's cost (0: the lab's settings)
  double periods = 0.0;                 ///< over this many nutation periods
};

/// Hands the lab's figures to the set.
void draw(FigureSet& set, const Figures& f);

/// The top's attitude and angular velocity in body axes at a time.
struct TopState {
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();
  Eigen::Vector3d omega_body = Eigen::Vector3d::Zero();
};
/// The state at a time: an integrator's (the exact motion's when empty).
using TopStateAt = std::function<TopState(double)>;

/// The top at time t (s): its disk (with spokes, so its spin shows), L, the gravity
/// torque, omega, the centre of mass's circle at the current tilt, and the path of
/// the symmetry axis's end since t = 0 (through `path_times` up to t, or 400 points a
/// nutation period); t = 0 is the "top" figure. States from `state_at`, else exact.
render::Scene3D top_scene(const HeavyTopExact& motion, double arm, double disk_radius, double t,
                          const TopStateAt& state_at = {},
                          const std::vector<double>& path_times = {});

}  // namespace rigid::lab::top_nutation
