// Draws a sample 2D plot and 3D scene to /tmp/render_demo (a visual check of rigid::render).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "rigid/render/context.h"
#include "rigid/render/draw.h"
#include "rigid/render/palette.h"
#include "rigid/render/plot2d.h"
#include "rigid/render/png.h"
#include "rigid/render/scene3d.h"

namespace rr = rigid::render;

namespace {

rr::Plot2D sample_plot() {
  rr::Plot2D plot(1, 2);
  plot.title = "Tennis racquet: \\omega components, I_1 = 0.0103, I_3 = 0.0200 kg m^2";
  rr::Panel& a = plot.panel(0, 0);
  a.title = "Body angular velocity";
  a.x.label = "t (s)";
  a.y.label = "\\omega_i (rad/s)";
  std::vector<double> t, w1, w2, w3, lo, hi;
  for (int i = 0; i <= 600; ++i) {
    const double s = i * 0.01;
    t.push_back(s);
    w1.push_back(10 * std::cos(2.1 * s) * std::exp(-0.05 * s));
    w2.push_back(6 * std::sin(2.1 * s + 0.5));
    w3.push_back(3 + 0.5 * std::sin(5 * s));
    lo.push_back(w3.back() - 1);
    hi.push_back(w3.back() + 1);
  }
  a.add_band(t, lo, hi, "\\omega_3 \\pm 1");
  a.add_line(t, w1, "\\omega_1");
  a.add_line(t, w2, "\\omega_2").dash = rr::Dash::kDashed;
  a.add_line(t, w3, "\\omega_3");
  a.add_ref_line(0, false);
  a.annotate(t[157], w1[157], "\\dot{\\theta} = 0");

  rr::Panel& b = plot.panel(0, 1);
  b.title = "Energy drift";
  b.x.label = "steps per period";
  b.x.scale = rr::Scale::kLog10;
  b.y.scale = rr::Scale::kLog10;
  b.y.label = "|\\Delta{}E| / E";
  std::vector<double> n, e2, e4;
  for (int k = 0; k <= 12; ++k) {
    n.push_back(10 * std::pow(2.0, k));
    e2.push_back(0.3 * std::pow(n.back(), -2.0));
    e4.push_back(2.0 * std::pow(n.back(), -4.0));
  }
  auto& s2 = b.add_line(n, e2, "RK2, \\dot{\\phi} drift");
  s2.marker = rr::Marker::kCircle;
  auto& s4 = b.add_line(n, e4, "RK4 10^{-6} m a^2");
  s4.marker = rr::Marker::kSquare;
  b.add_span(1e-12, 1e-10, false, "roundoff");
  return plot;
}

rr::Scene3D sample_scene() {
  rr::Scene3D scene;
  scene.title = "Poinsot: energy ellipsoid inside the momentum ellipsoid, I = (1, 2, 3)";
  scene.camera.eye = {5.2, 3.6, 3.0};
  const Eigen::Matrix3d I3 = Eigen::Matrix3d::Identity();
  rr::Material outer{rr::kSkyBlue, 0.28f};
  rr::Material inner{rr::kOrange, 0.55f};
  scene.add_ellipsoid({0, 0, 0}, {1.6, 1.25, 1.05}, I3, outer, "momentum ellipsoid");
  scene.add_ellipsoid({0, 0, 0}, {1.25, 0.95, 0.8}, I3, inner, "energy ellipsoid");
  // A polhode-like curve on the inner ellipsoid.
  std::vector<Eigen::Vector3d> curve;
  for (int i = 0; i <= 400; ++i) {
    const double a = 2 * EIGEN_PI * i / 400;
    Eigen::Vector3d d(0.45 * std::cos(a), 0.5 * std::sin(a), 1.0);
    d = d.cwiseQuotient(Eigen::Vector3d(1.25, 0.95, 0.8));
    d.normalize();
    curve.push_back(d.cwiseProduct(Eigen::Vector3d(1.25, 0.95, 0.8)));
  }
  scene.add_tube(curve, 0.025, {rr::kVermillion}, "polhode");
  scene.add_axes({0, 0, 0}, I3, 2.2, {"1", "2", "3"});
  scene.add_arrow({0, 0, 0}, {0.9, 0.6, 1.6}, 0.035, {rr::kBluishGreen}, "\\omega");
  scene.add_arrow({0, 0, 0}, {0.6, 1.1, 1.9}, 0.035, {rr::kReddishPurple}, "L");
  scene.add_label({0.9, 0.6, 1.6}, "\\omega", rr::kBluishGreen);
  scene.add_cone({0, 0, 0}, {-1.4, -1.6, -0.6}, 0.5, {rr::kBlue, 0.9f}, "space cone");
  scene.add_disk({1.8, -1.4, -0.9}, {0, 0, 1}, 0.6, {rr::kYellow}, "disk");
  scene.add_polyline({{-2, -2, -1.2}, {2, -2, -1.2}, {2, 2, -1.2}, {-2, 2, -1.2}, {-2, -2, -1.2}},
                     rr::kGray, 3, "invariable plane");
  return scene;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = "/tmp/render_demo";
  std::filesystem::create_directories(dir);
  using clock = std::chrono::steady_clock;
  auto t0 = clock::now();
  const rr::ContextInfo& info = rr::context();
  std::printf("context: %s, %s, %s, samples %d, %.3f s\n", rr::backend_name(info.backend),
              info.gl_version.c_str(), info.gl_renderer.c_str(), info.samples,
              info.creation_seconds);
  (void)t0;
  const rr::Plot2D plot = sample_plot();
  for (int rep = 0; rep < 3; ++rep) {
    auto t1 = clock::now();
    rr::Image img = rr::draw(plot, 1600, 1200);
    auto t2 = clock::now();
    rr::write_png(img, dir + "/plot.png");
    auto t3 = clock::now();
    std::printf("plot 1600x1200: render %.1f ms, png %.1f ms\n",
                std::chrono::duration<double, std::milli>(t2 - t1).count(),
                std::chrono::duration<double, std::milli>(t3 - t2).count());
  }
  rr::save_png(plot, dir + "/plot_800.png", 800, 600);
  const rr::Scene3D scene = sample_scene();
  for (int rep = 0; rep < 2; ++rep) {
    auto t1 = clock::now();
    rr::save_png(scene, dir + "/scene.png");
    std::printf("scene 1600x1200 render+png %.1f ms\n",
                std::chrono::duration<double, std::milli>(clock::now() - t1).count());
  }
  rr::save_png(scene, dir + "/scene_800.png", 800, 600);
  (void)argc;
  (void)argv;
  return 0;
}
