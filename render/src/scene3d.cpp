// 3D scenes: object placement, tessellation by on-screen size, shading,
// translucency order, and the text overlay.
#include "rigid/render/scene3d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <tuple>

#include "gl.h"
#include "painter.h"
#include "rigid/render/png.h"
#include "target.h"

namespace rigid::render {

using Eigen::Affine3d;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

constexpr double kPi = 3.14159265358979323846;

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
  if (!v.allFinite()) throw std::invalid_argument(std::string("Scene3D: ") + what + " is not finite");
}

// ---- GPU side --------------------------------------------------------------

const char* kMeshVertex = R"(#version 330 core
in vec3 a_pos;
in vec3 a_normal;
uniform mat4 u_mvp;
uniform mat4 u_mv;
uniform mat3 u_nmat;
out vec3 v_n;
out vec3 v_p;
void main() {
  gl_Position = u_mvp * vec4(a_pos, 1.0);
  v_p = (u_mv * vec4(a_pos, 1.0)).xyz;
  v_n = u_nmat * a_normal;
}
)";

// Soft shading in view space: hemispheric ambient (sky above, ground below),
// Lambert from a key light (upper left, in front) and a weaker fill (right),
// and a mild Blinn-Phong highlight from the key. Back faces are lit as their
// own side so open surfaces and the insides of translucent shells look right.
const char* kMeshFragment = R"(#version 330 core
in vec3 v_n;
in vec3 v_p;
uniform vec4 u_color;
uniform float u_spec;
uniform float u_shininess;
uniform int u_ortho;
out vec4 frag;
void main() {
  vec3 n = normalize(v_n);
  if (!gl_FrontFacing) n = -n;
  vec3 v = u_ortho == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-v_p);
  const vec3 key = normalize(vec3(-0.45, 0.65, 0.62));
  const vec3 fill = normalize(vec3(0.75, -0.15, 0.45));
  float hemi = 0.5 + 0.5 * n.y;
  float ambient = mix(0.30, 0.46, hemi);
  float diffuse = 0.55 * max(dot(n, key), 0.0) + 0.20 * max(dot(n, fill), 0.0);
  float spec = u_spec * pow(max(dot(n, normalize(key + v)), 0.0), u_shininess);
  vec3 c = u_color.rgb * (ambient + diffuse) + vec3(spec);
  frag = vec4(min(c, vec3(1.0)), u_color.a);
}
)";

struct GpuMesh {
  GLuint vao = 0, vbo = 0, ibo = 0;
  GLsizei count = 0;
};

GpuMesh upload(const Mesh& m) {
  GpuMesh g;
  std::vector<float> data;
  data.reserve(m.positions.size() * 6);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    data.insert(data.end(), {m.positions[i].x(), m.positions[i].y(), m.positions[i].z()});
    data.insert(data.end(), {m.normals[i].x(), m.normals[i].y(), m.normals[i].z()});
  }
  auto& gl = detail::gl;
  gl.GenVertexArrays(1, &g.vao);
  gl.BindVertexArray(g.vao);
  gl.GenBuffers(1, &g.vbo);
  gl.BindBuffer(GL_ARRAY_BUFFER, g.vbo);
  gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
                GL_STATIC_DRAW);
  gl.GenBuffers(1, &g.ibo);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.ibo);
  gl.BufferData(GL_ELEMENT_ARRAY_BUFFER,
                static_cast<GLsizeiptr>(m.indices.size() * sizeof(std::uint32_t)), m.indices.data(),
                GL_STATIC_DRAW);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                         reinterpret_cast<const void*>(3 * sizeof(float)));
  gl.BindVertexArray(0);
  g.count = static_cast<GLsizei>(m.indices.size());
  return g;
}

void release(GpuMesh& g) {
  auto& gl = detail::gl;
  GLuint bufs[] = {g.vbo, g.ibo};
  gl.DeleteBuffers(2, bufs);
  gl.DeleteVertexArrays(1, &g.vao);
  g = GpuMesh{};
}

struct MeshProgram {
  GLuint program = 0;
  GLint mvp = -1, mv = -1, nmat = -1, color = -1, spec = -1, shininess = -1, ortho = -1;
};

