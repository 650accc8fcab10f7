// Drawing a planned 2D plot: each panel's spans and grid, its data (bands under lines,
// markers over them), annotations, frame and ticks, labels, title and legend, on any
// Canvas: cairo's for a PNG, SVG or PDF (vector.cpp), GL triangles for a live view.
#include <algorithm>
#include <cmath>
#include <optional>

#include "painter.h"
#include "plot2d_plan.h"
#include "rigid/render/text.h"
#include "target.h"

namespace rigid::render {

namespace detail {

using Eigen::Vector2d;

namespace {

// v clamped to [lo, hi]; the midpoint when the interval is empty.
double clamp_safe(double v, double lo, double hi) {
  return lo <= hi ? std::clamp(v, lo, hi) : 0.5 * (lo + hi);
}

}  // namespace

void PanelPlan::draw(Canvas& p) const {
  background(p);
  data(p);
  frame_and_ticks(p);
  labels(p);
  draw_legend(p, entries_, legend_, st_);
}

void PanelPlan::background(Canvas& p) const {
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
      p.rect(xm_(v) - 0.5 * gw, rect_.y0, xm_(v) + 0.5 * gw, rect_.y1, kGridColor);
  if (pn_.y.grid)
    for (double v : yt_.values)
      p.rect(rect_.x0, ym_(v) - 0.5 * gw, rect_.x1, ym_(v) + 0.5 * gw, kGridColor);
}

void PanelPlan::data(Canvas& p) const {
  // Bands first (translucent, under the lines), as quads between consecutive samples.
  for (std::size_t b = 0; b < pn_.bands.size(); ++b) {
    const Band& band = pn_.bands[b];
    const Color c = colors_.bands[b].with_alpha(band.opacity);
    const std::size_t n = std::min({band.x.size(), band.y_lo.size(), band.y_hi.size()});
    for (std::size_t i = 0; i + 1 < n; ++i) {
      if (!xm_.valid(band.x[i]) || !xm_.valid(band.x[i + 1]) || !ym_.valid(band.y_lo[i]) ||
          !ym_.valid(band.y_hi[i]) || !ym_.valid(band.y_lo[i + 1]) || !ym_.valid(band.y_hi[i + 1]))
        continue;
      p.convex({map(band.x[i], band.y_lo[i]), map(band.x[i + 1], band.y_lo[i + 1]),
                map(band.x[i + 1], band.y_hi[i + 1]), map(band.x[i], band.y_hi[i])},
               c);
    }
  }
  for (const RefLine& r : pn_.ref_lines) {
    const double w = st_.line(r.width);
    const auto dash = dash_pattern(r.dash, w, st_);
    if (r.vertical)
      p.polyline({{xm_(r.value), rect_.y1, 0}, {xm_(r.value), rect_.y0, 0}}, w, r.color, dash);
    else
      p.polyline({{rect_.x0, ym_(r.value), 0}, {rect_.x1, ym_(r.value), 0}}, w, r.color, dash);
  }
  // Every line, then every series' markers over them: a marker is not hidden by a line
  // drawn after it (curves on one another each show theirs).
  series_lines(p);
  series_markers(p);
  // Reference-line labels where they were placed (a vertical line's reads upwards).
  for (std::size_t k = 0; k < pn_.ref_lines.size(); ++k) {
    const RefLine& r = pn_.ref_lines[k];
    const ScreenRect& b = ref_boxes_[k];
    if (r.label.empty() || b.empty()) continue;
    // A label with no place clear of the data (a line the data crosses often) stands
    // on a pale ground, as a legend does, so that it reads and the data shows through.
    if (ref_on_data_[k]) {
      const double m = 0.25 * st_.pad;
      p.rect(b.x0 - m, b.y0 - m, b.x1 + m, b.y1 + m, kLegendFill);
    }
    if (r.vertical)
      p.text(r.label, b.x1, b.y0, ref_sizes_[k], r.color, HAlign::kRight, VAlign::kBottom, true);
    else
      p.text(r.label, b.x0, b.y0, ref_sizes_[k], r.color, HAlign::kLeft, VAlign::kTop);
  }
  p.no_clip();
  annotations(p);
}

// The series in the order they are drawn, a later one over an earlier.
std::size_t PanelPlan::drawn_series(std::size_t i) const {
  return pn_.first_on_top ? pn_.series.size() - 1 - i : i;
}

void PanelPlan::series_lines(Canvas& p) const {
  for (std::size_t i = 0; i < pn_.series.size(); ++i) {
    const std::size_t k = drawn_series(i);
    const Series& s = pn_.series[k];
    if (s.width <= 0) continue;
    const Color c = colors_.series[k];
    const std::size_t n = std::min(s.x.size(), s.y.size());
    const double w = st_.line(s.width);
    const auto dash = dash_pattern(s.dash, w, st_);
    const bool round = s.dash == Dash::kDotted || s.dash == Dash::kDashDot;
    // Break the line at points an axis cannot show (NaN, or <= 0 on a log axis).
    std::vector<P3> run;
    auto emit = [&] {
      if (run.size() >= 2) p.polyline(run, w, c, dash, round);
      run.clear();
    };
    for (std::size_t j = 0; j < n; ++j) {
      if (!xm_.valid(s.x[j]) || !ym_.valid(s.y[j])) {
        emit();
        continue;
      }
      P3 q = map(s.x[j], s.y[j]);
      q.x() = std::clamp(q.x(), -1e5, 1e5);
      q.y() = std::clamp(q.y(), -1e5, 1e5);
      run.push_back(q);
    }
    emit();
  }
}

void PanelPlan::series_markers(Canvas& p) const {
  for (std::size_t i = 0; i < pn_.series.size(); ++i) {
    const std::size_t k = drawn_series(i);
    const Series& s = pn_.series[k];
    if (s.marker == Marker::kNone) continue;
    const double size = st_.marker(s.marker_size);
    for (const Vector2d& q : marker_points(s))
      draw_marker(p, s.marker, q.x(), q.y(), size, colors_.series[k]);
  }
}

void PanelPlan::annotations(Canvas& p) const {
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

void PanelPlan::frame_and_ticks(Canvas& p) const {
  const double fw = st_.frame_width;
  p.rect_outline(rect_.x0 - fw, rect_.y0 - fw, rect_.x1 + fw, rect_.y1 + fw, fw, kAxisColor);
  const double tw = fw, tl = st_.tick_len;
  for (std::size_t i = 0; i < xt_.values.size(); ++i) {
    const double x = xm_(xt_.values[i]);
    p.rect(x - 0.5 * tw, rect_.y1 + fw, x + 0.5 * tw, rect_.y1 + fw + tl, kAxisColor);
    p.text(xt_.labels[i], x, rect_.y1 + fw + tl + 0.4 * st_.pad, st_.tick_font, kTickTextColor,
           HAlign::kCenter, VAlign::kTop);
  }
  for (double v : xt_.minor) {
    const double x = xm_(v);
    p.rect(x - 0.5 * tw, rect_.y1 + fw, x + 0.5 * tw, rect_.y1 + fw + 0.55 * tl, kAxisColor);
  }
  for (std::size_t i = 0; i < yt_.values.size(); ++i) {
    const double y = ym_(yt_.values[i]);
    p.rect(rect_.x0 - fw - tl, y - 0.5 * tw, rect_.x0 - fw, y + 0.5 * tw, kAxisColor);
    p.text(yt_.labels[i], rect_.x0 - fw - tl - 0.4 * st_.pad, y, st_.tick_font, kTickTextColor,
           HAlign::kRight, VAlign::kCenter);
  }
  for (double v : yt_.minor) {
    const double y = ym_(v);
    p.rect(rect_.x0 - fw - 0.55 * tl, y - 0.5 * tw, rect_.x0 - fw, y + 0.5 * tw, kAxisColor);
  }
}

void PanelPlan::labels(Canvas& p) const {
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
  draw_title(p, title_);
}

}  // namespace detail

using detail::FigurePlan;
using detail::PanelPlan;
using detail::plan_figure;

namespace {

Plot2D::Layout layout_of(const FigurePlan& fp) {
  Plot2D::Layout out;
  out.title = fp.title.box;
  out.title_lines = static_cast<int>(fp.title.lines.size());
  out.title_size = fp.title.size;
  out.legend = fp.legend_box;
  for (const PanelPlan& p : fp.panels) out.panels.push_back(p.report());
  return out;
}

}  // namespace

Plot2D::Layout layout(const Plot2D& plot, int width, int height) {
  return layout_of(plan_figure(plot, width, height));
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

Plot2D::Layout detail::render_into_target(const Plot2D& plot, int width, int height,
                                          PhaseClock& clock) {
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
  return layout_of(fp);
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
