// The camera of a 3D scene: projection, and the fit that frames the scene.
#include "scene_fit.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <unordered_map>

#include "scene_shapes.h"

namespace rigid::render::detail {

using Eigen::Matrix3d;
using Eigen::Vector3d;

View make_view(const Camera& cam, int width, int height, double znear, double zfar) {
  View v;
  v.width = width;
  v.height = height;
  v.ortho = cam.orthographic;
  const Vector3d f = (cam.target - cam.eye).normalized();
  Vector3d up = cam.up;
  if (std::abs(f.dot(up.normalized())) > 0.999) up = f.unitOrthogonal();
  const Vector3d s = f.cross(up).normalized();
  const Vector3d u = s.cross(f);
  v.view.block<1, 3>(0, 0) = s.transpose();
  v.view.block<1, 3>(1, 0) = u.transpose();
  v.view.block<1, 3>(2, 0) = -f.transpose();
  v.view(0, 3) = -s.dot(cam.eye);
  v.view(1, 3) = -u.dot(cam.eye);
  v.view(2, 3) = f.dot(cam.eye);
  // Perspective depth must stay in front of the eye.
  if (!cam.orthographic) {
    zfar = std::max(zfar, 1e-3);
    znear = std::max(znear, zfar * 1e-4);
  }
  const double aspect = double(width) / height;
  const double tan_half = std::tan(0.5 * cam.fov_y_deg * EIGEN_PI / 180.0);
  v.proj.setZero();
  if (cam.orthographic) {
    const double h =
        cam.ortho_height > 0 ? cam.ortho_height : 2 * (cam.target - cam.eye).norm() * tan_half;
    v.proj(0, 0) = 2 / (h * aspect);
    v.proj(1, 1) = 2 / h;
    v.proj(2, 2) = -2 / (zfar - znear);
    v.proj(2, 3) = -(zfar + znear) / (zfar - znear);
    v.proj(3, 3) = 1;
    v.focal_px = height / h;
  } else {
    v.proj(0, 0) = 1 / (tan_half * aspect);
    v.proj(1, 1) = 1 / tan_half;
    v.proj(2, 2) = -(zfar + znear) / (zfar - znear);
    v.proj(2, 3) = -2 * zfar * znear / (zfar - znear);
    v.proj(3, 2) = -1;
    v.focal_px = 0.5 * height / tan_half;
  }
  return v;
}

namespace {

// Points on the surfaces of the unit shapes, finely spaced: the drawn meshes, inscribed in
// the same surfaces with fewer segments, lie within them.
const std::vector<Vector3d>& unit_outline(Scene3D::Shape shape, double torus_minor) {
  constexpr int kSegments = 64;
  using Key = std::pair<int, int>;
  static std::map<Key, std::vector<Vector3d>> cache;
  const int ratio = torus_ratio_key(shape, torus_minor);
  const Key key{static_cast<int>(shape), ratio};
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  const Mesh m = unit_shape_mesh(shape, kSegments, ratio);
  std::vector<Vector3d> points;
  points.reserve(m.positions.size());
  for (const auto& p : m.positions) points.push_back(p.cast<double>());
  return cache.emplace(key, std::move(points)).first->second;
}

}  // namespace

// Everything the image must show: surfaces and thick lines (labels are the caller's).
std::vector<FitPoint> fit_points(const Scene3D& scene, double geo) {
  using S = Scene3D::Shape;
  std::size_t n = 0;
  for (const Scene3D::Object& o : scene.objects()) {
    n += o.shape == S::kTube     ? o.path.size()
         : o.shape == S::kCustom ? o.mesh.positions.size()
                                 : unit_outline(o.shape, o.torus_minor).size();
  }
  for (const Scene3D::Polyline& pl : scene.polylines()) n += pl.points.size();
  std::vector<FitPoint> out;
  out.reserve(n + scene.labels().size());
  for (const Scene3D::Object& o : scene.objects()) {
    if (o.shape == S::kTube) {
      for (const Vector3d& p : o.path) out.push_back({p, o.tube_radius});
    } else if (o.shape == S::kCustom) {
      for (const auto& p : o.mesh.positions) out.push_back({o.transform * p.cast<double>()});
    } else {
      for (const Vector3d& p : unit_outline(o.shape, o.torus_minor))
        out.push_back({o.transform * p});
    }
  }
  for (const Scene3D::Polyline& pl : scene.polylines()) {
    const double hw = 0.5 * std::max(2.0, pl.width * geo);
    for (const Vector3d& p : pl.points) out.push_back({p, 0, hw, hw, hw, hw});
  }
  return out;
}

namespace {

// A bound on the eye's sideways shift, linear in its distance d from the target plane: c + m d.
struct Bound {
  double c = 0, m = 0;
  double at(double d) const { return c + m * d; }
};

// The camera's axes about its target (s right, u up, f forward), and the image's centre
// and focal length in pixels.
struct Axes {
  Vector3d target, f, s, u;
  bool ortho;
  double focal, cx, cy;
};

// Bounds of one kind as they come, kept one a slope: of bounds that share a slope only the
// tightest constrains, at every d, and rounding keeps that order (c + m d rounds
// monotonically in c). Most points share their slopes (all but those carrying text
// boxes), and come in runs of one slope (a polyline's, a surface's): the last slope is
// looked at first.
class Tightest {
 public:
  explicit Tightest(bool keep_max) : keep_max_(keep_max) {}
  void add(const Bound& b) {
    if (last_ >= bounds_.size() || bounds_[last_].m != b.m) {
      const auto it = slot_.find(b.m);
      if (it == slot_.end()) {
        last_ = bounds_.size();
        slot_.emplace(b.m, last_);
        bounds_.push_back(b);
        return;
      }
      last_ = it->second;
    }
    double& c = bounds_[last_].c;
    c = keep_max_ ? std::max(c, b.c) : std::min(c, b.c);
  }
  std::vector<Bound> take() { return std::move(bounds_); }

