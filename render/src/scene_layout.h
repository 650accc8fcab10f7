// Internal: a 3D scene framed at one size: the shared overlay (title, legend),
// the camera fitted into the region the overlay leaves, and where each label's
// text goes. draw() draws exactly this; layout() reports it (both in draw.h).
#pragma once

#include <vector>

#include "overlay.h"
#include "rigid/render/image.h"
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

class Canvas;

/// Draws a frame's text overlay (each label where it was placed, the title, the legend) on
/// any canvas: GL over the scene's image, or cairo's vectors over it in an SVG or a PDF.
void draw_scene_overlay(Canvas& p, const std::vector<Label3D>& labels, const SceneFrame& fr);

/// A scene drawn without its overlay, and what the overlay needs: a vector file puts its
/// text over this image as text.
struct SceneParts {
  Image image;
  SceneFrame frame;
  std::vector<Label3D> labels;
};
SceneParts draw_scene_parts(const Scene3D& scene, int width, int height, FigureTiming* timing);

}  // namespace rigid::render::detail
