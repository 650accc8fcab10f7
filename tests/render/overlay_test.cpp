// Tests of the shared overlay and of self-placing text: one style for plots and
// scenes, long titles kept inside the margin, legends, annotations and labels
// that keep clear of the data and of each other.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "rigid/render/draw.h"
#include "rigid/render/palette.h"
#include "rigid/render/plot2d.h"
#include "rigid/render/scene3d.h"
#include "rigid/render/text.h"

using namespace rigid::render;

namespace {

// The figure style's outer margin at 1600×1200 and 800×600: two paddings of 14 px × f.
double margin_at(int w, int h) {
  return 28 * std::pow(std::min(w / 1600.0, h / 1200.0), 0.7);
}

// A data point's pixel in a panel's layout (linear axes).
struct Mapper {
  Plot2D::PanelLayout p;
  double x(double v) const {
    return p.frame.x0 + (v - p.x_lo) / (p.x_hi - p.x_lo) * p.frame.width();
  }
  double y(double v) const {
    return p.frame.y1 - (v - p.y_lo) / (p.y_hi - p.y_lo) * p.frame.height();
  }
};

// Points along every segment of every series, in pixels (what "covers data" means).
std::vector<std::pair<double, double>> drawn_points(const Panel& panel, const Mapper& m) {
  std::vector<std::pair<double, double>> out;
  for (const Series& s : panel.series)
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      out.push_back({m.x(s.x[i]), m.y(s.y[i])});
      if (i + 1 < s.x.size() && s.width > 0)
        for (int k = 1; k < 16; ++k)
          out.push_back({m.x(s.x[i] + (s.x[i + 1] - s.x[i]) * k / 16.0),
                         m.y(s.y[i] + (s.y[i + 1] - s.y[i]) * k / 16.0)});
    }
  return out;
}

long points_inside(const std::vector<std::pair<double, double>>& pts, const ScreenRect& r) {
  long n = 0;
  for (const auto& [x, y] : pts) n += r.contains(x, y);
  return n;
}

// Three sine waves filling a panel from edge to edge: every legend place covers some.
void fill_with_waves(Panel& p) {
  std::vector<double> t, a, b, c;
  for (int i = 0; i <= 400; ++i) {
    t.push_back(0.1 * i);
    a.push_back(std::sin(t.back()));
    b.push_back(std::cos(1.3 * t.back()));
    c.push_back(0.8 * std::sin(2.1 * t.back() + 1));
  }
  p.add_line(t, a, "\\omega_1");
  p.add_line(t, b, "\\omega_2");
  p.add_line(t, c, "\\omega_3");
}

// Pixels of a colour (within a tolerance) inside a rectangle.
long pixels_of(const Image& img, const ScreenRect& r, Color c, int tol = 40) {
  long n = 0;
  const int cr = int(c.r * 255 + 0.5), cg = int(c.g * 255 + 0.5), cb = int(c.b * 255 + 0.5);
  for (int y = std::max(0, int(r.y0)); y < std::min(img.height, int(std::ceil(r.y1))); ++y)
    for (int x = std::max(0, int(r.x0)); x < std::min(img.width, int(std::ceil(r.x1))); ++x) {
      const std::uint8_t* p = img.at(x, y);
      n += std::abs(p[0] - cr) <= tol && std::abs(p[1] - cg) <= tol && std::abs(p[2] - cb) <= tol;
    }
  return n;
}

}  // namespace

TEST_CASE("overlay: a plot's and a scene's legend and title come from one style",
          "[render][overlay]") {
  const std::vector<std::string> labels = {"\\omega_1 against t", "energy ellipsoid 2T",
                                           "principal axis 1: I_1 = 0.1262 kg m^2"};
  const std::string title = "poinsot: I = (1, 2, 3) kg m^2";
  for (const auto& [w, h] : {std::pair{1600, 1200}, std::pair{800, 600}}) {
    CAPTURE(w, h);
    Plot2D plot;
    plot.title = title;
    Scene3D scene;
    scene.title = title;
    for (std::size_t k = 0; k < labels.size(); ++k) {
      plot.panel().add_line({0, 1}, {double(k), double(k) + 1}, labels[k]);
      scene.add_sphere(Eigen::Vector3d(double(k), 0, 0), 0.3, {}, labels[k]);
    }
    const ScreenRect pl = layout(plot, w, h).panels.at(0).legend, sl = layout(scene, w, h).legend;
    // The same rows, font, swatch and paddings give the same box, to rounding.
    CHECK(pl.width() == Approx(sl.width()).margin(1e-9));
    CHECK(pl.height() == Approx(sl.height()).margin(1e-9));
    CHECK(layout(plot, w, h).title_size == Approx(layout(scene, w, h).title_size).margin(1e-12));
    CHECK(layout(plot, w, h).title.y0 == Approx(layout(scene, w, h).title.y0).margin(1e-12));
  }
}

