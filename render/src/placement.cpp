// Occupancy grid and first-clear placement of text and legend boxes.
#include "placement.h"

#include <algorithm>
#include <cmath>

namespace rigid::render::detail {

using Eigen::Vector2d;

Occupancy::Occupancy(const ScreenRect& area, double cell)
    : area_(area), cell_(std::max(1.0, cell)) {
  cols_ = std::max(1, static_cast<int>(std::ceil(area.width() / cell_)));
  rows_ = std::max(1, static_cast<int>(std::ceil(area.height() / cell_)));
  w_.assign(static_cast<std::size_t>(cols_) * rows_, 0.0f);
}

int Occupancy::col(double x) const {
  return std::clamp(static_cast<int>(std::floor((x - area_.x0) / cell_)), 0, cols_ - 1);
}

int Occupancy::row(double y) const {
  return std::clamp(static_cast<int>(std::floor((y - area_.y0) / cell_)), 0, rows_ - 1);
}

void Occupancy::mark(int i, int j, float weight) {
  float& c = w_[static_cast<std::size_t>(j) * cols_ + i];
  c = std::max(c, weight);
}

void Occupancy::add_rect(const ScreenRect& r, float weight) {
  if (!(r.x1 >= area_.x0 && r.x0 <= area_.x1 && r.y1 >= area_.y0 && r.y0 <= area_.y1)) return;
  const int i0 = col(r.x0), i1 = col(r.x1), j1 = row(r.y1);
  for (int j = row(r.y0); j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) mark(i, j, weight);
}

void Occupancy::add_segment(const Vector2d& a, const Vector2d& b, double half_width, float weight) {
  if (!a.allFinite() || !b.allFinite()) return;
  // Clip to the grid grown by the half width (Liang–Barsky), so a segment
  // running far outside (a steep curve clamped at 1e5 px) costs nothing.
  const ScreenRect box = area_.grown(half_width);
  double t0 = 0, t1 = 1;
  const Vector2d d = b - a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x() - box.x0, box.x1 - a.x(), a.y() - box.y0, box.y1 - a.y()};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0) {
      if (q[k] < 0) return;
      continue;
    }
    const double t = q[k] / p[k];
    if (p[k] < 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t0 > t1) return;
  }
  const Vector2d s = a + t0 * d, e = a + t1 * d;
  // Steps of half a cell leave no gap between marked cells.
  const int n = std::max(1, static_cast<int>(std::ceil((e - s).norm() / (0.5 * cell_))));
  for (int k = 0; k <= n; ++k) {
    const Vector2d c = s + (e - s) * (double(k) / n);
    add_rect({c.x() - half_width, c.y() - half_width, c.x() + half_width, c.y() + half_width},
             weight);
  }
}

void Occupancy::add_triangle(const Vector2d& a, const Vector2d& b, const Vector2d& c,
                             float weight) {
  if (!a.allFinite() || !b.allFinite() || !c.allFinite()) return;
  const double x0 = std::min({a.x(), b.x(), c.x()}), x1 = std::max({a.x(), b.x(), c.x()});
  const double y0 = std::min({a.y(), b.y(), c.y()}), y1 = std::max({a.y(), b.y(), c.y()});
  if (x1 < area_.x0 || x0 > area_.x1 || y1 < area_.y0 || y0 > area_.y1) return;
  auto edge = [](const Vector2d& p, const Vector2d& q, double x, double y) {
    return (q.x() - p.x()) * (y - p.y()) - (q.y() - p.y()) * (x - p.x());
  };
  const int i0 = col(x0), i1 = col(x1), j1 = row(y1);
  for (int j = row(y0); j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const double x = area_.x0 + (i + 0.5) * cell_, y = area_.y0 + (j + 0.5) * cell_;
      const double e0 = edge(a, b, x, y), e1 = edge(b, c, x, y), e2 = edge(c, a, x, y);
      if ((e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0)) mark(i, j, weight);
    }
  // Triangles smaller than a cell may hold no cell centre.
  add_points({&a, &b, &c}, weight);
}

