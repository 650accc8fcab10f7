// Tests of text measurement and the markup.
#include "rigid/render/text.h"

#include <catch2/catch.hpp>

using namespace rigid::render;

TEST_CASE("text: extent of digits matches DejaVu Sans metrics", "[render][text]") {
  // DejaVu Sans: 2048 units per em, every digit advances 1303 units,
  // ascender 1901, descender 483. Unhinted, so exact up to rounding.
  const TextExtent e = measure_text("0123456789", 20);
  CHECK(e.width == Approx(10 * 1303.0 / 2048 * 20).margin(0.5));
  CHECK(e.ascent == Approx(1901.0 / 2048 * 20).margin(0.5));
  CHECK(e.descent == Approx(483.0 / 2048 * 20).margin(0.5));
}

TEST_CASE("text: extent grows linearly with font size", "[render][text]") {
  const char* s = "Energy drift |\\Delta E| / E";
  const double w10 = measure_text(s, 10).width, w20 = measure_text(s, 20).width,
               w40 = measure_text(s, 40).width;
  CHECK(w20 == Approx(2 * w10).margin(1.0));
  CHECK(w40 == Approx(2 * w20).margin(1.0));
  CHECK(measure_text(s, 40).height() == Approx(2 * measure_text(s, 20).height()).margin(1.0));
}

TEST_CASE("text: markup turns names into Greek and scripts into smaller glyphs", "[render][text]") {
  CHECK(plain_text("\\omega_1 (rad/s)") == "\u03c9\u2081 (rad/s)");
  CHECK(plain_text("10^{-6}") == "10\u207b\u2076");
  CHECK(plain_text("\\dot{\\theta}") == "\u03b8\u0307");
  CHECK(plain_text("m a^2") == "m a\u00b2");
  // A subscript is narrower than the same character at full size.
  CHECK(measure_text("I_3", 30).width < measure_text("I3", 30).width);
  // Superscripts raise the ascent: strictly, by a good part of the raised glyph.
  CHECK(measure_text("a^2", 30).ascent > measure_text("a2", 30).ascent + 3.0);
  // U+0307 after a letter is the same as \dot.
  CHECK(measure_text("\u03b8\u0307", 30).width == Approx(measure_text("\\dot\\theta", 30).width));
}
