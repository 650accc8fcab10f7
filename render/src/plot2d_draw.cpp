// Drawing 2D plots: each panel is planned first (ranges, ticks, frame, and
// where the legend, reference-line labels and annotations go, from an
// occupancy grid of the data), then drawn. Title and legend come from the
// shared overlay (overlay.h), so they look as in a 3D scene.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "overlay.h"
#include "painter.h"
#include "placement.h"
#include "rigid/render/draw.h"
#include "rigid/render/plot2d.h"
#include "rigid/render/text.h"
#include "rigid/render/ticks.h"
#include "target.h"

namespace rigid::render {

using detail::P3;
using detail::Style;
using Eigen::Vector2d;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// v clamped to [lo, hi]; the midpoint when the interval is empty.
double clamp_safe(double v, double lo, double hi) {
  return lo <= hi ? std::clamp(v, lo, hi) : 0.5 * (lo + hi);
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
  double lo = 0, hi = 1;  // data range
  double p0 = 0, p1 = 1;  // pixel positions of lo and hi
  double t(double v) const { return scale == Scale::kLog10 ? std::log10(v) : v; }
  double from_t(double u) const { return scale == Scale::kLog10 ? std::pow(10.0, u) : u; }
  double operator()(double v) const { return p0 + (t(v) - t(lo)) / (t(hi) - t(lo)) * (p1 - p0); }
  // The data value at a pixel position.
  double inverse(double p) const { return from_t(t(lo) + (p - p0) / (p1 - p0) * (t(hi) - t(lo))); }
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
  // a fixed end past the other, or a span lost to rounding at a huge offset (lo + 1 ==
  // lo at 1e20): a range of the data's own size
  if (!(hi > lo)) hi = log ? lo * 10 : lo + std::max(1.0, 0.1 * std::abs(lo));
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) {
    lo = log ? 1 : 0;
    hi = log ? 10 : 1;
  }
}

bool fixed_min(const Axis& a) {
  return std::isfinite(a.min) && (a.scale == Scale::kLinear || a.min > 0);
}
bool fixed_max(const Axis& a) {
  return std::isfinite(a.max) && (a.scale == Scale::kLinear || a.max > 0);
}

Ticks make_ticks(const Axis& axis, double lo, double hi, int target) {
  return axis.scale == Scale::kLog10 ? log_ticks(lo, hi, std::max(2, target + 2))
                                     : linear_ticks(lo, hi, std::max(2, target));
}

// The legend's candidate places in matplotlib's order of preference for loc="best".
enum class Spot { kTopRight, kTopLeft, kBottomLeft, kBottomRight, kRight, kLeft, kBottom, kTop };
constexpr Spot kSpots[] = {Spot::kTopRight, Spot::kTopLeft, Spot::kBottomLeft, Spot::kBottomRight,
                           Spot::kRight,    Spot::kLeft,    Spot::kBottom,     Spot::kTop};

bool at_top(Spot s) {
  return s == Spot::kTopRight || s == Spot::kTopLeft || s == Spot::kTop;
}
bool at_bottom(Spot s) {
  return s == Spot::kBottomRight || s == Spot::kBottomLeft || s == Spot::kBottom;
}

// The colour each series and band is drawn in: its own, or the palette's next.
struct PanelColors {
  std::vector<Color> series, bands;
};
PanelColors resolve_colors(const Panel& pn) {
  PanelColors c;
  std::size_t k = 0;
  for (const Series& s : pn.series)
    c.series.push_back(s.color.a < 0 ? palette_color(k++) : s.color);
  for (const Band& b : pn.bands) c.bands.push_back(b.color.a < 0 ? palette_color(k++) : b.color);
  return c;
}

// The legend entries of a panel's labelled series, bands and spans, each drawn as what it
// names is: one source for a swatch and its item.
std::vector<detail::LegendEntry> legend_entries(const Panel& pn, const PanelColors& colors) {
  std::vector<detail::LegendEntry> entries;
  for (std::size_t k = 0; k < pn.series.size(); ++k) {
    const Series& s = pn.series[k];
    if (!s.label.empty())
      entries.push_back(
          {s.label, colors.series[k], false, s.width, s.dash, s.marker, s.marker_size});
  }
  for (std::size_t k = 0; k < pn.bands.size(); ++k)
    if (!pn.bands[k].label.empty())
      entries.push_back({pn.bands[k].label,
                         colors.bands[k].with_alpha(std::max(0.35f, pn.bands[k].opacity)), true});
  for (const Span& s : pn.spans)
    if (!s.label.empty())
      entries.push_back({s.label, s.color.with_alpha(std::max(0.3f, s.opacity)), true});
  return entries;
}

// Everything about one panel at one size, worked out before drawing.
class PanelPlan {
 public:
  // `own_legend` false: the figure's shared legend lists this panel's entries.
  PanelPlan(const Panel& panel, const Style& st, const ScreenRect& cell, bool own_legend = true)
      : pn_(panel), st_(st), cell_(cell), colors_(resolve_colors(panel)) {
    data_ranges();
    if (own_legend && pn_.legend != LegendPlace::kNone) {
      entries_ = legend_entries(pn_, colors_);
      legend_size_ = detail::measure_legend(entries_, st_);
    }
    plan();
  }

