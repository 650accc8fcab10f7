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

/// The other shape for contrast (oblate beside a prolate run, prolate beside an
/// oblate one), at the run's omega and alpha.
struct Contrast {
  double ratio = 1.0;  ///< its Is / I
  SymmetricPrecession precession;
  std::string title, caption;
};

/// The cones at time t (s) of the motion: the plane of L, 3 and omega turned about L
/// by phi_dot t, the body cone rolled on the space cone (lines fixed in it show it);
/// t = 0 is the "cones" figure. `prefix` starts the title.
render::Scene3D cones_scene(double ratio, double alpha_deg, const SymmetricPrecession& p,
                            const std::string& prefix, double t);

/// Hands the lab's figures to the set; `p` is the closed-form precession of `in`.
void draw(FigureSet& set, const Inputs& in, const SymmetricPrecession& p, const Contrast& other);

}  // namespace rigid::lab::football
