// The font face through FreeType: what every native program draws text with.
#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <stdexcept>

#include "font_face.h"

namespace rigid::render::detail {

struct FontFace::Impl {
  FT_Library lib = nullptr;
  FT_Face face = nullptr;
};

FontFace::FontFace() : impl_(std::make_unique<Impl>()) {
  if (FT_Init_FreeType(&impl_->lib) != 0)
    throw std::runtime_error("rigid::render: FreeType init failed");
  if (FT_New_Face(impl_->lib, RIGID_FONT_PATH, 0, &impl_->face) != 0)
    throw std::runtime_error("rigid::render: cannot load font " RIGID_FONT_PATH);
}

FontFace::~FontFace() {
  if (impl_->face != nullptr) FT_Done_Face(impl_->face);
  if (impl_->lib != nullptr) FT_Done_FreeType(impl_->lib);
}

GlyphMetrics FontFace::metrics(char32_t cp) {
  FT_Face face = impl_->face;
  GlyphMetrics g;
  g.index = FT_Get_Char_Index(face, cp);
  if (FT_Load_Glyph(face, g.index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0) {
    const FT_Glyph_Metrics& m = face->glyph->metrics;
    g.advance = face->glyph->advance.x;
    g.ink_x0 = m.horiBearingX;
    g.ink_x1 = m.horiBearingX + m.width;
    g.ink_y1 = m.horiBearingY;
    g.ink_y0 = m.horiBearingY - m.height;
  }
  return g;
}

long FontFace::kerning(std::uint32_t left, std::uint32_t right) {
  if (!FT_HAS_KERNING(impl_->face) || left == 0 || right == 0) return 0;
  FT_Vector k{0, 0};
  FT_Get_Kerning(impl_->face, left, right, FT_KERNING_UNSCALED, &k);
  return k.x;
}

double FontFace::units_per_em() const {
  return impl_->face->units_per_EM;
}
double FontFace::ascender() const {
  return impl_->face->ascender;
}
double FontFace::descender() const {
  return -impl_->face->descender;
}

GlyphBitmap FontFace::rasterize(std::uint32_t glyph, int size_px) {
  FT_Face face = impl_->face;
  GlyphBitmap b;
  FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(size_px));
  if (FT_Load_Glyph(face, glyph, FT_LOAD_NO_HINTING | FT_LOAD_RENDER) != 0) return b;
  const FT_Bitmap& bm = face->glyph->bitmap;
  b.width = static_cast<int>(bm.width);
  b.height = static_cast<int>(bm.rows);
  b.left = face->glyph->bitmap_left;
  b.top = face->glyph->bitmap_top;
  b.coverage.resize(static_cast<std::size_t>(b.width) * b.height);
  for (int y = 0; y < b.height; ++y)
    std::copy_n(bm.buffer + y * bm.pitch, b.width, b.coverage.data() + y * b.width);
  return b;
}

}  // namespace rigid::render::detail
