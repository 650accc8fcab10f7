// Figures of the tire_balancing lab: the wheel, its crooked axle, the two
// balancing masses, and the cone that L sweeps when the wheel is unbalanced.
#pragma once

#include "common/lab.h"
#include "rigid/balancing.h"

namespace rigid::lab {

/// Writes tire_balancing_<what>.png figures into the lab's figure directory.
void draw_tire_figures(Lab& lab, const CrookedWheel& wheel, double m0, double omega);

}  // namespace rigid::lab
