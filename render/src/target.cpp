// Internal: FBO set-up, MSAA resolve and read-back.
#include "target.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "rigid/render/context.h"
#include "rigid/render/png.h"

namespace rigid::render::detail {

namespace {
Target* g_current = nullptr;
}  // namespace

Target& target() {
  // never destroyed: its buffers die with the context, which outlives every static
  static Target* const process_target = new Target;
  return g_current != nullptr ? *g_current : *process_target;
}

UseTarget::UseTarget(Target& t) : previous_(g_current) {
  g_current = &t;
}

UseTarget::~UseTarget() {
  g_current = previous_;
}

Target::~Target() {
  if (color_fbo_ != 0) release();
}

void Target::release() {
  GLuint fbos[] = {color_fbo_, depth_fbo_, resolve_fbo_};
  GLuint rbs[] = {color_rb_, depth_rb_};
  GLuint texs[] = {color_tex_, resolve_tex_};
  gl.DeleteFramebuffers(3, fbos);
  gl.DeleteRenderbuffers(2, rbs);
  gl.DeleteTextures(2, texs);
  color_fbo_ = depth_fbo_ = resolve_fbo_ = color_rb_ = depth_rb_ = resolve_tex_ = color_tex_ = 0;
}

namespace {

// The resolve: one triangle covering the viewport; each pixel the mean of its samples.
const char* kResolveVertex = R"(
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

// The sample count is a constant of the source, so the compiler unrolls the
// loop (a uniform count kept it a loop, and the resolve measurably slower).
std::string resolve_fragment(int samples) {
  return "const int kSamples = " + std::to_string(samples) + ";\n" + R"(
uniform sampler2DMS u_samples;
out vec4 frag;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 sum = vec4(0.0);
  for (int i = 0; i < kSamples; ++i) sum += texelFetch(u_samples, p, i);
  frag = sum / float(kSamples);
}
)";
}

struct ResolveProgram {
  GLuint program = 0, vao = 0;
  GLint samples = -1;
};

// One program for the process: its sample count is the context's.
const ResolveProgram& resolve_program(int samples) {
  static const ResolveProgram p = [samples] {
    ResolveProgram r;
    r.program = build_program(kResolveVertex, resolve_fragment(samples).c_str(), nullptr, 0);
    r.samples = gl.GetUniformLocation(r.program, "u_samples");
    gl.GenVertexArrays(1, &r.vao);  // core profile: a draw needs a bound VAO, even an empty one
    return r;
  }();
  return p;
}

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
  attach_color();
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb_);
  check_complete("drawing (with depth)");
}

void Target::attach_color() {
  if (color_tex_ != 0)
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D_MULTISAMPLE,
                            color_tex_, 0);
  else
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_rb_);
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
    if (scale_ == 1 && !info.es) {
      // fixed sample locations: required to share the FBO with a multisampled renderbuffer (depth)
      gl.GenTextures(1, &color_tex_);
      gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, color_tex_);
      gl.TexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples_, GL_RGBA8, pw, ph, GL_TRUE);
      gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    } else {
      gl.GenRenderbuffers(1, &color_rb_);
      gl.BindRenderbuffer(GL_RENDERBUFFER, color_rb_);
      storage(scale_ == 1 ? samples_ : 0, GL_RGBA8, pw, ph);
    }
    gl.GenFramebuffers(1, &color_fbo_);
    gl.BindFramebuffer(GL_FRAMEBUFFER, color_fbo_);
    attach_color();
    check_complete("drawing");
    gl.GenFramebuffers(1, &resolve_fbo_);
    gl.BindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
    // a texture, so that a live view shows the image where it is
    gl.GenTextures(1, &resolve_tex_);
    gl.BindTexture(GL_TEXTURE_2D, resolve_tex_);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    // shown pixel for pixel, where nearest sampling is exact, and on a software
    // rasteriser (llvmpipe) much cheaper than linear
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, resolve_tex_, 0);
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

void Target::resolve() {
  gl.Disable(GL_SCISSOR_TEST);
  if (color_tex_ == 0) {
    // supersampling: 2× down, linear = the mean of each 2×2 block; or (OpenGL ES) the
    // samples of a multisampled renderbuffer averaged by the blit itself
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, depth_ ? depth_fbo_ : color_fbo_);
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
    gl.BlitFramebuffer(0, 0, width_ * scale_, height_ * scale_, 0, 0, width_, height_,
                       GL_COLOR_BUFFER_BIT, scale_ == 1 ? GL_NEAREST : GL_LINEAR);
    return;
  }
  const ResolveProgram& r = resolve_program(samples_);
  gl.BindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
  gl.Viewport(0, 0, width_, height_);
  gl.Disable(GL_DEPTH_TEST);
  gl.Disable(GL_BLEND);
  gl.Disable(GL_CULL_FACE);
  gl.UseProgram(r.program);
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, color_tex_);
  gl.Uniform1i(r.samples, 0);
  gl.BindVertexArray(r.vao);
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
  gl.BindVertexArray(0);
  gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
}

Image Target::finish() {
  resolve();
  return read();
}

Image Target::read() {
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_);
  Image img;
  img.width = width_;
  img.height = height_;
  img.rgb = std::move(spare_);  // the last saved figure's pixels, already faulted in
  spare_ = {};
  img.rgb.resize(static_cast<std::size_t>(width_) * height_ * 3);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  // GL rows run bottom-up: read them straight into the image, then swap rows
  // in place (no second image-sized buffer to fault in).
  if (context().es) {
    // OpenGL ES promises only RGBA reads
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width_) * height_ * 4);
    gl.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    for (std::size_t i = 0, n = rgba.size() / 4; i < n; ++i)
      std::copy_n(&rgba[4 * i], 3, &img.rgb[3 * i]);
  } else {
    gl.ReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, img.rgb.data());
  }
  const std::size_t row = static_cast<std::size_t>(width_) * 3;
  for (int y = 0; y < height_ / 2; ++y)
    std::swap_ranges(img.rgb.begin() + y * row, img.rgb.begin() + (y + 1) * row,
                     img.rgb.begin() + (height_ - 1 - y) * row);
  if (GLenum err = gl.GetError(); err != GL_NO_ERROR)
    throw std::runtime_error("rigid::render: GL error " + std::to_string(err) + " while drawing");
  return img;
}

namespace {
double seconds_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

PhaseClock::PhaseClock(FigureTiming* timing) : timing_(timing), last_(timing ? seconds_now() : 0) {}

void PhaseClock::lap(double FigureTiming::*phase, bool wait_for_gl) {
  if (timing_ == nullptr) return;
  if (wait_for_gl) gl.Finish();
  const double now = seconds_now();
  timing_->*phase += now - last_;
  last_ = now;
}

void Target::recycle(std::vector<std::uint8_t>&& pixels) {
  spare_ = std::move(pixels);
}

void save_timed(Image img, const std::string& path, FigureTiming* timing) {
  PhaseClock clock(timing);
  write_png(img, path);
  clock.lap(&FigureTiming::encode);
  target().recycle(std::move(img.rgb));
}

}  // namespace rigid::render::detail
