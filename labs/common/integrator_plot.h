// The plot every lab that integrates draws alike (poinsot, top_nutation): each
// integrator's error against the exact motion, and its energy error, against t.
#pragma once

#include <string>
#include <vector>

#include "rigid/compare.h"
#include "rigid/render/plot2d.h"

namespace rigid::lab {

/// One method's curves; a method that did not run or blew up is listed but not drawn.
struct MethodCurve {
  Method method;     ///< its line's colour and dash (its own colour; a family's dash)
  std::string name;  ///< e.g. "rk4, h = 0.001 s"
  bool drawn = false;
  std::vector<double> t, error, energy_error;
};

/// A method and its setting as a legend names it: "dopri5, tol 4.3e-06" or "rk4, h = 0.001 s".
std::string method_label(const OdeOptions& options);

/// Each compared method's curves: its error against the exact motion (`in_unit` of it,
/// or as it is) and its energy error; one that did not finish or blew up is not drawn,
/// nor a projected run (--project; its method's style is its plain run's).
std::vector<MethodCurve> method_curves(const std::vector<MethodComparison>& comparisons,
                                       double (*in_unit)(double) = nullptr);

/// The time axis of the plot: in periods of the motion (`period` > 0, named by
/// `name`, e.g. "polhode periods"), or in seconds (period 0).
struct TimeAxis {
  double period = 0.0;
  std::string name;
};

/// The level below which a relative error is roundoff: eps (2.2e-16) times the 10^4 steps
/// a run takes at most at the figures' cost, rounded to a decade up. Below it a run's
/// error follows the last bits of the maths library (another CPU's libm changed the top's
/// vern8 error from 2.3e-11 to 1.5e-11 deg), so the figures draw it at this floor and
/// their axes start there: the same pixels on every machine.
inline constexpr double kRoundoffFloor = 1e-12;

/// The most a run that keeps its invariants can be off, in the error's unit (omega
/// reversed; theta across the whole nutation band), named
/// for the reader; drawn as a line where some run comes within a decade of it, so that a
/// curve stopped at it reads as "as wrong as can be" (a motion this sensitive, or a run
/// this cheap), not as a level of accuracy. Value 0: none.
struct ErrorCeiling {
  double value = 0.0;
  std::string label;
};

/// Two panels under `title`: `error_label` and |E - E0| (`energy_label`), each
/// the largest so far at each t, on log axes: what a run has lost by then, its
/// trend plain where the error itself oscillates sample to sample (a symplectic
/// method's band shows as a level line, a steady drift as a rising one). The
/// first sample (t = 0, no error) is left out. Errors below roundoff are drawn at it:
/// `error_floor` (kRoundoffFloor in the error's unit) and kRoundoffFloor for the
/// energy's, where each axis starts; the title says so. One legend under both panels, in
/// the order of `methods` (the lab's table's: at equal cost, its ranking), each method its
/// own colour, dash and marker, so that curves at the floor each show.
render::Plot2D integrators_plot(const std::vector<MethodCurve>& methods, const std::string& title,
                                const TimeAxis& time, const std::string& error_title,
                                const std::string& error_label, const std::string& energy_label,
                                double error_floor, const ErrorCeiling& ceiling = {});

}  // namespace rigid::lab
