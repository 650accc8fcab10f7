// tire_balancing: sections 2.2 and 2.3 of the chapter, as a library.
// A wheel (a uniform disk of mass m and radius a) sits on an axle tilted by
// theta from its symmetry axis. Spinning, its L is not along the axle, so L
// sweeps a cone and the bearings must supply a torque. Two masses m0 at
// (-b, a) and (b, -a) swing a principal axis onto the axle and balance it.
#pragma once

#include <optional>

#include "common/figures.h"
#include "common/inputs.h"
#include "common/program.h"
#include "common/report.h"
#include "rigid/balancing.h"

namespace rigid::lab::tire_balancing {

/// The lab's inputs, with the text's defaults (section 2.3: m = 10 kg, a = 18 cm,
/// b = 5 cm, theta = 1 deg).
struct Inputs {
  double mass = 10.0;    ///< kg, the disk
  double radius = 0.18;  ///< m, the disk's radius a
  double offset = 0.05;  ///< m, each balancing mass's distance b from the disk
  double tilt_deg = 1.0;
  /// rad/s; 90 rad/s is a wheel of 0.31 m rolling radius at about 100 km/h.
  double omega = 90.0;
  std::optional<double> road_speed;  ///< m/s: if set, omega = road_speed / tire_radius
  double tire_radius = 0.31;         ///< m, the tire's rolling radius, used with road_speed
};

/// What the lab reports, and what its figures draw.
struct Report : lab::Report {
  using lab::Report::Report;
  CrookedWheel wheel;  ///< the wheel with its tilt in radians
  double omega = 0.0;  ///< the spin used, rad/s
  double m0 = 0.0;     ///< the exact balancing mass, kg
};

/// The inputs' rules: options, widgets and compute()'s checks.
const InputTable<Inputs>& input_table();
/// Everything the lab reports. Throws InputError naming a broken input.
Report compute(const Inputs& in);
/// The wheel on its crooked axle with the cone L sweeps; the balancing mass
/// against the tilt, exact and small-angle.
void figures(const Report& report, FigureSink& sink);

/// The lab as one program.
LabProgram<Inputs, Report> program();

}  // namespace rigid::lab::tire_balancing