 private:
  bool keep_max_;
  std::vector<Bound> bounds_;
  std::unordered_map<double, std::size_t> slot_;
  std::size_t last_ = 0;
};

// The legend's corners a < alpha, b < beta, grouped by their two slopes; of a group only
// those no other corner of the group contains are kept, as they come: a staircase, alpha
// rising and beta falling, in which a corner is looked up in log time.
class Corners {
 public:
  void add(const Bound& a, const Bound& b) {
    const std::pair<double, double> slopes{a.m, b.m};
    if (last_ >= groups_.size() || groups_[last_].first != slopes) {
      const auto it = slot_.find(slopes);
      if (it == slot_.end()) {
        slot_.emplace(slopes, groups_.size());
        groups_.push_back({slopes, {}});
        last_ = groups_.size() - 1;
      } else {
        last_ = it->second;
      }
    }
    std::map<double, double>& stair = groups_[last_].second;
    // contained in the corner of least alpha at or past this one's, the tallest of those
    auto at = stair.lower_bound(a.c);
    if (at != stair.end() && at->second >= b.c) return;
    at = stair.insert_or_assign(at, a.c, b.c);
    // the corners it contains, narrower and no taller, go
    while (at != stair.begin() && std::prev(at)->second <= b.c) stair.erase(std::prev(at));
  }
  void take(std::vector<Bound>& a_legend, std::vector<Bound>& b_legend) {
    for (const auto& [slopes, stair] : groups_) {
      for (const auto& [ca, cb] : stair) {
        a_legend.push_back({ca, slopes.first});
        b_legend.push_back({cb, slopes.second});
      }
    }
  }

