// Planning a 2D plot: each panel's data ranges, its frame inside its cell with margins
// from measured text, ticks thinned until their labels clear each other, equal aspect;
// and the figure's cells, title and shared legend.
#include "plot2d_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "rigid/render/text.h"

namespace rigid::render::detail {

namespace {

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

Ticks make_ticks(const Axis& axis, double lo, double hi, int target) {
  return axis.scale == Scale::kLog10 ? log_ticks(lo, hi, std::max(2, target + 2))
                                     : linear_ticks(lo, hi, std::max(2, target));
}

// The legend entries of a panel's labelled series, bands and spans, each drawn as what it
// names is: one source for a swatch and its item.
std::vector<LegendEntry> legend_entries(const Panel& pn, const PanelColors& colors) {
  std::vector<LegendEntry> entries;
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

}  // namespace

PanelColors resolve_colors(const Panel& pn) {
  PanelColors c;
  std::size_t k = 0;
  for (const Series& s : pn.series)
    c.series.push_back(s.color.a < 0 ? palette_color(k++) : s.color);
  for (const Band& b : pn.bands) c.bands.push_back(b.color.a < 0 ? palette_color(k++) : b.color);
  return c;
}

PanelPlan::PanelPlan(const Panel& panel, const Style& st, const ScreenRect& cell, bool own_legend)
    : pn_(panel), st_(st), cell_(cell), colors_(resolve_colors(panel)) {
  data_ranges();
  if (own_legend && pn_.legend != LegendPlace::kNone) {
    entries_ = legend_entries(pn_, colors_);
    legend_size_ = measure_legend(entries_, st_);
  }
  plan();
}

Plot2D::PanelLayout PanelPlan::report() const {
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

void PanelPlan::data_ranges() {
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
void PanelPlan::plan() {
  constexpr int kMaxHeadroomPasses = 4;
  for (int pass = 0;; ++pass) {
    xm_.lo = x_lo_, xm_.hi = x_hi_, ym_.lo = y_lo_, ym_.hi = y_hi_;
    layout();
    if (pn_.equal_aspect) equalize();
    xt_ = ticks_fitting(pn_.x, xm_, true);
    yt_ = ticks_fitting(pn_.y, ym_, false);
    Occupancy grid = data_grid();
    place_ref_labels(grid);
    for (const ScreenRect& r : ref_boxes_) grid.add_rect(r, 1.0f);
    if (entries_.empty()) break;
    // The legend also keeps off the annotations' texts (each is near its point) and
    // the horizontal reference lines (which a label may cross, but a box would hide;
    // headroom clears them as it clears data, where no room clears a vertical one).
    Occupancy legend_grid = grid;
    add_ref_lines(legend_grid, 1.0f, false);
    for (const Annotation& a : pn_.annotations) {
      if (!xm_.valid(a.x) || !ym_.valid(a.y)) continue;
      const TextExtent e = measure_text(a.text, st_.note_font);
      const P3 q = map(a.x, a.y);
      legend_grid.add_rect(
          {q.x() - 0.5 * e.width, q.y() - e.height(), q.x() + 0.5 * e.width, q.y() + e.height()},
          1.0f);
    }
    const Placement best = place_legend(legend_grid);
    legend_ = best.box;
    if (best.cover.hard == 0 || pn_.legend != LegendPlace::kAuto || pass == kMaxHeadroomPasses)
      break;
    if (!add_headroom(legend_grid)) break;
  }
  place_annotations();
}

// Widest tick label width and tallest height for a tick set.
TextExtent PanelPlan::tick_extent(const Ticks& t) const {
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
Ticks PanelPlan::ticks_fitting(const Axis& axis, const AxisMap& m, bool horizontal) const {
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
void PanelPlan::layout() {
  const ScreenRect& cell = cell_;
  // First guess of the rectangle, to choose ticks; then margins from their labels.
  ScreenRect r{cell.x0 + 0.15 * cell.width(), cell.y0 + 0.08 * cell.height(),
               cell.x1 - 0.04 * cell.width(), cell.y1 - 0.14 * cell.height()};
  title_ = layout_title(pn_.title, st_.panel_title_font, cell.x0 + st_.pad, cell.x1 - st_.pad,
                        0.5 * (cell.x0 + cell.x1), cell.y0 + 0.4 * st_.pad, st_.title_floor);
  for (int pass = 0; pass < 2; ++pass) {
    xm_.p0 = r.x0, xm_.p1 = r.x1, ym_.p0 = r.y1, ym_.p1 = r.y0;
    const Ticks xt = ticks_fitting(pn_.x, xm_, true);
    const Ticks yt = ticks_fitting(pn_.y, ym_, false);
    const TextExtent xe = tick_extent(xt), ye = tick_extent(yt);
    // Axis labels shrink if longer than their side of the cell.
    xlabel_size_ = fitting_size(pn_.x.label, st_.axis_label_font, cell.width() - 2 * st_.pad);
    ylabel_size_ = fitting_size(pn_.y.label, st_.axis_label_font, cell.height() - 2 * st_.pad);
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
  title_ = layout_title(pn_.title, st_.panel_title_font, cell.x0 + st_.pad, cell.x1 - st_.pad,
                        0.5 * (r.x0 + r.x1), cell.y0 + 0.4 * st_.pad, st_.title_floor);
}

// Equal aspect: widen whichever axis range has more pixels per unit (linear axes only).
void PanelPlan::equalize() {
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

// The shared legend's entries: every panel's, a label once.
std::vector<LegendEntry> shared_entries(const Plot2D& plot) {
  std::vector<LegendEntry> entries;
  for (int r = 0; r < plot.rows(); ++r)
    for (int c = 0; c < plot.cols(); ++c) {
      const Panel& pn = plot.panel(r, c);
      for (LegendEntry& e : legend_entries(pn, resolve_colors(pn))) {
        const auto same = [&](const LegendEntry& o) { return o.label == e.label; };
        if (std::none_of(entries.begin(), entries.end(), same)) entries.push_back(std::move(e));
      }
    }
  return entries;
}

FigurePlan plan_figure(const Plot2D& plot, int width, int height) {
  FigurePlan fp;
  fp.st = figure_style(width, plot.style_height > 0 ? plot.style_height : height, plot.min_text_px);
  const Style& st = fp.st;
  fp.title = layout_title(plot.title, st.title_font, st.margin, width - st.margin, 0.5 * width,
                          st.margin, st.title_floor);
  // Panels keep a padding inside their cells, so the cells reach to a padding short of the
  // margin: a panel's outermost text then sits at the margin, as the title does.
  const double edge = st.margin - st.pad;
  const double top = plot.title.empty() ? edge : fp.title.box.y1 + 0.8 * st.pad;
  // A shared legend sits centred under the panels, at the margin.
  double bottom = height - edge;
  if (plot.shared_legend) {
    fp.legend = shared_entries(plot);
    fp.legend_size = measure_legend(fp.legend, st, width - 2 * st.margin);
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

}  // namespace rigid::render::detail
