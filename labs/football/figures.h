// football's inputs and figures: the body cone rolling on the space cone, with
// omega along their line of contact, L and the symmetry axis; the rates against alpha.
#pragma once

#include <Eigen/Core>
#include <string>

#include "common/figures.h"
#include "rigid/symmetric_top.h"

namespace rigid::lab::football {

/// The lab's inputs. The moments, omega and alpha come from the preset unless given.
struct Inputs {
  std::string preset = "football";
  Eigen::Vector2d inertia{0.0, 0.0};  ///< (I, Is), kg m^2
  double omega = 0.0;                 ///< |omega|, rad/s
  double alpha_deg = 0.0;             ///< angle between omega and the symmetry axis
};

/// Hands the lab's figures to the set; `p` is the closed-form precession of `in`.
void draw(FigureSet& set, const Inputs& in, const SymmetricPrecession& p);

}  // namespace rigid::lab::football
