// The memory drawing takes, as a model of the renderer's measured peak: a base (the
// program, the GL driver and its threads, the fonts) and a cost per pixel of the
// image (multisampled colour and depth, the resolved image, the one read back, the
// PNG encoded while the next figure draws; for a film, the encoder's frames too).
//
// Measured as peak resident memory (/usr/bin/time's %M) of a lab drawing its figures
// on Mesa llvmpipe: 0.19 GB at 1600x1200, 0.29 GB at 2048x2048, 0.88 GB at 4096x4096,
// 3.18 GB at 8192x8192, which is 117 MiB and 47 bytes a pixel; a film at 1920x1080
// and 3840x2160 (H.264 above WebP) is 125 bytes a pixel over the same base. The
// model rounds both up, so it bounds the measured peaks (a test holds it to that);
// a GPU's driver keeps its buffers in the GPU's memory and needs less.
#pragma once

#include <cstdint>

namespace rigid::render {

inline constexpr std::uint64_t kDrawingBaseBytes = std::uint64_t{128} << 20;
inline constexpr std::uint64_t kFigureBytesPerPixel = 48;
inline constexpr std::uint64_t kFilmBytesPerPixel = 128;

/// The memory a program drawing figures of `width` x `height` pixels takes at its peak.
constexpr std::uint64_t figure_peak_bytes(int width, int height) {
  return kDrawingBaseBytes + kFigureBytesPerPixel * static_cast<std::uint64_t>(width) *
                                 static_cast<std::uint64_t>(height);
}

/// The memory a program writing a film of `width` x `height` frames takes at its peak.
constexpr std::uint64_t film_peak_bytes(int width, int height) {
  return kDrawingBaseBytes + kFilmBytesPerPixel * static_cast<std::uint64_t>(width) *
                                 static_cast<std::uint64_t>(height);
}

}  // namespace rigid::render
