// The view's commands pinned by what they do to the camera and to what is drawn: turn,
// zoom and reset-view as the camera's eye, hide and show and the legend as the scene
// described and its pixels drawn again, another lab's scene, the keys 1 to 9.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "effects_bench.h"

using namespace rigid::test::effects;

TEST_CASE("explore: turn and zoom and reset-view set the orbit the scene is seen through") {
  Bench b("poinsot");
  const Scene3D plain = described(b.e);
  b.run("turn 30 -10\nzoom 1.5");
  CHECK(b.e.view().orbit.yaw_deg == 30);
  CHECK(b.e.view().orbit.pitch_deg == -10);
  CHECK(b.e.view().orbit.zoom == 1.5);
  // each adds to the last
  b.run("turn 30 -10\nzoom 2");
  CHECK(b.e.view().orbit.yaw_deg == 60);
  CHECK(b.e.view().orbit.pitch_deg == -20);
  CHECK(b.e.view().orbit.zoom == 3);
  const Scene3D turned = described(b.e);
  CHECK(same_camera(turned.camera, b.e.view().orbit.apply(plain.camera)));
  CHECK_FALSE(same_camera(turned.camera, plain.camera));
  b.run("reset-view");
  CHECK(b.e.view().orbit.is_identity());
  CHECK(same_camera(described(b.e).camera, plain.camera));
  b.run("turn 200 0\nturn 200 0");
  CHECK(b.e.view().orbit.yaw_deg == 40);

  // the camera itself: yaw turns the eye about up by its degrees, pitch raises it by its
  // degrees, zoom brings it nearer by its factor (to roundoff: a few ulps of the angles)
  const auto sight = [](const rigid::render::Camera& c) {
    return Eigen::Vector3d(c.eye - c.target);
  };
  const Eigen::Vector3d up = plain.camera.up.normalized(), s0 = sight(plain.camera);
  const auto elevation_deg = [&](const Eigen::Vector3d& s) {
    return std::asin(s.normalized().dot(up)) * 180.0 / M_PI;
  };
  const auto azimuth_deg = [&](const Eigen::Vector3d& s) {
    const Eigen::Vector3d x = (s0 - s0.dot(up) * up).normalized(), y = up.cross(x);
    return std::atan2(s.dot(y), s.dot(x)) * 180.0 / M_PI;
  };
  b.run("reset-view\nturn 35 0");
  const Eigen::Vector3d s1 = sight(described(b.e).camera);
  CHECK(azimuth_deg(s1) == Approx(35).margin(1e-9));
  CHECK(elevation_deg(s1) == Approx(elevation_deg(s0)).margin(1e-9));
  CHECK(s1.norm() == Approx(s0.norm()).epsilon(1e-12));
  b.run("reset-view\nturn 0 -10\nzoom 2");
  const Eigen::Vector3d s2 = sight(described(b.e).camera);
  CHECK(elevation_deg(s2) == Approx(elevation_deg(s0) - 10).margin(1e-9));  // the eye lower
  CHECK(azimuth_deg(s2) == Approx(0).margin(1e-9));
  CHECK(s2.norm() == Approx(s0.norm() / 2).epsilon(1e-12));
}

TEST_CASE("explore: hide and show take a part of the scene out of what is drawn and back") {
  Bench b("poinsot");
  const std::string part = "energy ellipsoid";
  REQUIRE(draws(described(b.e), part));
  b.run("hide \"" + part + "\"");
  CHECK(b.e.view().hidden == std::vector<std::string>{part});
  CHECK_FALSE(draws(described(b.e), part));
  CHECK(draws(described(b.e), "invariable plane"));
  // hiding a hidden part leaves it hidden, and showing a shown one leaves it shown
  b.run("hide \"" + part + "\"\nshow \"invariable plane\"");
  CHECK(b.e.view().hidden == std::vector<std::string>{part});
  CHECK_FALSE(draws(described(b.e), part));
  CHECK(draws(described(b.e), "invariable plane"));
  b.run("hide \"invariable plane\"\nshow \"" + part + "\"");
  CHECK(b.e.view().hidden == std::vector<std::string>{"invariable plane"});
  CHECK(draws(described(b.e), part));
  CHECK_FALSE(draws(described(b.e), "invariable plane"));
  b.run("show \"invariable plane\"\nshow \"invariable plane\"");
  CHECK(b.e.view().hidden.empty());
  CHECK(draws(described(b.e), "invariable plane"));

  // the legend collapses and opens again; what is drawn changes with it
  const long version = b.e.view().hidden_version;
  b.e.apply(ex::action::ToggleLegend{});
  CHECK_FALSE(described(b.e).show_legend);
  CHECK(b.e.view().hidden_version != version);
  CHECK(draws(described(b.e), "invariable plane"));
  b.e.apply(ex::action::ToggleLegend{});
  CHECK(described(b.e).show_legend);
}