TEST_CASE("overlay: a long title wraps at a top-level separator, keeping the margin",
          "[render][overlay]") {
  const std::string long_title =
      "poinsot: I = (3.142, 6.283, 8.168) kg m^2, \\omega_0 = (1, 1, 1) rad/s: integrators "
      "against the exact solution, every method at its tolerance";
  for (const auto& [w, h] : {std::pair{1600, 1200}, std::pair{800, 600}}) {
    CAPTURE(w, h);
    const double margin = margin_at(w, h);
    Plot2D plot;
    plot.title = long_title;
    Scene3D scene;
    scene.title = long_title;
    scene.add_sphere({0, 0, 0}, 1, {kBlue});
    for (const auto& [lines, size, box] :
         {std::tuple{layout(plot, w, h).title_lines, layout(plot, w, h).title_size,
                     layout(plot, w, h).title},
          std::tuple{layout(scene, w, h).title_lines, layout(scene, w, h).title_size,
                     layout(scene, w, h).title}}) {
      CHECK(lines == 2);
      CHECK(box.x0 >= margin - 1e-9);
      CHECK(box.x1 <= w - margin + 1e-9);
      CHECK(box.y0 == Approx(margin));
      // Two lines side by side would not fit: the title really is wider than the room.
      CHECK(measure_text(long_title, size).width > w - 2 * margin);
    }
  }
  // At 1600 px the two halves fit at full size: nothing shrinks.
  Plot2D plot;
  plot.title = long_title;
  CHECK(layout(plot, 1600, 1200).title_size == Approx(40.0));
  // The image stays white within the margin on both sides of the title band.
  const Image img = draw(plot, 1600, 1200);
  const ScreenRect band = layout(plot, 1600, 1200).title;
  CHECK(pixels_of(img, {0, band.y0, margin_at(1600, 1200) - 1, band.y1}, kTextColor, 120) == 0);
  CHECK(pixels_of(img, {1600 - margin_at(1600, 1200) + 1, band.y0, 1600, band.y1}, kTextColor,
                  120) == 0);
}

TEST_CASE("overlay: the wrap never splits inside parentheses, a title without a separator shrinks",
          "[render][overlay]") {
  // The only top-level separator is the first ": "; the commas in the middle are inside ( ).
  std::string inner = "(";
  for (int k = 1; k <= 24; ++k)
    inner += (k > 1 ? ", " : "") + std::string("x_{") + std::to_string(k) + "}";
  inner += ") end";
  Plot2D plot;
  plot.title = "A: " + inner;
  const Plot2D::Layout l = layout(plot, 1600, 1200);
  REQUIRE(l.title_lines == 2);
  // The title is as wide as its second line, all of the parenthesis: it was not split there.
  CHECK(l.title.width() == Approx(measure_text(inner, l.title_size).width).margin(0.5));
  // No separator at all: one line, shrunk to the room between the margins.
  Plot2D plain;
  plain.title = std::string(160, 'W');
  const Plot2D::Layout p = layout(plain, 1600, 1200);
  CHECK(p.title_lines == 1);
  CHECK(p.title_size < 40);
  CHECK(p.title.width() <= 1600 - 2 * margin_at(1600, 1200));
  // Fonts snap to whole pixels: the shrunk title fills the room to within a size step.
  CHECK(p.title.width() > 0.9 * (1600 - 2 * margin_at(1600, 1200)));
}

TEST_CASE("legend: kAuto takes the one corner free of data", "[render][legend]") {
  // Clusters of points in three corners of the data range; the bottom right is empty.
  Plot2D plot;
  Panel& p = plot.panel();
  std::vector<double> x, y;
  for (const auto& [cx, cy] : {std::pair{0.0, 1.0}, std::pair{1.0, 1.0}, std::pair{0.0, 0.0}})
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j) {
        x.push_back(cx + (cx > 0.5 ? -0.05 : 0.05) * i);
        y.push_back(cy + (cy > 0.5 ? -0.05 : 0.05) * j);
      }
  p.add_points(x, y, "measured").color = kBlue;
  p.add_line({0.5, 0.5}, {0.45, 0.55}, "a short line");
  const Plot2D::PanelLayout l = layout(plot, 1600, 1200).panels.at(0);
  REQUIRE(!l.legend.empty());
  const double cx = 0.5 * (l.frame.x0 + l.frame.x1), cy = 0.5 * (l.frame.y0 + l.frame.y1);
  CHECK(l.legend.x0 > cx);
  CHECK(l.legend.y0 > cy);
  CHECK(points_inside(drawn_points(p, {l}), l.legend.grown(6)) == 0);
  // No headroom was needed: the y range is the data's with its 4 % padding.
  CHECK(l.y_hi == Approx(1.04));
  CHECK(l.y_lo == Approx(-0.04));
}