 private:
  struct PairHash {
    std::size_t operator()(const std::pair<double, double>& p) const {
      return std::hash<double>()(p.first) * 31 + std::hash<double>()(p.second);
    }
  };
  using Group = std::pair<std::pair<double, double>, std::map<double, double>>;
  std::vector<Group> groups_;
  std::unordered_map<std::pair<double, double>, std::size_t, PairHash> slot_;
  std::size_t last_ = 0;
};

// What the points ask of the shift (a, b) at a distance d: a_min <= a <= a_max and
// b_min <= b <= b_max keep them in the region; a < a_legend and b < b_legend put one under
// the legend. With the least distance that keeps them in front of the eye, and their extent.
// Only the bounds that can constrain are kept: the fit is the same, bit for bit, at a cost
// in distinct slopes rather than points (a live view fits a motion's many frames at once).
struct FitBounds {
  std::vector<Bound> a_min, a_max, b_min, b_max, a_legend, b_legend;
  double d_min = 0, extent = 0;
};

FitBounds point_bounds(const std::vector<FitPoint>& points, const Axes& ax,
                       const ScreenRect& region, const ScreenRect& legend, double margin) {
  const bool ortho = ax.ortho, has_legend = !legend.empty();
  const double focal = ax.focal, cx = ax.cx, cy = ax.cy;
  // Point left of (below) an edge at slope k: a >= ...; right of (above) it: a <= ... .
  // (a point's r is most often 0, whose product with the secant is 0 exactly)
  auto reach = [&](double r, double k) { return r == 0 || ortho ? r : r * std::hypot(1.0, k); };
  auto left_of = [&](double x, double z, double r, double k) {
    return Bound{x + reach(r, k) - k * z, -k};
  };
  auto right_of = [&](double x, double z, double r, double k) {
    return Bound{x - reach(r, k) - k * z, -k};
  };
  Tightest a_min(true), b_min(true), a_max(false), b_max(false);
  Corners corners;
  FitBounds out;
  for (FitPoint p : points) {
    // A text box wider than the region cannot fit whole: fit what can be.
    const double wx = p.left + p.right, wy = p.up + p.down;
    const double max_w = 0.9 * (region.x1 - region.x0), max_h = 0.9 * (region.y1 - region.y0);
    if (wx > max_w) p.left *= max_w / wx, p.right *= max_w / wx;
    if (wy > max_h) p.up *= max_h / wy, p.down *= max_h / wy;
    const Vector3d q = p.p - ax.target;
    const double x = q.dot(ax.s), y = q.dot(ax.u), z = ortho ? 0.0 : q.dot(ax.f), r = p.radius;
    a_min.add(left_of(x, z, r, (region.x1 - cx - p.right) / focal));
    a_max.add(right_of(x, z, r, (region.x0 - cx + p.left) / focal));
    b_min.add(left_of(y, z, r, (cy - region.y0 - p.up) / focal));
    b_max.add(right_of(y, z, r, (cy - region.y1 + p.down) / focal));
    if (has_legend) {
      corners.add(left_of(x, z, r, (legend.x0 - margin - cx - p.right) / focal),
                  left_of(y, z, r, (cy - legend.y1 - margin - p.up) / focal));
    }
    if (!ortho) out.d_min = std::max(out.d_min, r - z);
    out.extent = std::max(out.extent, q.norm() + r);
  }
  out.a_min = a_min.take(), out.a_max = a_max.take();
  out.b_min = b_min.take(), out.b_max = b_max.take();
  corners.take(out.a_legend, out.b_legend);
  return out;
}

// The shifts that keep every point in the region at a distance d.
struct Window {
  double a_lo, a_hi, b_lo, b_hi;
};

Window window(const FitBounds& fb, double d) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Window w{-kInf, kInf, -kInf, kInf};
  for (const Bound& bd : fb.a_min) w.a_lo = std::max(w.a_lo, bd.at(d));
  for (const Bound& bd : fb.a_max) w.a_hi = std::min(w.a_hi, bd.at(d));
  for (const Bound& bd : fb.b_min) w.b_lo = std::max(w.b_lo, bd.at(d));
  for (const Bound& bd : fb.b_max) w.b_hi = std::min(w.b_hi, bd.at(d));
  return w;
}

bool clear_of_legend(const FitBounds& fb, double d, double a, double b) {
  for (std::size_t i = 0; i < fb.a_legend.size(); ++i)
    if (a < fb.a_legend[i].at(d) && b < fb.b_legend[i].at(d)) return false;
  return true;
}

bool fits(const FitBounds& fb, double d) {
  const Window w = window(fb, d);
  return w.a_lo <= w.a_hi && w.b_lo <= w.b_hi && clear_of_legend(fb, d, w.a_hi, w.b_hi);
}

// The least distance that fits: bracketed, then bisected (fits(hi) holds throughout);
// none if no distance within the bracket's reach fits.
std::optional<double> least_distance(const FitBounds& fb) {
  double lo = fb.d_min, hi = fb.d_min + std::max(fb.extent, 1e-12);
  for (int k = 0; k < 200 && !fits(fb, hi); ++k) hi = lo + 2 * (hi - lo);
  if (!fits(fb, hi)) return std::nullopt;
  for (int k = 0; k < 100 && hi - lo > 1e-12 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (fits(fb, mid) ? hi : lo) = mid;
  }
  return hi;
}

// The shift nearest the window's centre that clears the legend: the centre itself, or
// the centre moved right-of-legend only, below-legend only, or towards (a_hi, b_hi).
std::pair<double, double> centred_shift(const FitBounds& fb, double d) {
  const Window w = window(fb, d);
  const double a_c = 0.5 * (w.a_lo + w.a_hi), b_c = 0.5 * (w.b_lo + w.b_hi);
  double a = a_c, b = b_c;
  if (clear_of_legend(fb, d, a_c, b_c)) return {a, b};
  double a_only = a_c, b_only = b_c, t = 0;
  for (std::size_t i = 0; i < fb.a_legend.size(); ++i) {
    const double alpha = fb.a_legend[i].at(d), beta = fb.b_legend[i].at(d);
    if (b_c < beta) a_only = std::max(a_only, alpha);
    if (a_c < alpha) b_only = std::max(b_only, beta);
    const double ta = w.a_hi > a_c ? (alpha - a_c) / (w.a_hi - a_c) : (alpha <= a_c ? 0.0 : 1.0);
    const double tb = w.b_hi > b_c ? (beta - b_c) / (w.b_hi - b_c) : (beta <= b_c ? 0.0 : 1.0);
    t = std::max(t, std::min(ta, tb));
  }
  t = std::min(t, 1.0);
  a = a_c + t * (w.a_hi - a_c);
  b = b_c + t * (w.b_hi - b_c);
  double best = std::hypot(a - a_c, b - b_c);
  if (a_only <= w.a_hi && a_only - a_c < best) a = a_only, b = b_c, best = a_only - a_c;
  if (b_only <= w.b_hi && b_only - b_c < best) a = a_c, b = b_only;
  return {a, b};
}

}  // namespace

