// The figure style, the title and the legend of every plot and scene.
#include "overlay.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace rigid::render::detail {

Style figure_style(int width, int height, double min_text_px) {
  // the smallest fonts (ticks, legend, notes) are 27 px at the reference
  constexpr double kSmallestFont = 27;
  Style st;
  st.s = std::min(width / 1600.0, height / 1200.0);
  st.f = std::max(std::pow(st.s, 0.7), min_text_px / kSmallestFont);
  const double f = st.f, s = st.s;
  st.title_font = 40 * f;
  st.panel_title_font = 33 * f;
  st.axis_label_font = 31 * f;
  st.tick_font = kSmallestFont * f;
  st.legend_font = kSmallestFont * f;
  st.note_font = kSmallestFont * f;
  st.label_font = 34 * f;
  st.pad = 14 * f;
  // Two paddings: the title, a plot's axis labels and a scene's geometry all
  // keep this much white between themselves and the image's edge.
  st.margin = 2 * st.pad;
  st.tick_len = 9 * s;
  st.frame_width = std::max(1.0, 1.6 * s);
  st.grid_width = std::max(1.0, 1.5 * s);
  st.swatch = 52 * f;
  st.swatch_gap = 0.7 * st.pad;
  st.legend_padding = 0.8 * st.pad;
  st.row_gap = 0.35 * st.pad;
  st.legend_edge = std::max(1.0, 1.2 * s);
  st.title_floor = min_text_px > 0 ? st.legend_font : 0.0;
  return st;
}

double Style::line(double ref) const {
  return std::max(2.0, ref * s);
}

double Style::marker(double ref) const {
  return std::max(5.0, ref * s);
}

DashPattern dash_pattern(Dash d, double width, const Style& st) {
  const double u = st.s;
  switch (d) {
    case Dash::kSolid:
      return {};
    case Dash::kDashed:
      return {std::max(6.0, 18 * u), std::max(4.0, 11 * u) + width};
    case Dash::kDotted:
      return {0.01, std::max(3.0, 2.2 * width)};
    case Dash::kDashDot:
      return {std::max(6.0, 18 * u), std::max(3.0, 8 * u) + width, 0.01,
              std::max(3.0, 8 * u) + width};
  }
  return {};
}

namespace {
constexpr double kPi = 3.14159265358979323846;

// A regular polygon of n corners on a circle of radius r about (x, y), the first at angle a0
// (radians, counter-clockwise from +x on screen, y down).
std::vector<P3> regular_polygon(double x, double y, double r, int n, double a0) {
  std::vector<P3> pts;
  for (int k = 0; k < n; ++k) {
    const double a = a0 + 2 * kPi * k / n;
    pts.push_back({x + r * std::cos(a), y - r * std::sin(a), 0});
  }
  return pts;
}

// A bar of half length h and half width w through (x, y) at angle a: a plus's or a cross's
// arm.
std::vector<P3> bar(double x, double y, double h, double w, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {{x + h * c - w * s, y - h * s - w * c, 0},
          {x + h * c + w * s, y - h * s + w * c, 0},
          {x - h * c + w * s, y + h * s + w * c, 0},
          {x - h * c - w * s, y + h * s - w * c, 0}};
}

void marker_shape(Canvas& p, Marker m, double x, double y, double r, Color c) {
  // the triangles' centroid on the point, their area about the square's
  const double t = 1.25 * r;
  switch (m) {
    case Marker::kNone:
      break;
    case Marker::kCircle:
      p.disc({x, y, 0}, r, c);
      break;
    case Marker::kSquare:
      p.rect(x - 0.85 * r, y - 0.85 * r, x + 0.85 * r, y + 0.85 * r, c);
      break;
    case Marker::kTriangle:
      p.convex(regular_polygon(x, y, t, 3, kPi / 2), c);
      break;
    case Marker::kTriangleDown:
      p.convex(regular_polygon(x, y, t, 3, -kPi / 2), c);
      break;
    case Marker::kTriangleLeft:
      p.convex(regular_polygon(x, y, t, 3, kPi), c);
      break;
    case Marker::kTriangleRight:
      p.convex(regular_polygon(x, y, t, 3, 0), c);
      break;
    case Marker::kDiamond:
      p.convex(regular_polygon(x, y, 1.2 * r, 4, 0), c);
      break;
    case Marker::kHexagon:
      p.convex(regular_polygon(x, y, 1.05 * r, 6, kPi / 2), c);
      break;
    case Marker::kPlus:
    case Marker::kCross: {
      const double a = m == Marker::kPlus ? 0 : kPi / 4;
      p.convex(bar(x, y, 1.15 * r, 0.38 * r, a), c);
      p.convex(bar(x, y, 1.15 * r, 0.38 * r, a + kPi / 2), c);
      break;
    }
  }
}
}  // namespace

