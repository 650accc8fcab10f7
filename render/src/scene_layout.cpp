// A 3D scene's overlay, camera fit and label placement at one size.
#include "scene_layout.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "placement.h"
#include "scene_shapes.h"

namespace rigid::render::detail {

using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {

// How bright the shader (kMeshFragment in scene_gpu.cpp) draws a surface that faces
// the viewer, n = (0, 0, 1): the hemispheric ambient at its middle, mix(0.30, 0.46,
// 0.5), plus the key light 0.55 n.key and the fill 0.20 n.fill, with the lights'
// directions as the shader has them. About 0.82: a swatch at full colour would be
// lighter than the surface it names.
double facing_light() {
  const Vector3d key = Vector3d(-0.45, 0.65, 0.62).normalized();
  const Vector3d fill = Vector3d(0.75, -0.15, 0.45).normalized();
  return 0.38 + 0.55 * key.z() + 0.20 * fill.z();
}

// The legend rows: surfaces as filled swatches, each the colour a face toward the
// viewer is drawn in (lit, then a translucent one over white), markers as dots,
// polylines as lines.
std::vector<LegendEntry> legend_entries(const Scene3D& shown) {
  std::vector<LegendEntry> out;
  std::set<std::string> listed;  // an entry once, the first of its name (merged frames)
  const float light = static_cast<float>(facing_light());
  const auto add = [&](const Scene3D& scene) {
    for (const Scene3D::Object& o : scene.objects())
      if (!o.label.empty() && listed.insert(o.label).second) {
        const float a = o.material.opacity;
        const Color c = o.material.color;
        const float k = o.material.lit ? light : 1.0f;
        // A closed translucent shape is seen through two of its faces (its back, then
        // its front, each blended over what lies behind); an open one (a disk, a plane)
        // through one.
        const bool open = is_open(o.shape);
        const auto seen = [&](float v) {
          const float lit = std::min(1.0f, v * k), once = lit * a + (1 - a);
          return open ? once : lit * a + (1 - a) * once;
        };
        const Color swatch{seen(c.r), seen(c.g), seen(c.b), 1};
        // a point (a start, a mass, a pivot) is a dot, not a bar, so it is not read as a
        // line of its colour (the separatrix beside omega_0's ball)
        if (o.marker) {
          out.push_back({o.label, swatch, false, 0, Dash::kSolid, Marker::kCircle, 18});
        } else {
          out.push_back({o.label, swatch, true});
        }
      }
    for (const Scene3D::Polyline& pl : scene.polylines())
      if (!pl.label.empty() && listed.insert(pl.label).second)
        out.push_back({pl.label, pl.color, false, pl.width});
  };
  // a film's legend first, then any part this frame draws that it lacks (one the inputs
  // of a dragged slider brought in): every part drawn is named
  if (shown.legend_from) add(*shown.legend_from);
  add(shown);
  return out;
}

// Unit-shape triangles coarse enough to be cheap, fine enough to show a shape's outline
// within a grid cell or two.
const Mesh& coarse_mesh(Scene3D::Shape shape, double torus_minor) {
  constexpr int kSegments = 24;
  static std::map<std::pair<int, int>, Mesh> cache;
  const int ratio = torus_ratio_key(shape, torus_minor);
  const std::pair<int, int> key{static_cast<int>(shape), ratio};
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, unit_shape_mesh(shape, kSegments, ratio)).first;
  return it->second;
}

// What the scene covers on screen: opaque surfaces and lines in full weight, translucent
// surfaces in proportion to their opacity (text over a faint shell is readable).
Occupancy scene_grid(const Scene3D& scene, const View& view, const Style& st) {
  Occupancy grid({0, 0, double(view.width), double(view.height)}, std::max(3.0, 4 * st.s));
  auto screen = [&](const Vector3d& p, Vector2d& out) {
    const Eigen::Vector4d s = view.project(p);
    out = {s.x(), s.y()};
    return s.w() > 0;
  };
  // A closed convex surface's back faces lie under its front faces: `front_only` leaves
  // them out (half the triangles), keeping their corners' cells, which it also covers.
  auto add_mesh = [&](const Mesh& m, const Eigen::Affine3d& t, float w, bool front_only) {
    std::vector<Vector2d> q(m.positions.size());
    std::vector<char> ok(m.positions.size());
    for (std::size_t i = 0; i < q.size(); ++i)
      ok[i] = screen(t * m.positions[i].cast<double>(), q[i]);
    // outward faces turn clockwise on the screen (y down), or the other way mirrored
    const double facing = t.linear().determinant() < 0 ? -1.0 : 1.0;
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
      const auto a = m.indices[i], b = m.indices[i + 1], c = m.indices[i + 2];
      if (!(ok[a] && ok[b] && ok[c])) continue;
      const Vector2d ab = q[b] - q[a], ac = q[c] - q[a];
      if (front_only && facing * (ab.x() * ac.y() - ab.y() * ac.x()) > 0) {
        grid.add_points({&q[a], &q[b], &q[c]}, w);
        continue;
      }
      grid.add_triangle(q[a], q[b], q[c], w);
    }
  };
  auto add_path = [&](const std::vector<Vector3d>& path, double half_width_px, double radius,
                      float w) {
    Vector2d prev;
    bool have_prev = false;
    for (const Vector3d& p : path) {
      Vector2d cur;
      const bool ok = screen(p, cur);
      const double hw = half_width_px + (radius > 0 ? view.pixels(radius, p) : 0.0);
      if (ok && have_prev)
        grid.add_segment(prev, cur, hw, w);
      else if (ok)
        grid.add_segment(cur, cur, hw, w);
      prev = cur;
      have_prev = ok;
    }
  };
  for (const Scene3D::Object& o : scene.objects()) {
    const float w = o.material.opacity >= 0.99f ? 1.0f : 0.5f * o.material.opacity;
    if (o.shape == Scene3D::Shape::kTube)
      add_path(o.path, 1.0, o.tube_radius, w);
    else if (o.shape == Scene3D::Shape::kCustom)
      add_mesh(o.mesh, o.transform, w, false);
    else
      add_mesh(coarse_mesh(o.shape, o.torus_minor), o.transform, w,
               !is_open(o.shape) && o.shape != Scene3D::Shape::kTorus);
  }
  for (const Scene3D::Polyline& pl : scene.polylines())
    add_path(pl.points, 0.5 * st.line(pl.width) + 1, 0, 1.0f);
  return grid;
}

