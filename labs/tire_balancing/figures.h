// tire_balancing's inputs and figures: the wheel on its crooked axle with the
// cone L sweeps; the balancing mass against the tilt, exact and small-angle.
#pragma once

#include "common/figures.h"
#include "rigid/balancing.h"

namespace rigid::lab::tire_balancing {

/// The lab's inputs, with the text's defaults (section 2.3: m = 10 kg, a = 18 cm,
/// b = 5 cm, theta = 1 deg).
struct Inputs {
  CrookedWheel wheel;  ///< mass, radius and offset; its tilt is set from tilt_deg
  double tilt_deg = 1.0;
  /// 90 rad/s is a wheel of 0.31 m rolling radius at about 100 km/h.
  double omega = 90.0;
  double road_speed = 0.0;    ///< m/s, used only when given: omega = road_speed / tyre_radius
  double tyre_radius = 0.31;  ///< m, the tyre's rolling radius, with --road-speed-m-s
};

/// Hands the lab's figures to the set; m0 is the exact balancing mass.
void draw(FigureSet& set, const Inputs& in, double m0);

}  // namespace rigid::lab::tire_balancing
