// Internal: where text and legend boxes go. An occupancy grid records, in
// cells of a few pixels, what a figure draws (weight 1 for data that text must
// not hide: lines, markers, bands, opaque surfaces, other text; less for what
// it may cover if it must: translucent surfaces, reference lines). A box then
// takes the first of its candidate places, in order of preference, that lies
// inside its bounds, overlaps none of the boxes already taken and covers
// nothing; if none is clear, the one covering the least.
#pragma once

#include <Eigen/Core>
#include <initializer_list>
#include <vector>

#include "rigid/render/rect.h"

namespace rigid::render::detail {

/// What a box covers: cells of weight 1 (hard) and the summed weight of lighter cells (soft).
struct Cover {
  long hard = 0;
  double soft = 0;
  /// True when the box covers nothing at all.
  bool clear() const { return hard == 0 && soft == 0; }
  /// Less cover: fewer hard cells, then less soft weight.
  bool operator<(const Cover& o) const { return hard != o.hard ? hard < o.hard : soft < o.soft; }
};

/// A grid over a pixel area that remembers the heaviest weight drawn in each cell.
class Occupancy {
 public:
  /// A grid over `area` with square cells of `cell` pixels, all empty.
  Occupancy(const ScreenRect& area, double cell);

  /// Marks the cells a rectangle touches.
  void add_rect(const ScreenRect& r, float weight);
  /// Marks the cells within half_width of a segment (clipped to the grid).
  void add_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double half_width,
                   float weight);
  /// Marks the cells a triangle covers (centres inside, and the corners' cells).
  /// The cells of points (a triangle's corners: one smaller than a cell holds no centre).
  void add_points(std::initializer_list<const Eigen::Vector2d*> points, float weight);
  void add_triangle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                    float weight);
  /// What the cells a rectangle touches hold.
  Cover cover(const ScreenRect& r) const;
  /// The pixel rows of the highest and lowest hard cells in the columns x0..x1; false if none.
  bool hard_extent(double x0, double x1, double& top, double& bottom) const;

 private:
  int col(double x) const;
  int row(double y) const;
  void mark(int i, int j, float weight);
  ScreenRect area_;
  double cell_;
  int cols_ = 0, rows_ = 0;
  std::vector<float> w_;
};

/// Boxes of a w × h text around (x, y), their nearest edge or corner `distance` from it:
/// right, left, above, below, then above-right, above-left, below-right, below-left.
std::vector<ScreenRect> boxes_around(double x, double y, double w, double h, double distance);

/// The box moved (not resized) the least to lie inside bounds; left- and top-aligned in
/// them when it is larger.
ScreenRect keep_inside(const ScreenRect& box, const ScreenRect& bounds);

/// A chosen place and what it covers; found is false when every candidate inside the bounds
/// overlaps a box taken (box is then the one overlapping least) or none is inside (box empty).
struct Placement {
  ScreenRect box;
  Cover cover;
  bool found = false;
};

/// The first candidate inside `bounds`, overlapping none of `taken`, that covers nothing;
/// else, of those inside and clear of `taken`, the one covering the least (earliest on ties);
/// else the one inside overlapping `taken` the least.
Placement choose_place(const std::vector<ScreenRect>& candidates, const Occupancy& grid,
                       const ScreenRect& bounds, const std::vector<ScreenRect>& taken);

}  // namespace rigid::render::detail