TEST_CASE("legend: a panel full of data gets headroom and the legend covers none of it",
          "[render][legend]") {
  for (const auto& [w, h] : {std::pair{1600, 1200}, std::pair{800, 600}}) {
    CAPTURE(w, h);
    SECTION("one free end grows") {
      Plot2D plot;
      Panel& p = plot.panel();
      fill_with_waves(p);
      const Plot2D::PanelLayout l = layout(plot, w, h).panels.at(0);
      REQUIRE(!l.legend.empty());
      // The data's range padded by 4 % is -1.08..1.08; exactly one end grew beyond it.
      const bool top = l.y_hi > 1.08 + 1e-6, bottom = l.y_lo < -1.08 - 1e-6;
      CHECK(top != bottom);
      CHECK(std::max(l.y_hi - 1.08, -1.08 - l.y_lo) > 0.02);
      CHECK(points_inside(drawn_points(p, {l}), l.legend) == 0);
      // And in the pixels: no curve colour in the legend box right of its swatches (the
      // style's inner padding and swatch, 0.8 × 14 + 52 reference px scaled by f).
      const Image img = draw(plot, w, h);
      const double f = std::pow(std::min(w / 1600.0, h / 1200.0), 0.7);
      const ScreenRect text_part{l.legend.x0 + (0.8 * 14 + 52) * f + 2, l.legend.y0, l.legend.x1,
                                 l.legend.y1};
      CHECK(pixels_of(img, text_part, palette_color(0)) == 0);
      CHECK(pixels_of(img, text_part, palette_color(1)) == 0);
    }
    SECTION("the bottom grows when the user fixed the top") {
      Plot2D plot;
      Panel& p = plot.panel();
      fill_with_waves(p);
      p.y.max = 1.1;
      const Plot2D::PanelLayout l = layout(plot, w, h).panels.at(0);
      CHECK(l.y_hi == 1.1);
      CHECK(l.y_lo < -1.08 - 0.02);
      CHECK(l.legend.y0 > 0.5 * (l.frame.y0 + l.frame.y1));
      CHECK(points_inside(drawn_points(p, {l}), l.legend) == 0);
    }
    SECTION("both ends fixed: no headroom, the legend covers the least it can") {
      Plot2D plot;
      Panel& p = plot.panel();
      fill_with_waves(p);
      p.y.min = -1.1, p.y.max = 1.1;
      const Plot2D::PanelLayout l = layout(plot, w, h).panels.at(0);
      CHECK(l.y_lo == -1.1);
      CHECK(l.y_hi == 1.1);
      CHECK(!l.legend.empty());
    }
    SECTION("an explicit place stays, and kNone draws none") {
      Plot2D plot;
      Panel& p = plot.panel();
      fill_with_waves(p);
      p.legend = LegendPlace::kBottomLeft;
      Plot2D::PanelLayout l = layout(plot, w, h).panels.at(0);
      CHECK(l.legend.x0 < 0.5 * (l.frame.x0 + l.frame.x1));
      CHECK(l.legend.y0 > 0.5 * (l.frame.y0 + l.frame.y1));
      CHECK(l.y_hi == Approx(1.08));
      CHECK(l.y_lo == Approx(-1.08));
      p.legend = LegendPlace::kNone;
      l = layout(plot, w, h).panels.at(0);
      CHECK(l.legend.empty());
    }
  }
}

