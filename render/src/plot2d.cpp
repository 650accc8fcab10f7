// 2D plots: layout from measured text, axes and ticks, series, legend.
#include "rigid/render/plot2d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "painter.h"
#include "rigid/render/png.h"
#include "rigid/render/text.h"
#include "rigid/render/ticks.h"
#include "target.h"

namespace rigid::render {

using detail::P3;

// ---- Panel builders --------------------------------------------------------

Series& Panel::add_line(std::vector<double> xs, std::vector<double> ys, std::string label) {
  Series s;
  s.x = std::move(xs);
  s.y = std::move(ys);
  s.label = std::move(label);
  series.push_back(std::move(s));
  return series.back();
}

Series& Panel::add_points(std::vector<double> xs, std::vector<double> ys, std::string label,
                          Marker marker) {
  Series& s = add_line(std::move(xs), std::move(ys), std::move(label));
  s.width = 0;
  s.marker = marker;
  return s;
}

Band& Panel::add_band(std::vector<double> xs, std::vector<double> lo, std::vector<double> hi,
                      std::string label) {
  Band b;
  b.x = std::move(xs);
  b.y_lo = std::move(lo);
  b.y_hi = std::move(hi);
  b.label = std::move(label);
  bands.push_back(std::move(b));
  return bands.back();
}

Span& Panel::add_span(double lo, double hi, bool vertical, std::string label) {
  Span s;
  s.lo = lo;
  s.hi = hi;
  s.vertical = vertical;
  s.label = std::move(label);
  spans.push_back(std::move(s));
  return spans.back();
}

RefLine& Panel::add_ref_line(double value, bool vertical, std::string label) {
  RefLine r;
  r.value = value;
  r.vertical = vertical;
  r.label = std::move(label);
  ref_lines.push_back(std::move(r));
  return ref_lines.back();
}

Annotation& Panel::annotate(double x_, double y_, std::string text) {
  Annotation a;
  a.x = x_;
  a.y = y_;
  a.text = std::move(text);
  annotations.push_back(std::move(a));
  return annotations.back();
}

Plot2D::Plot2D(int rows, int cols) : rows_(rows), cols_(cols) {
  if (rows < 1 || cols < 1 || rows * cols > 64)
    throw std::invalid_argument("Plot2D: rows and cols must be 1..8 panels each way");
  panels_.resize(static_cast<std::size_t>(rows) * cols);
}

Panel& Plot2D::panel(int row, int col) {
  if (row < 0 || row >= rows_ || col < 0 || col >= cols_)
    throw std::out_of_range("Plot2D::panel: no such panel");
  return panels_[static_cast<std::size_t>(row) * cols_ + col];
}

const Panel& Plot2D::panel(int row, int col) const {
  return const_cast<Plot2D*>(this)->panel(row, col);
}

void Plot2D::save(const std::string& path, int width, int height) const {
  write_png(render(width, height), path);
}

// ---- Rendering -------------------------------------------------------------

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const Color kAxisColor = rgb8(60, 60, 60);
const Color kGridColor = rgb8(232, 232, 232);
const Color kTickTextColor = rgb8(50, 50, 50);

// Sizes at the 1600×1200 reference, multiplied by the figure's scale.
struct Style {
  double s = 1;       // geometry scale
  double f = 1;       // font scale (shrinks more slowly so small figures stay readable)
  double title = 0, panel_title = 0, label = 0, tick = 0, legend = 0, note = 0;
  double pad = 0, tick_len = 0, frame = 0;

  explicit Style(int w, int h) {
    s = std::min(w / 1600.0, h / 1200.0);
    f = std::pow(s, 0.7);
    title = 40 * f;
    panel_title = 33 * f;
    label = 31 * f;
    tick = 27 * f;
    legend = 27 * f;
    note = 27 * f;
    pad = 14 * f;
    tick_len = 9 * s;
    frame = std::max(1.0, 1.6 * s);
  }
  // A line width in reference pixels, never under 2 px.
  double line(double ref) const { return std::max(2.0, ref * s); }
};

// v clamped to [lo, hi]; the midpoint when the interval is empty.
double clamp_safe(double v, double lo, double hi) {
  return lo <= hi ? std::clamp(v, lo, hi) : 0.5 * (lo + hi);
}

// A font size no larger than `size` at which text fits into max_width.
double fit_size(const std::string& text, double size, double max_width) {
  const double w = measure_text(text, size).width;
  return w > max_width && w > 0 ? size * max_width / w : size;
}

struct Range {
  double lo = kNaN, hi = kNaN;
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::isnan(lo) ? v : std::min(lo, v);
    hi = std::isnan(hi) ? v : std::max(hi, v);
  }
};

