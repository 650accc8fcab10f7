// Image comparison for tests and golden figures.
#include "rigid/render/image.h"

#include <vector>

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
  std::vector<std::uint8_t> differs(n, 0);
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int d = pixel_diff(a, b, i);
    r.max_channel_diff = std::max(r.max_channel_diff, d);
    sum += d;
    if (d > threshold) {
      ++r.differing_pixels;
      differs[i] = 1;
    }
  }
  r.differing_fraction = n ? double(r.differing_pixels) / double(n) : 0.0;
  r.mean_diff = n ? sum / double(n) : 0.0;
  // Clusters by flood fill over the 8 neighbours (an explicit stack: no recursion).
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < n; ++start) {
    if (differs[start] != 1) continue;
    long size = 0;
    differs[start] = 2;
    stack.push_back(start);
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      ++size;
      const int x = static_cast<int>(i % a.width), y = static_cast<int>(i / a.width);
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= a.width || ny >= a.height) continue;
          const std::size_t j = static_cast<std::size_t>(ny) * a.width + nx;
          if (differs[j] == 1) {
            differs[j] = 2;
            stack.push_back(j);
          }
        }
      }
    }
    r.largest_cluster = std::max(r.largest_cluster, size);
  }
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
