// The plot every lab that integrates draws alike (poinsot, top_nutation): each
// integrator's error against the exact motion, and its energy error, against t.
#pragma once

#include <string>
#include <vector>

#include "rigid/ode.h"
#include "rigid/render/plot2d.h"

namespace rigid::lab {

/// One method's curves; a method that did not run or blew up is listed but not drawn.
struct MethodCurve {
  std::string name;  ///< e.g. "rk4, h = 0.001 s"
  bool drawn = false;
  std::vector<double> t, error, energy_error;
};

/// A method and its setting as a legend names it: "dopri5, tol 1e-10" or "rk4, h = 0.001 s".
std::string method_label(const OdeOptions& options);

/// Two panels: `error_label` (a log axis) and |E - E0| against t; the first sample
/// (t = 0, no error) is left out and zeros sit at a floor below double roundoff.
render::Plot2D integrators_plot(const std::vector<MethodCurve>& methods,
                                const std::string& error_title, const std::string& error_label,
                                const std::string& energy_label);

}  // namespace rigid::lab
