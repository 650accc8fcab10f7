// Figures of the lamina_tensor lab: the lamina with its rotation axis, omega,
// L and the principal axes.
#pragma once

#include <string>

#include "common/lab.h"
#include "rigid/inertia.h"

namespace rigid::lab {

/// The lab's command-line inputs, with the text's defaults.
struct LaminaInputs {
  double mass = 1.0;
  double a = 1.0;
  double b = 2.0;
  double c = 0.5;
  std::string origin = "corner";
  Vec3 axis = Vec3(0.8, 0.6, 0.0);
  double omega = 1.0;
};

/// Writes lamina_tensor_<what>.png figures into the lab's figure directory.
void draw_lamina_figures(Lab& lab, const LaminaInputs& in, const Mat3& I,
                         const PrincipalAxes& principal);

}  // namespace rigid::lab
