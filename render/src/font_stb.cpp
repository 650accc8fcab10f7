// The font face through stb_truetype (Debian's libstb-dev): the WebAssembly page's,
// where FreeType is not to be had. The font file is read whole once; metrics come
// in font units as FreeType gives them unscaled, bitmaps unhinted at pixels per em.
#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#include <stb_truetype.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "font_face.h"

namespace rigid::render::detail {

struct FontFace::Impl {
  std::vector<unsigned char> data;
  stbtt_fontinfo info{};
  double units = 2048;
  int ascent = 0, descent = 0;
};

FontFace::FontFace() : impl_(std::make_unique<Impl>()) {
  std::ifstream file(RIGID_FONT_PATH, std::ios::binary);
  impl_->data.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
  const unsigned char* data = impl_->data.data();
  if (impl_->data.empty() ||
      stbtt_InitFont(&impl_->info, data, stbtt_GetFontOffsetForIndex(data, 0)) == 0)
    throw std::runtime_error("rigid::render: cannot load font " RIGID_FONT_PATH);
  impl_->units = std::round(1.0 / stbtt_ScaleForMappingEmToPixels(&impl_->info, 1.0f));
  int gap = 0;
  stbtt_GetFontVMetrics(&impl_->info, &impl_->ascent, &impl_->descent, &gap);
}

FontFace::~FontFace() = default;

GlyphMetrics FontFace::metrics(char32_t cp) {
  GlyphMetrics g;
  const int index = stbtt_FindGlyphIndex(&impl_->info, static_cast<int>(cp));
  g.index = static_cast<std::uint32_t>(index);
  int advance = 0, bearing = 0;
  stbtt_GetGlyphHMetrics(&impl_->info, index, &advance, &bearing);
  g.advance = advance;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  if (stbtt_GetGlyphBox(&impl_->info, index, &x0, &y0, &x1, &y1) != 0) {
    g.ink_x0 = x0;
    g.ink_x1 = x1;
    g.ink_y0 = y0;
    g.ink_y1 = y1;
  }
  return g;
}

long FontFace::kerning(std::uint32_t left, std::uint32_t right) {
  if (left == 0 || right == 0) return 0;
  return stbtt_GetGlyphKernAdvance(&impl_->info, static_cast<int>(left), static_cast<int>(right));
}

double FontFace::units_per_em() const {
  return impl_->units;
}
double FontFace::ascender() const {
  return impl_->ascent;
}
double FontFace::descender() const {
  return -impl_->descent;
}

GlyphBitmap FontFace::rasterize(std::uint32_t glyph, int size_px) {
  GlyphBitmap b;
  const float scale = static_cast<float>(size_px / impl_->units);
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  const int index = static_cast<int>(glyph);
  stbtt_GetGlyphBitmapBox(&impl_->info, index, scale, scale, &x0, &y0, &x1, &y1);
  b.width = x1 - x0;
  b.height = y1 - y0;
  if (b.width <= 0 || b.height <= 0) return GlyphBitmap{};
  b.left = x0;
  b.top = -y0;  // stb's y runs down from the baseline
  b.coverage.resize(static_cast<std::size_t>(b.width) * b.height);
  stbtt_MakeGlyphBitmap(&impl_->info, b.coverage.data(), b.width, b.height, b.width, scale, scale,
                        index);
  return b;
}

}  // namespace rigid::render::detail
