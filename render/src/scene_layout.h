// Internal: a 3D scene framed at one size: the shared overlay (title, legend),
// the camera fitted into the region the overlay leaves, and where each label's
// text goes. draw() draws exactly this; layout() reports it (both in draw.h).
#pragma once

#include <vector>

#include "overlay.h"
#include "rigid/render/scene3d.h"
#include "scene_fit.h"

namespace rigid::render::detail {

/// Everything about a scene at one size that is decided before drawing.
struct SceneFrame {
  Style st;
  TitleBlock title;
  std::vector<LegendEntry> entries;
  ScreenRect legend, region;
  Camera camera;
  View view;
  std::vector<ScreenRect> labels;  ///< one per label; empty when its point is behind the eye
};

/// Frames a scene (already normalised to about unit size) at width × height.
SceneFrame frame_scene(const Scene3D& scene, int width, int height, bool place_labels = true);

}  // namespace rigid::render::detail