// A marker with a contrasting edge, white round a dark one and dark round a light one,
// so it stays visible on a curve of its own colour.
void draw_marker(Canvas& p, Marker m, double x, double y, double size, Color c) {
  const double r = 0.5 * size, edge = std::max(1.5, 0.2 * r);
  const double luminance = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
  const Color rim = luminance < 0.6 ? kWhite : kTextColor;
  marker_shape(p, m, x, y, r + edge, rim.with_alpha(c.a));
  marker_shape(p, m, x, y, r, c);
}

ScreenRect text_box(const TextExtent& e, double x, double y, HAlign h, VAlign v) {
  const double x0 = x + text_start_offset(e, h), base = y + text_baseline_offset(e, v);
  return {x0, base - e.ascent, x0 + e.width, base + e.descent};
}

// ---- Title -------------------------------------------------------------------

double fitting_size(std::string_view markup, double size, double max_width) {
  double w = measure_text(markup, size).width;
  for (int k = 0; k < 8 && w > max_width && size > 1; ++k) {
    size = std::min(size * max_width / w, size - 0.5);
    w = measure_text(markup, size).width;
  }
  return std::max(size, 1.0);  // no room at all still gives a size, not zero or less
}

std::vector<std::string> split_title(std::string_view m, double size) {
  // Candidate break points: the index of the mark of a ", " or ": " at depth 0.
  std::vector<std::size_t> marks;
  int depth = 0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const char c = m[i];
    if (c == '\\') {
      // An escaped character (\{, \_, \\) is literal; a command name is letters.
      if (i + 1 < m.size() && !std::isalpha(static_cast<unsigned char>(m[i + 1]))) ++i;
      continue;
    }
    if (c == '(' || c == '{' || c == '[')
      ++depth;
    else if (c == ')' || c == '}' || c == ']')
      depth = std::max(0, depth - 1);
    else if ((c == ',' || c == ':') && depth == 0 && i + 1 < m.size() && m[i + 1] == ' ')
      marks.push_back(i);
  }
  if (marks.empty()) return {};
  // Nearest the middle by drawn width, so both lines come out about as long.
  const double half = 0.5 * measure_text(m, size).width;
  std::size_t best = marks.front();
  double best_gap = 1e300;
  for (std::size_t i : marks) {
    const double gap = std::abs(measure_text(m.substr(0, i + 1), size).width - half);
    if (gap < best_gap) best_gap = gap, best = i;
  }
  return {std::string(m.substr(0, best + 1)), std::string(m.substr(best + 2))};
}

namespace {

// Markup's words: split at the blanks outside markup groups ("\\omega_{1 2}" stays whole).
std::vector<std::string> title_words(std::string_view m) {
  std::vector<std::string> words(1);
  int depth = 0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const char c = m[i];
    if (c == '\\' && i + 1 < m.size() && !std::isalpha(static_cast<unsigned char>(m[i + 1]))) {
      words.back() += m.substr(i, 2);
      ++i;
      continue;
    }
    if (c == '{') ++depth;
    if (c == '}') depth = std::max(0, depth - 1);
    if (c == ' ' && depth == 0) {
      if (!words.back().empty()) words.emplace_back();
      continue;
    }
    words.back() += c;
  }
  if (words.back().empty()) words.pop_back();
  return words;
}

// Words that read as one stay on one line: "omega = 10 rad/s", not "omega" above "= 10".
// A "=" joins both its neighbours, and a word after a number (its unit) joins that number.
std::vector<std::string> title_phrases(std::string_view m) {
  std::vector<std::string> phrases;
  bool join_next = false;
  for (const std::string& w : title_words(m)) {
    const bool after_number = !phrases.empty() &&
                              std::isdigit(static_cast<unsigned char>(phrases.back().back())) &&
                              !std::isdigit(static_cast<unsigned char>(w.front()));
    if (!phrases.empty() && (join_next || w == "=" || after_number)) {
      phrases.back() += " " + w;
    } else {
      phrases.push_back(w);
    }
    join_next = w == "=";
  }
  return phrases;
}

// Phrases filled into lines no wider than `room` at `size`; one wider alone is a line.
std::vector<std::string> fill_lines(std::string_view m, double size, double room) {
  std::vector<std::string> lines;
  for (const std::string& w : title_phrases(m)) {
    if (!lines.empty() && measure_text(lines.back() + " " + w, size).width <= room) {
      lines.back() += " " + w;
    } else {
      lines.push_back(w);
    }
  }
  return lines;
}

}  // namespace