MeshProgram& mesh_program() {
  static MeshProgram* p = [] {
    auto* m = new MeshProgram;
    const char* attrs[] = {"a_pos", "a_normal"};
    m->program = detail::build_program(kMeshVertex, kMeshFragment, attrs, 2);
    auto& gl = detail::gl;
    m->mvp = gl.GetUniformLocation(m->program, "u_mvp");
    m->mv = gl.GetUniformLocation(m->program, "u_mv");
    m->nmat = gl.GetUniformLocation(m->program, "u_nmat");
    m->color = gl.GetUniformLocation(m->program, "u_color");
    m->spec = gl.GetUniformLocation(m->program, "u_spec");
    m->shininess = gl.GetUniformLocation(m->program, "u_shininess");
    m->ortho = gl.GetUniformLocation(m->program, "u_ortho");
    return m;
  }();
  return *p;
}

// Unit meshes, made once per process per (shape, segments, torus ratio).
// The minor/major ratio of a torus in thousandths (0 for other shapes): a cache key.
int torus_ratio_key(Scene3D::Shape shape, double torus_minor) {
  return shape == Scene3D::Shape::kTorus ? static_cast<int>(std::lround(torus_minor * 1000)) : 0;
}

// The unit mesh of a built-in shape with `segments` around (empty for tubes and custom meshes).
Mesh unit_shape_mesh(Scene3D::Shape shape, int segments, int ratio) {
  switch (shape) {
    case Scene3D::Shape::kSphere: return make_sphere(segments);
    case Scene3D::Shape::kCone: return make_cone(segments);
    case Scene3D::Shape::kCylinder: return make_cylinder(segments);
    case Scene3D::Shape::kDisk: return make_disk(segments);
    case Scene3D::Shape::kBox: return make_box();
    case Scene3D::Shape::kTorus:
      return make_torus(ratio / 1000.0, segments,
                        std::max(8, static_cast<int>(segments * ratio / 1000.0) + 8));
    case Scene3D::Shape::kPlane: return make_plane();
    case Scene3D::Shape::kTube:
    case Scene3D::Shape::kCustom: break;
  }
  return {};
}

const GpuMesh& unit_mesh(Scene3D::Shape shape, int segments, double torus_minor) {
  using Key = std::tuple<int, int, int>;
  static std::map<Key, GpuMesh> cache;
  const int ratio = torus_ratio_key(shape, torus_minor);
  const Key key{static_cast<int>(shape), segments, ratio};
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  return cache.emplace(key, upload(unit_shape_mesh(shape, segments, ratio))).first->second;
}

// View and projection for a camera at an aspect ratio, with depth range fitted to the scene.
struct View {
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  Eigen::Matrix4d proj = Eigen::Matrix4d::Identity();
  double focal_px = 1;  // pixels per unit length at unit depth (perspective) or per unit (ortho)
  bool ortho = false;
  int width = 1, height = 1;

