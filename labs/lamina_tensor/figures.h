// lamina_tensor's inputs and figures: the lamina with omega, L and the
// principal axes; the moment about an in-plane axis against its angle.
#pragma once

#include <string>

#include "common/figures.h"
#include "rigid/inertia.h"

namespace rigid::lab::lamina_tensor {

/// The lab's inputs, with the text's defaults (section 1: b = 2a, corner, n at 37 deg).
struct Inputs {
  double mass = 1.0;
  double a = 1.0;
  double b = 2.0;
  double c = 0.5;
  std::string origin = "corner";
  Vec3 axis = Vec3(0.8, 0.6, 0.0);
  double axis_deg = 0.0;  ///< used only when given: n = (cos, sin, 0), from x toward y
  double omega = 1.0;
  bool examples = false;  ///< section 2.1's paddle, block and cube beside any plate
};

/// Hands the lab's figures to the set.
void draw(FigureSet& set, const Inputs& in, const Mat3& I, const PrincipalAxes& principal);

}  // namespace rigid::lab::lamina_tensor