TEST_CASE("explore: the window's scene is drawn again when a part or the legend goes") {
  Bench b("poinsot");
  const auto pixels = [&] { return b.e.views().scene_pixels().rgb; };
  b.run("frames 1");
  const std::vector<std::uint8_t> all = pixels();
  b.run("hide \"energy ellipsoid\"\nframes 1");
  const std::vector<std::uint8_t> without = pixels();
  CHECK(without != all);
  b.run("show \"energy ellipsoid\"\nframes 1");
  CHECK(pixels() == all);
  b.e.apply(ex::action::ToggleLegend{});
  b.run("frames 1");
  CHECK(pixels() != all);
}

TEST_CASE("explore: another lab's scene is drawn as that lab opened alone draws it") {
  std::vector<std::uint8_t> alone;
  {
    Bench b("tennis_racquet");
    b.run("frames 1");
    alone = b.e.views().scene_pixels().rgb;
  }
  Bench b("poinsot");
  b.run("seek 0.5\nframes 1\nlab tennis_racquet\nframes 1");
  CHECK(b.e.session().name() == "tennis_racquet");
  CHECK(b.e.views().scene_pixels().rgb == alone);
}

TEST_CASE("explore: the keys 1 to 9 show and hide the scene's parts in the legend's order") {
  Bench b("poinsot");
  b.run("frames 1");
  ex::SceneCache cache;
  const std::vector<std::string> parts = cache.parts(b.e.session(), b.e.view());
  REQUIRE(parts.size() >= 3);
  ImGuiIO& io = ImGui::GetIO();
  for (std::size_t k = 0; k < 3; ++k) {
    INFO("key " << k + 1);
    // Dear ImGui 1.86 reads GLFW's key codes, a digit's its character
    io.KeysDown['1' + k] = true;
    b.imgui.frame(b.e);
    io.KeysDown['1' + k] = false;
    b.imgui.frame(b.e);
    CHECK(b.e.view().hidden == std::vector<std::string>{parts[k]});
    io.KeysDown['1' + k] = true;
    b.imgui.frame(b.e);
    io.KeysDown['1' + k] = false;
    b.imgui.frame(b.e);
    CHECK(b.e.view().hidden.empty());
  }
}

TEST_CASE("explore: the motion and its strip are drawn without describing the lab's figures") {
  // Describing every figure is much of a change's work; the motion's scene and its strip
  // (tennis_racquet's plot) need none of it, and the export's choice and the views' lists
  // name the figures without describing them.
  Bench b("tennis_racquet");
  b.run("frames 2");
  CHECK_FALSE(b.e.session().figures_described());
  const std::string named = b.e.view().export_figure_name;
  REQUIRE(named == b.e.session().figures()[0].name);
  for (const char* step : {"set --omega 12\nframes 3", "play 0.5", "drag --omega 11\nframes 2"}) {
    INFO(step);
    b.run(step);
    CHECK_FALSE(b.e.session().figures_described());
    CHECK(b.e.view().export_figure_name == named);
  }
  // a figure shown is that figure described, and no other
  b.run("show-plot omega\nframes 1");
  CHECK(b.e.session().figures_described());
  b.run("set --omega 10\nframes 2");
  CHECK(b.e.session().figures_described());
  const rigid::lab::NamedFigure* omega = b.e.session().figure("omega");
  REQUIRE(omega != nullptr);
  CHECK(omega->caption == b.e.session().figures()[0].caption);
}
