// Figures of the poinsot lab: the energy and momentum ellipsoids with their
// polhode, a family of polhodes with the separatrix, omega(t) and its phase
// plot, and each integrator's error against the exact solution.
#pragma once

#include <string>
#include <vector>

#include "common/lab.h"
#include "rigid/free_body_exact.h"
#include "rigid/integrate.h"

namespace rigid::lab {

/// One integrator's run, measured against the exact solution at its samples.
struct MethodTrace {
  Method method;
  std::string setting;  ///< "tol 1e-10" or "h = 0.005 s", for the legend
  std::vector<double> t, omega_error, energy_error;
};

/// Writes poinsot_<what>.png figures into the lab's figure directory.
void draw_poinsot_figures(Lab& lab, const FreeBodyExact& motion, const Eigen::Vector3d& omega0,
                          const std::vector<FreeBodySample>& samples,
                          const std::vector<MethodTrace>& traces);

}  // namespace rigid::lab
