// Tests of 3D scenes by their pixels.
#include "rigid/render/scene3d.h"

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <memory>
#include <thread>

#include "rigid/render/draw.h"
#include "rigid/render/image.h"
#include "rigid/render/mesh.h"
#include "rigid/render/palette.h"

using namespace rigid::render;

namespace {

Camera front_camera() {
  Camera c;
  c.eye = {0, -10, 0};
  c.target = {0, 0, 0};
  c.up = {0, 0, 1};
  c.fit = false;
  return c;
}

}  // namespace

TEST_CASE("scene3d: an opaque sphere is shaded in its colour, background white",
          "[render][scene3d]") {
  Scene3D scene;
  scene.camera = front_camera();
  scene.add_sphere({0, 0, 0}, 1.0, {kBlue});
  const Image img = draw(scene, 400, 300);
  const std::uint8_t* c = img.at(200, 150);
  // Lit blue: blue dominates, not white, not black.
  CHECK(c[2] > c[0] + 60);
  CHECK(c[2] > 120);
  CHECK(c[0] < 100);
  const std::uint8_t* bg = img.at(5, 5);
  CHECK((bg[0] == 255 && bg[1] == 255 && bg[2] == 255));
}

TEST_CASE("scene3d: an opaque box hides what is behind it", "[render][scene3d]") {
  Scene3D scene;
  scene.camera = front_camera();
  scene.add_sphere({0, 3, 0}, 1.0, {kVermillion});  // farther from the eye
  scene.add_box({0, 0, 0}, {0.5, 0.5, 0.5}, Eigen::Matrix3d::Identity(), {kBlue});
  const Image img = draw(scene, 400, 300);
  const std::uint8_t* c = img.at(200, 150);
  CHECK(c[2] > c[0]);  // blue box in front, not the vermillion sphere
}

TEST_CASE("scene3d: nested translucent shells show both colours", "[render][scene3d]") {
  Scene3D scene;
  scene.camera = front_camera();
  scene.add_sphere({0, 0, 0}, 2.0, {kSkyBlue, 0.3f});
  scene.add_sphere({0, 0, 0}, 1.0, {kOrange, 1.0f});
  const Image img = draw(scene, 400, 300);
  const std::uint8_t* inner = img.at(200, 150);
  const std::uint8_t* shell = img.at(200 + 70, 150);  // outside the inner sphere, inside the outer
  // The opaque orange core shows through the blue shell: red stays above blue.
  CHECK(inner[0] > inner[2]);
  // The shell alone is a light blue tint, not white.
  CHECK(shell[2] > shell[0]);
  CHECK(shell[0] < 250);
}

TEST_CASE("mesh: unit shapes are closed and sized by on-screen radius", "[render][mesh]") {
  const Mesh s = make_sphere(32);
  CHECK(s.indices.size() % 3 == 0);
  // Closed: every edge is shared by exactly two triangles, in opposite directions
  // (a hole leaves an edge used once; a flipped triangle, one used twice the same way).
  std::map<std::pair<unsigned, unsigned>, int> edges;
  for (std::size_t i = 0; i + 2 < s.indices.size(); i += 3) {
    for (int k = 0; k < 3; ++k) {
      const unsigned from = s.indices[i + k], to = s.indices[i + (k + 1) % 3];
      ++edges[{from, to}];
    }
  }
  // Seam vertices may be duplicated at equal positions: compare edges by position.
  std::map<std::pair<std::array<float, 3>, std::array<float, 3>>, int> by_position;
  const auto key = [&](unsigned v) {
    const auto& p = s.positions[v];
    return std::array<float, 3>{std::round(p.x() * 1e5f), std::round(p.y() * 1e5f),
                                std::round(p.z() * 1e5f)};
  };
  for (const auto& [e, n] : edges) {
    if (key(e.first) == key(e.second)) continue;  // degenerate at a pole
    by_position[{key(e.first), key(e.second)}] += n;
  }
  for (const auto& [e, n] : by_position) {
    CHECK(n == 1);
    const auto back = by_position.find({e.second, e.first});
    CHECK((back != by_position.end() && back->second == 1));
  }
  for (const auto& p : s.positions) CHECK(p.norm() == Approx(1.0f).margin(1e-5));
  CHECK(segments_for_radius(1) == 12);
  CHECK(segments_for_radius(1000) == 160);
  CHECK(segments_for_radius(100) > segments_for_radius(20));
  const Mesh t = make_tube({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, 0.1, 8);
  CHECK(!t.indices.empty());
}

namespace {

// Where a fitted scene lands: the bounding box of its non-white pixels outside the title
// band and the legend box, and how many pixels inside the legend box are tinted by the
// vermillion geometry (the legend itself is drawn in neutral, blue and green only).
struct Placement {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  long under_legend = 0;
};

Placement place_of(const Image& img, const Scene3D::Layout& layout) {
  Placement p;
  const ScreenRect& lg = layout.legend;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* c = img.at(x, y);
      // The legend's outline is antialiased a pixel or two beyond its box.
      if (x >= lg.x0 - 2 && x < lg.x1 + 2 && y >= lg.y0 - 2 && y < lg.y1 + 2) {
        if (c[0] > c[2] + 12) ++p.under_legend;
        continue;
      }
      if (y < layout.title.y1 + 2 || (c[0] == 255 && c[1] == 255 && c[2] == 255)) continue;
      p.x0 = std::min(p.x0, x);
      p.x1 = std::max(p.x1, x + 1);
      p.y0 = std::min(p.y0, y);
      p.y1 = std::max(p.y1, y + 1);
    }
  return p;
}

// A vermillion bar along `axis` seen obliquely, labelled at its ends, with a legend of a
// blue marker and a green line; nothing vermillion is in the legend.
Scene3D bar_scene(const Eigen::Vector3d& axis) {
  Scene3D scene;
  scene.title = "fit: a bar, its end labels, a legend";
  scene.camera.eye = {3, -10, 2};
  scene.camera.fov_y_deg = 30;
  const Eigen::Vector3d half = 2.0 * axis + 0.25 * Eigen::Vector3d::Ones();
  scene.add_box({0, 0, 0}, half, Eigen::Matrix3d::Identity(), {kVermillion});
  scene.add_sphere(-1.5 * axis, 0.5, {kVermillion});
  scene.add_sphere(0.3 * Eigen::Vector3d::UnitY(), 0.1, {kBlue}, "marker");
  scene.add_polyline({{0, 0, 0}, {0, -0.3, 0}}, kBluishGreen, 3.5, "a line");
  scene.add_label(-2.3 * axis, "low end");
  scene.add_label(2.3 * axis, "high end");
  return scene;
}

}  // namespace

