// The golden-image comparison: whether two drawings of one figure differ in what
// a reader would see (figure_test.cpp's goldens, the explorer's figures).
#pragma once

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "rigid/render/image.h"

namespace rigid::test {

// What a reader sees changed. A pixel differs when no pixel within 2 px of it in
// the other image is within kChannelThreshold of it (both ways round): a curve that
// moves by a pixel or two, as another CPU's rounding of roundoff-level data may
// move it, is no change; a replaced glyph, a moved label, a recoloured swatch or an
// erased marker is. The figure fails on any 8-connected cluster of differing pixels
// larger than kMaxCluster, or on a mean difference above kMaxMeanDiff (a
// background turned faint grey moves every pixel a little). OSMesa and EGL, one
// llvmpipe thread or many, 128-bit or native vectors all draw these figures byte
// for byte alike here (measured: difference 0).
inline constexpr int kChannelThreshold = 40;
inline constexpr long kMaxCluster = 12;
inline constexpr double kMaxMeanDiff = 0.5;
inline constexpr int kReach = 2;

// Pixels of `a` that no pixel within kReach of the same place in `b` matches.
inline std::vector<std::uint8_t> unmatched(const rigid::render::Image& a,
                                           const rigid::render::Image& b) {
  std::vector<std::uint8_t> out(static_cast<std::size_t>(a.width) * a.height, 0);
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const std::uint8_t* p = a.at(x, y);
      bool matched = false;
      for (int dy = -kReach; dy <= kReach && !matched; ++dy) {
        for (int dx = -kReach; dx <= kReach && !matched; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= b.width || ny >= b.height) continue;
          const std::uint8_t* q = b.at(nx, ny);
          matched = std::abs(p[0] - q[0]) <= kChannelThreshold &&
                    std::abs(p[1] - q[1]) <= kChannelThreshold &&
                    std::abs(p[2] - q[2]) <= kChannelThreshold;
        }
      }
      out[static_cast<std::size_t>(y) * a.width + x] = matched ? 0 : 1;
    }
  }
  return out;
}

// The verdict of one comparison: empty when the figure matches.
inline std::string mismatch(const rigid::render::Image& actual,
                            const rigid::render::Image& expected) {
  std::string why;
  for (const auto& mark : {unmatched(actual, expected), unmatched(expected, actual)}) {
    const long cluster = rigid::render::largest_cluster(mark, actual.width);
    if (cluster > kMaxCluster) why += " a changed region of " + std::to_string(cluster) + " px;";
  }
  const auto d = rigid::render::compare_images(actual, expected, kChannelThreshold);
  if (d.mean_diff > kMaxMeanDiff) why += " mean difference " + std::to_string(d.mean_diff) + ";";
  return why;
}

}  // namespace rigid::test