TEST_CASE("legend: a shared legend sits under the panels in columns and grows no axis",
          "[render][legend]") {
  // two panels drawing the same ten labelled curves, edge to edge, as the integrator
  // figures do: one legend box for both, where no axis makes room for it
  const auto fill = [](Plot2D& plot) {
    for (int col = 0; col < 2; ++col) {
      for (int k = 0; k < 10; ++k) {
        std::vector<double> t, y;
        for (int i = 0; i <= 200; ++i) {
          t.push_back(0.05 * i);
          y.push_back(std::sin(t.back() + k));
        }
        plot.panel(0, col).add_line(t, y, "method " + std::to_string(k) + ", tol 1.5e-12");
      }
    }
  };
  for (const auto& [w, h] : {std::pair{1600, 1200}, std::pair{800, 600}, std::pair{1920, 1080}}) {
    INFO(w << "x" << h);
    Plot2D own(1, 2), shared(1, 2);
    fill(own);
    fill(shared);
    shared.shared_legend = true;
    const Plot2D::Layout a = layout(own, w, h), b = layout(shared, w, h);
    CHECK(a.legend.empty());
    REQUIRE(!b.legend.empty());
    const double m = margin_at(w, h);
    CHECK(b.legend.x0 >= m - 1);
    CHECK(b.legend.x1 <= w - m + 1);
    CHECK(b.legend.y1 <= h - m + 1);
    for (const Plot2D::PanelLayout& p : b.panels) {
      CHECK(p.legend.empty());
      CHECK(b.legend.y0 > p.frame.y1);  // under the frames (and their x labels' row)
      // the data's range padded by 4 %, not grown for a box
      CHECK(p.y_hi == Approx(1.08).epsilon(1e-3));
      CHECK(p.y_lo == Approx(-1.08).epsilon(1e-3));
    }
    // ten rows in one column (a panel's own legend) are over twice as tall
    CHECK(b.legend.height() < 0.5 * a.panels[0].legend.height());
  }
}

TEST_CASE("ref line: a label longer than its panel shrinks to fit inside the frame",
          "[render][annotation]") {
  Plot2D plot(1, 2);
  for (int col = 0; col < 2; ++col) {
    Panel& p = plot.panel(0, col);
    p.add_line({0, 1, 2, 3}, {1e-12, 1e-6, 1, 1});
    p.y.scale = Scale::kLog10;
    p.add_ref_line(2.0, false, "a reference line whose label is longer than a narrow panel");
  }
  for (const auto& [w, h] : {std::pair{800, 600}, std::pair{1600, 1200}}) {
    for (const Plot2D::PanelLayout& l : layout(plot, w, h).panels) {
      INFO(w << "x" << h);
      REQUIRE(l.ref_labels.size() == 1);
      const ScreenRect& b = l.ref_labels[0];
      CHECK(b.x0 >= l.frame.x0);
      CHECK(b.x1 <= l.frame.x1);
      CHECK(b.y0 >= l.frame.y0);
      CHECK(b.y1 <= l.frame.y1);
    }
  }
}

TEST_CASE("ticks: a narrow panel's axis has two labelled ticks at least", "[render][ticks]") {
  // four panels side by side at 800x600: each x axis is about 150 px for 0.1 to 3.1,
  // where a step of 2 would label only "2"
  Plot2D plot(1, 4);
  for (int col = 0; col < 4; ++col) plot.panel(0, col).add_line({0.1, 3.1}, {1e-12, 1e-4});
  for (int col = 0; col < 4; ++col) plot.panel(0, col).y.scale = Scale::kLog10;
  for (const Plot2D::PanelLayout& p : layout(plot, 800, 600).panels) {
    CHECK(p.x_ticks.size() >= 2);
    CHECK(p.y_ticks.size() >= 2);
  }
}

TEST_CASE("annotation: placed texts overlap no data, no legend and no other text",
          "[render][annotation]") {
  // A damped wave with notes crowded about its first peaks, one at the frame's corner, and
  // a legend and a reference-line label competing for the same room.
  Plot2D plot;
  Panel& p = plot.panel();
  std::vector<double> t, y, z;
  for (int i = 0; i <= 300; ++i) {
    t.push_back(0.05 * i);
    y.push_back(std::exp(-0.15 * t.back()) * std::cos(t.back()));
    z.push_back(-0.5 * std::exp(-0.3 * t.back()));
  }
  p.add_line(t, y, "x(t)");
  p.add_line(t, z, "envelope").dash = Dash::kDashed;
  p.add_ref_line(0.0, false, "rest");
  const std::vector<std::pair<double, double>> notes = {{0.0, 1.0},
                                                        {0.5, y[10]},
                                                        {3.14159, -std::exp(-0.15 * 3.14159)},
                                                        {3.6, y[72]},
                                                        {15.0, y[300]}};
  for (const auto& [nx, ny] : notes)
    p.annotate(nx, ny, "note at t = " + std::to_string(nx).substr(0, 4));
  for (const auto& [w, h] : {std::pair{1600, 1200}, std::pair{800, 600}}) {
    CAPTURE(w, h);
    const Plot2D::PanelLayout l = layout(plot, w, h).panels.at(0);
    REQUIRE(l.annotations.size() == notes.size());
    REQUIRE(!l.legend.empty());
    const Mapper m{l};
    const auto pts = drawn_points(p, m);
    for (std::size_t i = 0; i < l.annotations.size(); ++i) {
      const ScreenRect& a = l.annotations[i];
      CAPTURE(i);
      CHECK(l.frame.contains(a));
      CHECK_FALSE(a.overlaps(l.legend));
      for (const ScreenRect& r : l.ref_labels) CHECK_FALSE(a.overlaps(r));
      for (std::size_t j = 0; j < i; ++j) CHECK_FALSE(a.overlaps(l.annotations[j]));
      CHECK(points_inside(pts, a) == 0);
      // No note's text hides any annotated point, its own included, so every arrow shows.
      for (const auto& [nx, ny] : notes) CHECK_FALSE(a.contains(m.x(nx), m.y(ny)));
    }
  }
}