TEST_CASE("scene3d: the fit fills the free region to its edges and keeps clear of the legend",
          "[render][scene3d]") {
  for (const auto& [w, h] : {std::pair{1600, 1200}, std::pair{800, 600}}) {
    CAPTURE(w, h);
    const double tol_x = 0.02 * w, tol_y = 0.02 * h;
    SECTION("a wide bar spans the region from left to right") {
      const Scene3D scene = bar_scene(Eigen::Vector3d::UnitX());
      const Scene3D::Layout layout = rigid::render::layout(scene, w, h);
      REQUIRE(!layout.legend.empty());
      const Placement p = place_of(draw(scene, w, h), layout);
      CHECK(p.under_legend == 0);
      // Nothing clipped or outside the region (a pixel for antialiasing)...
      CHECK(p.x0 >= layout.region.x0 - 1);
      CHECK(p.x1 <= layout.region.x1 + 1);
      CHECK(p.y0 >= layout.region.y0 - 1);
      CHECK(p.y1 <= layout.region.y1 + 1);
      // ...and the limiting direction touches both edges.
      CHECK(p.x0 <= layout.region.x0 + tol_x);
      CHECK(p.x1 >= layout.region.x1 - tol_x);
    }
    SECTION("a tall bar spans the region from top to bottom") {
      const Scene3D scene = bar_scene(Eigen::Vector3d::UnitZ());
      const Scene3D::Layout layout = rigid::render::layout(scene, w, h);
      const Placement p = place_of(draw(scene, w, h), layout);
      CHECK(p.under_legend == 0);
      CHECK(p.x0 >= layout.region.x0 - 1);
      CHECK(p.x1 <= layout.region.x1 + 1);
      CHECK(p.y0 >= layout.region.y0 - 1);
      CHECK(p.y1 <= layout.region.y1 + 1);
      CHECK(p.y0 <= layout.region.y0 + tol_y);
      CHECK(p.y1 >= layout.region.y1 - tol_y);
    }
    SECTION("a round scene tucks under and beside the legend, touching it") {
      Scene3D scene = bar_scene(Eigen::Vector3d::UnitX());
      scene.add_sphere({0, 0, 0}, 2.2, {kVermillion});
      const Scene3D::Layout layout = rigid::render::layout(scene, w, h);
      const Placement p = place_of(draw(scene, w, h), layout);
      CHECK(p.under_legend == 0);
      CHECK(p.x0 >= layout.region.x0 - 1);
      CHECK(p.x1 <= layout.region.x1 + 1);
      CHECK(p.y0 >= layout.region.y0 - 1);
      CHECK(p.y1 <= layout.region.y1 + 1);
      // Limited by the legend's corner: the bottom edge is reached.
      CHECK(p.y1 >= layout.region.y1 - tol_y);
      // Unfitted, the sphere fills the view and shows under the legend: the check can fail.
      scene.camera.fit = false;
      scene.camera.eye *= 0.35;
      CHECK(place_of(draw(scene, w, h), layout).under_legend > 1000);
    }
  }
}

