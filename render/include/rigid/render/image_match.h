// Whether two drawings of one figure differ in what a reader would see: the golden
// tests' verdict, and the main job's (a figure regenerated within it is not replaced,
// so figures/ stays as committed unless a figure really changed).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "rigid/render/image.h"

namespace rigid::render {

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

/// How much two drawings of one figure may differ and still be the same figure.
struct MatchRule {
  long max_cluster;      ///< the largest 8-connected cluster of differing pixels allowed
  double max_mean_diff;  ///< the largest mean difference allowed
  /// Differing pixels in runs one pixel thin (no differing neighbour across the run)
  /// do not count: the edge of a line, antialiased otherwise.
  bool ignore_hairlines = false;
};
/// The same renderer (the goldens, on any machine, through any GL backend).
inline constexpr MatchRule kSameRenderer{kMaxCluster, kMaxMeanDiff};
/// Another rasteriser of the same drawing: an SVG or PDF figure rendered by librsvg or
/// poppler against the PNG. Their antialiasing differs everywhere a little (text is
/// not darkened as the PNG's is; where lines overlap exactly, the lower ones' colours
/// show at the upper one's edges, as cairo composites each in turn): measured on every
/// lab's figures, a mean difference of 0 to 2.3, clusters up to 9 px, and along such
/// shared edges runs one pixel thin of up to 31 px. A moved label, a recoloured swatch,
/// an erased marker or a grey background is still more than these.
inline constexpr MatchRule kAcrossRasterisers{kMaxCluster, 3.0, true};

// Whether p is, within kChannelThreshold, a blend of two pixels of `b` in the 3x3 about
// (x, y): what an antialiased edge moved by a fraction of a pixel (another CPU's
// roundoff-level data) draws. Its pixels change which are full colour and which partial
// by more than the threshold, and no single neighbour need match; a moved glyph, a
// recoloured swatch or an erased marker leaves colours no two neighbours blend to.
inline bool blend_of_neighbours(const std::uint8_t* p, const Image& b, int x, int y) {
  const std::uint8_t* q[9];
  int n = 0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx >= 0 && ny >= 0 && nx < b.width && ny < b.height) q[n++] = b.at(nx, ny);
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      // the point of the segment q_i q_j nearest p, then its largest channel difference
      double along = 0, length = 0;
      for (int c = 0; c < 3; ++c) {
        const double d = q[j][c] - q[i][c];
        along += (p[c] - q[i][c]) * d, length += d * d;
      }
      const double t = length > 0 ? std::min(1.0, std::max(0.0, along / length)) : 0.0;
      bool near = true;
      for (int c = 0; c < 3 && near; ++c) {
        near = std::abs(p[c] - (q[i][c] + t * (q[j][c] - q[i][c]))) <= kChannelThreshold;
      }
      if (near) return true;
    }
  }
  return false;
}

// Pixels of `a` that no pixel within kReach of the same place in `b` matches, nor a blend
// of two beside it.
inline std::vector<std::uint8_t> unmatched(const Image& a, const Image& b) {
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
      if (!matched) matched = blend_of_neighbours(p, b, x, y);
      out[static_cast<std::size_t>(y) * a.width + x] = matched ? 0 : 1;
    }
  }
  return out;
}

// The marks of `mask` (width wide) with a marked neighbour both across and along: runs
// one pixel thin dropped.
inline std::vector<std::uint8_t> without_hairlines(const std::vector<std::uint8_t>& mask,
                                                   int width) {
  const int height = static_cast<int>(mask.size() / static_cast<std::size_t>(width));
  auto at = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < width && y < height &&
           mask[static_cast<std::size_t>(y) * width + x] != 0;
  };
  std::vector<std::uint8_t> out(mask.size(), 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      out[static_cast<std::size_t>(y) * width + x] =
          at(x, y) && (at(x - 1, y) || at(x + 1, y)) && (at(x, y - 1) || at(x, y + 1));
  return out;
}

// The verdict of one comparison: empty when the figure matches.
inline std::string mismatch(const Image& actual, const Image& expected,
                            const MatchRule& rule = kSameRenderer) {
  std::string why;
  for (const auto& mark : {unmatched(actual, expected), unmatched(expected, actual)}) {
    const long cluster = largest_cluster(
        rule.ignore_hairlines ? without_hairlines(mark, actual.width) : mark, actual.width);
    if (cluster > rule.max_cluster)
      why += " a changed region of " + std::to_string(cluster) + " px;";
  }
  const auto d = compare_images(actual, expected, kChannelThreshold);
  if (d.mean_diff > rule.max_mean_diff)
    why += " mean difference " + std::to_string(d.mean_diff) + ";";
  return why;
}

}  // namespace rigid::render