// Data-to-pixel map for one axis.
struct AxisMap {
  Scale scale = Scale::kLinear;
  double lo = 0, hi = 1;    // data range
  double p0 = 0, p1 = 1;    // pixel positions of lo and hi
  double t(double v) const { return scale == Scale::kLog10 ? std::log10(v) : v; }
  double operator()(double v) const {
    return p0 + (t(v) - t(lo)) / (t(hi) - t(lo)) * (p1 - p0);
  }
  bool valid(double v) const { return std::isfinite(v) && (scale == Scale::kLinear || v > 0); }
};

// Axis range from data: padded by 4% (in log space for log axes), or as the user fixed it.
void finish_range(const Axis& axis, Range r, double& lo, double& hi) {
  const bool log = axis.scale == Scale::kLog10;
  if (std::isnan(r.lo)) r = log ? Range{1, 10} : Range{0, 1};
  double a = log ? std::log10(r.lo) : r.lo, b = log ? std::log10(r.hi) : r.hi;
  // Flat data (a span below 1e-12 of its size, whatever its units) gets a
  // range of its own size, or 1 about zero; data of any magnitude keep their scale.
  if (b - a <= 1e-12 * std::max(std::abs(a), std::abs(b))) {
    const double d = log ? 0.5 : (a == 0 ? 1.0 : std::abs(a) * 0.1);
    a -= d;
    b += d;
  } else {
    const double pad = 0.04 * (b - a);
    a -= pad;
    b += pad;
  }
  lo = log ? std::pow(10.0, a) : a;
  hi = log ? std::pow(10.0, b) : b;
  if (std::isfinite(axis.min) && (!log || axis.min > 0)) lo = axis.min;
  if (std::isfinite(axis.max) && (!log || axis.max > 0)) hi = axis.max;
  if (!(hi > lo)) hi = lo + (log ? lo * 9 : 1);
}

Ticks make_ticks(const Axis& axis, double lo, double hi, int target) {
  return axis.scale == Scale::kLog10 ? log_ticks(lo, hi, std::max(2, target + 2))
                                     : linear_ticks(lo, hi, std::max(2, target));
}

detail::DashPattern dash_pattern(Dash d, double width, const Style& st) {
  const double u = st.s;
  switch (d) {
    case Dash::kSolid: return {};
    case Dash::kDashed: return {std::max(6.0, 18 * u), std::max(4.0, 11 * u) + width};
    case Dash::kDotted: return {0.01, std::max(3.0, 2.2 * width)};
    case Dash::kDashDot:
      return {std::max(6.0, 18 * u), std::max(3.0, 8 * u) + width, 0.01, std::max(3.0, 8 * u) + width};
  }
  return {};
}

void draw_marker(detail::Painter& p, Marker m, double x, double y, double size, Color c) {
  const double r = 0.5 * size;
  switch (m) {
    case Marker::kNone: break;
    case Marker::kCircle: p.disc({x, y, 0}, r, c); break;
    case Marker::kSquare: p.rect(x - 0.85 * r, y - 0.85 * r, x + 0.85 * r, y + 0.85 * r, c); break;
    case Marker::kTriangle:
      p.triangle({x, y - 1.15 * r, 0}, {x - r, y + 0.6 * r, 0}, {x + r, y + 0.6 * r, 0}, c);
      break;
  }
}

struct LegendEntry {
  std::string label;
  Color color;
  double width = 0;
  Dash dash = Dash::kSolid;
  Marker marker = Marker::kNone;
  double marker_size = 0;
  bool filled = false;  // a band or span: a filled swatch
};

struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