TEST_CASE("scene3d: the fit keeps the viewing direction and up", "[render][scene3d]") {
  // A sphere seen head-on stays round and centred across the free width: no shear or tilt.
  Scene3D scene;
  scene.camera.eye = {0, -10, 0};
  SECTION("perspective") {}
  SECTION("orthographic") {
    scene.camera.orthographic = true;
  }
  scene.add_sphere({0, 0, 0}, 1.0, {kVermillion});
  const Scene3D::Layout layout = rigid::render::layout(scene, 800, 600);
  const Placement p = place_of(draw(scene, 800, 600), layout);
  CHECK(std::abs((p.x1 - p.x0) - (p.y1 - p.y0)) <= 2);
  CHECK(std::abs(0.5 * (p.x0 + p.x1) - 400) <= 1.5);
  CHECK(std::abs(0.5 * (p.y0 + p.y1) - 300) <= 1.5);
  CHECK(p.y1 - p.y0 >= layout.region.y1 - layout.region.y0 - 0.02 * 600);
}

TEST_CASE("scene3d: a scene looks the same at any scale (GL's float range is no limit)",
          "[render][scene3d]") {
  // Lengths from 1e-40 m to 1e30 m would underflow or overflow float; the
  // renderer normalises in double first, so the picture is that of scale 1.
  const auto draw = [](double k) {
    Scene3D scene;
    scene.camera.eye = Eigen::Vector3d(3, 2, 2) * k;
    scene.add_ellipsoid(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0.7, 0.5) * k,
                        Eigen::Matrix3d::Identity(), {kSkyBlue, 0.5f});
    scene.add_tube({Eigen::Vector3d(-k, 0, 0.6 * k), Eigen::Vector3d(k, 0, 0.6 * k)}, 0.03 * k,
                   {kVermillion});
    scene.add_arrow(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, k), 0.02 * k, {kBlack});
    return rigid::render::draw(scene, 400, 300);
  };
  const Image reference = draw(1.0);
  for (double k : {1e-40, 1e-8, 1e8, 1e30}) {
    INFO("scale " << k);
    // The same picture up to float rounding of the normalised scene: a few edge pixels.
    CHECK(compare_images(draw(k), reference).differing_fraction < 0.001);
  }
}

TEST_CASE("scene3d: the fitted camera is the one render uses, and a merge fits both scenes",
          "[render][scene3d]") {
  Scene3D a;
  a.title = "a sphere and an arrow";
  a.add_sphere({0, 0, 0}, 1.0, {kSkyBlue}, "sphere");
  a.add_arrow({0, 0, 0}, {0, 0, 2.5}, 0.05, {kVermillion}, "arrow");
  // drawn with its own fit, and with the camera that fit returns (fit off): pixel for pixel
  Scene3D fixed = a;
  fixed.camera = fitted_camera(a, 640, 480);
  CHECK_FALSE(fixed.camera.fit);
  const ImageDiff same = compare_images(draw(a, 640, 480), draw(fixed, 640, 480), 0);
  CHECK(same.differing_pixels == 0);
  // a camera fitted to a and a far-off second scene keeps both in view: a's own fit,
  // applied to the merge, would not (the far sphere falls outside)
  Scene3D b;
  b.add_sphere({6, 0, 0}, 1.0, {kBluishGreen}, "far sphere");
  Scene3D both = a;
  both.merge(b);
  CHECK(both.objects().size() == a.objects().size() + b.objects().size());
  const Camera wide = fitted_camera(both, 640, 480), tight = fitted_camera(a, 640, 480);
  CHECK((wide.eye - wide.target).norm() > (tight.eye - tight.target).norm());
}

TEST_CASE("scene3d: a part hidden by its legend entry takes its unlabelled followers, no more") {
  Scene3D s;
  s.add_sphere({0, 0, 0}, 1.0, {}, "body");
  s.add_tube({{0, 0, 0}, {1, 0, 0}}, 0.1, {}, "polhode");
  s.add_tube({{0, 1, 0}, {1, 1, 0}}, 0.1);  // the polhode's second loop
  s.add_arrow({0, 0, 0}, {0, 0, 2}, 0.05, {}, "L");
  s.add_polyline({{0, 0, 0}, {2, 2, 2}}, kBlack, 2.0, "path");
  s.add_polyline({{0, 0, 0}, {-2, 2, 2}}, kBlack, 2.0);
  CHECK(s.legend_labels() == std::vector<std::string>{"body", "polhode", "L", "path"});
  const Scene3D without = s.without({"polhode", "path"});
  std::vector<std::string> labels;
  for (const auto& o : without.objects()) labels.push_back(o.label);
  // the sphere and the arrow (its shaft, then its unlabelled head), their labels intact:
  // both polhode loops gone
  CHECK(labels == std::vector<std::string>{"body", "L", ""});
  CHECK(without.polylines().empty());
  CHECK(without.legend_labels() == std::vector<std::string>{"body", "L"});
  CHECK(s.without({}).objects().size() == s.objects().size());
}

