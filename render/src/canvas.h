// Internal: what a 2D figure is drawn on. The plot's and the overlay's drawing
// (plot2d_draw.cpp, overlay.cpp) speak only this interface, so one drawing makes
// both the raster figure (Painter: OpenGL triangles, MSAA) and the vector one
// (CairoCanvas: SVG and PDF paths, text as glyphs of the embedded font).
// Coordinates are logical pixels with y down; an optional third coordinate is
// NDC depth, used only by the raster canvas for lines in 3D scenes.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <string_view>
#include <vector>

#include "rigid/render/palette.h"
#include "rigid/render/text.h"

namespace rigid::render {
class Plot2D;
}

namespace rigid::render::detail {

/// Screen point: x, y in logical pixels (y down), z in NDC depth (0 for 2D).
using P3 = Eigen::Vector3d;

/// Dash pattern in pixels: alternating on/off lengths; empty is solid.
using DashPattern = std::vector<double>;

class Canvas {
 public:
  virtual ~Canvas() = default;

  /// Restricts the following drawing to a rectangle (x0, y0, x1, y1).
  virtual void clip(double x0, double y0, double x1, double y1) = 0;
  virtual void no_clip() = 0;
  /// Enables the depth test for the following drawing (3D overlays; a 2D canvas ignores it).
  virtual void depth_test(bool on) = 0;

  virtual void triangle(const P3& a, const P3& b, const P3& c, Color color) = 0;
  virtual void rect(double x0, double y0, double x1, double y1, Color color) = 0;
  /// Outline of a rectangle with a stroke width (drawn inside the rectangle).
  virtual void rect_outline(double x0, double y0, double x1, double y1, double width,
                            Color color) = 0;
  /// Filled convex polygon.
  virtual void convex(const std::vector<P3>& pts, Color color) = 0;
  /// Filled disc.
  virtual void disc(const P3& c, double radius, Color color) = 0;
  /// Thick polyline with joins; round_caps also makes dotted patterns round.
  virtual void polyline(const std::vector<P3>& pts, double width, Color color,
                        const DashPattern& dash = {}, bool round_caps = false) = 0;
  /// Text (markup) anchored at (x, y); rotated 90° counter-clockwise when vertical.
  virtual TextExtent text(std::string_view markup, double x, double y, double size, Color color,
                          HAlign h = HAlign::kLeft, VAlign v = VAlign::kBaseline,
                          bool vertical = false, double depth = 0) = 0;
};

/// How far along its baseline a text of extent e starts from its anchor (negative: before it).
inline double text_start_offset(const TextExtent& e, HAlign h) {
  return h == HAlign::kLeft ? 0 : h == HAlign::kCenter ? -0.5 * e.width : -e.width;
}
/// How far below its anchor a text of extent e has its baseline.
inline double text_baseline_offset(const TextExtent& e, VAlign v) {
  return v == VAlign::kTop        ? e.ascent
         : v == VAlign::kCenter   ? 0.5 * (e.ascent - e.descent)
         : v == VAlign::kBaseline ? 0
                                  : -e.descent;
}

/// Where a text of extent e anchored at (x, y) has its origin (the baseline's start), on
/// whole pixels so that every canvas puts it at the same place; vertical text reads
/// upwards, its glyph tops pointing left.
inline Eigen::Vector2d text_origin(const TextExtent& e, double x, double y, HAlign h, VAlign v,
                                   bool vertical) {
  const double ax = text_start_offset(e, h), ay = text_baseline_offset(e, v);
  return vertical ? Eigen::Vector2d(std::round(x + ay), std::round(y - ax))
                  : Eigen::Vector2d(std::round(x + ax), std::round(y + ay));
}

class PhaseClock;

/// Lays out the plot at width × height and draws it on `canvas` (plot2d_draw.cpp); the
/// clock, if given, laps the layout.
void draw_plot(const Plot2D& plot, int width, int height, Canvas& canvas,
               PhaseClock* clock = nullptr);

}  // namespace rigid::render::detail
