// A rectangle in pixels: how a figure's layout (title, legend, labels, plot
// frames) is reported to callers and tests.
#pragma once

#include <algorithm>

namespace rigid::render {

/// A rectangle in pixels, y down; empty when x1 <= x0 or y1 <= y0.
struct ScreenRect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  /// True when the rectangle has no area.
  bool empty() const { return !(x1 > x0 && y1 > y0); }
  /// True when the two rectangles share some area (touching edges do not count).
  bool overlaps(const ScreenRect& o) const {
    return !empty() && !o.empty() && x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
  }
  /// True when o lies wholly inside this rectangle.
  bool contains(const ScreenRect& o) const {
    return o.x0 >= x0 && o.x1 <= x1 && o.y0 >= y0 && o.y1 <= y1;
  }
  /// True when the point (x, y) lies inside or on the edge.
  bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
  /// The rectangle grown by d on every side (shrunk if d < 0).
  ScreenRect grown(double d) const { return {x0 - d, y0 - d, x1 + d, y1 + d}; }
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

}  // namespace rigid::render