TitleBlock layout_title(const std::string& markup, double size, double left, double right,
                        double centre, double top, double floor) {
  TitleBlock t;
  if (markup.empty()) return t;
  const double room = std::max(1.0, right - left);
  t.lines = {markup};
  if (measure_text(markup, size).width > room) {
    std::vector<std::string> two = split_title(markup, size);
    if (!two.empty()) t.lines = std::move(two);
  }
  t.size = size;
  for (const std::string& l : t.lines) t.size = std::min(t.size, fitting_size(l, size, room));
  if (t.size < floor) {
    t.size = std::min(size, floor);
    t.lines = fill_lines(markup, t.size, room);
    const double at = t.size;
    for (const std::string& l : t.lines) t.size = std::min(t.size, fitting_size(l, at, room));
  }
  // Lines a tenth of a text height apart.
  double height = 0, widest = 0;
  for (const std::string& l : t.lines) {
    const TextExtent e = measure_text(l, t.size);
    widest = std::max(widest, e.width);
    height = std::max(height, e.height());
  }
  t.line_step = 1.1 * height;
  const double half = 0.5 * widest;
  const double x = std::clamp(centre, left + half, std::max(left + half, right - half));
  t.box = {x - half, top, x + half, top + t.line_step * (t.lines.size() - 1) + height};
  return t;
}

void draw_title(Canvas& p, const TitleBlock& t, Color color) {
  const double x = 0.5 * (t.box.x0 + t.box.x1);
  for (std::size_t i = 0; i < t.lines.size(); ++i)
    p.text(t.lines[i], x, t.box.y0 + i * t.line_step, t.size, color, HAlign::kCenter, VAlign::kTop);
}

// ---- Legend ------------------------------------------------------------------

LegendSize measure_legend(const std::vector<LegendEntry>& entries, const Style& st) {
  LegendSize z;
  if (entries.empty()) return z;
  double text_w = 0;
  for (const LegendEntry& e : entries) {
    const TextExtent m = measure_text(e.label, st.legend_font);
    text_w = std::max(text_w, m.width);
    z.row = std::max(z.row, m.height());
  }
  z.row += st.row_gap;
  z.column = st.swatch + st.swatch_gap + text_w;
  z.width = 2 * st.legend_padding + z.column;
  z.height = 2 * st.legend_padding + z.row * entries.size();
  return z;
}

LegendSize measure_legend(const std::vector<LegendEntry>& entries, const Style& st,
                          double max_width) {
  LegendSize z = measure_legend(entries, st);
  if (entries.empty()) return z;
  // as few rows as the columns that fit allow, then as few columns as those rows need
  // (10 entries, room for 3: rows of 4, columns of 4, 4 and 2); columns a text's width
  // apart, with two swatch gaps between them
  const double gap = 2 * st.swatch_gap;
  const int n = static_cast<int>(entries.size());
  const int fit = static_cast<int>((max_width - 2 * st.legend_padding + gap) / (z.column + gap));
  const int rows = (n + std::clamp(fit, 1, n) - 1) / std::clamp(fit, 1, n);
  z.columns = (n + rows - 1) / rows;
  z.width = 2 * st.legend_padding + z.columns * z.column + (z.columns - 1) * gap;
  z.height = 2 * st.legend_padding + z.row * rows;
  return z;
}

void draw_legend(Canvas& p, const std::vector<LegendEntry>& entries, const ScreenRect& box,
                 const Style& st, const LegendSize& z) {
  if (entries.empty() || box.empty()) return;
  p.rect(box.x0, box.y0, box.x1, box.y1, kLegendFill);
  p.rect_outline(box.x0, box.y0, box.x1, box.y1, st.legend_edge, kLegendEdge);
  const std::size_t rows = (entries.size() + z.columns - 1) / z.columns;
  const double step =
      z.columns > 1 ? (box.width() - 2 * st.legend_padding - z.column) / (z.columns - 1) : 0.0;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const LegendEntry& e = entries[k];
    const double y = box.y0 + st.legend_padding + (0.5 + static_cast<double>(k % rows)) * z.row;
    const double x0 = box.x0 + st.legend_padding + static_cast<double>(k / rows) * step,
                 x1 = x0 + st.swatch;
    if (e.filled) {
      p.rect(x0, y - 0.3 * z.row, x1, y + 0.3 * z.row, e.color);
    } else {
      if (e.line_width > 0) {
        const double w = st.line(e.line_width);
        p.polyline({{x0, y, 0}, {x1, y, 0}}, w, e.color, dash_pattern(e.dash, w, st),
                   e.dash == Dash::kDotted || e.dash == Dash::kDashDot);
      }
      if (e.marker != Marker::kNone)
        draw_marker(p, e.marker, 0.5 * (x0 + x1), y, st.marker(e.marker_size), e.color);
    }
    p.text(e.label, x1 + st.swatch_gap, y, st.legend_font, kTextColor, HAlign::kLeft,
           VAlign::kCenter);
  }
}

void draw_legend(Canvas& p, const std::vector<LegendEntry>& entries, const ScreenRect& box,
                 const Style& st) {
  draw_legend(p, entries, box, st, measure_legend(entries, st));
}

}  // namespace rigid::render::detail
