// 2D plots from data: a figure of one or more panels (a rows × cols grid),
// each with linear or log10 axes, nice ticks, axis labels with units, line
// series, markers, reference lines, shaded bands, annotations and a legend.
// The plot knows only numbers and strings (text.h markup for labels); a lab
// hands it series computed elsewhere. Rendering draws antialiased thick lines with
// no depth buffer and no lighting: cairo's paths for a PNG, an SVG or a PDF, GL
// triangle strips (4× MSAA) in a live view.
//
// Sizes (line widths, marker sizes) are given in pixels at the reference
// 1600×1200 figure and scale with the image, so a figure looks the same from
// 800×600 to 1600×1200; lines never get thinner than 2 px. Fonts, paddings and
// the legend's look are the one figure style shared with Scene3D.
//
// Nothing here takes a pixel offset: the legend, annotations and reference-line
// labels place themselves clear of the data and of each other.
//
// This header is the description library (rigid::render, Eigen only): it
// declares nothing it cannot define, so a program linking only the description
// links. Laying out, drawing and saving a figure take fonts and OpenGL; they are
// free functions of the drawing library (rigid::render_gl, draw.h), which
// exists only in builds with the renderer.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "rigid/render/palette.h"

namespace rigid::render {

/// How an axis maps data to the page.
enum class Scale { kLinear, kLog10 };
/// Dash pattern of a line.
enum class Dash { kSolid, kDashed, kDotted, kDashDot };
/// Symbol drawn at each data point (or along a line, Series::marker_spacing): ten shapes,
/// so that as many curves lying on one another each show their own.
enum class Marker {
  kNone,
  kCircle,
  kSquare,
  kTriangle,
  kDiamond,
  kTriangleDown,
  kPlus,
  kCross,
  kTriangleLeft,
  kTriangleRight,
  kHexagon
};
/// Where a legend box goes. kAuto (like matplotlib's loc="best") takes the place among the
/// corners, the top and bottom centre and the middle of the sides whose box covers the least
/// data; if each covers some, the y axis grows at its free end (top or bottom, not one the
/// user fixed) just enough for the box to sit clear of the data.
enum class LegendPlace { kAuto, kTopRight, kTopLeft, kBottomRight, kBottomLeft, kNone };

/// One axis of a panel; min/max left NaN are taken from the data.
struct Axis {
  std::string label;  ///< with its unit, e.g. "\\omega_1 (rad/s)"
  Scale scale = Scale::kLinear;
  double min = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
  bool grid = true;  ///< light grid lines at the major ticks
  /// The axis is the time of the motion a figure goes with: a live view playing that
  /// motion marks the time it shows on it.
  bool motion_time = false;
};

/// A curve y(x) drawn as a line and/or markers.
struct Series {
  std::vector<double> x, y;
  std::string label;  ///< legend entry; empty for none
  Color color = kAutoColor;
  double width = 3.5;  ///< line width in reference pixels; 0 draws markers only
  Dash dash = Dash::kSolid;
  Marker marker = Marker::kNone;
  double marker_size = 11;  ///< marker diameter in reference pixels
  /// 0: a marker at each data point. Else markers along the line, where it crosses
  /// x = (k + marker_phase) * marker_spacing reference pixels from the frame's left edge
  /// (k = 0, 1, ...): curves that lie on one another, given phases apart, each show their
  /// markers beside the others' instead of under them.
  double marker_spacing = 0;
  double marker_phase = 0;  ///< 0 to 1, a share of marker_spacing
};

/// The region between two curves y_lo(x) and y_hi(x), filled translucent.
struct Band {
  std::vector<double> x, y_lo, y_hi;
  std::string label;
  Color color = kAutoColor;
  float opacity = 0.22f;
};

/// A shaded interval across the whole panel: lo <= y <= hi (or lo <= x <= hi if vertical).
struct Span {
  double lo = 0, hi = 0;
  bool vertical = false;
  std::string label;
  Color color = kGray;
  float opacity = 0.15f;
};

/// A horizontal (y = value) or vertical (x = value) reference line across the panel.
struct RefLine {
  double value = 0;
  bool vertical = false;
  std::string label;  ///< drawn at the line's end inside the panel, not in the legend
  Color color = kGray;
  double width = 2.5;
  Dash dash = Dash::kDashed;
};

/// Text about a data point, optionally with an arrow to it; the text places itself near the
/// point, clear of the data, the legend, other labels and the panel's frame.
struct Annotation {
  double x = 0, y = 0;
  std::string text;
  bool arrow = true;
  Color color = kTextColor;
};

/// One panel of a figure: axes and everything drawn in them.
struct Panel {
  std::string title;
  Axis x, y;
  std::vector<Series> series;
  std::vector<Band> bands;
  std::vector<Span> spans;
  std::vector<RefLine> ref_lines;
  std::vector<Annotation> annotations;
  LegendPlace legend = LegendPlace::kAuto;
  bool equal_aspect = false;  ///< one data unit is as long on x as on y (phase portraits)
  /// Series are drawn in order, a later one over an earlier; true draws them last to first,
  /// so that the legend's first entries lie on top where curves coincide (several at a
  /// floor).
  bool first_on_top = false;

