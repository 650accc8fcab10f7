// Placing what a 2D panel labels: an occupancy grid of what the data draws, then each
// reference line's label, the legend (the user's corner, or matplotlib's "best" spot,
// with headroom grown for it where the data would be under it) and each annotation's
// text, where they cover the least.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "plot2d_plan.h"
#include "rigid/render/text.h"

namespace rigid::render::detail {

using Eigen::Vector2d;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool fixed_min(const Axis& a) {
  return std::isfinite(a.min) && (a.scale == Scale::kLinear || a.min > 0);
}
bool fixed_max(const Axis& a) {
  return std::isfinite(a.max) && (a.scale == Scale::kLinear || a.max > 0);
}

constexpr Spot kSpots[] = {Spot::kTopRight, Spot::kTopLeft, Spot::kBottomLeft, Spot::kBottomRight,
                           Spot::kRight,    Spot::kLeft,    Spot::kBottom,     Spot::kTop};

bool at_top(Spot s) {
  return s == Spot::kTopRight || s == Spot::kTopLeft || s == Spot::kTop;
}
bool at_bottom(Spot s) {
  return s == Spot::kBottomRight || s == Spot::kBottomLeft || s == Spot::kBottom;
}

}  // namespace

std::vector<Vector2d> PanelPlan::marker_points(const Series& s) const {
  std::vector<Vector2d> out;
  const std::size_t n = std::min(s.x.size(), s.y.size());
  const auto valid = [&](std::size_t i) { return xm_.valid(s.x[i]) && ym_.valid(s.y[i]); };
  if (!(s.marker_spacing > 0)) {
    for (std::size_t i = 0; i < n; ++i)
      if (valid(i)) out.emplace_back(xm_(s.x[i]), ym_(s.y[i]));
    return out;
  }
  // where the line crosses each x of the comb, each segment taking its crossings in
  // [left, right) so that a vertex two segments share is counted once
  const double d = std::max(1.0, s.marker_spacing * st_.s), phase = s.marker_phase;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (!valid(i) || !valid(i + 1)) continue;
    const Vector2d a(xm_(s.x[i]), ym_(s.y[i])), b(xm_(s.x[i + 1]), ym_(s.y[i + 1]));
    const double lo = std::min(a.x(), b.x()), hi = std::max(a.x(), b.x());
    if (!(hi > lo)) continue;
    for (double k = std::ceil((lo - rect_.x0) / d - phase);; ++k) {
      const double x = rect_.x0 + (k + phase) * d;
      if (x >= hi) break;
      out.push_back(a + (x - a.x()) / (b.x() - a.x()) * (b - a));
    }
  }
  return out;
}

// What the data draws inside the frame: lines, markers, bands and the annotated points in
// full weight; reference lines lightly (text may cross them if it must).
Occupancy PanelPlan::data_grid() const {
  Occupancy grid(rect_, std::max(3.0, 4 * st_.s));
  auto xy = [&](double x, double y) { return Vector2d(xm_(x), ym_(y)); };
  for (std::size_t k = 0; k < pn_.series.size(); ++k) {
    const Series& s = pn_.series[k];
    const std::size_t n = std::min(s.x.size(), s.y.size());
    const double hw = 0.5 * st_.line(s.width) + 1;
    for (std::size_t i = 0; s.width > 0 && i + 1 < n; ++i) {
      if (!xm_.valid(s.x[i]) || !ym_.valid(s.y[i])) continue;
      if (xm_.valid(s.x[i + 1]) && ym_.valid(s.y[i + 1]))
        grid.add_segment(xy(s.x[i], s.y[i]), xy(s.x[i + 1], s.y[i + 1]), hw, 1.0f);
    }
    if (s.marker != Marker::kNone) {
      const double r = 0.5 * st_.marker(s.marker_size) + 1;
      for (const Vector2d& q : marker_points(s))
        grid.add_rect({q.x() - r, q.y() - r, q.x() + r, q.y() + r}, 1.0f);
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
void PanelPlan::add_ref_lines(Occupancy& grid, float weight, bool vertical) const {
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
void PanelPlan::place_ref_labels(const Occupancy& grid) {
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
    ref_sizes_[k] = fitting_size(r.label, st_.note_font, room);
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
    const Placement pl = choose_place(c, grid, rect_, taken);
    ref_boxes_[k] = pl.box.empty() ? c.front() : pl.box;
    ref_on_data_[k] = pl.box.empty() || pl.cover.hard > 0;
    taken.push_back(ref_boxes_[k]);
  }
}

ScreenRect PanelPlan::spot_box(Spot s) const {
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
Placement PanelPlan::place_legend(const Occupancy& grid) const {
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
  Placement p = choose_place(spots, grid, rect_.grown(1), {});
  if (!p.found) p = {spots.front(), grid.cover(spots.front()), true};
  return p;
}

// Grows the y range at its free end just enough for the legend, at the top or bottom spot
// needing the least growth, to clear the data under it; false if no end may grow.
bool PanelPlan::add_headroom(const Occupancy& grid) {
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
void PanelPlan::place_annotations() {
  const Occupancy grid = data_grid();
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
          boxes_around(q.x(), q.y(), e.width, e.height(), d * st_.pad);
      c.insert(c.end(), ring.begin(), ring.end());
    }
    const Placement pl = choose_place(c, grid, bounds, taken);
    // No place inside the frame (a text wider than it): keep what fits in view.
    const ScreenRect box = pl.box.empty() ? keep_inside(c.front(), bounds) : pl.box;
    note_boxes_.push_back(box);
    taken.push_back(box.grown(0.3 * st_.pad));
  }
}

}  // namespace rigid::render::detail
