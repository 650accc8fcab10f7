// Image comparison for tests and golden figures.
#include "rigid/render/image.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace rigid::render {

namespace {

void check_sizes(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("compare_images: sizes differ");
}

int pixel_diff(const Image& a, const Image& b, std::size_t i) {
  int d = 0;
  for (int c = 0; c < 3; ++c)
    d = std::max(d, std::abs(int(a.rgb[3 * i + c]) - int(b.rgb[3 * i + c])));
  return d;
}

}  // namespace

long largest_cluster(const std::vector<std::uint8_t>& mask, int width) {
  // Flood fill over the 8 neighbours, an explicit stack (no recursion); 2 marks visited.
  std::vector<std::uint8_t> mark(mask.size());
  for (std::size_t i = 0; i < mask.size(); ++i) mark[i] = mask[i] != 0;
  long best = 0;
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < mark.size(); ++start) {
    if (mark[start] != 1) continue;
    long size = 0;
    mark[start] = 2;
    stack.push_back(start);
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      ++size;
      const long x = static_cast<long>(i % width), y = static_cast<long>(i / width);
      for (long dy = -1; dy <= 1; ++dy) {
        for (long dx = -1; dx <= 1; ++dx) {
          const long nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= width) continue;
          const std::size_t j = static_cast<std::size_t>(ny) * width + static_cast<std::size_t>(nx);
          if (j < mark.size() && mark[j] == 1) {
            mark[j] = 2;
            stack.push_back(j);
          }
        }
      }
    }
    best = std::max(best, size);
  }
  return best;
}

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
  r.largest_cluster = largest_cluster(differs, a.width);
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
