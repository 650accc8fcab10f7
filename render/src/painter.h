// Internal: the raster canvas, batched OpenGL triangles, shared by plots and scene
// overlays. The third coordinate of a point is NDC depth, so screen-space lines in
// 3D scenes are hidden behind surfaces. Everything is triangles; thick lines are
// tessellated here with miter joins (round where sharp) and MSAA smooths their
// edges.
#pragma once

#include <string_view>
#include <vector>

#include "canvas.h"
#include "gl.h"

namespace rigid::render::detail {

class Painter final : public Canvas {
 public:
  /// Starts drawing on a width × height logical canvas (the target must be bound).
  void begin(int width, int height);
  /// Draws everything queued so far.
  void flush();

  void clip(double x0, double y0, double x1, double y1) override;
  void no_clip() override;
  void depth_test(bool on) override;

  void triangle(const P3& a, const P3& b, const P3& c, Color color) override;
  void rect(double x0, double y0, double x1, double y1, Color color) override;
  void rect_outline(double x0, double y0, double x1, double y1, double width, Color color) override;
  /// A fan of triangles.
  void convex(const std::vector<P3>& pts, Color color) override;
  void disc(const P3& c, double radius, Color color) override;
  /// Miter joins, round where the turn is sharp.
  void polyline(const std::vector<P3>& pts, double width, Color color, const DashPattern& dash = {},
                bool round_caps = false) override;
  TextExtent text(std::string_view markup, double x, double y, double size, Color color,
                  HAlign h = HAlign::kLeft, VAlign v = VAlign::kBaseline, bool vertical = false,
                  double depth = 0) override;

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
