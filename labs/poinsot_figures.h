// Figures of the poinsot lab: the energy and momentum ellipsoids with their
// polhode, a family of polhodes with the separatrix, omega(t) and its phase
// plot, and each integrator's error against the exact solution.
#pragma once

#include <vector>

#include "common/lab.h"
#include "rigid/free_body_exact.h"
#include "rigid/integrate.h"

namespace rigid::lab {

/// Writes poinsot_<what>.png figures into the lab's figure directory; the
/// integrator figure runs every method with `options` at `times`.
void draw_poinsot_figures(Lab& lab, const FreeBodyExact& motion, const Eigen::Vector3d& omega0,
                          const std::vector<FreeBodySample>& samples,
                          const std::vector<double>& times, const IntegrateOptions& options);

}  // namespace rigid::lab
