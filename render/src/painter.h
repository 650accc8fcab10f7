// Internal: the batched 2D drawing layer shared by plots and scene overlays.
// Coordinates are logical pixels with y down; an optional third coordinate is
// NDC depth, so screen-space lines in 3D scenes are hidden behind surfaces.
// Everything is triangles; thick lines are tessellated here with miter joins
// (round where sharp) and MSAA smooths their edges.
#pragma once

#include <Eigen/Core>
#include <string_view>
#include <vector>

#include "gl.h"
#include "rigid/render/palette.h"
#include "rigid/render/text.h"

namespace rigid::render::detail {

/// Screen point: x, y in logical pixels (y down), z in NDC depth (0 for 2D).
using P3 = Eigen::Vector3d;

/// Dash pattern in pixels: alternating on/off lengths; empty is solid.
using DashPattern = std::vector<double>;

class Painter {
 public:
  /// Starts drawing on a width × height logical canvas (the target must be bound).
  void begin(int width, int height);
  /// Draws everything queued so far.
  void flush();

  /// Restricts the following drawing to a rectangle (x0, y0, x1, y1); empty rect turns clipping
  /// off.
  void clip(double x0, double y0, double x1, double y1);
  void no_clip();
  /// Enables the depth test for the following drawing (3D overlays).
  void depth_test(bool on);

  void triangle(const P3& a, const P3& b, const P3& c, Color color);
  void rect(double x0, double y0, double x1, double y1, Color color);
  /// Outline of a rectangle with a stroke width (drawn inside-centred).
  void rect_outline(double x0, double y0, double x1, double y1, double width, Color color);
  /// Filled convex polygon (fan).
  void convex(const std::vector<P3>& pts, Color color);
  /// Filled disc.
  void disc(const P3& c, double radius, Color color);
  /// Thick polyline with miter/round joins; round_caps also makes dotted patterns round.
  void polyline(const std::vector<P3>& pts, double width, Color color, const DashPattern& dash = {},
                bool round_caps = false);
  /// Text (markup) anchored at (x, y); rotated 90° counter-clockwise when vertical.
  TextExtent text(std::string_view markup, double x, double y, double size, Color color,
                  HAlign h = HAlign::kLeft, VAlign v = VAlign::kBaseline, bool vertical = false,
                  double depth = 0);

 private:
  struct Vertex {
    float x, y, z;
    float r, g, b, a;
    float u, v, textured;
  };
  struct Batch {
    std::size_t first = 0, count = 0;
    bool clip = false;
    int sx = 0, sy = 0, sw = 0, sh = 0;
    bool depth = false;
  };
  void push(const P3& p, Color c, float u = 0, float v = 0, float t = 0);
  void new_batch();
  void solid_strip(const std::vector<P3>& pts, double hw, Color color, bool round_caps);

  int width_ = 0, height_ = 0;
  std::vector<Vertex> verts_;
  std::vector<Batch> batches_;
  Batch state_;
};

/// The process's painter (shader, buffers and glyph atlas made once).
Painter& painter();

}  // namespace rigid::render::detail