void Occupancy::add_points(std::initializer_list<const Vector2d*> points, float weight) {
  for (const Vector2d* v : points)
    if (area_.contains(v->x(), v->y())) mark(col(v->x()), row(v->y()), weight);
}

Cover Occupancy::cover(const ScreenRect& r) const {
  Cover c;
  if (!(r.x1 > area_.x0 && r.x0 < area_.x1 && r.y1 > area_.y0 && r.y0 < area_.y1)) return c;
  const int i0 = col(r.x0), i1 = col(r.x1), j1 = row(r.y1);
  for (int j = row(r.y0); j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const float w = w_[static_cast<std::size_t>(j) * cols_ + i];
      if (w >= 1.0f)
        ++c.hard;
      else
        c.soft += w;
    }
  return c;
}

bool Occupancy::hard_extent(double x0, double x1, double& top, double& bottom) const {
  int first = -1, last = -1;
  const int i0 = col(x0), i1 = col(x1);
  for (int j = 0; j < rows_; ++j)
    for (int i = i0; i <= i1; ++i)
      if (w_[static_cast<std::size_t>(j) * cols_ + i] >= 1.0f) {
        if (first < 0) first = j;
        last = j;
        break;
      }
  if (first < 0) return false;
  top = area_.y0 + first * cell_;
  bottom = area_.y0 + (last + 1) * cell_;
  return true;
}

std::vector<ScreenRect> boxes_around(double x, double y, double w, double h, double d) {
  const double r = d / std::sqrt(2.0);  // diagonal boxes touch the circle of radius d
  return {
      {x + d, y - 0.5 * h, x + d + w, y + 0.5 * h},  // right
      {x - d - w, y - 0.5 * h, x - d, y + 0.5 * h},  // left
      {x - 0.5 * w, y - d - h, x + 0.5 * w, y - d},  // above
      {x - 0.5 * w, y + d, x + 0.5 * w, y + d + h},  // below
      {x + r, y - r - h, x + r + w, y - r},          // above right
      {x - r - w, y - r - h, x - r, y - r},          // above left
      {x + r, y + r, x + r + w, y + r + h},          // below right
      {x - r - w, y + r, x - r, y + r + h},          // below left
  };
}

ScreenRect keep_inside(const ScreenRect& box, const ScreenRect& bounds) {
  const double dx =
      std::clamp(box.x0, bounds.x0, std::max(bounds.x0, bounds.x1 - box.width())) - box.x0;
  const double dy =
      std::clamp(box.y0, bounds.y0, std::max(bounds.y0, bounds.y1 - box.height())) - box.y0;
  return {box.x0 + dx, box.y0 + dy, box.x1 + dx, box.y1 + dy};
}

Placement choose_place(const std::vector<ScreenRect>& candidates, const Occupancy& grid,
                       const ScreenRect& bounds, const std::vector<ScreenRect>& taken) {
  // Area shared with the boxes taken: zero for an acceptable place.
  auto clash = [&](const ScreenRect& c) {
    double area = 0;
    for (const ScreenRect& t : taken)
      if (t.overlaps(c))
        area += (std::min(c.x1, t.x1) - std::max(c.x0, t.x0)) *
                (std::min(c.y1, t.y1) - std::max(c.y0, t.y0));
    return area;
  };
  Placement best;
  double best_clash = 0;
  for (const ScreenRect& c : candidates) {
    if (!bounds.contains(c)) continue;
    const double k = clash(c);
    const Cover cover = grid.cover(c);
    // Clear of other text first, then the least data covered.
    if (!best.found || k < best_clash || (k == best_clash && cover < best.cover)) {
      best = {c, cover, true};
      best_clash = k;
    }
    if (k == 0 && cover.clear()) break;
  }
  best.found = best.found && best_clash == 0;
  return best;
}

}  // namespace rigid::render::detail
