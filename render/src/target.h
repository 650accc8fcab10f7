// Internal: the framebuffer a figure is drawn into. With MSAA it is a
// multisampled texture resolved by a shader of our own (averaging the samples
// of each pixel); in an OpenGL ES 3.0 context (which has no multisampled
// textures) a multisampled renderbuffer resolved by glBlitFramebuffer; without
// MSAA, a 2×-size FBO filtered down by glBlitFramebuffer (supersampling). The
// resolved image is a texture, which a live view shows as it is. The shader, not glBlitFramebuffer,
// resolves the samples because llvmpipe builds its blit shaders afresh in every process, before the
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
#include "rigid/render/draw.h"
#include "rigid/render/image.h"
#include "rigid/render/palette.h"
#include "rigid/render/plot2d.h"
#include "rigid/render/scene3d.h"

namespace rigid::render::detail {

class Target {
 public:
  Target() = default;
  ~Target();
  Target(const Target&) = delete;
  Target& operator=(const Target&) = delete;
  /// Makes the context if needed, binds a width × height drawing buffer (with depth if asked) and
  /// clears it.
  void begin(int width, int height, bool depth, Color clear);
  /// Resolves the samples into the texture (texture()).
  void resolve();
  /// Resolves the samples and reads the image back (rows top to bottom).
  Image finish();
  /// Reads the resolved image back (rows top to bottom).
  Image read();
  /// The resolved image as a GL texture (RGBA8, rows bottom-up), valid after resolve().
  GLuint texture() const { return resolve_tex_; }
  int width() const { return width_; }
  int height() const { return height_; }
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
  GLuint color_fbo_ = 0, depth_fbo_ = 0, depth_rb_ = 0;
  GLuint color_tex_ = 0;  // multisampled colour (MSAA)
  GLuint color_rb_ = 0;   // 2×-size colour (supersampling), or multisampled (OpenGL ES)
  GLuint resolve_fbo_ = 0, resolve_tex_ = 0;
  std::vector<std::uint8_t> spare_;
};

/// The drawing target figures go to: the process's own, or a live view's while it draws
/// (valid after context()).
Target& target();

/// Makes `t` the drawing target until this goes out of scope.
class UseTarget {
 public:
  explicit UseTarget(Target& t);
  ~UseTarget();
  UseTarget(const UseTarget&) = delete;
  UseTarget& operator=(const UseTarget&) = delete;

 private:
  Target* previous_;
};

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

/// Draws a figure into target() at width × height, unresolved (draw.h's draw() resolves
/// and reads it back; a live view shows the resolved texture).
Plot2D::Layout render_into_target(const Plot2D& plot, int width, int height, PhaseClock& clock);
/// Each gives back where its title, legend and labels or panels went.
Scene3D::Layout render_into_target(const Scene3D& scene, int width, int height, PhaseClock& clock);

/// Draws the plot with cairo's rasteriser into an image (vector.cpp): no GL buffers,
/// no multisample resolve, no read-back.
Image draw_plot_on_cpu(const Plot2D& plot, int width, int height, FigureTiming* timing);

/// Writes img as a PNG (png.h), its time as timing's encode phase, then gives its
/// pixels back to the target.
void save_timed(Image img, const std::string& path, FigureTiming* timing);

}  // namespace rigid::render::detail
