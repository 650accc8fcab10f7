// Image comparison for tests and golden figures.
#include "rigid/render/image.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace rigid::render {

namespace {

void check_sizes(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("compare_images: sizes differ");
}

int pixel_diff(const Image& a, const Image& b, std::size_t i) {
  int d = 0;
  for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.rgb[3 * i + c]) - int(b.rgb[3 * i + c])));
  return d;
}

}  // namespace

ImageDiff compare_images(const Image& a, const Image& b, int threshold) {
  check_sizes(a, b);
  ImageDiff r;
  const std::size_t n = static_cast<std::size_t>(a.width) * a.height;
  for (std::size_t i = 0; i < n; ++i) {
    const int d = pixel_diff(a, b, i);
    r.max_channel_diff = std::max(r.max_channel_diff, d);
    if (d > threshold) ++r.differing_pixels;
  }
  r.differing_fraction = n ? double(r.differing_pixels) / double(n) : 0.0;
  return r;
}

Image difference_image(const Image& a, const Image& b, int threshold) {
  check_sizes(a, b);
  Image out = a;
  const std::size_t n = static_cast<std::size_t>(a.width) * a.height;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint8_t* p = &out.rgb[3 * i];
    if (pixel_diff(a, b, i) > threshold) {
      p[0] = 255, p[1] = 0, p[2] = 0;
    } else {
      // Faded grey copy of a so the differences stand out.
      const int g = (p[0] + p[1] + p[2]) / 3;
      p[0] = p[1] = p[2] = static_cast<std::uint8_t>(200 + g * 55 / 255);
    }
  }
  return out;
}

}  // namespace rigid::render
