// Internal: FBO set-up, MSAA resolve and read-back.
#include "target.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "rigid/render/context.h"

namespace rigid::render::detail {

Target& target() {
  static Target t;
  return t;
}

void Target::release() {
  GLuint fbos[] = {color_fbo_, depth_fbo_, resolve_fbo_};
  GLuint rbs[] = {color_rb_, depth_rb_, resolve_rb_};
  gl.DeleteFramebuffers(3, fbos);
  gl.DeleteRenderbuffers(3, rbs);
  color_fbo_ = depth_fbo_ = resolve_fbo_ = color_rb_ = depth_rb_ = resolve_rb_ = 0;
}

namespace {

// Storage for the bound renderbuffer: multisampled, or plain for supersampling.
void storage(int samples, GLenum format, int w, int h) {
  if (samples >= 2)
    gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, w, h);
  else
    gl.RenderbufferStorage(GL_RENDERBUFFER, format, w, h);
}

void check_complete(const char* what) {
  if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error(std::string("rigid::render: ") + what + " framebuffer is incomplete");
}

}  // namespace

void Target::add_depth() {
  const int pw = width_ * scale_, ph = height_ * scale_;
  gl.GenRenderbuffers(1, &depth_rb_);
  gl.BindRenderbuffer(GL_RENDERBUFFER, depth_rb_);
  storage(scale_ == 1 ? samples_ : 0, GL_DEPTH_COMPONENT24, pw, ph);
  gl.GenFramebuffers(1, &depth_fbo_);
  gl.BindFramebuffer(GL_FRAMEBUFFER, depth_fbo_);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_rb_);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb_);
  check_complete("drawing (with depth)");
}

void Target::begin(int width, int height, bool depth, Color clear) {
  if (width < 1 || height < 1 || width > 8192 || height > 8192)
    throw std::invalid_argument("rigid::render: image size " + std::to_string(width) + "x" +
                                std::to_string(height) + " is outside 1..8192");
  const ContextInfo& info = context();
  if (color_fbo_ == 0 || width != width_ || height != height_) {
    if (color_fbo_ != 0) release();
    width_ = width;
    height_ = height;
    samples_ = info.samples;
    scale_ = samples_ >= 2 ? 1 : 2;
    const int pw = width * scale_, ph = height * scale_;
    gl.GenRenderbuffers(1, &color_rb_);
    gl.BindRenderbuffer(GL_RENDERBUFFER, color_rb_);
    storage(scale_ == 1 ? samples_ : 0, GL_RGBA8, pw, ph);
    gl.GenFramebuffers(1, &color_fbo_);
    gl.BindFramebuffer(GL_FRAMEBUFFER, color_fbo_);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_rb_);
    check_complete("drawing");
    gl.GenFramebuffers(1, &resolve_fbo_);
    gl.BindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
    gl.GenRenderbuffers(1, &resolve_rb_);
    gl.BindRenderbuffer(GL_RENDERBUFFER, resolve_rb_);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_rb_);
    check_complete("resolve");
  }
  if (depth && depth_rb_ == 0) add_depth();
  depth_ = depth;
  gl.BindFramebuffer(GL_FRAMEBUFFER, depth ? depth_fbo_ : color_fbo_);
  gl.Viewport(0, 0, width_ * scale_, height_ * scale_);
  gl.Disable(GL_SCISSOR_TEST);
  gl.ClearColor(clear.r, clear.g, clear.b, 1.0f);
  gl.DepthMask(GL_TRUE);
  gl.Clear(GL_COLOR_BUFFER_BIT | (depth ? GL_DEPTH_BUFFER_BIT : 0));
}

Image Target::finish() {
  // MSAA resolve (same size) or supersampling filter (2× down, linear = 2×2 box).
  gl.Disable(GL_SCISSOR_TEST);
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, depth_ ? depth_fbo_ : color_fbo_);
  gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
  gl.BlitFramebuffer(0, 0, width_ * scale_, height_ * scale_, 0, 0, width_, height_,
                     GL_COLOR_BUFFER_BIT, scale_ == 1 ? GL_NEAREST : GL_LINEAR);
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_);
  Image img;
  img.width = width_;
  img.height = height_;
  img.rgb.resize(static_cast<std::size_t>(width_) * height_ * 3);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  // GL rows run bottom-up: read them straight into the image, then swap rows
  // in place (no second image-sized buffer to fault in).
  gl.ReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, img.rgb.data());
  const std::size_t row = static_cast<std::size_t>(width_) * 3;
  for (int y = 0; y < height_ / 2; ++y)
    std::swap_ranges(img.rgb.begin() + y * row, img.rgb.begin() + (y + 1) * row,
                     img.rgb.begin() + (height_ - 1 - y) * row);
  if (GLenum err = gl.GetError(); err != GL_NO_ERROR)
    throw std::runtime_error("rigid::render: GL error " + std::to_string(err) + " while drawing");
  return img;
}

}  // namespace rigid::render::detail
