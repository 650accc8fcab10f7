// Internal: a 2D plot planned before it is drawn. Each panel's plan works out, at one
// image size, its ranges, ticks and frame (plot2d_plan.cpp), then where its legend,
// reference-line labels and annotations go, from an occupancy grid of what the data
// draws (plot2d_place.cpp); drawing it (plot2d_draw.cpp) only follows the plan. Title
// and legend come from the shared overlay (overlay.h), so they look as in a 3D scene.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "canvas.h"
#include "overlay.h"
#include "placement.h"
#include "rigid/render/draw.h"
#include "rigid/render/plot2d.h"
#include "rigid/render/ticks.h"

namespace rigid::render::detail {

// The data's extent along one axis, NaN while empty.
struct Range {
  double lo = std::numeric_limits<double>::quiet_NaN(), hi = lo;
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::isnan(lo) ? v : std::min(lo, v);
    hi = std::isnan(hi) ? v : std::max(hi, v);
  }
};

// Data-to-pixel map for one axis.
struct AxisMap {
  Scale scale = Scale::kLinear;
  double lo = 0, hi = 1;  // data range
  double p0 = 0, p1 = 1;  // pixel positions of lo and hi
  double t(double v) const { return scale == Scale::kLog10 ? std::log10(v) : v; }
  double from_t(double u) const { return scale == Scale::kLog10 ? std::pow(10.0, u) : u; }
  double operator()(double v) const { return p0 + (t(v) - t(lo)) / (t(hi) - t(lo)) * (p1 - p0); }
  // The data value at a pixel position.
  double inverse(double p) const { return from_t(t(lo) + (p - p0) / (p1 - p0) * (t(hi) - t(lo))); }
  bool valid(double v) const { return std::isfinite(v) && (scale == Scale::kLinear || v > 0); }
};

// The colour each series and band is drawn in: its own, or the palette's next.
struct PanelColors {
  std::vector<Color> series, bands;
};
/// A panel's colours.
PanelColors resolve_colors(const Panel& pn);

// The legend's candidate places in matplotlib's order of preference for loc="best".
enum class Spot { kTopRight, kTopLeft, kBottomLeft, kBottomRight, kRight, kLeft, kBottom, kTop };

// Everything about one panel at one size, worked out before drawing.
class PanelPlan {
 public:
  /// Plans `panel` in `cell`; `own_legend` false: the figure's shared legend lists its
  /// entries.
  PanelPlan(const Panel& panel, const Style& st, const ScreenRect& cell, bool own_legend = true);

  /// Where everything went, for tests and callers that place things over the plot.
  Plot2D::PanelLayout report() const;
  /// Draws the panel as planned.
  void draw(Canvas& p) const;

 private:
  // Planning (plot2d_plan.cpp)
  void data_ranges();
  void plan();
  TextExtent tick_extent(const Ticks& t) const;
  Ticks ticks_fitting(const Axis& axis, const AxisMap& m, bool horizontal) const;
  void layout();
  void equalize();
  P3 map(double x, double y) const { return {xm_(x), ym_(y), 0}; }
  // Where a series' markers go, in pixels: at its points, or along its line
  // (Series::marker_spacing).
  std::vector<Eigen::Vector2d> marker_points(const Series& s) const;

  // Placing (plot2d_place.cpp)
  Occupancy data_grid() const;
  void add_ref_lines(Occupancy& grid, float weight, bool vertical = true) const;
  void place_ref_labels(const Occupancy& grid);
  ScreenRect spot_box(Spot s) const;
  Placement place_legend(const Occupancy& grid) const;
  bool add_headroom(const Occupancy& grid);
  void place_annotations();

  // Drawing (plot2d_draw.cpp)
  void background(Canvas& p) const;
  void data(Canvas& p) const;
  std::size_t drawn_series(std::size_t i) const;
  void series_lines(Canvas& p) const;
  void series_markers(Canvas& p) const;
  void annotations(Canvas& p) const;
  void frame_and_ticks(Canvas& p) const;
  void labels(Canvas& p) const;

  const Panel& pn_;
  Style st_;  // a copy: plans are moved about with their figure
  ScreenRect cell_;
  PanelColors colors_;
  double x_lo_ = 0, x_hi_ = 1, y_lo_ = 0, y_hi_ = 1;  // ranges before equal aspect
  AxisMap xm_, ym_;
  Ticks xt_, yt_;
  ScreenRect rect_;
  TitleBlock title_;
  double xlabel_size_ = 0, ylabel_size_ = 0;
  std::vector<LegendEntry> entries_;
  LegendSize legend_size_;
  ScreenRect legend_;
  std::vector<ScreenRect> ref_boxes_, note_boxes_;
  std::vector<bool> ref_on_data_;  ///< each reference label covers data where it is
  std::vector<double> ref_sizes_;  ///< each reference label's font size
};

// The figure at a size: its title and one plan per panel, row by row.
struct FigurePlan {
  Style st;
  TitleBlock title;
  std::vector<PanelPlan> panels;
  std::vector<LegendEntry> legend;  // the shared legend's entries
  LegendSize legend_size;
  ScreenRect legend_box;
};

/// The figure at width x height: its title, its shared legend and one plan per panel.
FigurePlan plan_figure(const Plot2D& plot, int width, int height);

}  // namespace rigid::render::detail