  Plot2D::PanelLayout report() const {
    Plot2D::PanelLayout out;
    out.frame = rect_;
    out.title = title_.box;
    out.legend = legend_;
    out.annotations = note_boxes_;
    for (const ScreenRect& r : ref_boxes_)
      if (!r.empty()) out.ref_labels.push_back(r);
    out.x_lo = xm_.lo, out.x_hi = xm_.hi, out.y_lo = ym_.lo, out.y_hi = ym_.hi;
    out.x_ticks = xt_.values, out.y_ticks = yt_.values;
    return out;
  }

  void draw(detail::Canvas& p) const {
    background(p);
    data(p);
    frame_and_ticks(p);
    labels(p);
    detail::draw_legend(p, entries_, legend_, st_);
  }

 private:
  // ---- Planning ----------------------------------------------------------

  void data_ranges() {
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
    for (const RefLine& r : pn_.ref_lines)
      add(r.vertical ? pn_.x : pn_.y, r.vertical ? rx : ry, r.value);
    for (const Annotation& a : pn_.annotations) {
      add(pn_.x, rx, a.x);
      add(pn_.y, ry, a.y);
    }
    xm_.scale = pn_.x.scale;
    ym_.scale = pn_.y.scale;
    finish_range(pn_.x, rx, x_lo_, x_hi_);
    finish_range(pn_.y, ry, y_lo_, y_hi_);
  }

  // Ranges, frame and ticks; then the legend, growing the y range for it if it must; then
  // reference-line labels and annotations around what is drawn.
  void plan() {
    constexpr int kMaxHeadroomPasses = 4;
    for (int pass = 0;; ++pass) {
      xm_.lo = x_lo_, xm_.hi = x_hi_, ym_.lo = y_lo_, ym_.hi = y_hi_;
      layout();
      if (pn_.equal_aspect) equalize();
      xt_ = ticks_fitting(pn_.x, xm_, true);
      yt_ = ticks_fitting(pn_.y, ym_, false);
      detail::Occupancy grid = data_grid();
      place_ref_labels(grid);
      for (const ScreenRect& r : ref_boxes_) grid.add_rect(r, 1.0f);
      if (entries_.empty()) break;
      // The legend also keeps off the annotations' texts (each is near its point) and
      // the horizontal reference lines (which a label may cross, but a box would hide;
      // headroom clears them as it clears data, where no room clears a vertical one).
      detail::Occupancy legend_grid = grid;
      add_ref_lines(legend_grid, 1.0f, false);
      for (const Annotation& a : pn_.annotations) {
        if (!xm_.valid(a.x) || !ym_.valid(a.y)) continue;
        const TextExtent e = measure_text(a.text, st_.note_font);
        const P3 q = map(a.x, a.y);
        legend_grid.add_rect(
            {q.x() - 0.5 * e.width, q.y() - e.height(), q.x() + 0.5 * e.width, q.y() + e.height()},
            1.0f);
      }
      const detail::Placement best = place_legend(legend_grid);
      legend_ = best.box;
      if (best.cover.hard == 0 || pn_.legend != LegendPlace::kAuto || pass == kMaxHeadroomPasses)
        break;
      if (!add_headroom(legend_grid)) break;
    }
    place_annotations();
  }