  // Screen position in logical pixels (y down) and NDC depth; w <= 0 means behind the camera.
  Eigen::Vector4d project(const Vector3d& p) const {
    const Eigen::Vector4d c = proj * view * p.homogeneous();
    if (c.w() <= 1e-12) return {0, 0, 0, -1};
    const Eigen::Vector3d n = c.head<3>() / c.w();
    return {(n.x() + 1) * 0.5 * width, (1 - n.y()) * 0.5 * height, n.z(), 1};
  }
  double depth(const Vector3d& p) const { return -(view * p.homogeneous()).z(); }
  // Pixels covered by a length r at point p.
  double pixels(double r, const Vector3d& p) const {
    return ortho ? r * focal_px : r * focal_px / std::max(1e-6, depth(p));
  }
};

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
  const double tan_half = std::tan(0.5 * cam.fov_y_deg * kPi / 180.0);
  v.proj.setZero();
  if (cam.orthographic) {
    const double h = cam.ortho_height > 0 ? cam.ortho_height : 2 * (cam.target - cam.eye).norm() * tan_half;
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

// The path of a tube thinned to what the screen shows: a point is dropped while
// every point between its neighbours kept stays within kTubePathError pixels of
// the straight segment that replaces them (measured in 3D, in pixels at the
// point's depth, so a chord cannot sink into a surface the tube lies on even
// where the path turns towards the camera), and no segment grows past
// kTubeSegmentMax pixels (so shading along the tube stays smooth). Each dropped
// point saves a ring of triangles, which llvmpipe sets up and rasterises one
// by one; a polhode of 240 samples keeps about a third of them.
std::vector<Vector3d> thin_path(const std::vector<Vector3d>& path, const View& view) {
  constexpr double kTubePathError = 0.2, kTubeSegmentMax = 40.0;
  if (path.size() < 3) return path;
  for (const Vector3d& p : path)
    if (view.project(p).w() < 0) return path;  // behind the camera: keep every point
  auto off_chord = [&](const Vector3d& a, const Vector3d& b, const Vector3d& q) {
    const Vector3d d = b - a;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((q - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return view.pixels((a + t * d - q).norm(), q);
  };
  std::vector<Vector3d> out{path.front()};
  std::size_t anchor = 0;
  for (std::size_t j = 2; j < path.size(); ++j) {
    const Vector3d& a = path[anchor];
    bool ok = view.pixels((path[j] - a).norm(), a) <= kTubeSegmentMax;
    for (std::size_t k = anchor + 1; ok && k < j; ++k)
      ok = off_chord(a, path[j], path[k]) <= kTubePathError;
    if (!ok) {
      anchor = j - 1;
      out.push_back(path[anchor]);
    }
  }
  out.push_back(path.back());
  return out;
}

// Bounding sphere of an object in world space (centre, radius).
std::pair<Vector3d, double> bounds(const Scene3D::Object& o) {
  using S = Scene3D::Shape;
  const Matrix3d l = o.transform.linear();
  const double sx = l.col(0).norm(), sy = l.col(1).norm(), sz = l.col(2).norm();
  const Vector3d t = o.transform.translation();
  switch (o.shape) {
    case S::kSphere: return {t, std::max({sx, sy, sz})};
    case S::kBox: return {t, std::sqrt(sx * sx + sy * sy + sz * sz)};
    case S::kCone:
    case S::kCylinder: {
      const Vector3d c = t + 0.5 * l.col(2);
      return {c, std::hypot(std::max(sx, sy), 0.5 * sz)};
    }
    case S::kDisk:
    case S::kPlane: return {t, std::max(sx, sy) * (o.shape == S::kPlane ? std::sqrt(2.0) : 1.0)};
    case S::kTorus: return {t, std::max(sx, sy) * (1 + o.torus_minor)};
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

// ---- Overlay layout and camera fit ---------------------------------------------

// Reference-pixel scales at an image size: geometry (line widths, offsets) and text.
double geometry_scale(int width, int height) { return std::min(width / 1600.0, height / 1200.0); }
double font_scale(int width, int height) { return std::pow(geometry_scale(width, height), 0.7); }

struct LegendEntry {
  std::string label;
  Color color;
  bool line;
};

// Title and legend laid out once, so that the fit reserves exactly the boxes that are drawn.
struct Overlay {
  Scene3D::Layout layout;
  double pad = 0;
  double title_size = 0;                        // after shrinking a long title to the width
  double legend_size = 0, swatch = 0, row = 0;  // legend font size, swatch width, row height
  double margin_x = 0, margin_y = 0;            // kept free on each side of the scene
  std::vector<LegendEntry> entries;
};

Overlay overlay_layout(const std::string& title, bool show_legend, const std::vector<Scene3D::Object>& objects,
                       const std::vector<Scene3D::Polyline>& polylines, int width, int height) {
  constexpr double kMargin = 0.03;  // of the image's width and height, on each side of the scene
  Overlay o;
  const double font = font_scale(width, height);
  o.pad = 16 * font;
  o.margin_x = kMargin * width;
  o.margin_y = kMargin * height;
  double title_bottom = 0;
  if (!title.empty()) {
    o.title_size = 40 * font;
    const double w = measure_text(title, o.title_size).width;
    if (w > width - 2 * o.pad) o.title_size *= (width - 2 * o.pad) / w;
    const TextExtent e = measure_text(title, o.title_size);
    o.layout.title = {0.5 * (width - e.width), o.pad, 0.5 * (width + e.width), o.pad + e.height()};
    title_bottom = o.layout.title.y1;
  }
  o.layout.region = {o.margin_x, title_bottom + o.margin_y, width - o.margin_x, height - o.margin_y};
  for (const Scene3D::Object& obj : objects)
    if (!obj.label.empty()) {
      // Translucent swatches show the colour as it looks over white.
      const float a = obj.material.opacity;
      const Color c = obj.material.color;
      o.entries.push_back({obj.label, {c.r * a + (1 - a), c.g * a + (1 - a), c.b * a + (1 - a), 1}, false});
    }
  for (const Scene3D::Polyline& pl : polylines)
    if (!pl.label.empty()) o.entries.push_back({pl.label, pl.color, true});
  if (!show_legend || o.entries.empty()) {
    o.entries.clear();
    return o;
  }
  o.legend_size = 28 * font;
  o.swatch = 40 * font;
  double tw = 0;
  for (const LegendEntry& e : o.entries) {
    const TextExtent m = measure_text(e.label, o.legend_size);
    tw = std::max(tw, m.width);
    o.row = std::max(o.row, m.height());
  }
  o.row += 0.4 * o.pad;
  const double pad = o.pad;
  const double x1 = width - pad, x0 = x1 - (pad + o.swatch + 0.6 * pad + tw + pad);
  const double y0 = title.empty() ? pad : title_bottom + pad;
  o.layout.legend = {x0, y0, x1, y0 + 2 * 0.8 * pad + o.row * o.entries.size()};
  return o;
}

// What the fit keeps in view: a sphere of a world radius about p (0 for a point), and a
// screen box reaching left, right, up and down that many pixels beyond its projection
// (a label's text, half a line's width).
struct FitPoint {
  Vector3d p;
  double radius = 0;
  double left = 0, right = 0, up = 0, down = 0;
};

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

// Everything the image must show: surfaces, thick lines, and labels with their text boxes.
std::vector<FitPoint> fit_points(const std::vector<Scene3D::Object>& objects,
                                 const std::vector<Scene3D::Polyline>& polylines,
                                 const std::vector<Label3D>& labels, double geo, double font) {
  using S = Scene3D::Shape;
  std::vector<FitPoint> out;
  for (const Scene3D::Object& o : objects) {
    if (o.shape == S::kTube) {
      for (const Vector3d& p : o.path) out.push_back({p, o.tube_radius});
    } else if (o.shape == S::kCustom) {
      for (const auto& p : o.mesh.positions) out.push_back({o.transform * p.cast<double>()});
    } else {
      for (const Vector3d& p : unit_outline(o.shape, o.torus_minor)) out.push_back({o.transform * p});
    }
  }
  for (const Scene3D::Polyline& pl : polylines) {
    const double hw = 0.5 * std::max(2.0, pl.width * geo);
    for (const Vector3d& p : pl.points) out.push_back({p, 0, hw, hw, hw, hw});
  }
  // A label's box about its anchor, as Painter::text places it.
  for (const Label3D& l : labels) {
    if (l.text.empty()) continue;
    const TextExtent e = measure_text(l.text, l.size * font);
    const double ax = l.halign == HAlign::kLeft ? 0 : l.halign == HAlign::kCenter ? -0.5 * e.width : -e.width;
    const double ay = l.valign == VAlign::kTop        ? e.ascent
                      : l.valign == VAlign::kCenter   ? 0.5 * (e.ascent - e.descent)
                      : l.valign == VAlign::kBaseline ? 0
                                                      : -e.descent;
    const double left = l.offset_x * geo + ax, baseline = l.offset_y * geo + ay;
    out.push_back({l.position, 0, -left, left + e.width, e.ascent - baseline, baseline + e.descent});
  }
  return out;
}

// A bound on the eye's sideways shift, linear in its distance d from the target plane: c + m d.
struct Bound {
  double c = 0, m = 0;
  double at(double d) const { return c + m * d; }
};

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
Camera fitted(Camera cam, std::vector<FitPoint> points, const Overlay& overlay, int width, int height) {
  if (!cam.fit || points.empty()) return cam;
  Vector3d f = cam.target - cam.eye;
  const double eye_distance = f.norm();
  if (!(eye_distance > 0)) return cam;
  f.normalize();
  Vector3d up = cam.up;
  if (std::abs(f.dot(up.normalized())) > 0.999) up = f.unitOrthogonal();
  const Vector3d s = f.cross(up).normalized(), u = s.cross(f);
  const bool ortho = cam.orthographic;
  const double tan_half = std::tan(0.5 * cam.fov_y_deg * kPi / 180.0);
  const double focal = 0.5 * height / tan_half;
  const double cx = 0.5 * width, cy = 0.5 * height;
  const ScreenRect& region = overlay.layout.region;
  const ScreenRect& legend = overlay.layout.legend;
  const bool has_legend = !legend.empty();
  if (region.empty()) return cam;

  // Point left of (below) an edge at slope k: a >= ...; right of (above) it: a <= ... .
  auto left_of = [&](double x, double z, double r, double k) {
    return Bound{x + r * (ortho ? 1 : std::hypot(1.0, k)) - k * z, -k};
  };
  auto right_of = [&](double x, double z, double r, double k) {
    return Bound{x - r * (ortho ? 1 : std::hypot(1.0, k)) - k * z, -k};
  };
  const std::size_t n = points.size();
  std::vector<Bound> a_min(n), a_max(n), b_min(n), b_max(n), a_legend, b_legend;
  if (has_legend) {
    a_legend.resize(n);
    b_legend.resize(n);
  }
  double d_min = 0, extent = 0;
  for (std::size_t i = 0; i < n; ++i) {
    FitPoint& p = points[i];
    // A text box wider than the region cannot fit whole: fit what can be.
    const double wx = p.left + p.right, wy = p.up + p.down;
    const double max_w = 0.9 * (region.x1 - region.x0), max_h = 0.9 * (region.y1 - region.y0);
    if (wx > max_w) p.left *= max_w / wx, p.right *= max_w / wx;
    if (wy > max_h) p.up *= max_h / wy, p.down *= max_h / wy;
    const Vector3d q = p.p - cam.target;
    const double x = q.dot(s), y = q.dot(u), z = ortho ? 0.0 : q.dot(f), r = p.radius;
    a_min[i] = left_of(x, z, r, (region.x1 - cx - p.right) / focal);
    a_max[i] = right_of(x, z, r, (region.x0 - cx + p.left) / focal);
    b_min[i] = left_of(y, z, r, (cy - region.y0 - p.up) / focal);
    b_max[i] = right_of(y, z, r, (cy - region.y1 + p.down) / focal);
    if (has_legend) {
      a_legend[i] = left_of(x, z, r, (legend.x0 - overlay.margin_x - cx - p.right) / focal);
      b_legend[i] = left_of(y, z, r, (cy - legend.y1 - overlay.margin_y - p.up) / focal);
    }
    if (!ortho) d_min = std::max(d_min, r - z);
    extent = std::max(extent, q.norm() + r);
  }
  struct Window {
    double a_lo, a_hi, b_lo, b_hi;
  };
  auto window = [&](double d) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    Window w{-kInf, kInf, -kInf, kInf};
    for (std::size_t i = 0; i < n; ++i) {
      w.a_lo = std::max(w.a_lo, a_min[i].at(d));
      w.a_hi = std::min(w.a_hi, a_max[i].at(d));
      w.b_lo = std::max(w.b_lo, b_min[i].at(d));
      w.b_hi = std::min(w.b_hi, b_max[i].at(d));
    }
    return w;
  };
  auto clear_of_legend = [&](double d, double a, double b) {
    for (std::size_t i = 0; i < a_legend.size(); ++i)
      if (a < a_legend[i].at(d) && b < b_legend[i].at(d)) return false;
    return true;
  };
  auto fits = [&](double d) {
    const Window w = window(d);
    return w.a_lo <= w.a_hi && w.b_lo <= w.b_hi && clear_of_legend(d, w.a_hi, w.b_hi);
  };
  // Bracket the least distance that fits, then bisect (fits(hi) holds throughout).
  double lo = d_min, hi = d_min + std::max(extent, 1e-12);
  for (int k = 0; k < 200 && !fits(hi); ++k) hi = lo + 2 * (hi - lo);
  if (!fits(hi)) return cam;
  for (int k = 0; k < 100 && hi - lo > 1e-12 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (fits(mid) ? hi : lo) = mid;
  }
  const double d = hi;

  // The shift nearest the window's centre that clears the legend: the centre itself, or
  // the centre moved right-of-legend only, below-legend only, or towards (a_hi, b_hi).
  const Window w = window(d);
  const double a_c = 0.5 * (w.a_lo + w.a_hi), b_c = 0.5 * (w.b_lo + w.b_hi);
  double a = a_c, b = b_c;
  if (!clear_of_legend(d, a_c, b_c)) {
    double a_only = a_c, b_only = b_c, t = 0;
    for (std::size_t i = 0; i < a_legend.size(); ++i) {
      const double alpha = a_legend[i].at(d), beta = b_legend[i].at(d);
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
  }
  cam.target += a * s + b * u;
  if (ortho) {
    cam.eye = cam.target - eye_distance * f;
    cam.ortho_height = 2 * d * tan_half;
  } else {
    cam.eye = cam.target - d * f;
  }
  return cam;
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

}  // namespace

// ---- Scene building -----------------------------------------------------------

namespace {

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

void Scene3D::add_ellipsoid(const Vector3d& center, const Vector3d& semi_axes, const Matrix3d& rotation,
                            Material m, std::string label) {
  check_finite(center, "ellipsoid centre");
  if (!(semi_axes.minCoeff() > 0)) throw std::invalid_argument("Scene3D: ellipsoid semi-axes must be > 0");
  objects_.push_back(make_object(Shape::kSphere, place(center, rotation, semi_axes), resolve(m), std::move(label)));
}

void Scene3D::add_cone(const Vector3d& apex, const Vector3d& base_center, double radius, Material m,
                       std::string label) {
  const Vector3d axis = apex - base_center;
  if (!(axis.norm() > 0) || !(radius > 0)) throw std::invalid_argument("Scene3D: cone needs height and radius > 0");
  objects_.push_back(make_object(Shape::kCone, place(base_center, frame_z(axis), {radius, radius, axis.norm()}),
                      resolve(m), std::move(label)));
}

void Scene3D::add_cylinder(const Vector3d& p0, const Vector3d& p1, double radius, Material m,
                           std::string label) {
  const Vector3d axis = p1 - p0;
  if (!(axis.norm() > 0) || !(radius > 0))
    throw std::invalid_argument("Scene3D: cylinder needs length and radius > 0");
  objects_.push_back(make_object(Shape::kCylinder, place(p0, frame_z(axis), {radius, radius, axis.norm()}),
                      resolve(m), std::move(label)));
}

void Scene3D::add_arrow(const Vector3d& from, const Vector3d& to, double radius, Material m,
                        std::string label) {
  const Vector3d d = to - from;
  const double len = d.norm();
  if (!(len > 0) || !(radius > 0)) throw std::invalid_argument("Scene3D: arrow needs length and radius > 0");
  m = resolve(m);
  const double head = std::min(0.35 * len, 7.0 * radius);
  const double head_r = std::min(2.6 * radius, 0.5 * head);
  const Vector3d base = to - d / len * head;
  add_cylinder(from, base, radius, m, std::move(label));
  add_cone(to, base, std::max(head_r, radius * 1.5), m);
}

void Scene3D::add_box(const Vector3d& center, const Vector3d& half_extents, const Matrix3d& rotation,
                      Material m, std::string label) {
  if (!(half_extents.minCoeff() > 0)) throw std::invalid_argument("Scene3D: box half-extents must be > 0");
  objects_.push_back(make_object(Shape::kBox, place(center, rotation, half_extents), resolve(m), std::move(label)));
}

void Scene3D::add_disk(const Vector3d& center, const Vector3d& normal, double radius, Material m,
                       std::string label) {
  if (!(normal.norm() > 0) || !(radius > 0)) throw std::invalid_argument("Scene3D: disk needs normal and radius > 0");
  objects_.push_back(make_object(Shape::kDisk, place(center, frame_z(normal), {radius, radius, radius}), resolve(m),
                      std::move(label)));
}

void Scene3D::add_torus(const Vector3d& center, const Vector3d& normal, double major_radius,
                        double minor_radius, Material m, std::string label) {
  if (!(normal.norm() > 0) || !(major_radius > 0) || !(minor_radius > 0) || minor_radius >= major_radius)
    throw std::invalid_argument("Scene3D: torus needs 0 < minor radius < major radius");
  Object o = make_object(Shape::kTorus, place(center, frame_z(normal), Vector3d::Constant(major_radius)), resolve(m),
           std::move(label));
  o.torus_minor = minor_radius / major_radius;
  objects_.push_back(std::move(o));
}

void Scene3D::add_plane(const Vector3d& center, const Vector3d& normal, double half_size, Material m,
                        std::string label) {
  if (!(normal.norm() > 0) || !(half_size > 0)) throw std::invalid_argument("Scene3D: plane needs normal and size > 0");
  objects_.push_back(make_object(Shape::kPlane, place(center, frame_z(normal), Vector3d::Constant(half_size)),
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

void Scene3D::add_polyline(std::vector<Vector3d> points, Color color, double width, std::string label) {
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
    Label3D l;
    l.position = origin + (length + 6 * r) * d;
    l.text = labels[k];
    l.size = 38;
    labels_.push_back(l);
  }
}

void Scene3D::add_label(Label3D label) { labels_.push_back(std::move(label)); }

void Scene3D::add_label(const Vector3d& position, std::string text, Color color) {
  Label3D l;
  l.position = position;
  l.text = std::move(text);
  l.color = color;
  labels_.push_back(std::move(l));
}

Scene3D::Layout Scene3D::layout(int width, int height) const {
  return overlay_layout(title, show_legend, objects_, polylines_, width, height).layout;
}

void Scene3D::save(const std::string& path, int width, int height) const {
  write_png(render(width, height), path);
}

// ---- Rendering -------------------------------------------------------------------

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

Image Scene3D::render(int width, int height) const {
  // GL works in float: bring a scene of any size (1e-50 m or 1e30 m) to about
  // unit size, in double, before anything reaches the GPU. Perspective and the
  // picture are unchanged by a uniform scale.
  double extent = 0.0;
  for (const Object& o : objects_) {
    const auto [c, r] = bounds(o);
    extent = std::max(extent, c.norm() + r);
  }
  for (const Polyline& pl : polylines_)
    for (const Vector3d& p : pl.points) extent = std::max(extent, p.norm());
  if (extent > 0.0 && std::isfinite(extent) && (extent < 1e-3 || extent > 1e3)) {
    return scaled(1.0 / extent).render(width, height);
  }
  detail::Target& tgt = detail::target();
  tgt.begin(width, height, true, kWhite);
  auto& gl = detail::gl;

  // Frame the scene in the space the title and legend leave, then fit the depth range to it.
  const double geo = geometry_scale(width, height);
  const double font = font_scale(width, height);
  const Overlay overlay = overlay_layout(title, show_legend, objects_, polylines_, width, height);
  const std::vector<FitPoint> points = fit_points(objects_, polylines_, labels_, geo, font);
  const Camera cam = fitted(camera, points, overlay, width, height);
  const auto [znear, zfar] = depth_range(cam, points);
  const View view = make_view(cam, width, height, znear, zfar);

  MeshProgram& prog = mesh_program();
  gl.UseProgram(prog.program);
  gl.Uniform1i(prog.ortho, view.ortho ? 1 : 0);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);

  // Tubes and custom meshes are uploaded for this render only.
  std::vector<GpuMesh> temporary;
  auto draw = [&](const Object& o) {
    const Affine3d& t = o.transform;
    const auto [c, r] = bounds(o);
    const GpuMesh* g = nullptr;
    if (o.shape == Shape::kTube || o.shape == Shape::kCustom) {
      if (o.shape == Shape::kTube)
        temporary.push_back(upload(make_tube(thin_path(o.path, view), o.tube_radius,
                                             std::min(48, segments_for_radius(view.pixels(o.tube_radius, c))))));
      else
        temporary.push_back(upload(o.mesh));
      g = &temporary.back();
    } else {
      // Segments from the on-screen radius of the object's round cross-section.
      const Matrix3d l = t.linear();
      const double round_r = o.shape == Shape::kSphere ? std::max({l.col(0).norm(), l.col(1).norm(), l.col(2).norm()})
                                                       : std::max(l.col(0).norm(), l.col(1).norm());
      g = &unit_mesh(o.shape, segments_for_radius(view.pixels(round_r, c)), o.torus_minor);
    }
    const Eigen::Matrix4d mv = view.view * t.matrix();
    // A mirroring transform turns counter-clockwise (outward) faces clockwise.
    gl.FrontFace(t.linear().determinant() < 0 ? GL_CW : GL_CCW);
    const Eigen::Matrix4f mvp = (view.proj * mv).cast<float>();
    const Eigen::Matrix4f mvf = mv.cast<float>();
    const Eigen::Matrix3f nmat = mv.block<3, 3>(0, 0).inverse().transpose().cast<float>();
    gl.UniformMatrix4fv(prog.mvp, 1, GL_FALSE, mvp.data());
    gl.UniformMatrix4fv(prog.mv, 1, GL_FALSE, mvf.data());
    gl.UniformMatrix3fv(prog.nmat, 1, GL_FALSE, nmat.data());
    const Material& m = o.material;
    gl.Uniform4f(prog.color, m.color.r, m.color.g, m.color.b, m.opacity);
    gl.Uniform1f(prog.spec, m.specular);
    gl.Uniform1f(prog.shininess, m.shininess);
    gl.BindVertexArray(g->vao);
    gl.DrawElements(GL_TRIANGLES, g->count, GL_UNSIGNED_INT, nullptr);
  };

  // 1. Opaque surfaces, depth written. The back faces of a closed surface are
  //    always hidden behind its front faces, so they are culled: half the
  //    triangles never reach the rasteriser. Open ones (disk, plane) and
  //    custom meshes show both sides.
  auto is_open = [](const Object* o) { return o->shape == Shape::kDisk || o->shape == Shape::kPlane; };
  gl.Disable(GL_BLEND);
  gl.CullFace(GL_BACK);
  gl.DepthMask(GL_TRUE);
  std::vector<const Object*> translucent;
  for (const Object& o : objects_) {
    if (o.material.opacity < 1.0f) {
      translucent.push_back(&o);
      continue;
    }
    if (is_open(&o) || o.shape == Shape::kCustom) gl.Disable(GL_CULL_FACE);
    else gl.Enable(GL_CULL_FACE);
    draw(o);
  }
  gl.Disable(GL_CULL_FACE);
  gl.FrontFace(GL_CCW);

  // 2. Screen-space polylines, hidden by nearer opaque surfaces (nudged forward to avoid z-fighting).
  detail::Painter& p = detail::painter();
  p.begin(width, height);
  p.depth_test(true);
  for (const Polyline& pl : polylines_) {
    std::vector<detail::P3> pts;
    auto emit = [&] {
      if (pts.size() >= 2) p.polyline(pts, std::max(2.0, pl.width * geo), pl.color);
      pts.clear();
    };
    for (const Vector3d& q : pl.points) {
      const Eigen::Vector4d s = view.project(q);
      if (s.w() < 0) {
        emit();
        continue;
      }
      pts.push_back({s.x(), s.y(), s.z() - 2e-4});
    }
    emit();
  }
  p.flush();

  // 3. Translucent surfaces without depth writes: all back faces far to near,
  //    then all front faces far to near. For nested convex shells this gives
  //    outer-back, inner-back, inner-front, outer-front: the exact order.
  gl.UseProgram(prog.program);
  gl.Enable(GL_BLEND);
  gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl.DepthMask(GL_FALSE);
  gl.Enable(GL_CULL_FACE);
  auto far_key = [&](const Object* o) { const auto [c, r] = bounds(*o); return view.depth(c) + r; };
  auto near_key = [&](const Object* o) { const auto [c, r] = bounds(*o); return view.depth(c) - r; };
  std::vector<const Object*> order = translucent;
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return far_key(a) > far_key(b); });
  gl.CullFace(GL_FRONT);
  for (const Object* o : order)
    if (!is_open(o)) draw(*o);
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return near_key(a) > near_key(b); });
  for (const Object* o : order) {
    // Open surfaces have no back to draw first: both sides go in this pass.
    if (is_open(o)) gl.Disable(GL_CULL_FACE);
    else gl.CullFace(GL_BACK);
    draw(*o);
    gl.Enable(GL_CULL_FACE);
  }
  gl.Disable(GL_CULL_FACE);
  gl.FrontFace(GL_CCW);
  gl.DepthMask(GL_TRUE);
  gl.Disable(GL_DEPTH_TEST);
  gl.BindVertexArray(0);
  for (GpuMesh& g : temporary) release(g);

  // 4. Text overlay: labels at projected points, title, legend.
  p.begin(width, height);
  for (const Label3D& l : labels_) {
    const Eigen::Vector4d s = view.project(l.position);
    if (s.w() < 0) continue;
    p.text(l.text, s.x() + l.offset_x * geo, s.y() + l.offset_y * geo, l.size * font, l.color, l.halign,
           l.valign);
  }
  if (!title.empty())
    p.text(title, 0.5 * width, overlay.pad, overlay.title_size, kTextColor, HAlign::kCenter, VAlign::kTop);
  if (!overlay.layout.legend.empty()) {
    const ScreenRect& box = overlay.layout.legend;
    const double pad = overlay.pad, sw = overlay.swatch, rh = overlay.row;
    p.rect(box.x0, box.y0, box.x1, box.y1, kWhite.with_alpha(0.88f));
    p.rect_outline(box.x0, box.y0, box.x1, box.y1, std::max(1.0, 1.2 * geo), rgb8(190, 190, 190));
    double y = box.y0 + 0.8 * pad + 0.5 * rh;
    for (const LegendEntry& e : overlay.entries) {
      const double x = box.x0 + pad;
      if (e.line) p.polyline({{x, y, 0}, {x + sw, y, 0}}, std::max(2.0, 4 * geo), e.color);
      else p.rect(x, y - 0.3 * rh, x + sw, y + 0.3 * rh, e.color);
      p.text(e.label, x + sw + 0.6 * pad, y, overlay.legend_size, kTextColor, HAlign::kLeft, VAlign::kCenter);
      y += rh;
    }
  }
  p.flush();
  return tgt.finish();
}

}  // namespace rigid::render
