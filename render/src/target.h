// Internal: the framebuffer a figure is drawn into. With MSAA it is a
// multisampled texture resolved by a shader of our own (averaging the samples
// of each pixel); without, a 2×-size FBO filtered down by glBlitFramebuffer
// (supersampling). The shader, not glBlitFramebuffer, resolves the samples
// because llvmpipe builds its blit shaders afresh in every process, before the
// first figure, while ours is found in Mesa's shader cache like the other
// programs (bench/'s figure timings show the difference). Reused between
// figures of the same size: the
// colour buffer is shared by a colour-only FBO (2D plots) and a colour+depth
// FBO (3D scenes) whose depth buffer is made only when a scene first needs it,
// so a plot after a scene reallocates nothing and a 2D-only process never
// allocates a depth buffer. (Fresh buffers are costly on llvmpipe: every page
// of a 30 MB multisampled buffer is faulted in on first touch.)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gl.h"
#include "rigid/render/image.h"
#include "rigid/render/palette.h"

namespace rigid::render::detail {

class Target {
 public:
  /// Makes the context if needed, binds a width × height drawing buffer (with depth if asked) and
  /// clears it.
  void begin(int width, int height, bool depth, Color clear);
  /// Resolves the samples and reads the image back (rows top to bottom).
  Image finish();
  /// Takes back a finished image's pixels for the next finish() to fill: a 1600x1200
  /// image is 1400 fresh pages, each faulted in on first touch, when allocated anew.
  void recycle(std::vector<std::uint8_t>&& pixels);
  /// Physical pixels per logical pixel (2 with supersampling, else 1).
  int scale() const { return scale_; }

 private:
  void release();
  void add_depth();
  int width_ = 0, height_ = 0, scale_ = 1, samples_ = 0;
  bool depth_ = false;
  void attach_color();
  void resolve();
  GLuint color_fbo_ = 0, depth_fbo_ = 0, depth_rb_ = 0;
  GLuint color_tex_ = 0;  // multisampled colour (MSAA)
  GLuint color_rb_ = 0;   // 2×-size colour (supersampling)
  GLuint resolve_fbo_ = 0, resolve_rb_ = 0;
  std::vector<std::uint8_t> spare_;
};

/// The process's drawing target (valid after context()).
Target& target();

/// Times the phases of one figure into a FigureTiming (a no-op without one):
/// lap(&FigureTiming::draw, true) waits for the GL to finish, then adds the time
/// since the last lap to that phase.
class PhaseClock {
 public:
  explicit PhaseClock(FigureTiming* timing);
  void lap(double FigureTiming::*phase, bool wait_for_gl = false);

 private:
  FigureTiming* timing_;
  double last_ = 0;
};

/// Writes img as a PNG (png.h), its time as timing's encode phase, then gives its
/// pixels back to the target.
void save_timed(Image img, const std::string& path, FigureTiming* timing);

}  // namespace rigid::render::detail
