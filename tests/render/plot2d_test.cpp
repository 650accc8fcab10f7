// Tests of 2D plots by their pixels.
#include "rigid/render/plot2d.h"

#include <algorithm>
#include <catch2/catch.hpp>

#include "rigid/render/draw.h"
#include "rigid/render/palette.h"
#include "rigid/render/text.h"

using namespace rigid::render;

namespace {

bool near(const std::uint8_t* p, Color c, int tol = 2) {
  const int r = static_cast<int>(c.r * 255 + 0.5), g = static_cast<int>(c.g * 255 + 0.5),
            b = static_cast<int>(c.b * 255 + 0.5);
  return std::abs(p[0] - r) <= tol && std::abs(p[1] - g) <= tol && std::abs(p[2] - b) <= tol;
}

// Bounding box of pixels that are not white.
struct Ink {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};
Ink ink(const Image& img) {
  Ink k;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = img.at(x, y);
      if (p[0] < 200 || p[1] < 200 || p[2] < 200) {
        k.x0 = std::min(k.x0, x), k.x1 = std::max(k.x1, x);
        k.y0 = std::min(k.y0, y), k.y1 = std::max(k.y1, y);
      }
    }
  return k;
}

}  // namespace

TEST_CASE("plot2d: a filled span has its colour and the background is white", "[render][plot2d]") {
  Plot2D plot;
  Panel& p = plot.panel();
  p.x.min = 0, p.x.max = 1, p.y.min = 0, p.y.max = 1;
  Span& s = p.add_span(0.25, 0.75);
  s.color = kBlue;
  s.opacity = 1.0f;
  p.x.grid = p.y.grid = false;
  const Image img = draw(plot, 800, 600);
  REQUIRE(img.width == 800);
  REQUIRE(img.height == 600);
  // The plot area spans most of the image; its middle is inside the span.
  CHECK(near(img.at(400, 280), kBlue));
  CHECK(near(img.at(3, 3), kWhite, 0));
  CHECK(near(img.at(796, 596), kWhite, 0));
}

TEST_CASE("plot2d: a thick line has its colour along its centre", "[render][plot2d]") {
  Plot2D plot;
  Panel& p = plot.panel();
  p.x.min = 0, p.x.max = 1, p.y.min = 0, p.y.max = 1;
  p.x.grid = p.y.grid = false;
  Series& s = p.add_line({0, 1}, {0.5, 0.5});
  s.color = kVermillion;
  s.width = 12;
  const Image img = draw(plot, 800, 600);
  // Find the line in the middle column: the rows of vermillion pixels.
  int first = -1, last = -1;
  for (int y = 0; y < img.height; ++y)
    if (near(img.at(400, y), kVermillion)) {
      if (first < 0) first = y;
      last = y;
    }
  REQUIRE(first >= 0);
  // 12 reference px at half scale is 6 px (± MSAA edge pixels).
  CHECK(last - first + 1 >= 5);
  CHECK(last - first + 1 <= 7);
}

TEST_CASE("plot2d: drawn text has about its measured extent", "[render][plot2d]") {
  Plot2D plot;
  Panel& p = plot.panel();
  p.x.min = 0, p.x.max = 1, p.y.min = 0, p.y.max = 1;
  p.x.grid = p.y.grid = false;
  Annotation& a = p.annotate(0.5, 0.5, "0123456789");
  a.arrow = false;
  const Image img = draw(plot, 1600, 1200);
  // Blank out everything but the annotation's box (a few px around), then measure the ink.
  const ScreenRect box = layout(plot, 1600, 1200).panels.at(0).annotations.at(0);
  const double w = measure_text("0123456789", 27).width;  // annotations use 27 px at 1600×1200
  CHECK(box.width() == Approx(w).margin(0.5));
  Image crop = img;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (!box.grown(4).contains(x, y)) std::fill_n(crop.at(x, y), 3, 255);
  const Ink k = ink(crop);
  REQUIRE(k.x1 > k.x0);
  // Ink is the advance width less the side bearings of '0' and '9' (a few px).
  CHECK(k.x1 - k.x0 + 1 <= w + 1);
  CHECK(k.x1 - k.x0 + 1 >= w - 6);
  // The text's ink lies in its box: placement and drawing agree.
  CHECK(k.x0 >= box.x0 - 1);
  CHECK(k.x1 <= box.x1 + 1);
}

TEST_CASE("plot2d: nothing is drawn outside the image at 800x600 with long labels",
          "[render][plot2d]") {
  Plot2D plot(2, 2);
  plot.title =
      "A long title that has to shrink to fit: \\omega_1, \\omega_2, \\omega_3, I_1 < I_2 < I_3";
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) {
      Panel& p = plot.panel(r, c);
      p.x.label = "time t (s)";
      p.y.label = "angular velocity \\omega_1 (rad/s)";
      p.add_line({0, 1e4}, {-12345.678, 98765.4321}, "series");
    }
  const Image img = draw(plot, 800, 600);
  // The outermost row and column stay white: no text reaches the border.
  int touched = 0;
  for (int x = 0; x < img.width; ++x)
    touched += !near(img.at(x, 0), kWhite, 0) + !near(img.at(x, img.height - 1), kWhite, 0);
  for (int y = 0; y < img.height; ++y)
    touched += !near(img.at(0, y), kWhite, 0) + !near(img.at(img.width - 1, y), kWhite, 0);
  CHECK(touched == 0);
}
