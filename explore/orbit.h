// The explorer's view of a scene: the lab's own camera, fitted to the figure or the
// whole motion, turned about its target by the mouse and moved in or out by the
// wheel. Degrees and a factor, so a script states a view exactly.
#pragma once

#include "rigid/render/scene3d.h"

namespace rigid::explore {

struct Orbit {
  double yaw_deg = 0.0;    ///< about the camera's up axis, positive turning the view to the right
  double pitch_deg = 0.0;  ///< up over the target, positive looking from higher
  double zoom = 1.0;       ///< > 1 comes closer

  /// Turns by a mouse drag of (dx, dy) pixels in a view `height` pixels tall.
  void drag(double dx, double dy, double height);
  /// Zooms by wheel steps (positive: closer).
  void wheel(double steps);
  /// Turns by degrees right and up (the arrow keys, a script's turn).
  void turn(double right_deg, double up_deg);
  /// Comes closer by a factor (> 1), or goes away (< 1): a pinch, a script's zoom.
  void zoom_by(double factor);
  /// Keeps the angles and the zoom where a view stays well defined.
  void clamp();
  bool is_identity() const { return yaw_deg == 0.0 && pitch_deg == 0.0 && zoom == 1.0; }

  /// `base` seen from this orbit: its eye turned about its target, its distance (or
  /// orthographic height) divided by the zoom; never past straight above or below.
  render::Camera apply(const render::Camera& base) const;
};

}  // namespace rigid::explore