  /// Adds a line series and returns it for further settings.
  Series& add_line(std::vector<double> x, std::vector<double> y, std::string label = {});
  /// Adds a markers-only series and returns it.
  Series& add_points(std::vector<double> x, std::vector<double> y, std::string label = {},
                     Marker marker = Marker::kCircle);
  /// Adds a band between y_lo(x) and y_hi(x) and returns it.
  Band& add_band(std::vector<double> x, std::vector<double> y_lo, std::vector<double> y_hi,
                 std::string label = {});
  /// Adds a shaded interval lo..hi of y (or of x if vertical) and returns it.
  Span& add_span(double lo, double hi, bool vertical = false, std::string label = {});
  /// Adds the line y = value (or x = value if vertical) and returns it.
  RefLine& add_ref_line(double value, bool vertical = false, std::string label = {});
  /// Adds text at data point (x, y) and returns it.
  Annotation& annotate(double x, double y, std::string text);
};

/// A figure: a title over a rows × cols grid of panels.
class Plot2D {
 public:
  /// A figure with rows × cols empty panels.
  explicit Plot2D(int rows = 1, int cols = 1);

  /// Panel at (row, col), counted from the top left.
  Panel& panel(int row = 0, int col = 0);
  /// Read-only panel at (row, col).
  const Panel& panel(int row = 0, int col = 0) const;

  int rows() const { return rows_; }
  int cols() const { return cols_; }

  /// Figure title over all panels (text.h markup); empty for none.
  std::string title;
  /// One legend for the whole figure, in columns under the panels, instead of one a
  /// panel: for panels that draw the same items (each method's error and its energy
  /// error), so no panel's axis grows to make room for a box. It lists every panel's
  /// labelled items, a label once (its first panel's style).
  bool shared_legend = false;
  /// The height the figure style (fonts, line widths, margins) is sized for; 0: the
  /// image's own. A strip under an animation's scene sets the whole frame's height,
  /// so its text matches the scene's instead of shrinking with the strip.
  int style_height = 0;
  /// The smallest text drawn (ticks, the legend), in pixels; 0: the figure style's own
  /// at the image's size. A plot shown in a small panel on a screen sets it, so its
  /// text stays legible where a figure that small would shrink it.
  double min_text_px = 0;

  /// Where one panel's parts land at a size, and where the whole figure's do: what
  /// layout() in draw.h returns. Only declared here, as the description never lays
  /// itself out; draw.h defines them.
  struct PanelLayout;
  struct Layout;

 private:
  int rows_, cols_;
  std::vector<Panel> panels_;
};

}  // namespace rigid::render
