// Internal: the one figure style and the overlay every plot and scene shares.
// Style holds every size a figure uses (fonts, paddings, margins, line and
// frame widths, legend metrics) at an image size, and the neutral colours;
// the title and the legend are measured, laid out and drawn here and nowhere
// else, so a plot and a scene cannot drift apart.
//
// Sizes are set at the 1600×1200 reference and scaled with the image: lengths
// by s = min(w/1600, h/1200), fonts and paddings by f = s^0.7 (they shrink
// more slowly, so a small figure stays readable).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "canvas.h"
#include "rigid/render/palette.h"
#include "rigid/render/plot2d.h"
#include "rigid/render/rect.h"

namespace rigid::render::detail {

// Neutral colours of the overlay and the axes.
inline constexpr Color kAxisColor = rgb8(60, 60, 60);
inline constexpr Color kGridColor = rgb8(232, 232, 232);
inline constexpr Color kTickTextColor = rgb8(50, 50, 50);
inline constexpr Color kLegendFill = kWhite.with_alpha(0.88f);
inline constexpr Color kLegendEdge = rgb8(190, 190, 190);

/// Every size of a figure at one image size, in pixels.
struct Style {
  double s = 1;  ///< geometry scale
  double f = 1;  ///< font and padding scale
  // Fonts.
  double title_font = 0, panel_title_font = 0, axis_label_font = 0, tick_font = 0;
  double legend_font = 0, note_font = 0, label_font = 0;  ///< note: annotations; label: 3D labels
  // Spacing: pad between neighbours, margin between the figure's outermost ink and the image edge.
  double pad = 0, margin = 0;
  // Axes.
  double tick_len = 0, frame_width = 0, grid_width = 0;
  // Legend: swatch length, gap swatch-text, inner padding, extra row height, outline width.
  double swatch = 0, swatch_gap = 0, legend_padding = 0, row_gap = 0, legend_edge = 0;
  /// Where the smallest text has a floor (a live view's panel), titles keep to it too:
  /// they wrap onto more lines rather than shrink below it. 0: no floor.
  double title_floor = 0;

  /// A line width given in reference pixels, never under 2 px.
  double line(double ref) const;
  /// A marker diameter given in reference pixels, never under 5 px.
  double marker(double ref) const;
};

/// The figure style at an image size, its smallest text (ticks, legend) at least
/// `min_text_px` pixels (0: no floor), the other sizes scaled with it.
Style figure_style(int width, int height, double min_text_px = 0);

/// Dash pattern in pixels for a line of a width.
DashPattern dash_pattern(Dash dash, double width, const Style& st);
/// Draws a marker symbol of a diameter centred at (x, y).
void draw_marker(Canvas& p, Marker m, double x, double y, double size, Color c);

/// The largest font size up to `size` at which markup fits in max_width (glyphs snap to whole
/// pixel sizes, so a proportional shrink alone can overshoot).
double fitting_size(std::string_view markup, double size, double max_width);

/// A title laid out: one or two lines at a size, in a box.
struct TitleBlock {
  std::vector<std::string> lines;
  double size = 0;       ///< font size in pixels after any shrinking
  double line_step = 0;  ///< baseline-to-baseline distance between lines
  ScreenRect box;        ///< the lines' extent (empty when there is no title)
};

/// The two halves of a title split at the top-level ", " or ": " (outside parentheses and
/// markup groups) nearest its middle; the separator's mark ends the first; {} if there is none.
std::vector<std::string> split_title(std::string_view markup, double size);

/// Lays out a title at font size `size` between left and right, centred on `centre` as far
/// as the room allows, top at `top`: wrapped onto two lines if wider than the room, then
/// shrunk if still too wide; but never below `floor` (0: no floor) while wrapping at more
/// blanks can keep it there.
TitleBlock layout_title(const std::string& markup, double size, double left, double right,
                        double centre, double top, double floor = 0);
/// Draws a laid-out title.
void draw_title(Canvas& p, const TitleBlock& title, Color color = kTextColor);

/// One legend row: a swatch (a line with dash and marker, or a filled box) and its label.
struct LegendEntry {
  std::string label;
  Color color;
  bool filled = false;    ///< a filled box (bands, spans, surfaces) instead of a line
  double line_width = 0;  ///< reference pixels; 0 draws no line
  Dash dash = Dash::kSolid;
  Marker marker = Marker::kNone;
  double marker_size = 0;  ///< reference pixels
};

/// The size of a legend box in pixels, the height of one row, and its columns: the
/// entries fill the first column top to bottom, then the next.
struct LegendSize {
  double width = 0, height = 0, row = 0;
  int columns = 1;
  double column = 0;  ///< the width of one column, swatch and text
};

/// Measures the legend box for a list of entries in one column.
LegendSize measure_legend(const std::vector<LegendEntry>& entries, const Style& st);
/// Measures it in as few rows as the columns that fit in `max_width` allow, then as few
/// columns as those rows need (10 entries, room for 3: columns of 4, 4 and 2).
LegendSize measure_legend(const std::vector<LegendEntry>& entries, const Style& st,
                          double max_width);
/// Draws a legend's entries in a box of the measured size.
void draw_legend(Canvas& p, const std::vector<LegendEntry>& entries, const ScreenRect& box,
                 const Style& st, const LegendSize& size);
/// Draws a legend of one column.
void draw_legend(Canvas& p, const std::vector<LegendEntry>& entries, const ScreenRect& box,
                 const Style& st);

/// The box of a text at an anchor, as Canvas::text places it (horizontal text).
ScreenRect text_box(const TextExtent& e, double x, double y, HAlign h, VAlign v);

}  // namespace rigid::render::detail