// Where a label's text may go about its projected point: on it, then beside it (right,
// left, above, below, diagonally), near and then farther (farther for a point that
// several labels share, each kept off the others).
std::vector<ScreenRect> label_candidates(const Vector2d& q, const TextExtent& e, const Style& st) {
  const double w = e.width, h = e.height();
  std::vector<ScreenRect> c{{q.x() - 0.5 * w, q.y() - 0.5 * h, q.x() + 0.5 * w, q.y() + 0.5 * h}};
  for (double d : {0.5, 2.0, 4.0, 6.0, 8.0, 10.0, 12.0}) {
    const std::vector<ScreenRect> ring = boxes_around(q.x(), q.y(), w, h, d * st.pad);
    c.insert(c.end(), ring.begin(), ring.end());
  }
  return c;
}

}  // namespace

SceneFrame frame_scene(const Scene3D& scene, int width, int height, bool place_labels) {
  SceneFrame fr;
  fr.st = figure_style(width, height, scene.min_text_px);
  const Style& st = fr.st;
  fr.title = layout_title(scene.title, st.title_font, st.margin, width - st.margin, 0.5 * width,
                          st.margin, st.title_floor);
  const double below_title = scene.title.empty() ? 0.0 : fr.title.box.y1;
  fr.region = {st.margin, below_title + st.margin, width - st.margin, height - st.margin};
  if (scene.show_legend) fr.entries = legend_entries(scene);
  if (!fr.entries.empty()) {
    const LegendSize z = measure_legend(fr.entries, st);
    const double x1 = width - st.margin,
                 y0 = scene.title.empty() ? st.margin : below_title + st.pad;
    fr.legend = {x1 - z.width, y0, x1, y0 + z.height};
  }

  // The fit keeps each label's text, centred on its point and a little around, in view:
  // the placement below then finds room on or beside the point.
  std::vector<FitPoint> points = fit_points(scene, st.s);
  std::vector<TextExtent> extents;
  for (const Label3D& l : scene.labels()) {
    extents.push_back(measure_text(l.text, st.label_font));
    if (l.text.empty()) continue;
    const double hw = 0.5 * extents.back().width + 0.5 * st.pad;
    const double hh = 0.5 * extents.back().height() + 0.5 * st.pad;
    points.push_back({l.position, 0, hw, hw, hh, hh});
  }
  fr.camera = fitted(scene.camera, points, fr.region, fr.legend, st.margin, width, height);
  const auto [znear, zfar] = depth_range(fr.camera, points);
  fr.view = make_view(fr.camera, width, height, znear, zfar);

  // Labels in order, each clear of the geometry where it can be, never over the title,
  // the legend or near an earlier label, and inside the region the scene was fitted into.
  // (A camera asked for alone needs none of it: the geometry's grid is most of the work.)
  if (!place_labels) return fr;
  const Occupancy grid = scene_grid(scene, fr.view, st);
  std::vector<ScreenRect> taken;
  if (!fr.title.box.empty()) taken.push_back(fr.title.box);
  if (!fr.legend.empty()) taken.push_back(fr.legend.grown(0.5 * st.pad));
  const ScreenRect& bounds = fr.region;
  for (std::size_t k = 0; k < scene.labels().size(); ++k) {
    const Label3D& l = scene.labels()[k];
    const Eigen::Vector4d s = fr.view.project(l.position);
    if (s.w() < 0 || l.text.empty()) {
      fr.labels.push_back({});
      continue;
    }
    const std::vector<ScreenRect> c = label_candidates({s.x(), s.y()}, extents[k], st);
    Placement pl;
    if (l.pinned) {
      pl = choose_place({c.front()}, Occupancy(bounds, bounds.width()), bounds, taken);
      if (!pl.found) pl = {};
    }
    if (pl.box.empty()) pl = choose_place(c, grid, bounds, taken);
    // No candidate inside the region (text wider than it): on the point, kept in view.
    const ScreenRect box = pl.box.empty() ? keep_inside(c.front(), bounds) : pl.box;
    fr.labels.push_back(box);
    // later labels keep two fifths of a line's height off it, and on its line more than a
    // line's height: two labels a space apart read as one ("t = 0.769 s t = 0.984 s")
    const double h = box.height();
    taken.push_back({box.x0 - 1.1 * h, box.y0 - 0.4 * h, box.x1 + 1.1 * h, box.y1 + 0.4 * h});
  }
  return fr;
}

}  // namespace rigid::render::detail