TEST_CASE("scene3d: a frame that keeps a film's legend lists its parts and hides them there too") {
  Scene3D film;
  film.add_sphere({0, 0, 0}, 1.0, {}, "body");
  film.add_tube({{0, 0, 0}, {1, 0, 0}}, 0.1, {}, "polhode");
  Scene3D first;  // the first frame: no polhode drawn yet
  first.add_sphere({0, 0, 0}, 1.0, {}, "body");
  first.legend_from = std::make_shared<const Scene3D>(film);
  CHECK(first.legend_labels() == std::vector<std::string>{"body", "polhode"});
  CHECK(first.without({"polhode"}).legend_labels() == std::vector<std::string>{"body"});
  CHECK(layout(first.without({"body", "polhode"}), 800, 600).legend.empty());
  // a part the frame draws and the film's legend lacks (brought in by a dragged slider)
  // is named after the film's
  first.add_arrow({0, 0, 0}, {0, 0, 2}, 0.05, {}, "L");
  CHECK(first.legend_labels() == std::vector<std::string>{"body", "polhode", "L"});
  // and drawn: a row more than the film's two
  CHECK(layout(first, 800, 600).legend.height() >
        layout(first.without({"L"}), 800, 600).legend.height() + 1);
  // what a legend needs of a film and no more: each label once, no geometry
  film.add_tube({{0, 0, 1}, {1, 0, 1}, {2, 0, 1}}, 0.1, {}, "polhode");
  const Scene3D kept = film.legend_only();
  CHECK(kept.legend_labels() == std::vector<std::string>{"body", "polhode"});
  REQUIRE(kept.objects().size() == 2);
  CHECK(kept.objects()[1].path.empty());
}

TEST_CASE("scene3d: a faded scene is the same geometry, faint, under one legend entry") {
  Scene3D s;
  s.add_sphere({0, 0, 0}, 1.0, {kBlue, 0.8f}, "body");
  s.add_arrow({0, 0, 0}, {0, 0, 2}, 0.05, {kVermillion}, "L");
  s.add_polyline({{0, 0, 0}, {2, 2, 2}}, kBlack, 2.0, "path");
  s.add_label({1, 1, 1}, "P");
  const Scene3D f = s.faded("exact", 0.25f);
  REQUIRE(f.objects().size() == s.objects().size());
  CHECK(f.objects()[0].material.opacity == 0.8f * 0.25f);
  CHECK(f.objects()[1].material.opacity == 0.25f);
  CHECK(f.objects()[2].label.empty());
  CHECK(f.objects()[0].transform.matrix() == s.objects()[0].transform.matrix());
  CHECK(f.polylines()[0].color.a == 0.25f);
  CHECK(f.labels().empty());
  CHECK(f.legend_labels() == std::vector<std::string>{"exact"});
}

TEST_CASE("scene3d: a fit asked again of the same scene is the fit it had, of another its own",
          "[render][scene3d]") {
  // A live view asks for its camera on every typed value: where the scene is as it was the
  // fit is not searched again, and the camera given is the one a fresh search gives.
  Scene3D a;
  a.add_sphere({0, 0, 0}, 1.0, {rigid::render::kBlue}, "ball");
  a.add_polyline({{0, 0, 0}, {2, 0.5, 0.3}}, rigid::render::kOrange, 3.0, "arm");
  Scene3D b = a;
  b.add_polyline({{0, 0, 0}, {0, -3, 1}}, rigid::render::kBluishGreen, 3.0, "further");
  const auto same = [](const rigid::render::Camera& p, const rigid::render::Camera& q) {
    return p.eye == q.eye && p.target == q.target && p.ortho_height == q.ortho_height;
  };
  const rigid::render::Camera first = rigid::render::fitted_camera(a, 800, 600);
  const rigid::render::Camera other = rigid::render::fitted_camera(b, 800, 600);
  CHECK_FALSE(same(first, other));  // b reaches further: its eye stands back
  CHECK((other.eye - other.target).norm() > (first.eye - first.target).norm());
  CHECK(same(rigid::render::fitted_camera(a, 800, 600), first));
  CHECK(same(rigid::render::fitted_camera(b, 800, 600), other));
  CHECK_FALSE(same(rigid::render::fitted_camera(a, 640, 600), first));  // another size
  // a thread of its own keeps no fit of another's: its search gives the same camera
  rigid::render::Camera fresh;
  std::thread([&] { fresh = rigid::render::fitted_camera(a, 800, 600); }).join();
  CHECK(same(fresh, first));
}