// The camera framed on the points: its viewing direction and up kept, the eye moved along
// the line of sight to the nearest distance d, and sideways by (a, b) along the image's
// right and up, at which every point with its sphere and screen box lies in the layout's
// region, and left of or below the legend box (with the margin). The projection stays
// centred on the line of sight, so the perspective is that of the field of view.
//
// In camera coordinates about the target (x right, y up, z forward), a point projects to
// focal * (x - a) / (z + d) pixels right of the image centre. It stays left of an edge at
// slope k = pixels / focal, its sphere of radius r included, iff
//   x - a <= k (z + d) - r sqrt(1 + k^2),
// a bound linear in a and d; likewise for the other edges and for y and b. So for each d
// the shifts that fit form a window [a_lo, a_hi] × [b_lo, b_hi] (it grows with d), less
// the corners a < alpha_i, b < beta_i in which point i would be under the legend; the
// corner (a_hi, b_hi), the scene moved furthest left and down, is the last to clear it.
// Bisection finds the least d that fits; orthographic views are the case z = 0, sec = 1,
// of height 2 d tan(fov / 2).
namespace {

Camera fit(Camera cam, const std::vector<FitPoint>& points, const ScreenRect& region,
           const ScreenRect& legend, double margin, int width, int height) {
  Vector3d f = cam.target - cam.eye;
  const double eye_distance = f.norm();
  if (!(eye_distance > 0)) return cam;
  f.normalize();
  Vector3d up = cam.up;
  if (std::abs(f.dot(up.normalized())) > 0.999) up = f.unitOrthogonal();
  const Vector3d s = f.cross(up).normalized(), u = s.cross(f);
  const bool ortho = cam.orthographic;
  const double tan_half = std::tan(0.5 * cam.fov_y_deg * EIGEN_PI / 180.0);
  if (region.empty()) return cam;
  const Axes ax{cam.target, f, s, u, ortho, 0.5 * height / tan_half, 0.5 * width, 0.5 * height};

  const FitBounds fb = point_bounds(points, ax, region, legend, margin);
  const std::optional<double> d = least_distance(fb);
  if (!d) return cam;
  const auto [a, b] = centred_shift(fb, *d);
  cam.target += a * s + b * u;
  if (ortho) {
    cam.eye = cam.target - eye_distance * f;
    cam.ortho_height = 2 * *d * tan_half;
  } else {
    cam.eye = cam.target - *d * f;
  }
  return cam;
}

bool same(const Camera& a, const Camera& b) {
  return a.eye == b.eye && a.target == b.target && a.up == b.up && a.fov_y_deg == b.fov_y_deg &&
         a.orthographic == b.orthographic && a.ortho_height == b.ortho_height && a.fit == b.fit;
}

bool same(const ScreenRect& a, const ScreenRect& b) {
  return a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 && a.y1 == b.y1;
}

bool same(const std::vector<FitPoint>& a, const std::vector<FitPoint>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const FitPoint& p, const FitPoint& q) {
                      return p.p == q.p && p.radius == q.radius && p.left == q.left &&
                             p.right == q.right && p.up == q.up && p.down == q.down;
                    });
}

}  // namespace

