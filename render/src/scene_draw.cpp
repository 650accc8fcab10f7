// Drawing a 3D scene: opaque surfaces, screen-space polylines, translucent
// surfaces in back-to-front order, then the overlay (labels, title, legend).
// Where things go was decided by frame_scene (scene_layout.h).
#include <algorithm>
#include <cmath>
#include <vector>

#include "painter.h"
#include "rigid/render/draw.h"
#include "rigid/render/scene3d.h"
#include "scene_gpu.h"
#include "scene_layout.h"
#include "scene_shapes.h"
#include "target.h"

namespace rigid::render {

namespace detail {

namespace {

using Eigen::Affine3d;
using Eigen::Matrix3d;
using Eigen::Vector3d;

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

// The mesh program's pass over a render's objects: tubes and custom meshes are
// uploaded for this render only, and released when it is done.
struct MeshPass {
  const View& view;
  MeshProgram& prog;
  std::vector<GpuMesh> temporary;
};

// The mesh of an object, tessellated for its on-screen size.
const GpuMesh& object_mesh(MeshPass& pass, const Scene3D::Object& o) {
  const View& view = pass.view;
  const Affine3d& t = o.transform;
  const auto [c, r] = bounds(o);
  if (o.shape == Scene3D::Shape::kTube || o.shape == Scene3D::Shape::kCustom) {
    if (o.shape == Scene3D::Shape::kTube)
      pass.temporary.push_back(
          upload(make_tube(thin_path(o.path, view), o.tube_radius,
                           std::min(48, segments_for_radius(view.pixels(o.tube_radius, c))))));
    else
      pass.temporary.push_back(upload(o.mesh));
    return pass.temporary.back();
  }
  // Segments from the on-screen radius of the object's round cross-section.
  const Matrix3d l = t.linear();
  const double round_r = o.shape == Scene3D::Shape::kSphere
                             ? std::max({l.col(0).norm(), l.col(1).norm(), l.col(2).norm()})
                             : std::max(l.col(0).norm(), l.col(1).norm());
  return unit_mesh(o.shape, segments_for_radius(view.pixels(round_r, c)), o.torus_minor);
}

// One object: its mesh, placed by its transform, shaded by its material.
void draw_object(MeshPass& pass, const Scene3D::Object& o) {
  auto& gl = detail::gl;
  const MeshProgram& prog = pass.prog;
  const Affine3d& t = o.transform;
  const GpuMesh* g = &object_mesh(pass, o);
  const Eigen::Matrix4d mv = pass.view.view * t.matrix();
  // A mirroring transform turns counter-clockwise (outward) faces clockwise.
  gl.FrontFace(t.linear().determinant() < 0 ? GL_CW : GL_CCW);
  const Eigen::Matrix4f mvp = (pass.view.proj * mv).cast<float>();
  const Eigen::Matrix4f mvf = mv.cast<float>();
  const Eigen::Matrix3f nmat = mv.block<3, 3>(0, 0).inverse().transpose().cast<float>();
  gl.UniformMatrix4fv(prog.mvp, 1, GL_FALSE, mvp.data());
  gl.UniformMatrix4fv(prog.mv, 1, GL_FALSE, mvf.data());
  gl.UniformMatrix3fv(prog.nmat, 1, GL_FALSE, nmat.data());
  const Material& m = o.material;
  gl.Uniform4f(prog.color, m.color.r, m.color.g, m.color.b, m.opacity);
  gl.Uniform1f(prog.spec, m.specular);
  gl.Uniform1i(prog.lit, m.lit ? 1 : 0);
  gl.Uniform1f(prog.shininess, m.shininess);
  gl.BindVertexArray(g->vao);
  gl.DrawElements(GL_TRIANGLES, g->count, GL_UNSIGNED_INT, nullptr);
}

// 1. Opaque surfaces, depth written. The back faces of a closed surface are
//    always hidden behind its front faces, so they are culled: half the
//    triangles never reach the rasteriser. Open ones (disk, plane) and
//    custom meshes show both sides. Returns the translucent objects, in the
//    scene's order, for the last pass.
std::vector<const Scene3D::Object*> draw_opaque(const Scene3D& scene, MeshPass& pass) {
  auto& gl = detail::gl;
  gl.Disable(GL_BLEND);
  gl.CullFace(GL_BACK);
  gl.DepthMask(GL_TRUE);
  std::vector<const Scene3D::Object*> translucent;
  for (const Scene3D::Object& o : scene.objects()) {
    if (o.material.opacity < 1.0f) {
      translucent.push_back(&o);
      continue;
    }
    if (is_open(o.shape) || o.shape == Scene3D::Shape::kCustom)
      gl.Disable(GL_CULL_FACE);
    else
      gl.Enable(GL_CULL_FACE);
    draw_object(pass, o);
  }
  gl.Disable(GL_CULL_FACE);
  gl.FrontFace(GL_CCW);
  return translucent;
}

// 2. Screen-space polylines, hidden by nearer opaque surfaces (nudged forward to avoid
// z-fighting).
void draw_polylines(const Scene3D& scene, const SceneFrame& fr) {
  const View& view = fr.view;
  Painter& p = painter();
  p.begin(view.width, view.height);
  p.depth_test(true);
  for (const Scene3D::Polyline& pl : scene.polylines()) {
    std::vector<P3> pts;
    auto emit = [&] {
      if (pts.size() >= 2) p.polyline(pts, std::max(2.0, pl.width * fr.st.s), pl.color);
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
}

// 3. Translucent surfaces without depth writes: all back faces far to near,
//    then all front faces far to near. For nested convex shells this gives
//    outer-back, inner-back, inner-front, outer-front: the exact order. Depth-tested
//    against what is drawn (the painter's flush leaves the test off): a surface
//    behind a body or a line does not cover it.
void draw_translucent(std::vector<const Scene3D::Object*> order, MeshPass& pass) {
  auto& gl = detail::gl;
  const View& view = pass.view;
  gl.UseProgram(pass.prog.program);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.Enable(GL_BLEND);
  gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl.DepthMask(GL_FALSE);
  gl.Enable(GL_CULL_FACE);
  auto far_key = [&](const Scene3D::Object* o) {
    const auto [c, r] = bounds(*o);
    return view.depth(c) + r;
  };
  auto near_key = [&](const Scene3D::Object* o) {
    const auto [c, r] = bounds(*o);
    return view.depth(c) - r;
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](auto a, auto b) { return far_key(a) > far_key(b); });
  gl.CullFace(GL_FRONT);
  for (const Scene3D::Object* o : order)
    if (!is_open(o->shape)) draw_object(pass, *o);
  std::stable_sort(order.begin(), order.end(),
                   [&](auto a, auto b) { return near_key(a) > near_key(b); });
  for (const Scene3D::Object* o : order) {
    // Open surfaces have no back to draw first: both sides go in this pass.
    if (is_open(o->shape))
      gl.Disable(GL_CULL_FACE);
    else
      gl.CullFace(GL_BACK);
    draw_object(pass, *o);
    gl.Enable(GL_CULL_FACE);
  }
  gl.Disable(GL_CULL_FACE);
  gl.FrontFace(GL_CCW);
}

// Draws the surfaces and lines of a framed scene into the bound target. Tessellation
// follows each object's on-screen size.
void draw_geometry(const Scene3D& scene, const SceneFrame& fr) {
  auto& gl = detail::gl;
  MeshPass pass{fr.view, mesh_program(), {}};
  gl.UseProgram(pass.prog.program);
  gl.Uniform1i(pass.prog.ortho, fr.view.ortho ? 1 : 0);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  const std::vector<const Scene3D::Object*> translucent = draw_opaque(scene, pass);
  draw_polylines(scene, fr);
  draw_translucent(translucent, pass);
  gl.DepthMask(GL_TRUE);
  gl.Disable(GL_DEPTH_TEST);
  gl.BindVertexArray(0);
  for (GpuMesh& g : pass.temporary) release(g);
}

// The text overlay, in GL over the image drawn so far.
void draw_overlay(const Scene3D& scene, const SceneFrame& fr) {
  Painter& p = painter();
  p.begin(fr.view.width, fr.view.height);
  draw_scene_overlay(p, scene.labels(), fr);
  p.flush();
}

}  // namespace

void draw_scene_overlay(Canvas& p, const std::vector<Label3D>& labels, const SceneFrame& fr) {
  for (std::size_t k = 0; k < labels.size() && k < fr.labels.size(); ++k) {
    const ScreenRect& b = fr.labels[k];
    if (b.empty()) continue;
    p.text(labels[k].text, b.x0, b.y0, fr.st.label_font, labels[k].color, HAlign::kLeft,
           VAlign::kTop);
  }
  draw_title(p, fr.title);
  draw_legend(p, fr.entries, fr.legend, fr.st);
}

SceneParts draw_scene_parts(const Scene3D& scene, int width, int height, FigureTiming* timing) {
  const double k = normalising_scale(scene);
  if (k != 1.0) return draw_scene_parts(scene.scaled(k), width, height, timing);
  PhaseClock clock(timing);
  target().begin(width, height, true, kWhite);
  clock.lap(&FigureTiming::setup, true);
  SceneFrame frame = frame_scene(scene, width, height);
  clock.lap(&FigureTiming::layout);
  draw_geometry(scene, frame);
  clock.lap(&FigureTiming::draw, true);
  Image image = target().finish();
  clock.lap(&FigureTiming::resolve);
  return SceneParts{std::move(image), std::move(frame), scene.labels()};
}

}  // namespace detail

namespace {

Scene3D::Layout layout_of(const detail::SceneFrame& fr) {
  return {fr.title.box,  fr.legend, fr.region, static_cast<int>(fr.title.lines.size()),
          fr.title.size, fr.labels};
}

}  // namespace

Scene3D::Layout layout(const Scene3D& scene, int width, int height) {
  const double k = detail::normalising_scale(scene);
  if (k != 1.0) return layout(scene.scaled(k), width, height);
  return layout_of(detail::frame_scene(scene, width, height));
}

Camera fitted_camera(const Scene3D& scene, int width, int height) {
  const double k = detail::normalising_scale(scene);
  Camera c;
  if (k != 1.0) {
    c = fitted_camera(scene.scaled(k), width, height);
    c.eye /= k;
    c.target /= k;
    c.ortho_height /= k;
  } else {
    c = detail::frame_scene(scene, width, height, /*place_labels=*/false).camera;
  }
  c.fit = false;
  return c;
}

Scene3D::Layout detail::render_into_target(const Scene3D& scene, int width, int height,
                                           PhaseClock& clock) {
  const double k = detail::normalising_scale(scene);
  if (k != 1.0) return render_into_target(scene.scaled(k), width, height, clock);
  detail::target().begin(width, height, true, kWhite);
  clock.lap(&FigureTiming::setup, true);
  const detail::SceneFrame fr = detail::frame_scene(scene, width, height);
  clock.lap(&FigureTiming::layout);
  detail::draw_geometry(scene, fr);
  detail::draw_overlay(scene, fr);
  clock.lap(&FigureTiming::draw, true);
  return layout_of(fr);
}

Image draw(const Scene3D& scene, int width, int height, FigureTiming* timing) {
  detail::PhaseClock clock(timing);
  detail::render_into_target(scene, width, height, clock);
  Image img = detail::target().finish();
  clock.lap(&FigureTiming::resolve);
  return img;
}

void save_png(const Scene3D& scene, const std::string& path, int width, int height,
              FigureTiming* timing) {
  detail::save_timed(draw(scene, width, height, timing), path, timing);
}

}  // namespace rigid::render