  // Widest tick label width and tallest height for a tick set.
  TextExtent tick_extent(const Ticks& t) const {
    TextExtent e;
    for (const std::string& l : t.labels) {
      const TextExtent m = measure_text(l, st_.tick_font);
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
    // the labels clear each other along the axis, at the closest two ticks
    const auto fit = [&](const Ticks& t) {
      const TextExtent e = tick_extent(t);
      const double need = horizontal ? e.width + 2.5 * st_.pad : e.height() + 1.2 * st_.pad;
      double gap = std::numeric_limits<double>::infinity();
      for (std::size_t i = 1; i < t.values.size(); ++i)
        gap = std::min(gap, std::abs(m(t.values[i]) - m(t.values[i - 1])));
      return gap >= need;
    };
    Ticks t;
    for (; target >= 1; --target) {
      t = make_ticks(axis, m.lo, m.hi, target);
      if (fit(t) || t.values.size() <= 2) break;
    }
    // two ticks at least where a finer step gives them room: one alone gives no scale
    for (int finer = target + 1; t.values.size() < 2 && finer <= target + 4; ++finer) {
      Ticks more = make_ticks(axis, m.lo, m.hi, finer);
      if (more.values.size() >= 2 && fit(more)) t = std::move(more);
    }
    return t;
  }

  // Plot rectangle inside the cell, with margins from measured text.
  void layout() {
    const ScreenRect& cell = cell_;
    // First guess of the rectangle, to choose ticks; then margins from their labels.
    ScreenRect r{cell.x0 + 0.15 * cell.width(), cell.y0 + 0.08 * cell.height(),
                 cell.x1 - 0.04 * cell.width(), cell.y1 - 0.14 * cell.height()};
    title_ =
        detail::layout_title(pn_.title, st_.panel_title_font, cell.x0 + st_.pad, cell.x1 - st_.pad,
                             0.5 * (cell.x0 + cell.x1), cell.y0 + 0.4 * st_.pad);
    for (int pass = 0; pass < 2; ++pass) {
      xm_.p0 = r.x0, xm_.p1 = r.x1, ym_.p0 = r.y1, ym_.p1 = r.y0;
      const Ticks xt = ticks_fitting(pn_.x, xm_, true);
      const Ticks yt = ticks_fitting(pn_.y, ym_, false);
      const TextExtent xe = tick_extent(xt), ye = tick_extent(yt);
      // Axis labels shrink if longer than their side of the cell.
      xlabel_size_ =
          detail::fitting_size(pn_.x.label, st_.axis_label_font, cell.width() - 2 * st_.pad);
      ylabel_size_ =
          detail::fitting_size(pn_.y.label, st_.axis_label_font, cell.height() - 2 * st_.pad);
      const double ylabel_h =
          pn_.y.label.empty() ? 0 : measure_text(pn_.y.label, ylabel_size_).height() + st_.pad;
      const double xlabel_h =
          pn_.x.label.empty() ? 0 : measure_text(pn_.x.label, xlabel_size_).height() + st_.pad;
      const double title_bottom =
          pn_.title.empty() ? cell.y0 + st_.pad : title_.box.y1 + 0.8 * st_.pad;
      const double last_x_half =
          xt.labels.empty() ? 0 : 0.5 * measure_text(xt.labels.back(), st_.tick_font).width;
      r.x0 = cell.x0 + st_.pad + ylabel_h + ye.width + st_.tick_len + 0.8 * st_.pad;
      r.x1 = cell.x1 - std::max(1.5 * st_.pad, last_x_half + 0.5 * st_.pad);
      r.y0 = title_bottom + 0.5 * ye.height();
      r.y1 = cell.y1 - (st_.pad + xlabel_h + xe.height() + st_.tick_len + 0.6 * st_.pad);
      r.x0 = std::round(r.x0), r.x1 = std::round(r.x1), r.y0 = std::round(r.y0),
      r.y1 = std::round(r.y1);
      if (r.x1 - r.x0 < 20) r.x1 = r.x0 + 20;
      if (r.y1 - r.y0 < 20) r.y1 = r.y0 + 20;
    }
    rect_ = r;
    xm_.p0 = r.x0, xm_.p1 = r.x1, ym_.p0 = r.y1, ym_.p1 = r.y0;
    // The panel title is centred over the plot area, as far as the cell allows.
    title_ = detail::layout_title(pn_.title, st_.panel_title_font, cell.x0 + st_.pad,
                                  cell.x1 - st_.pad, 0.5 * (r.x0 + r.x1), cell.y0 + 0.4 * st_.pad);
  }

  // Equal aspect: widen whichever axis range has more pixels per unit (linear axes only).
  void equalize() {
    if (xm_.scale != Scale::kLinear || ym_.scale != Scale::kLinear) return;
    const double wx = rect_.width(), wy = rect_.height();
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

  // What the data draws inside the frame: lines, markers, bands and the annotated points in
  // full weight; reference lines lightly (text may cross them if it must).
  detail::Occupancy data_grid() const {
    detail::Occupancy grid(rect_, std::max(3.0, 4 * st_.s));
    auto xy = [&](double x, double y) { return Vector2d(xm_(x), ym_(y)); };
    for (std::size_t k = 0; k < pn_.series.size(); ++k) {
      const Series& s = pn_.series[k];
      const std::size_t n = std::min(s.x.size(), s.y.size());
      const double hw = 0.5 * st_.line(s.width) + 1;
      for (std::size_t i = 0; i < n; ++i) {
        if (!xm_.valid(s.x[i]) || !ym_.valid(s.y[i])) continue;
        const Vector2d q = xy(s.x[i], s.y[i]);
        if (s.width > 0 && i + 1 < n && xm_.valid(s.x[i + 1]) && ym_.valid(s.y[i + 1]))
          grid.add_segment(q, xy(s.x[i + 1], s.y[i + 1]), hw, 1.0f);
        if (s.marker != Marker::kNone) {
          const double r = 0.5 * st_.marker(s.marker_size) + 1;
          grid.add_rect({q.x() - r, q.y() - r, q.x() + r, q.y() + r}, 1.0f);
        }
      }
    }
    for (const Band& b : pn_.bands) {
      const std::size_t n = std::min({b.x.size(), b.y_lo.size(), b.y_hi.size()});
      for (std::size_t i = 0; i + 1 < n; ++i) {
        if (!xm_.valid(b.x[i]) || !xm_.valid(b.x[i + 1]) || !ym_.valid(b.y_lo[i]) ||
            !ym_.valid(b.y_hi[i]) || !ym_.valid(b.y_lo[i + 1]) || !ym_.valid(b.y_hi[i + 1]))
          continue;
        const Vector2d a = xy(b.x[i], b.y_lo[i]), c = xy(b.x[i + 1], b.y_lo[i + 1]);
        const Vector2d d = xy(b.x[i + 1], b.y_hi[i + 1]), e = xy(b.x[i], b.y_hi[i]);
        grid.add_triangle(a, c, d, 1.0f);
        grid.add_triangle(a, d, e, 1.0f);
      }
    }
    add_ref_lines(grid, 0.01f);
    for (const Annotation& a : pn_.annotations)
      if (xm_.valid(a.x) && ym_.valid(a.y)) {
        const Vector2d q = xy(a.x, a.y);
        grid.add_rect({q.x() - 2, q.y() - 2, q.x() + 2, q.y() + 2}, 1.0f);
      }
    return grid;
  }

  // The reference lines into an occupancy grid at a weight (the vertical ones too, or not).
  void add_ref_lines(detail::Occupancy& grid, float weight, bool vertical = true) const {
    for (const RefLine& r : pn_.ref_lines) {
      if (r.vertical && !vertical) continue;
      const double hw = 0.5 * st_.line(r.width);
      if (r.vertical)
        grid.add_segment({xm_(r.value), rect_.y0}, {xm_(r.value), rect_.y1}, hw, weight);
      else
        grid.add_segment({rect_.x0, ym_(r.value)}, {rect_.x1, ym_(r.value)}, hw, weight);
    }
  }

  // Each reference line's label at one of the line's ends, on one of its sides, where it
  // covers the least data (a vertical line's label reads upwards, beside it).
  void place_ref_labels(const detail::Occupancy& grid) {
    ref_boxes_.assign(pn_.ref_lines.size(), ScreenRect{});
    ref_on_data_.assign(pn_.ref_lines.size(), false);
    ref_sizes_.assign(pn_.ref_lines.size(), st_.note_font);
    std::vector<ScreenRect> taken;
    const double gap = 0.4 * st_.pad, end = 0.5 * st_.pad;
    for (std::size_t k = 0; k < pn_.ref_lines.size(); ++k) {
      const RefLine& r = pn_.ref_lines[k];
      // (a frame with no room along the line has no place for a label)
      const double room = (r.vertical ? rect_.height() : rect_.width()) - 2 * end;
      if (r.label.empty() || room <= 0) continue;
      // a label longer than its line's run inside the frame shrinks to fit it
      ref_sizes_[k] = detail::fitting_size(r.label, st_.note_font, room);
      const TextExtent e = measure_text(r.label, ref_sizes_[k]);
      std::vector<ScreenRect> c;
      if (r.vertical) {
        const double x = xm_(r.value), w = e.height(), h = e.width;
        c = {{x - gap - w, rect_.y0 + end, x - gap, rect_.y0 + end + h},
             {x + gap, rect_.y0 + end, x + gap + w, rect_.y0 + end + h},
             {x - gap - w, rect_.y1 - end - h, x - gap, rect_.y1 - end},
             {x + gap, rect_.y1 - end - h, x + gap + w, rect_.y1 - end}};
      } else {
        const double y = ym_(r.value), w = e.width, h = e.height();
        c = {{rect_.x1 - end - w, y - gap - h, rect_.x1 - end, y - gap},
             {rect_.x1 - end - w, y + gap, rect_.x1 - end, y + gap + h},
             {rect_.x0 + end, y - gap - h, rect_.x0 + end + w, y - gap},
             {rect_.x0 + end, y + gap, rect_.x0 + end + w, y + gap + h}};
      }
      // Where the data crosses the line near both ends, a place along it: the quarters
      // first, then every twentieth of the way (a gap between crossings may be narrow).
      std::vector<double> along{0.75, 0.25, 0.5};
      for (int i = 1; i < 20; ++i) along.push_back(i / 20.0);
      for (const double f : along) {
        if (r.vertical) {
          const double x = xm_(r.value), w = e.height(), h = e.width;
          const double y0 = rect_.y0 + f * (rect_.height() - h);
          c.push_back({x - gap - w, y0, x - gap, y0 + h});
          c.push_back({x + gap, y0, x + gap + w, y0 + h});
        } else {
          const double y = ym_(r.value), w = e.width, h = e.height();
          const double x0 = rect_.x0 + f * (rect_.width() - w);
          c.push_back({x0, y - gap - h, x0 + w, y - gap});
          c.push_back({x0, y + gap, x0 + w, y + gap + h});
        }
      }
      const detail::Placement pl = detail::choose_place(c, grid, rect_, taken);
      ref_boxes_[k] = pl.box.empty() ? c.front() : pl.box;
      ref_on_data_[k] = pl.box.empty() || pl.cover.hard > 0;
      taken.push_back(ref_boxes_[k]);
    }
  }

  ScreenRect spot_box(Spot s) const {
    const double in = st_.legend_padding, w = legend_size_.width, h = legend_size_.height;
    const double cx = 0.5 * (rect_.x0 + rect_.x1), cy = 0.5 * (rect_.y0 + rect_.y1);
    const double left = rect_.x0 + in, right = rect_.x1 - in - w, mid_x = cx - 0.5 * w;
    const double top = rect_.y0 + in, bottom = rect_.y1 - in - h, mid_y = cy - 0.5 * h;
    const auto box = [&](double x, double y) { return ScreenRect{x, y, x + w, y + h}; };
    switch (s) {
      case Spot::kTopRight:
        return box(right, top);
      case Spot::kTopLeft:
        return box(left, top);
      case Spot::kBottomLeft:
        return box(left, bottom);
      case Spot::kBottomRight:
        return box(right, bottom);
      case Spot::kRight:
        return box(right, mid_y);
      case Spot::kLeft:
        return box(left, mid_y);
      case Spot::kBottom:
        return box(mid_x, bottom);
      case Spot::kTop:
        return box(mid_x, top);
    }
    return box(right, top);
  }

  // The user's corner, or the spot covering the least (matplotlib's order on ties).
  detail::Placement place_legend(const detail::Occupancy& grid) const {
    switch (pn_.legend) {
      case LegendPlace::kTopRight:
        return {spot_box(Spot::kTopRight), grid.cover(spot_box(Spot::kTopRight)), true};
      case LegendPlace::kTopLeft:
        return {spot_box(Spot::kTopLeft), grid.cover(spot_box(Spot::kTopLeft)), true};
      case LegendPlace::kBottomRight:
        return {spot_box(Spot::kBottomRight), grid.cover(spot_box(Spot::kBottomRight)), true};
      case LegendPlace::kBottomLeft:
        return {spot_box(Spot::kBottomLeft), grid.cover(spot_box(Spot::kBottomLeft)), true};
      case LegendPlace::kAuto:
      case LegendPlace::kNone:
        break;
    }
    std::vector<ScreenRect> spots;
    for (Spot s : kSpots) spots.push_back(spot_box(s));
    detail::Placement p = detail::choose_place(spots, grid, rect_.grown(1), {});
    if (!p.found) p = {spots.front(), grid.cover(spots.front()), true};
    return p;
  }

  // Grows the y range at its free end just enough for the legend, at the top or bottom spot
  // needing the least growth, to clear the data under it; false if no end may grow.
  bool add_headroom(const detail::Occupancy& grid) {
    const double gap = 0.6 * st_.pad, h = rect_.height();
    const double t_lo = ym_.t(ym_.lo), t_hi = ym_.t(ym_.hi), span = t_hi - t_lo;
    double best_growth = std::numeric_limits<double>::infinity(), new_lo = kNaN, new_hi = kNaN;
    for (Spot s : kSpots) {
      const bool top = at_top(s), bottom = at_bottom(s);
      if ((!top && !bottom) || (top && fixed_max(pn_.y)) || (bottom && fixed_min(pn_.y))) continue;
      const ScreenRect b = spot_box(s);
      double data_top = 0, data_bottom = 0;
      if (!grid.hard_extent(b.x0 - gap, b.x1 + gap, data_top, data_bottom)) continue;
      // Fraction of the frame's height the data may keep, measured from the far edge.
      const double keep = (h - (b.height() + st_.legend_padding + gap)) / h;
      if (keep < 0.3) continue;  // a legend this tall would squash the data: leave it
      if (top) {
        const double v = ym_.t(ym_.inverse(data_top));
        const double hi = t_lo + (v - t_lo) / keep;
        if (hi - t_hi < best_growth) best_growth = hi - t_hi, new_hi = hi, new_lo = kNaN;
      } else {
        const double v = ym_.t(ym_.inverse(data_bottom));
        const double lo = t_hi - (t_hi - v) / keep;
        if (t_lo - lo < best_growth) best_growth = t_lo - lo, new_lo = lo, new_hi = kNaN;
      }
    }
    if (!std::isfinite(best_growth) || !(best_growth > 1e-9 * span)) return false;
    // The axis grows from the range drawn (equal aspect may have widened it already).
    if (std::isfinite(new_hi)) y_hi_ = ym_.from_t(new_hi), y_lo_ = ym_.lo;
    if (std::isfinite(new_lo)) y_lo_ = ym_.from_t(new_lo), y_hi_ = ym_.hi;
    return true;
  }

  // Each annotation's text beside its point: near first, then farther, clear of the data,
  // the legend, reference-line labels and earlier annotations, inside the frame.
  void place_annotations() {
    const detail::Occupancy grid = data_grid();
    std::vector<ScreenRect> taken = ref_boxes_;
    if (!legend_.empty()) taken.push_back(legend_.grown(0.3 * st_.pad));
    const ScreenRect bounds = rect_.grown(-0.3 * st_.pad);
    for (const Annotation& a : pn_.annotations) {
      if (!xm_.valid(a.x) || !ym_.valid(a.y)) {
        note_boxes_.push_back({});
        continue;
      }
      const TextExtent e = measure_text(a.text, st_.note_font);
      const P3 q = map(a.x, a.y);
      // With an arrow the text stands off far enough for the arrow to show.
      std::vector<ScreenRect> c;
      for (double d : a.arrow ? std::vector<double>{3, 6, 10} : std::vector<double>{0.5, 2, 4}) {
        const std::vector<ScreenRect> ring =
            detail::boxes_around(q.x(), q.y(), e.width, e.height(), d * st_.pad);
        c.insert(c.end(), ring.begin(), ring.end());
      }
      const detail::Placement pl = detail::choose_place(c, grid, bounds, taken);
      // No place inside the frame (a text wider than it): keep what fits in view.
      const ScreenRect box = pl.box.empty() ? detail::keep_inside(c.front(), bounds) : pl.box;
      note_boxes_.push_back(box);
      taken.push_back(box.grown(0.3 * st_.pad));
    }
  }

  // ---- Drawing -----------------------------------------------------------

  void background(detail::Canvas& p) const {
    p.clip(rect_.x0, rect_.y0, rect_.x1, rect_.y1);
    for (const Span& s : pn_.spans) {
      const Color c = s.color.with_alpha(s.opacity);
      if (s.vertical)
        p.rect(xm_(s.lo), rect_.y0, xm_(s.hi), rect_.y1, c);
      else
        p.rect(rect_.x0, ym_(s.hi), rect_.x1, ym_(s.lo), c);
    }
    const double gw = st_.grid_width;
    if (pn_.x.grid)
      for (double v : xt_.values)
        p.rect(xm_(v) - 0.5 * gw, rect_.y0, xm_(v) + 0.5 * gw, rect_.y1, detail::kGridColor);
    if (pn_.y.grid)
      for (double v : yt_.values)
        p.rect(rect_.x0, ym_(v) - 0.5 * gw, rect_.x1, ym_(v) + 0.5 * gw, detail::kGridColor);
  }

  void data(detail::Canvas& p) const {
    // Bands first (translucent, under the lines), as quads between consecutive samples.
    for (std::size_t b = 0; b < pn_.bands.size(); ++b) {
      const Band& band = pn_.bands[b];
      const Color c = colors_.bands[b].with_alpha(band.opacity);
      const std::size_t n = std::min({band.x.size(), band.y_lo.size(), band.y_hi.size()});
      for (std::size_t i = 0; i + 1 < n; ++i) {
        if (!xm_.valid(band.x[i]) || !xm_.valid(band.x[i + 1]) || !ym_.valid(band.y_lo[i]) ||
            !ym_.valid(band.y_hi[i]) || !ym_.valid(band.y_lo[i + 1]) ||
            !ym_.valid(band.y_hi[i + 1]))
          continue;
        p.convex({map(band.x[i], band.y_lo[i]), map(band.x[i + 1], band.y_lo[i + 1]),
                  map(band.x[i + 1], band.y_hi[i + 1]), map(band.x[i], band.y_hi[i])},
                 c);
      }
    }
    for (const RefLine& r : pn_.ref_lines) {
      const double w = st_.line(r.width);
      const auto dash = detail::dash_pattern(r.dash, w, st_);
      if (r.vertical)
        p.polyline({{xm_(r.value), rect_.y1, 0}, {xm_(r.value), rect_.y0, 0}}, w, r.color, dash);
      else
        p.polyline({{rect_.x0, ym_(r.value), 0}, {rect_.x1, ym_(r.value), 0}}, w, r.color, dash);
    }
    for (std::size_t i = 0; i < pn_.series.size(); ++i) {
      const std::size_t k = pn_.first_on_top ? pn_.series.size() - 1 - i : i;
      const Series& s = pn_.series[k];
      const Color c = colors_.series[k];
      const std::size_t n = std::min(s.x.size(), s.y.size());
      if (s.width > 0) {
        const double w = st_.line(s.width);
        const auto dash = detail::dash_pattern(s.dash, w, st_);
        const bool round = s.dash == Dash::kDotted || s.dash == Dash::kDashDot;
        // Break the line at points an axis cannot show (NaN, or <= 0 on a log axis).
        std::vector<P3> run;
        auto emit = [&] {
          if (run.size() >= 2) p.polyline(run, w, c, dash, round);
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
        const double size = st_.marker(s.marker_size);
        for (std::size_t i = 0; i < n; ++i)
          if (xm_.valid(s.x[i]) && ym_.valid(s.y[i]))
            detail::draw_marker(p, s.marker, xm_(s.x[i]), ym_(s.y[i]), size, c);
      }
    }
    // Reference-line labels where they were placed (a vertical line's reads upwards).
    for (std::size_t k = 0; k < pn_.ref_lines.size(); ++k) {
      const RefLine& r = pn_.ref_lines[k];
      const ScreenRect& b = ref_boxes_[k];
      if (r.label.empty() || b.empty()) continue;
      // A label with no place clear of the data (a line the data crosses often) stands
      // on a pale ground, as a legend does, so that it reads and the data shows through.
      if (ref_on_data_[k]) {
        const double m = 0.25 * st_.pad;
        p.rect(b.x0 - m, b.y0 - m, b.x1 + m, b.y1 + m, detail::kLegendFill);
      }
      if (r.vertical)
        p.text(r.label, b.x1, b.y0, ref_sizes_[k], r.color, HAlign::kRight, VAlign::kBottom, true);
      else
        p.text(r.label, b.x0, b.y0, ref_sizes_[k], r.color, HAlign::kLeft, VAlign::kTop);
    }
    p.no_clip();
    annotations(p);
  }

  void annotations(detail::Canvas& p) const {
    for (std::size_t k = 0; k < pn_.annotations.size(); ++k) {
      const Annotation& a = pn_.annotations[k];
      const ScreenRect& b = note_boxes_[k];
      if (b.empty()) continue;
      p.text(a.text, b.x0, b.y0, st_.note_font, a.color, HAlign::kLeft, VAlign::kTop);
      if (!a.arrow) continue;
      // Arrow from the text box's edge to just short of the point.
      const P3 pt = map(a.x, a.y);
      const double cx = 0.5 * (b.x0 + b.x1), cy = 0.5 * (b.y0 + b.y1);
      Vector2d d(pt.x() - cx, pt.y() - cy);
      const double len = d.norm();
      if (len < 1) continue;
      d /= len;
      const double hx = 0.5 * b.width() + 0.4 * st_.pad, hy = 0.5 * b.height() + 0.3 * st_.pad;
      const double t0 = std::min(std::abs(d.x()) > 1e-9 ? hx / std::abs(d.x()) : 1e9,
                                 std::abs(d.y()) > 1e-9 ? hy / std::abs(d.y()) : 1e9);
      const double t1 = len - 0.5 * st_.pad;
      if (t1 <= t0) continue;
      const double w = st_.line(2.0), head = std::max(8.0, 16 * st_.s);
      const Vector2d a0 = Vector2d(cx, cy) + d * t0, tip = Vector2d(cx, cy) + d * t1;
      const Vector2d base = tip - d * std::min(head, t1 - t0), nrm(-d.y(), d.x());
      p.polyline({{a0.x(), a0.y(), 0}, {base.x(), base.y(), 0}}, w, a.color);
      const Vector2d l = base + nrm * head * 0.4, r = base - nrm * head * 0.4;
      p.triangle({tip.x(), tip.y(), 0}, {l.x(), l.y(), 0}, {r.x(), r.y(), 0}, a.color);
    }
  }

  void frame_and_ticks(detail::Canvas& p) const {
    const double fw = st_.frame_width;
    p.rect_outline(rect_.x0 - fw, rect_.y0 - fw, rect_.x1 + fw, rect_.y1 + fw, fw,
                   detail::kAxisColor);
    const double tw = fw, tl = st_.tick_len;
    for (std::size_t i = 0; i < xt_.values.size(); ++i) {
      const double x = xm_(xt_.values[i]);
      p.rect(x - 0.5 * tw, rect_.y1 + fw, x + 0.5 * tw, rect_.y1 + fw + tl, detail::kAxisColor);
      p.text(xt_.labels[i], x, rect_.y1 + fw + tl + 0.4 * st_.pad, st_.tick_font,
             detail::kTickTextColor, HAlign::kCenter, VAlign::kTop);
    }
    for (double v : xt_.minor) {
      const double x = xm_(v);
      p.rect(x - 0.5 * tw, rect_.y1 + fw, x + 0.5 * tw, rect_.y1 + fw + 0.55 * tl,
             detail::kAxisColor);
    }
    for (std::size_t i = 0; i < yt_.values.size(); ++i) {
      const double y = ym_(yt_.values[i]);
      p.rect(rect_.x0 - fw - tl, y - 0.5 * tw, rect_.x0 - fw, y + 0.5 * tw, detail::kAxisColor);
      p.text(yt_.labels[i], rect_.x0 - fw - tl - 0.4 * st_.pad, y, st_.tick_font,
             detail::kTickTextColor, HAlign::kRight, VAlign::kCenter);
    }
    for (double v : yt_.minor) {
      const double y = ym_(v);
      p.rect(rect_.x0 - fw - 0.55 * tl, y - 0.5 * tw, rect_.x0 - fw, y + 0.5 * tw,
             detail::kAxisColor);
    }
  }

  void labels(detail::Canvas& p) const {
    if (!pn_.x.label.empty()) {
      const double half = 0.5 * measure_text(pn_.x.label, xlabel_size_).width + st_.pad;
      const double x = clamp_safe(0.5 * (rect_.x0 + rect_.x1), cell_.x0 + half, cell_.x1 - half);
      p.text(pn_.x.label, x, cell_.y1 - st_.pad, xlabel_size_, kTextColor, HAlign::kCenter,
             VAlign::kBottom);
    }
    if (!pn_.y.label.empty()) {
      const double half = 0.5 * measure_text(pn_.y.label, ylabel_size_).width + st_.pad;
      const double y = clamp_safe(0.5 * (rect_.y0 + rect_.y1), cell_.y0 + half, cell_.y1 - half);
      p.text(pn_.y.label, cell_.x0 + st_.pad, y, ylabel_size_, kTextColor, HAlign::kCenter,
             VAlign::kTop, true);
    }
    detail::draw_title(p, title_);
  }

  const Panel& pn_;
  Style st_;  // a copy: plans are moved about with their figure
  ScreenRect cell_;
  PanelColors colors_;
  double x_lo_ = 0, x_hi_ = 1, y_lo_ = 0, y_hi_ = 1;  // ranges before equal aspect
  AxisMap xm_, ym_;
  Ticks xt_, yt_;
  ScreenRect rect_;
  detail::TitleBlock title_;
  double xlabel_size_ = 0, ylabel_size_ = 0;
  std::vector<detail::LegendEntry> entries_;
  detail::LegendSize legend_size_;
  ScreenRect legend_;
  std::vector<ScreenRect> ref_boxes_, note_boxes_;
  std::vector<bool> ref_on_data_;  ///< each reference label covers data where it is
  std::vector<double> ref_sizes_;  ///< each reference label's font size
};

// The figure at a size: its title and one plan per panel, row by row.
struct FigurePlan {
  Style st;
  detail::TitleBlock title;
  std::vector<PanelPlan> panels;
  std::vector<detail::LegendEntry> legend;  // the shared legend's entries
  detail::LegendSize legend_size;
  ScreenRect legend_box;
};

// The shared legend's entries: every panel's, a label once.
std::vector<detail::LegendEntry> shared_entries(const Plot2D& plot) {
  std::vector<detail::LegendEntry> entries;
  for (int r = 0; r < plot.rows(); ++r)
    for (int c = 0; c < plot.cols(); ++c) {
      const Panel& pn = plot.panel(r, c);
      for (detail::LegendEntry& e : legend_entries(pn, resolve_colors(pn))) {
        const auto same = [&](const detail::LegendEntry& o) { return o.label == e.label; };
        if (std::none_of(entries.begin(), entries.end(), same)) entries.push_back(std::move(e));
      }
    }
  return entries;
}

FigurePlan plan_figure(const Plot2D& plot, int width, int height) {
  FigurePlan fp;
  fp.st = detail::figure_style(width, plot.style_height > 0 ? plot.style_height : height);
  const Style& st = fp.st;
  fp.title = detail::layout_title(plot.title, st.title_font, st.margin, width - st.margin,
                                  0.5 * width, st.margin);
  // Panels keep a padding inside their cells, so the cells reach to a padding short of the
  // margin: a panel's outermost text then sits at the margin, as the title does.
  const double edge = st.margin - st.pad;
  const double top = plot.title.empty() ? edge : fp.title.box.y1 + 0.8 * st.pad;
  // A shared legend sits centred under the panels, at the margin.
  double bottom = height - edge;
  if (plot.shared_legend) {
    fp.legend = shared_entries(plot);
    fp.legend_size = detail::measure_legend(fp.legend, st, width - 2 * st.margin);
    if (!fp.legend.empty()) {
      const double w = fp.legend_size.width, h = fp.legend_size.height;
      fp.legend_box = {std::round(0.5 * (width - w)), std::round(height - st.margin - h),
                       std::round(0.5 * (width + w)), std::round(height - st.margin)};
      bottom = fp.legend_box.y0 - 0.5 * st.pad;
    }
  }
  const double cw = (width - 2 * edge) / plot.cols(), ch = (bottom - top) / plot.rows();
  fp.panels.reserve(static_cast<std::size_t>(plot.rows()) * plot.cols());
  for (int r = 0; r < plot.rows(); ++r)
    for (int c = 0; c < plot.cols(); ++c)
      fp.panels.emplace_back(
          plot.panel(r, c), st,
          ScreenRect{edge + c * cw, top + r * ch, edge + (c + 1) * cw, top + (r + 1) * ch},
          !plot.shared_legend);
  return fp;
}

}  // namespace

Plot2D::Layout layout(const Plot2D& plot, int width, int height) {
  const FigurePlan fp = plan_figure(plot, width, height);
  Plot2D::Layout out;
  out.title = fp.title.box;
  out.title_lines = static_cast<int>(fp.title.lines.size());
  out.title_size = fp.title.size;
  out.legend = fp.legend_box;
  for (const PanelPlan& p : fp.panels) out.panels.push_back(p.report());
  return out;
}

namespace {
void draw_planned(const FigurePlan& fp, detail::Canvas& canvas) {
  detail::draw_title(canvas, fp.title);
  for (const PanelPlan& panel : fp.panels) panel.draw(canvas);
  detail::draw_legend(canvas, fp.legend, fp.legend_box, fp.st, fp.legend_size);
}
}  // namespace

void detail::draw_plot(const Plot2D& plot, int width, int height, Canvas& canvas,
                       PhaseClock* clock) {
  const FigurePlan fp = plan_figure(plot, width, height);
  if (clock != nullptr) clock->lap(&FigureTiming::layout);
  draw_planned(fp, canvas);
}

void detail::render_into_target(const Plot2D& plot, int width, int height, PhaseClock& clock) {
  const FigurePlan fp = plan_figure(plot, width, height);
  clock.lap(&FigureTiming::layout);
  // No depth buffer for 2D.
  detail::target().begin(width, height, false, kWhite);
  clock.lap(&FigureTiming::setup, true);
  detail::Painter& p = detail::painter();
  p.begin(width, height);
  draw_planned(fp, p);
  p.flush();
  clock.lap(&FigureTiming::draw, true);
}

// A plot as pixels is drawn by cairo on the CPU (vector.cpp), with the same drawing
// calls; render_into_target() draws it with GL for a live view's texture.
Image draw(const Plot2D& plot, int width, int height, FigureTiming* timing) {
  return detail::draw_plot_on_cpu(plot, width, height, timing);
}

Image draw_gl(const Plot2D& plot, int width, int height) {
  detail::PhaseClock clock(nullptr);
  detail::render_into_target(plot, width, height, clock);
  return detail::target().finish();
}

void save_png(const Plot2D& plot, const std::string& path, int width, int height,
              FigureTiming* timing) {
  detail::save_timed(draw(plot, width, height, timing), path, timing);
}

}  // namespace rigid::render
