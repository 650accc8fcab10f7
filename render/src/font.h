// Internal: the process's FreeType face (DejaVu Sans, unhinted), the markup
// parser, and glyph bitmaps for the atlas.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "rigid/render/text.h"

namespace rigid::render::detail {

/// One glyph placed by layout: pen position of its origin relative to the text's origin (baseline,
/// y up).
struct PlacedGlyph {
  std::uint32_t glyph = 0;  ///< FreeType glyph index
  char32_t code = 0;        ///< the character it draws
  int size_px = 0;          ///< pixel size it is rasterised at
  double x = 0, y = 0;
};

/// A laid-out string: glyphs and the extent they occupy.
struct TextLayout {
  std::vector<PlacedGlyph> glyphs;
  TextExtent extent;
};

/// Appends a character to a UTF-8 string.
void append_utf8(std::string& out, char32_t cp);

/// Parses markup and places its glyphs at a font size (rounded to whole pixels).
TextLayout layout_text(std::string_view markup, double size_px);

/// A rasterised glyph: 8-bit coverage, with its offset from the pen (left, top; y up).
struct GlyphBitmap {
  int width = 0, height = 0, left = 0, top = 0;
  std::vector<std::uint8_t> coverage;
};

/// Rasterises glyph index at a pixel size (unhinted, antialiased).
GlyphBitmap rasterize_glyph(std::uint32_t glyph, int size_px);

}  // namespace rigid::render::detail
