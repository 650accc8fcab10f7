// Internal: the font face text.cpp lays out and rasterises with, in font units
// (size independent) and as 8-bit coverage. Two builds of it: FreeType
// (font_freetype.cpp, every native program) and stb_truetype (font_stb.cpp, the
// WebAssembly page, where FreeType is not to be had). Both read DejaVu Sans
// unhinted, so a string lays out to the same advances in each.
#pragma once

#include <cstdint>
#include <memory>

#include "font.h"

namespace rigid::render::detail {

/// A glyph's index, advance and ink box, in font units.
struct GlyphMetrics {
  std::uint32_t index = 0;
  long advance = 0;
  long ink_x0 = 0, ink_x1 = 0;
  long ink_y0 = 0, ink_y1 = 0;
};

class FontFace {
 public:
  /// Opens the font at RIGID_FONT_PATH; throws std::runtime_error naming it if it cannot.
  FontFace();
  ~FontFace();
  FontFace(const FontFace&) = delete;
  FontFace& operator=(const FontFace&) = delete;

  /// Character cp's glyph (index 0 and no ink where the font has none).
  GlyphMetrics metrics(char32_t cp);
  /// The pair's kerning, font units (0 where the font has none).
  long kerning(std::uint32_t left, std::uint32_t right);
  double units_per_em() const;
  double ascender() const;   ///< font units, above the baseline
  double descender() const;  ///< font units, below the baseline (positive)
  /// The glyph at size_px pixels per em, unhinted and antialiased.
  GlyphBitmap rasterize(std::uint32_t glyph, int size_px);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rigid::render::detail
