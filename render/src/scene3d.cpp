// The scene description: what each add_* call puts in a scene, and the
// shape facts (unit meshes, bounding spheres) that drawing and the camera fit
// share. Part of the description library: no GL, no fonts.
#include "rigid/render/scene3d.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "scene_shapes.h"

namespace rigid::render {

using Eigen::Affine3d;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace detail {

// The minor/major ratio of a torus in thousandths (0 for other shapes): a cache key.
int torus_ratio_key(Scene3D::Shape shape, double torus_minor) {
  return shape == Scene3D::Shape::kTorus ? static_cast<int>(std::lround(torus_minor * 1000)) : 0;
}

// The unit mesh of a built-in shape with `segments` around (empty for tubes and custom meshes).
Mesh unit_shape_mesh(Scene3D::Shape shape, int segments, int ratio) {
  switch (shape) {
    case Scene3D::Shape::kSphere:
      return make_sphere(segments);
    case Scene3D::Shape::kCone:
      return make_cone(segments);
    case Scene3D::Shape::kCylinder:
      return make_cylinder(segments);
    case Scene3D::Shape::kDisk:
      return make_disk(segments);
    case Scene3D::Shape::kBox:
      return make_box();
    case Scene3D::Shape::kTorus:
      return make_torus(ratio / 1000.0, segments,
                        std::max(8, static_cast<int>(segments * ratio / 1000.0) + 8));
    case Scene3D::Shape::kPlane:
      return make_plane();
    case Scene3D::Shape::kTube:
    case Scene3D::Shape::kCustom:
      break;
  }
  return {};
}

// Bounding sphere of an object in world space (centre, radius).
std::pair<Vector3d, double> bounds(const Scene3D::Object& o) {
  using S = Scene3D::Shape;
  const Matrix3d l = o.transform.linear();
  const double sx = l.col(0).norm(), sy = l.col(1).norm(), sz = l.col(2).norm();
  const Vector3d t = o.transform.translation();
  switch (o.shape) {
    case S::kSphere:
      return {t, std::max({sx, sy, sz})};
    case S::kBox:
      return {t, std::sqrt(sx * sx + sy * sy + sz * sz)};
    case S::kCone:
    case S::kCylinder: {
      const Vector3d c = t + 0.5 * l.col(2);
      return {c, std::hypot(std::max(sx, sy), 0.5 * sz)};
    }
    case S::kDisk:
    case S::kPlane:
      return {t, std::max(sx, sy) * (o.shape == S::kPlane ? std::sqrt(2.0) : 1.0)};
    case S::kTorus:
      return {t, std::max(sx, sy) * (1 + o.torus_minor)};
    case S::kTube:
    case S::kCustom: {
      Eigen::AlignedBox3d box;
      if (o.shape == S::kTube)
        for (const Vector3d& p : o.path) box.extend(p);
      else
        for (const auto& p : o.mesh.positions) box.extend(o.transform * p.cast<double>());
      if (box.isEmpty()) return {t, 0};
      return {box.center(), 0.5 * box.diagonal().norm() + o.tube_radius};
    }
  }
  return {t, 1};
}

double scene_extent(const Scene3D& scene) {
  double extent = 0.0;
  for (const Scene3D::Object& o : scene.objects()) {
    const auto [c, r] = bounds(o);
    extent = std::max(extent, c.norm() + r);
  }
  for (const Scene3D::Polyline& pl : scene.polylines())
    for (const Vector3d& p : pl.points) extent = std::max(extent, p.norm());
  return extent;
}

double normalising_scale(const Scene3D& scene) {
  // GL works in float: a scene of 1e-50 m or 1e30 m is brought to unit size in
  // double first. Perspective and the picture are unchanged by a uniform scale.
  const double extent = scene_extent(scene);
  return extent > 0.0 && std::isfinite(extent) && (extent < 1e-3 || extent > 1e3) ? 1.0 / extent
                                                                                  : 1.0;
}

}  // namespace detail

namespace {

// A rotation whose z column is the unit vector d.
Matrix3d frame_z(const Vector3d& d) {
  const Vector3d z = d.normalized();
  const Vector3d x = z.unitOrthogonal();
  Matrix3d r;
  r.col(0) = x;
  r.col(1) = z.cross(x);
  r.col(2) = z;
  return r;
}

Affine3d place(const Vector3d& t, const Matrix3d& r, const Vector3d& scale) {
  Affine3d a = Affine3d::Identity();
  a.linear() = r * scale.asDiagonal();
  a.translation() = t;
  return a;
}

void check_finite(const Vector3d& v, const char* what) {
  if (!v.allFinite())
    throw std::invalid_argument(std::string("Scene3D: ") + what + " is not finite");
}

Scene3D::Object make_object(Scene3D::Shape shape, const Affine3d& transform, const Material& m,
                            std::string label) {
  Scene3D::Object o;
  o.shape = shape;
  o.transform = transform;
  o.material = m;
  o.label = std::move(label);
  return o;
}

}  // namespace

Material Scene3D::resolve(Material m) {
  if (m.color.a < 0) m.color = palette_color(auto_colors_++);
  m.opacity = std::clamp(m.opacity, 0.0f, 1.0f);
  return m;
}

void Scene3D::add_sphere(const Vector3d& center, double radius, Material m, std::string label) {
  add_ellipsoid(center, Vector3d::Constant(radius), Matrix3d::Identity(), m, std::move(label));
}

Scene3D Scene3D::recolored(const std::string& label, Color color) const {
  // A legend entry names everything drawn in its colour (an arrow's head with its shaft,
  // the same face in every panel of a strip): find the named item's colour, then recolour
  // every surface and line in it.
  std::optional<Color> named;
  for (const Object& o : objects_)
    if (!named && o.label == label) named = o.material.color;
  for (const Polyline& p : polylines_)
    if (!named && p.label == label) named = p.color;
  Scene3D out = *this;
  if (!named) return out;
  const auto same = [&](const Color& c) {
    return c.r == named->r && c.g == named->g && c.b == named->b;
  };
  for (Object& o : out.objects_)
    if (same(o.material.color)) o.material.color = color;
  for (Polyline& p : out.polylines_)
    if (same(p.color)) p.color = color;
  return out;
}

void Scene3D::add_marker(const Vector3d& center, double radius, Material m, std::string label) {
  add_sphere(center, radius, m, std::move(label));
  objects_.back().marker = true;
}

void Scene3D::add_ellipsoid(const Vector3d& center, const Vector3d& semi_axes,
                            const Matrix3d& rotation, Material m, std::string label) {
  check_finite(center, "ellipsoid centre");
  if (!(semi_axes.minCoeff() > 0))
    throw std::invalid_argument("Scene3D: ellipsoid semi-axes must be > 0");
  objects_.push_back(make_object(Shape::kSphere, place(center, rotation, semi_axes), resolve(m),
                                 std::move(label)));
}

void Scene3D::add_cone(const Vector3d& apex, const Vector3d& base_center, double radius, Material m,
                       std::string label) {
  const Vector3d axis = apex - base_center;
  if (!(axis.norm() > 0) || !(radius > 0))
    throw std::invalid_argument("Scene3D: cone needs height and radius > 0");
  objects_.push_back(make_object(Shape::kCone,
                                 place(base_center, frame_z(axis), {radius, radius, axis.norm()}),
                                 resolve(m), std::move(label)));
}

void Scene3D::add_cylinder(const Vector3d& p0, const Vector3d& p1, double radius, Material m,
                           std::string label) {
  const Vector3d axis = p1 - p0;
  if (!(axis.norm() > 0) || !(radius > 0))
    throw std::invalid_argument("Scene3D: cylinder needs length and radius > 0");
  objects_.push_back(make_object(Shape::kCylinder,
                                 place(p0, frame_z(axis), {radius, radius, axis.norm()}),
                                 resolve(m), std::move(label)));
}

void Scene3D::add_arrow(const Vector3d& from, const Vector3d& to, double radius, Material m,
                        std::string label) {
  const Vector3d d = to - from;
  const double len = d.norm();
  if (!(len > 0) || !(radius > 0))
    throw std::invalid_argument("Scene3D: arrow needs length and radius > 0");
  m = resolve(m);
  const double head = std::min(0.35 * len, 7.0 * radius);
  const double head_r = std::min(2.6 * radius, 0.5 * head);
  const Vector3d base = to - d / len * head;
  add_cylinder(from, base, radius, m, std::move(label));
  add_cone(to, base, std::max(head_r, radius * 1.5), m);
}

void Scene3D::add_box(const Vector3d& center, const Vector3d& half_extents,
                      const Matrix3d& rotation, Material m, std::string label) {
  if (!(half_extents.minCoeff() > 0))
    throw std::invalid_argument("Scene3D: box half-extents must be > 0");
  objects_.push_back(make_object(Shape::kBox, place(center, rotation, half_extents), resolve(m),
                                 std::move(label)));
}

void Scene3D::add_disk(const Vector3d& center, const Vector3d& normal, double radius, Material m,
                       std::string label) {
  if (!(normal.norm() > 0) || !(radius > 0))
    throw std::invalid_argument("Scene3D: disk needs normal and radius > 0");
  objects_.push_back(make_object(Shape::kDisk,
                                 place(center, frame_z(normal), {radius, radius, radius}),
                                 resolve(m), std::move(label)));
}

void Scene3D::add_torus(const Vector3d& center, const Vector3d& normal, double major_radius,
                        double minor_radius, Material m, std::string label) {
  if (!(normal.norm() > 0) || !(major_radius > 0) || !(minor_radius > 0) ||
      minor_radius >= major_radius)
    throw std::invalid_argument("Scene3D: torus needs 0 < minor radius < major radius");
  Object o =
      make_object(Shape::kTorus, place(center, frame_z(normal), Vector3d::Constant(major_radius)),
                  resolve(m), std::move(label));
  o.torus_minor = minor_radius / major_radius;
  objects_.push_back(std::move(o));
}

void Scene3D::add_plane(const Vector3d& center, const Vector3d& normal, double half_size,
                        Material m, std::string label) {
  if (!(normal.norm() > 0) || !(half_size > 0))
    throw std::invalid_argument("Scene3D: plane needs normal and size > 0");
  objects_.push_back(make_object(Shape::kPlane,
                                 place(center, frame_z(normal), Vector3d::Constant(half_size)),
                                 resolve(m), std::move(label)));
}

void Scene3D::add_tube(std::vector<Vector3d> path, double radius, Material m, std::string label) {
  if (!(radius > 0)) throw std::invalid_argument("Scene3D: tube radius must be > 0");
  Object o = make_object(Shape::kTube, Affine3d::Identity(), resolve(m), std::move(label));
  o.path = std::move(path);
  o.tube_radius = radius;
  objects_.push_back(std::move(o));
}

void Scene3D::add_mesh(Mesh mesh, const Affine3d& transform, Material m, std::string label) {
  Object o = make_object(Shape::kCustom, transform, resolve(m), std::move(label));
  o.mesh = std::move(mesh);
  objects_.push_back(std::move(o));
}

void Scene3D::add_polyline(std::vector<Vector3d> points, Color color, double width,
                           std::string label) {
  if (color.a < 0) color = palette_color(auto_colors_++);
  polylines_.push_back({std::move(points), color, width, std::move(label)});
}

void Scene3D::add_axes(const Vector3d& origin, const Matrix3d& rotation, double length,
                       const std::array<std::string, 3>& labels, double radius) {
  if (!(length > 0)) throw std::invalid_argument("Scene3D: axis length must be > 0");
  const double r = radius > 0 ? radius : 0.012 * length;
  Material m;
  m.color = rgb8(80, 80, 80);
  m.specular = 0.15f;
  for (int k = 0; k < 3; ++k) {
    const Vector3d d = rotation.col(k).normalized();
    add_arrow(origin, origin + length * d, r, m);
    labels_.push_back({origin + (length + 6 * r) * d, labels[k]});
  }
}

void Scene3D::add_label(Label3D label) {
  labels_.push_back(std::move(label));
}

void Scene3D::add_label(const Vector3d& position, std::string text, Color color) {
  Label3D l;
  l.position = position;
  l.text = std::move(text);
  l.color = color;
  labels_.push_back(std::move(l));
}

void Scene3D::merge(const Scene3D& other) {
  objects_.insert(objects_.end(), other.objects_.begin(), other.objects_.end());
  polylines_.insert(polylines_.end(), other.polylines_.begin(), other.polylines_.end());
  labels_.insert(labels_.end(), other.labels_.begin(), other.labels_.end());
}

Scene3D Scene3D::faded(const std::string& label, float opacity) const {
  Scene3D out = *this;
  for (Object& o : out.objects_) {
    o.material.opacity *= opacity;
    o.label.clear();
  }
  for (Polyline& pl : out.polylines_) {
    pl.color.a *= opacity;
    pl.label.clear();
  }
  out.labels_.clear();
  if (!out.objects_.empty()) {
    out.objects_.front().label = label;
  } else if (!out.polylines_.empty()) {
    out.polylines_.front().label = label;
  }
  return out;
}

std::vector<std::string> Scene3D::legend_labels() const {
  std::vector<std::string> out =
      legend_from ? legend_from->legend_labels() : std::vector<std::string>{};
  const auto add = [&out](const std::string& label) {
    if (!label.empty() && std::find(out.begin(), out.end(), label) == out.end())
      out.push_back(label);
  };
  for (const Object& o : objects_) add(o.label);
  for (const Polyline& pl : polylines_) add(pl.label);
  return out;
}

Scene3D Scene3D::legend_only() const {
  Scene3D out;
  out.title = title;
  std::vector<std::string> seen;
  const auto first = [&seen](const std::string& label) {
    if (label.empty() || std::find(seen.begin(), seen.end(), label) != seen.end()) return false;
    seen.push_back(label);
    return true;
  };
  for (const Object& o : objects_)
    if (first(o.label)) {
      Object kept = o;
      kept.path.clear();
      kept.mesh = {};
      out.objects_.push_back(std::move(kept));
    }
  for (const Polyline& pl : polylines_)
    if (first(pl.label)) {
      Polyline kept = pl;
      kept.points.clear();
      out.polylines_.push_back(std::move(kept));
    }
  return out;
}

Scene3D Scene3D::without(const std::vector<std::string>& hidden) const {
  if (hidden.empty()) return *this;
  const auto is_hidden = [&hidden](const std::string& label) {
    return std::find(hidden.begin(), hidden.end(), label) != hidden.end();
  };
  Scene3D out = *this;
  // each list on its own: an unlabelled part goes with the labelled part before it
  const auto filter = [&is_hidden](auto& parts) {
    bool hiding = false;
    std::size_t kept = 0;
    for (std::size_t k = 0; k < parts.size(); ++k) {
      if (!parts[k].label.empty()) hiding = is_hidden(parts[k].label);
      if (hiding) continue;
      if (kept != k) parts[kept] = std::move(parts[k]);
      ++kept;
    }
    parts.resize(kept);
  };
  filter(out.objects_);
  filter(out.polylines_);
  // a hidden part leaves the legend it shares with other frames too
  if (legend_from) out.legend_from = std::make_shared<const Scene3D>(legend_from->without(hidden));
  return out;
}

Scene3D Scene3D::scaled(double k) const {
  Scene3D out = *this;
  const Eigen::Affine3d scale(Eigen::Scaling(k));
  for (Object& o : out.objects_) {
    if (o.shape == Shape::kTube) {
      // A tube is built from its path in world coordinates (its transform is the identity).
      for (Vector3d& p : o.path) p *= k;
      o.tube_radius *= k;
    } else {
      o.transform = scale * o.transform;
    }
  }
  for (Polyline& pl : out.polylines_)
    for (Vector3d& p : pl.points) p *= k;
  for (Label3D& l : out.labels_) l.position *= k;
  out.camera.eye *= k;
  out.camera.target *= k;
  out.camera.ortho_height *= k;
  return out;
}

}  // namespace rigid::render