// The last fit of this thread, kept with everything it was made from: a live view fits
// its camera again for every typed value, and where the value leaves the scene's extent
// as it was (the same points, text boxes and legend) the camera is the one it had.
Camera fitted(Camera cam, const std::vector<FitPoint>& points, const ScreenRect& region,
              const ScreenRect& legend, double margin, int width, int height) {
  if (!cam.fit || points.empty()) return cam;
  struct Last {
    Camera cam, fitted;
    std::vector<FitPoint> points;
    ScreenRect region, legend;
    double margin = 0;
    int width = 0, height = 0;
    bool valid = false;
  };
  thread_local Last last;
  if (last.valid && same(last.cam, cam) && same(last.region, region) && same(last.legend, legend) &&
      last.margin == margin && last.width == width && last.height == height &&
      same(last.points, points)) {
    return last.fitted;
  }
  last.valid = false;
  last.fitted = fit(cam, points, region, legend, margin, width, height);
  last.cam = cam;
  last.points = points;
  last.region = region;
  last.legend = legend;
  last.margin = margin;
  last.width = width;
  last.height = height;
  last.valid = true;
  return last.fitted;
}

// Depth range of the points seen from a camera, padded a little.
std::pair<double, double> depth_range(const Camera& cam, const std::vector<FitPoint>& points) {
  const Vector3d f = (cam.target - cam.eye).normalized();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const FitPoint& p : points) {
    const double z = (p.p - cam.eye).dot(f);
    lo = std::min(lo, z - p.radius);
    hi = std::max(hi, z + p.radius);
  }
  if (!(lo <= hi)) {
    const double z = (cam.target - cam.eye).norm();
    lo = 0.5 * z;
    hi = 2 * z + 1e-3;
  }
  const double pad = 0.02 * (hi - lo) + 1e-9 * std::max({std::abs(lo), std::abs(hi), 1.0});
  return {lo - pad, hi + pad};
}

}  // namespace rigid::render::detail
