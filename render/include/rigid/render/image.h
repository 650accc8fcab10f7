// An 8-bit RGB image in memory, rows top to bottom, as every figure is
// returned before it is written to PNG.
#pragma once

#include <cstdint>
#include <vector>

namespace rigid::render {

/// Pixels of a rendered figure: width*height RGB triplets, first row at the top.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;

  /// Pointer to the three channels of pixel (x, y), y counted from the top.
  std::uint8_t* at(int x, int y) { return &rgb[3 * (static_cast<std::size_t>(y) * width + x)]; }
  /// Read-only access to pixel (x, y), y counted from the top.
  const std::uint8_t* at(int x, int y) const {
    return &rgb[3 * (static_cast<std::size_t>(y) * width + x)];
  }
};

/// Where one figure's time went, in seconds of wall time (draw() and save_png()
/// of draw.h fill it when given one; the phases are split by waiting for the GL
/// to finish each, which only timed figures do).
struct FigureTiming {
  double setup = 0;    ///< binding and clearing the drawing buffer (made by the first figure)
  double layout = 0;   ///< placing the title, legend, labels and the fit (CPU)
  double draw = 0;     ///< drawing, until the rasteriser has finished
  double resolve = 0;  ///< averaging the samples of each pixel and reading the image back
  double encode = 0;   ///< PNG encoding and the atomic write (save_png() only)
  double total() const { return setup + layout + draw + resolve + encode; }
};

/// Statistics of comparing two images of the same size channel by channel.
struct ImageDiff {
  long differing_pixels = 0;  ///< pixels with some channel differing by more than the threshold
  double differing_fraction = 0;
  int max_channel_diff = 0;
  /// The largest 8-connected cluster of differing pixels: a changed glyph, marker or
  /// swatch is tens of pixels, where antialiasing jitter is isolated pixels.
  long largest_cluster = 0;
  /// The mean over pixels of the largest channel difference: a background turned a
  /// faint grey moves every pixel a little.
  double mean_diff = 0;
};

/// Compares a and b; throws std::invalid_argument if their sizes differ.
ImageDiff compare_images(const Image& a, const Image& b, int threshold = 16);

/// The largest 8-connected cluster of the nonzero entries of `mask`, a
/// width-wide row-major grid of pixels (0: unmarked).
long largest_cluster(const std::vector<std::uint8_t>& mask, int width);

/// An image that shows where a and b differ (grey copy of a, differences in red).
Image difference_image(const Image& a, const Image& b, int threshold = 16);

}  // namespace rigid::render