class PanelRenderer {
 public:
  PanelRenderer(const Panel& panel, const Style& st, detail::Painter& p) : pn_(panel), st_(st), p_(p) {}

  void draw(const Box& cell) {
    resolve_colors();
    ranges();
    layout(cell);
    if (pn_.equal_aspect) equalize();
    xt_ = ticks_fitting(pn_.x, xm_, true);
    yt_ = ticks_fitting(pn_.y, ym_, false);
    background();
    data();
    frame_and_ticks();
    labels();
    legend();
  }

 private:
  void resolve_colors() {
    std::size_t k = 0;
    series_colors_.clear();
    for (const Series& s : pn_.series)
      series_colors_.push_back(s.color.a < 0 ? palette_color(k++) : s.color);
    band_colors_.clear();
    for (const Band& b : pn_.bands) band_colors_.push_back(b.color.a < 0 ? palette_color(k++) : b.color);
  }

  void ranges() {
    Range rx, ry;
    auto add = [&](const Axis& a, Range& r, double v) {
      if (a.scale == Scale::kLinear || v > 0) r.add(v);
    };
    for (const Series& s : pn_.series) {
      const std::size_t n = std::min(s.x.size(), s.y.size());
      for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
        add(pn_.x, rx, s.x[i]);
        add(pn_.y, ry, s.y[i]);
      }
    }
    for (const Band& b : pn_.bands) {
      const std::size_t n = std::min({b.x.size(), b.y_lo.size(), b.y_hi.size()});
      for (std::size_t i = 0; i < n; ++i) {
        add(pn_.x, rx, b.x[i]);
        add(pn_.y, ry, b.y_lo[i]);
        add(pn_.y, ry, b.y_hi[i]);
      }
    }
    for (const Span& s : pn_.spans) {
      add(s.vertical ? pn_.x : pn_.y, s.vertical ? rx : ry, s.lo);
      add(s.vertical ? pn_.x : pn_.y, s.vertical ? rx : ry, s.hi);
    }
    for (const RefLine& r : pn_.ref_lines) add(r.vertical ? pn_.x : pn_.y, r.vertical ? rx : ry, r.value);
    for (const Annotation& a : pn_.annotations) {
      add(pn_.x, rx, a.x);
      add(pn_.y, ry, a.y);
    }
    xm_.scale = pn_.x.scale;
    ym_.scale = pn_.y.scale;
    finish_range(pn_.x, rx, xm_.lo, xm_.hi);
    finish_range(pn_.y, ry, ym_.lo, ym_.hi);
  }

  // Widest tick label width and tallest height for a tick set.
  TextExtent tick_extent(const Ticks& t) const {
    TextExtent e;
    for (const std::string& l : t.labels) {
      const TextExtent m = measure_text(l, st_.tick);
      e.width = std::max(e.width, m.width);
      e.ascent = std::max(e.ascent, m.ascent);
      e.descent = std::max(e.descent, m.descent);
    }
    return e;
  }

  // Ticks thinned until their labels do not collide along the axis.
  Ticks ticks_fitting(const Axis& axis, const AxisMap& m, bool horizontal) const {
    const double len = std::abs(m.p1 - m.p0);
    int target = std::max(2, static_cast<int>(len / ((horizontal ? 190 : 120) * st_.f)));
    Ticks t;
    for (; target >= 1; --target) {
      t = make_ticks(axis, m.lo, m.hi, target);
      const TextExtent e = tick_extent(t);
      const double need = horizontal ? e.width + 2.5 * st_.pad : e.height() + 1.2 * st_.pad;
      double gap = std::numeric_limits<double>::infinity();
      for (std::size_t i = 1; i < t.values.size(); ++i)
        gap = std::min(gap, std::abs(m(t.values[i]) - m(t.values[i - 1])));
      if (gap >= need || t.values.size() <= 2) break;
    }
    return t;
  }

  // Plot rectangle inside the cell, with margins from measured text.
  void layout(const Box& cell) {
    // First guess of the rectangle, to choose ticks; then margins from their labels.
    Box r{cell.x0 + 0.15 * (cell.x1 - cell.x0), cell.y0 + 0.08 * (cell.y1 - cell.y0),
          cell.x1 - 0.04 * (cell.x1 - cell.x0), cell.y1 - 0.14 * (cell.y1 - cell.y0)};
    for (int pass = 0; pass < 2; ++pass) {
      xm_.p0 = r.x0, xm_.p1 = r.x1, ym_.p0 = r.y1, ym_.p1 = r.y0;
      const Ticks xt = ticks_fitting(pn_.x, xm_, true);
      const Ticks yt = ticks_fitting(pn_.y, ym_, false);
      const TextExtent xe = tick_extent(xt), ye = tick_extent(yt);
      // Axis labels shrink if longer than their side of the cell.
      xlabel_size_ = fit_size(pn_.x.label, st_.label, cell.x1 - cell.x0 - 2 * st_.pad);
      ylabel_size_ = fit_size(pn_.y.label, st_.label, cell.y1 - cell.y0 - 2 * st_.pad);
      const double ylabel_h = pn_.y.label.empty() ? 0 : measure_text(pn_.y.label, ylabel_size_).height() + st_.pad;
      const double xlabel_h = pn_.x.label.empty() ? 0 : measure_text(pn_.x.label, xlabel_size_).height() + st_.pad;
      title_size_ = fit_size(pn_.title, st_.panel_title, cell.x1 - cell.x0 - 2 * st_.pad);
      const double title_h =
          pn_.title.empty() ? st_.pad : measure_text(pn_.title, title_size_).height() + 1.2 * st_.pad;
      const double last_x_half = xt.labels.empty() ? 0 : 0.5 * measure_text(xt.labels.back(), st_.tick).width;
      r.x0 = cell.x0 + st_.pad + ylabel_h + ye.width + st_.tick_len + 0.8 * st_.pad;
      r.x1 = cell.x1 - std::max(1.5 * st_.pad, last_x_half + 0.5 * st_.pad);
      r.y0 = cell.y0 + title_h + 0.5 * ye.height();
      r.y1 = cell.y1 - (st_.pad + xlabel_h + xe.height() + st_.tick_len + 0.6 * st_.pad);
      r.x0 = std::round(r.x0), r.x1 = std::round(r.x1), r.y0 = std::round(r.y0), r.y1 = std::round(r.y1);
      if (r.x1 - r.x0 < 20) r.x1 = r.x0 + 20;
      if (r.y1 - r.y0 < 20) r.y1 = r.y0 + 20;
    }
    rect_ = r;
    cell_ = cell;
    xm_.p0 = r.x0, xm_.p1 = r.x1, ym_.p0 = r.y1, ym_.p1 = r.y0;
  }

  // Equal aspect: widen whichever axis range has more pixels per unit (linear axes only).
  void equalize() {
    if (xm_.scale != Scale::kLinear || ym_.scale != Scale::kLinear) return;
    const double wx = rect_.x1 - rect_.x0, wy = rect_.y1 - rect_.y0;
    const double ux = wx / (xm_.hi - xm_.lo), uy = wy / (ym_.hi - ym_.lo);
    if (ux > uy) {
      const double c = 0.5 * (xm_.lo + xm_.hi), half = 0.5 * wx / uy;
      xm_.lo = c - half, xm_.hi = c + half;
    } else {
      const double c = 0.5 * (ym_.lo + ym_.hi), half = 0.5 * wy / ux;
      ym_.lo = c - half, ym_.hi = c + half;
    }
  }

  P3 map(double x, double y) const { return {xm_(x), ym_(y), 0}; }

  void background() {
    p_.clip(rect_.x0, rect_.y0, rect_.x1, rect_.y1);
    for (const Span& s : pn_.spans) {
      const Color c = s.color.with_alpha(s.opacity);
      if (s.vertical) p_.rect(xm_(s.lo), rect_.y0, xm_(s.hi), rect_.y1, c);
      else p_.rect(rect_.x0, ym_(s.hi), rect_.x1, ym_(s.lo), c);
    }
    const double gw = std::max(1.0, 1.5 * st_.s);
    if (pn_.x.grid)
      for (double v : xt_.values) p_.rect(xm_(v) - 0.5 * gw, rect_.y0, xm_(v) + 0.5 * gw, rect_.y1, kGridColor);
    if (pn_.y.grid)
      for (double v : yt_.values) p_.rect(rect_.x0, ym_(v) - 0.5 * gw, rect_.x1, ym_(v) + 0.5 * gw, kGridColor);
  }

  void data() {
    // Bands first (translucent, under the lines), as quads between consecutive samples.
    for (std::size_t b = 0; b < pn_.bands.size(); ++b) {
      const Band& band = pn_.bands[b];
      const Color c = band_colors_[b].with_alpha(band.opacity);
      const std::size_t n = std::min({band.x.size(), band.y_lo.size(), band.y_hi.size()});
      for (std::size_t i = 0; i + 1 < n; ++i) {
        if (!xm_.valid(band.x[i]) || !xm_.valid(band.x[i + 1]) || !ym_.valid(band.y_lo[i]) ||
            !ym_.valid(band.y_hi[i]) || !ym_.valid(band.y_lo[i + 1]) || !ym_.valid(band.y_hi[i + 1]))
          continue;
        p_.convex({map(band.x[i], band.y_lo[i]), map(band.x[i + 1], band.y_lo[i + 1]),
                   map(band.x[i + 1], band.y_hi[i + 1]), map(band.x[i], band.y_hi[i])},
                  c);
      }
    }
    for (const RefLine& r : pn_.ref_lines) {
      const double w = st_.line(r.width);
      const auto dash = dash_pattern(r.dash, w, st_);
      if (r.vertical) p_.polyline({{xm_(r.value), rect_.y1, 0}, {xm_(r.value), rect_.y0, 0}}, w, r.color, dash);
      else p_.polyline({{rect_.x0, ym_(r.value), 0}, {rect_.x1, ym_(r.value), 0}}, w, r.color, dash);
    }
    for (std::size_t k = 0; k < pn_.series.size(); ++k) {
      const Series& s = pn_.series[k];
      const Color c = series_colors_[k];
      const std::size_t n = std::min(s.x.size(), s.y.size());
      if (s.width > 0) {
        const double w = st_.line(s.width);
        const auto dash = dash_pattern(s.dash, w, st_);
        const bool round = s.dash == Dash::kDotted || s.dash == Dash::kDashDot;
        // Break the line at points an axis cannot show (NaN, or <= 0 on a log axis).
        std::vector<P3> run;
        auto emit = [&] {
          if (run.size() >= 2) p_.polyline(run, w, c, dash, round);
          run.clear();
        };
        for (std::size_t i = 0; i < n; ++i) {
          if (!xm_.valid(s.x[i]) || !ym_.valid(s.y[i])) {
            emit();
            continue;
          }
          P3 q = map(s.x[i], s.y[i]);
          q.x() = std::clamp(q.x(), -1e5, 1e5);
          q.y() = std::clamp(q.y(), -1e5, 1e5);
          run.push_back(q);
        }
        emit();
      }
      if (s.marker != Marker::kNone) {
        const double size = std::max(5.0, s.marker_size * st_.s);
        for (std::size_t i = 0; i < n; ++i)
          if (xm_.valid(s.x[i]) && ym_.valid(s.y[i]))
            draw_marker(p_, s.marker, xm_(s.x[i]), ym_(s.y[i]), size, c);
      }
    }
    // Reference-line labels sit inside the panel at the line's far end.
    for (const RefLine& r : pn_.ref_lines) {
      if (r.label.empty()) continue;
      if (r.vertical)
        p_.text(r.label, xm_(r.value) - 0.4 * st_.pad, rect_.y0 + 0.5 * st_.pad, st_.note, r.color,
                HAlign::kRight, VAlign::kBottom, true);
      else
        p_.text(r.label, rect_.x1 - 0.5 * st_.pad, ym_(r.value) - 0.4 * st_.pad, st_.note, r.color,
                HAlign::kRight, VAlign::kBottom);
    }
    p_.no_clip();
    annotations();
  }

  void annotations() {
    for (const Annotation& a : pn_.annotations) {
      if (!xm_.valid(a.x) || !ym_.valid(a.y)) continue;
      const P3 pt = map(a.x, a.y);
      const double tx = pt.x() + a.offset_x * st_.s, ty = pt.y() + a.offset_y * st_.s;
      const TextExtent e = measure_text(a.text, st_.note);
      // Keep the text inside the panel cell.
      const double cx = clamp_safe(tx, cell_.x0 + 0.5 * e.width + 2, cell_.x1 - 0.5 * e.width - 2);
      const double cy = clamp_safe(ty, cell_.y0 + 0.5 * e.height() + 2, cell_.y1 - 0.5 * e.height() - 2);
      p_.text(a.text, cx, cy, st_.note, a.color, HAlign::kCenter, VAlign::kCenter);
      if (!a.arrow) continue;
      // Arrow from the text box's edge to just short of the point.
      Eigen::Vector2d d(pt.x() - cx, pt.y() - cy);
      const double len = d.norm();
      if (len < 1) continue;
      d /= len;
      const double hx = 0.5 * e.width + 0.4 * st_.pad, hy = 0.5 * e.height() + 0.3 * st_.pad;
      const double t0 = std::min(std::abs(d.x()) > 1e-9 ? hx / std::abs(d.x()) : 1e9,
                                 std::abs(d.y()) > 1e-9 ? hy / std::abs(d.y()) : 1e9);
      const double t1 = len - 0.5 * st_.pad;
      if (t1 <= t0) continue;
      const double w = st_.line(2.0), head = std::max(8.0, 16 * st_.s);
      const Eigen::Vector2d a0 = Eigen::Vector2d(cx, cy) + d * t0, tip = Eigen::Vector2d(cx, cy) + d * t1;
      const Eigen::Vector2d base = tip - d * head, nrm(-d.y(), d.x());
      p_.polyline({{a0.x(), a0.y(), 0}, {base.x(), base.y(), 0}}, w, a.color);
      const Eigen::Vector2d l = base + nrm * head * 0.4, r = base - nrm * head * 0.4;
      p_.triangle({tip.x(), tip.y(), 0}, {l.x(), l.y(), 0}, {r.x(), r.y(), 0}, a.color);
    }
  }

  void frame_and_ticks() {
    const double fw = st_.frame;
    p_.rect_outline(rect_.x0 - fw, rect_.y0 - fw, rect_.x1 + fw, rect_.y1 + fw, fw, kAxisColor);
    const double tw = fw, tl = st_.tick_len;
    for (std::size_t i = 0; i < xt_.values.size(); ++i) {
      const double x = xm_(xt_.values[i]);
      p_.rect(x - 0.5 * tw, rect_.y1 + fw, x + 0.5 * tw, rect_.y1 + fw + tl, kAxisColor);
      p_.text(xt_.labels[i], x, rect_.y1 + fw + tl + 0.4 * st_.pad, st_.tick, kTickTextColor,
              HAlign::kCenter, VAlign::kTop);
    }
    for (double v : xt_.minor) {
      const double x = xm_(v);
      p_.rect(x - 0.5 * tw, rect_.y1 + fw, x + 0.5 * tw, rect_.y1 + fw + 0.55 * tl, kAxisColor);
    }
    for (std::size_t i = 0; i < yt_.values.size(); ++i) {
      const double y = ym_(yt_.values[i]);
      p_.rect(rect_.x0 - fw - tl, y - 0.5 * tw, rect_.x0 - fw, y + 0.5 * tw, kAxisColor);
      p_.text(yt_.labels[i], rect_.x0 - fw - tl - 0.4 * st_.pad, y, st_.tick, kTickTextColor,
              HAlign::kRight, VAlign::kCenter);
    }
    for (double v : yt_.minor) {
      const double y = ym_(v);
      p_.rect(rect_.x0 - fw - 0.55 * tl, y - 0.5 * tw, rect_.x0 - fw, y + 0.5 * tw, kAxisColor);
    }
  }

  void labels() {
    if (!pn_.x.label.empty())
      p_.text(pn_.x.label, clamp_safe(0.5 * (rect_.x0 + rect_.x1), cell_.x0 + 0.5 * measure_text(pn_.x.label, xlabel_size_).width + st_.pad, cell_.x1 - 0.5 * measure_text(pn_.x.label, xlabel_size_).width - st_.pad),
              cell_.y1 - st_.pad, xlabel_size_, kTextColor, HAlign::kCenter, VAlign::kBottom);
    if (!pn_.y.label.empty())
      p_.text(pn_.y.label, cell_.x0 + st_.pad, clamp_safe(0.5 * (rect_.y0 + rect_.y1), cell_.y0 + 0.5 * measure_text(pn_.y.label, ylabel_size_).width + st_.pad, cell_.y1 - 0.5 * measure_text(pn_.y.label, ylabel_size_).width - st_.pad),
              ylabel_size_, kTextColor, HAlign::kCenter, VAlign::kTop, true);
    if (!pn_.title.empty()) {
      // Centred over the plot area, but kept inside the cell.
      const double half = 0.5 * measure_text(pn_.title, title_size_).width + st_.pad;
      const double x = clamp_safe(0.5 * (rect_.x0 + rect_.x1), cell_.x0 + half, cell_.x1 - half);
      p_.text(pn_.title, x, rect_.y0 - 0.8 * st_.pad, title_size_, kTextColor, HAlign::kCenter, VAlign::kBottom);
    }
  }

  void legend() {
    std::vector<LegendEntry> entries;
    for (std::size_t k = 0; k < pn_.series.size(); ++k) {
      const Series& s = pn_.series[k];
      if (!s.label.empty())
        entries.push_back({s.label, series_colors_[k], s.width, s.dash, s.marker, s.marker_size, false});
    }
    for (std::size_t k = 0; k < pn_.bands.size(); ++k)
      if (!pn_.bands[k].label.empty())
        entries.push_back({pn_.bands[k].label, band_colors_[k].with_alpha(std::max(0.35f, pn_.bands[k].opacity)),
                           0, Dash::kSolid, Marker::kNone, 0, true});
    for (const Span& s : pn_.spans)
      if (!s.label.empty())
        entries.push_back({s.label, s.color.with_alpha(std::max(0.3f, s.opacity)), 0, Dash::kSolid,
                           Marker::kNone, 0, true});
    if (entries.empty() || pn_.legend == LegendPlace::kNone) return;

    const double swatch = 60 * st_.f, gap = 0.7 * st_.pad, pad = 0.8 * st_.pad;
    double text_w = 0, row_h = 0;
    for (const LegendEntry& e : entries) {
      const TextExtent m = measure_text(e.label, st_.legend);
      text_w = std::max(text_w, m.width);
      row_h = std::max(row_h, m.height());
    }
    row_h += 0.35 * st_.pad;
    const double bw = pad + swatch + gap + text_w + pad, bh = 2 * pad + row_h * entries.size();
    const double inset = 0.8 * st_.pad;
    const Box corners[4] = {
        {rect_.x1 - inset - bw, rect_.y0 + inset, rect_.x1 - inset, rect_.y0 + inset + bh},  // TR
        {rect_.x0 + inset, rect_.y0 + inset, rect_.x0 + inset + bw, rect_.y0 + inset + bh},  // TL
        {rect_.x1 - inset - bw, rect_.y1 - inset - bh, rect_.x1 - inset, rect_.y1 - inset},  // BR
        {rect_.x0 + inset, rect_.y1 - inset - bh, rect_.x0 + inset + bw, rect_.y1 - inset}};  // BL
    int pick = 0;
    switch (pn_.legend) {
      case LegendPlace::kTopRight: pick = 0; break;
      case LegendPlace::kTopLeft: pick = 1; break;
      case LegendPlace::kBottomRight: pick = 2; break;
      case LegendPlace::kBottomLeft: pick = 3; break;
      default: pick = least_covered(corners); break;
    }
    const Box b = corners[pick];
    p_.rect(b.x0, b.y0, b.x1, b.y1, kWhite.with_alpha(0.88f));
    p_.rect_outline(b.x0, b.y0, b.x1, b.y1, std::max(1.0, 1.2 * st_.s), rgb8(190, 190, 190));
    double y = b.y0 + pad + 0.5 * row_h;
    for (const LegendEntry& e : entries) {
      const double x0 = b.x0 + pad, x1 = x0 + swatch;
      if (e.filled) {
        p_.rect(x0, y - 0.3 * row_h, x1, y + 0.3 * row_h, e.color);
      } else {
        if (e.width > 0) {
          const double w = st_.line(e.width);
          p_.polyline({{x0, y, 0}, {x1, y, 0}}, w, e.color, dash_pattern(e.dash, w, st_),
                      e.dash == Dash::kDotted || e.dash == Dash::kDashDot);
        }
        if (e.marker != Marker::kNone)
          draw_marker(p_, e.marker, 0.5 * (x0 + x1), y, std::max(5.0, e.marker_size * st_.s), e.color);
      }
      p_.text(e.label, x1 + gap, y, st_.legend, kTextColor, HAlign::kLeft, VAlign::kCenter);
      y += row_h;
    }
  }

  // The corner box covering the fewest drawn data points (ties: TR, TL, BR, BL).
  int least_covered(const Box (&boxes)[4]) const {
    long counts[4] = {0, 0, 0, 0};
    auto count_point = [&](double x, double y) {
      if (!xm_.valid(x) || !ym_.valid(y)) return;
      const P3 q = map(x, y);
      for (int k = 0; k < 4; ++k)
        if (boxes[k].contains(q.x(), q.y())) ++counts[k];
    };
    for (const Series& s : pn_.series) {
      const std::size_t n = std::min(s.x.size(), s.y.size());
      for (std::size_t i = 0; i < n; ++i) {
        count_point(s.x[i], s.y[i]);
        // Also sample long segments so a straight line through a corner counts.
        if (i + 1 < n)
          for (int j = 1; j < 8; ++j)
            count_point(s.x[i] + (s.x[i + 1] - s.x[i]) * j / 8.0, s.y[i] + (s.y[i + 1] - s.y[i]) * j / 8.0);
      }
    }
    for (const Band& b : pn_.bands) {
      const std::size_t n = std::min({b.x.size(), b.y_lo.size(), b.y_hi.size()});
      for (std::size_t i = 0; i < n; ++i)
        for (int j = 0; j <= 4; ++j) count_point(b.x[i], b.y_lo[i] + (b.y_hi[i] - b.y_lo[i]) * j / 4.0);
    }
    for (const Annotation& a : pn_.annotations) {
      count_point(a.x, a.y);
      const P3 q = map(a.x, a.y);
      for (int k = 0; k < 4; ++k)
        if (boxes[k].contains(q.x() + a.offset_x * st_.s, q.y() + a.offset_y * st_.s)) counts[k] += 50;
    }
    return static_cast<int>(std::min_element(counts, counts + 4) - counts);
  }

  const Panel& pn_;
  const Style& st_;
  detail::Painter& p_;
  std::vector<Color> series_colors_, band_colors_;
  AxisMap xm_, ym_;
  Ticks xt_, yt_;
  Box rect_, cell_;
  double title_size_ = 0, xlabel_size_ = 0, ylabel_size_ = 0;
};

}  // namespace

Image Plot2D::render(int width, int height) const {
  detail::Target& tgt = detail::target();
  // No depth buffer for 2D.
  tgt.begin(width, height, false, kWhite);
  detail::Painter& p = detail::painter();
  p.begin(width, height);
  const Style st(width, height);
  double top = 0;
  if (!title.empty()) {
    const double size = fit_size(title, st.title, width - 2 * st.pad);
    const TextExtent e = measure_text(title, size);
    p.text(title, 0.5 * width, st.pad, size, kTextColor, HAlign::kCenter, VAlign::kTop);
    top = st.pad + e.height() + 0.3 * st.pad;
  }
  const double cw = double(width) / cols_, ch = (height - top) / rows_;
  for (int r = 0; r < rows_; ++r)
    for (int c = 0; c < cols_; ++c) {
      const Box cell{c * cw, top + r * ch, (c + 1) * cw, top + (r + 1) * ch};
      PanelRenderer(panel(r, c), st, p).draw(cell);
    }
  p.flush();
  return tgt.finish();
}

}  // namespace rigid::render
