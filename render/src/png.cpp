// PNG output and input through libpng, written atomically (atomic_file.h).
#include "rigid/render/png.h"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "rigid/render/atomic_file.h"

namespace rigid::render {

namespace {

// Compression chosen by measurement on the labs' figures (zlib levels 1 and 2,
// with and without PNG's row filters, and RLE): zlib 1 without filters was the
// fastest at about the same size, and libpng's default (zlib 6, every filter)
// several times slower; bench/ reports the encode time of every figure. The
// figures are mostly flat colour: deflate's matches find the repeats that a
// filter would, and skipping the filter saves a pass over every row.
constexpr int kZlibLevel = 1;
constexpr int kFilters = PNG_FILTER_NONE;

// libpng reports errors by longjmp; its default handler also prints to stderr,
// which a caller that catches the exception does not want.
void on_error(png_structp png, png_const_charp) {
  png_longjmp(png, 1);
}
void on_warning(png_structp, png_const_charp) {}

// Writes img to an open FILE; returns an error message or nullptr. No C++
// objects with destructors live in this frame because libpng longjmps.
const char* encode(std::FILE* f, const Image& img, const std::uint8_t* const* rows) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, on_error, on_warning);
  if (png == nullptr) return "png_create_write_struct failed";
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    return "png_create_info_struct failed";
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return "libpng failed while encoding";
  }
  png_init_io(png, f);
  png_set_compression_level(png, kZlibLevel);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, kFilters);
  png_set_IHDR(png, info, static_cast<png_uint_32>(img.width), static_cast<png_uint_32>(img.height),
               8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE,
               PNG_FILTER_TYPE_BASE);
  png_write_info(png, info);
  // png_write_image is this loop for an image not interlaced, but it takes rows it may write
  for (int y = 0; y < img.height; ++y) png_write_row(png, rows[y]);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return nullptr;
}

struct Decoded {
  png_uint_32 width = 0, height = 0;
  int color_type = 0, bit_depth = 0;
};

const char* decode_header(std::FILE* f, png_structp png, png_infop info, Decoded& d) {
  if (setjmp(png_jmpbuf(png))) return "not a readable PNG";
  png_init_io(png, f);
  png_read_info(png, info);
  png_get_IHDR(png, info, &d.width, &d.height, &d.bit_depth, &d.color_type, nullptr, nullptr,
               nullptr);
  // Normalise to 8-bit RGB(A).
  if (d.bit_depth == 16) png_set_strip_16(png);
  if (d.color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (d.color_type == PNG_COLOR_TYPE_GRAY || d.color_type == PNG_COLOR_TYPE_GRAY_ALPHA)
    png_set_gray_to_rgb(png);
  if (d.bit_depth < 8) png_set_packing(png);
  png_set_strip_alpha(png);
  png_read_update_info(png, info);
  return nullptr;
}

const char* decode_rows(png_structp png, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return "PNG data is corrupt";
  png_read_image(png, rows);
  png_read_end(png, nullptr);
  return nullptr;
}

}  // namespace

void write_png(const Image& img, const std::string& path) {
  if (img.width <= 0 || img.height <= 0 ||
      img.rgb.size() != static_cast<std::size_t>(img.width) * img.height * 3)
    throw std::invalid_argument("write_png: image buffer does not match its size");
  std::vector<const std::uint8_t*> rows(img.height);
  for (int y = 0; y < img.height; ++y) rows[y] = img.at(0, y);
  write_file_atomically(path, [&](std::FILE* f) {
    if (const char* err = encode(f, img, rows.data())) throw std::runtime_error(err);
  });
}

Image read_png(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (info == nullptr) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    std::fclose(f);
    throw std::runtime_error("cannot read " + path + ": libpng set-up failed");
  }
  Decoded d;
  const char* err = decode_header(f, png, info, d);
  Image img;
  if (err == nullptr) {
    img.width = static_cast<int>(d.width);
    img.height = static_cast<int>(d.height);
    img.rgb.resize(static_cast<std::size_t>(d.width) * d.height * 3);
    std::vector<png_bytep> rows(d.height);
    for (png_uint_32 y = 0; y < d.height; ++y) rows[y] = img.at(0, static_cast<int>(y));
    err = decode_rows(png, rows.data());
  }
  png_destroy_read_struct(&png, &info, nullptr);
  std::fclose(f);
  if (err != nullptr) throw std::runtime_error("cannot read " + path + ": " + err);
  return img;
}

}  // namespace rigid::render