TEST_CASE("label3d: labels at one point spread out, clear of each other, the legend and the title",
          "[render][label3d]") {
  Scene3D scene;
  scene.title = "labels";
  scene.camera.eye = {0, -10, 2};
  // An opaque bar that runs on past the labels' point: text must not sit on it.
  scene.add_box({0, 0, 0}, {2.5, 0.1, 0.1}, Eigen::Matrix3d::Identity(), {kVermillion}, "bar");
  for (const char* t : {"first", "second", "third", "fourth"})
    scene.add_label({1.5, 0, 0}, t, kBlack);
  scene.add_label({-2.5, 0, 0}, "end", kBlack);
  for (const auto& [w, h] : {std::pair{1600, 1200}, std::pair{800, 600}}) {
    CAPTURE(w, h);
    const Scene3D::Layout l = layout(scene, w, h);
    REQUIRE(l.labels.size() == 5);
    const ScreenRect image{0, 0, double(w), double(h)};
    for (std::size_t i = 0; i < l.labels.size(); ++i) {
      CAPTURE(i);
      CHECK(image.contains(l.labels[i]));
      CHECK_FALSE(l.labels[i].overlaps(l.legend));
      CHECK_FALSE(l.labels[i].overlaps(l.title));
      for (std::size_t j = 0; j < i; ++j) CHECK_FALSE(l.labels[i].overlaps(l.labels[j]));
    }
    // None of the bar's shaded vermillion under any label's text: each found a clear place.
    const Image img = draw(scene, w, h);
    long under = 0, bar = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::uint8_t* c = img.at(x, y);
        const bool red = c[0] > c[2] + 80 && c[0] > 100;
        bar += red;
        for (const ScreenRect& r : l.labels) under += red && r.contains(x, y);
      }
    CHECK(bar > 1000);  // the bar is there to be avoided
    CHECK(under == 0);
  }
}

TEST_CASE("overlay: with a text floor a long title wraps onto more lines rather than shrink",
          "[render][overlay]") {
  // A live view's narrow scene (the explorer at 800x600): the figure's text floor is 12 px,
  // and the title keeps to it, each line inside the margins, every word whole.
  const std::string long_title =
      "poinsot: A, B, C = (3, 2, 1) m, M = 3.14159 kg, \\omega_0 = (1, 1, 1) rad/s: the body "
      "turning, L fixed; its energy ellipsoid rolls on the invariable plane: t = 0.00 s";
  for (const int w : {300, 420}) {
    CAPTURE(w);
    Scene3D scene;
    scene.title = long_title;
    scene.min_text_px = 12;
    scene.add_sphere({0, 0, 0}, 1, {kBlue});
    const Scene3D::Layout l = layout(scene, w, 400);
    CHECK(l.title_size >= 12);
    CHECK(l.title_lines >= 3);
    CHECK(l.title.x0 >= 0);
    CHECK(l.title.x1 <= w);
    // Without the floor the same title shrinks onto two lines, below 12 px.
    scene.min_text_px = 0;
    const Scene3D::Layout shrunk = layout(scene, w, 400);
    CHECK(shrunk.title_lines == 2);
    CHECK(shrunk.title_size < 12);
  }
  // A plot's title keeps the same floor.
  Plot2D plot;
  plot.title = long_title;
  plot.min_text_px = 12;
  plot.panel().add_line({0, 1}, {0, 1}, "a line");
  CHECK(layout(plot, 420, 400).title_size >= 12);
}
