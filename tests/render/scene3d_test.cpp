// Tests of 3D scenes by their pixels.
#include <catch2/catch.hpp>

#include "rigid/render/mesh.h"
#include "rigid/render/palette.h"
#include "rigid/render/scene3d.h"

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

TEST_CASE("scene3d: an opaque sphere is shaded in its colour, background white", "[render][scene3d]") {
  Scene3D scene;
  scene.camera = front_camera();
  scene.add_sphere({0, 0, 0}, 1.0, {kBlue});
  const Image img = scene.render(400, 300);
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
  const Image img = scene.render(400, 300);
  const std::uint8_t* c = img.at(200, 150);
  CHECK(c[2] > c[0]);  // blue box in front, not the vermillion sphere
}

TEST_CASE("scene3d: nested translucent shells show both colours", "[render][scene3d]") {
  Scene3D scene;
  scene.camera = front_camera();
  scene.add_sphere({0, 0, 0}, 2.0, {kSkyBlue, 0.3f});
  scene.add_sphere({0, 0, 0}, 1.0, {kOrange, 1.0f});
  const Image img = scene.render(400, 300);
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
  for (const auto& p : s.positions) CHECK(p.norm() == Approx(1.0f).margin(1e-5));
  CHECK(segments_for_radius(1) == 12);
  CHECK(segments_for_radius(1000) == 160);
  CHECK(segments_for_radius(100) > segments_for_radius(20));
  const Mesh t = make_tube({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, 0.1, 8);
  CHECK(!t.indices.empty());
}
