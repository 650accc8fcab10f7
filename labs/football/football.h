// football: "Analysis of a football" and section 6.1, the free symmetric top
// (eqs. 104-115, 142-149), as a library.
//
// A body with moments I (transverse, I1 = I2) and Is (about its symmetry axis
// 3) spins freely with |omega| at angle alpha to 3. L is fixed in space; 3 and
// omega lie in one plane with it, at angles theta (tan theta = (I/Is) tan alpha,
// eq. 144) and |theta - alpha| from L. Seen in the body, omega turns about 3 at
// Omega = omega cos(alpha) (Is - I)/I (eq. 109); in space, 3 and omega turn
// about L at phi_dot = |L|/I (eq. 147). The body cone (half-angle alpha about 3)
// rolls on the space cone (half-angle |theta - alpha| about L) along omega: on
// its outside for a prolate body (a football, theta > alpha), round it for an
// oblate one (a frisbee, eqs. 148-149: the wobble twice the spin; the Earth,
// whose free wobble the text puts at 305 days).
//
// The lab takes a preset body (football, frisbee, earth) and, if given, its own
// moments, omega and alpha; it reports the rates, periods, angles and cones,
// checks phi_dot by integrating Euler's equations, and draws the cones, the
// same cones for the other kind of body, and the rates against alpha. Its
// motion is the body cone rolling on the space cone for two precession periods.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "common/figures.h"
#include "common/inputs.h"
#include "common/program.h"
#include "common/report.h"
#include "rigid/symmetric_top.h"

namespace rigid::lab::football {

/// The lab's inputs, with the text's default: the football. The moments, omega
/// and alpha are the preset's unless given.
struct Inputs {
  std::string preset = "football";
  std::optional<Eigen::Vector2d> inertia;  ///< (I, Is), kg m^2
  std::optional<double> moment_ratio;      ///< Is / I with the preset's I
  std::optional<double> omega;             ///< |omega|, rad/s
  std::optional<double> day;               ///< s, one turn: omega = 2 pi / day
  std::optional<double> alpha_deg;         ///< angle between omega and the symmetry axis
};

/// The other kind of body for contrast (oblate beside a prolate run, prolate beside
/// an oblate one), at the run's omega and alpha.
struct Contrast {
  double ratio = 1.0;  ///< its Is / I
  SymmetricPrecession precession;
  std::string title, caption;
};

/// What the lab reports, and what its figures and motion draw.
struct Report : lab::Report {
  using lab::Report::Report;
  double I = 0.0;                  ///< kg m^2, the transverse moment used (the preset's or given)
  double Is = 0.0;                 ///< kg m^2, the moment about the symmetry axis used
  double omega = 0.0;              ///< rad/s, |omega| used
  double alpha_deg = 0.0;          ///< deg, alpha used
  SymmetricPrecession precession;  ///< the closed form (eqs. 109, 143-147)
  Contrast contrast;
};

/// A period in the unit a student reads it in: seconds up to 1000 s, hours up to half a
/// day, days of 86400 s beyond (the Earth's 0.994 d and 305 d, as the text says them).
std::string readable_period(double seconds);

/// The inputs' rules: options, widgets and compute()'s checks.
const InputTable<Inputs>& input_table();
/// Everything the lab reports. Throws InputError naming a broken input.
Report compute(const Inputs& in);
/// The body cone rolling on the space cone, the same for the other kind of body,
/// and the rates against alpha.
void figures(const Report& report, FigureSink& sink);

/// The lab's motion: the scene at any time t, exact, cheap, in any order.
class Motion {
 public:
  /// Copies what it needs: never keeps a reference to the report.
  explicit Motion(const Report& report);
  /// Two turns of 3 about L: two precession periods 2 pi / phi_dot.
  double seconds() const;
  /// The plane of L, 3 and omega turned about L by phi_dot t and the body cone
  /// rolled on the space cone; scene(0) is the "cones" figure.
  render::Scene3D scene(double t) const;

 private:
  double ratio_, alpha_deg_;
  SymmetricPrecession precession_;
};

/// The motion as the command line and a live view show it.
Animation animation(const Report& report, const FrameTimes& frame_times);

/// The lab as one program.
LabProgram<Inputs, Report> program();

}  // namespace rigid::lab::football
