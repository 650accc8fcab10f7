// Figures drawn into textures of the caller's context (live.h).
#include "rigid/render/live.h"

#include "target.h"

namespace rigid::render {

LiveImage::LiveImage() : target_(std::make_unique<detail::Target>()) {}

LiveImage::~LiveImage() = default;

template <class Figure>
auto LiveImage::draw_figure(const Figure& figure, int width, int height, FigureTiming* timing) {
  using detail::gl;
  // The window's own state, given back however the drawing ends: its framebuffer and
  // viewport.
  GLint draw_fbo = 0, read_fbo = 0, viewport[4] = {};
  gl.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_fbo);
  gl.GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_fbo);
  gl.GetIntegerv(GL_VIEWPORT, viewport);
  struct Restore {
    const GLint draw_fbo, read_fbo, *viewport;
    ~Restore() {
      gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_fbo));
      gl.BindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_fbo));
      gl.Viewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    }
  } restore{draw_fbo, read_fbo, viewport};
  const detail::UseTarget use(*target_);
  detail::PhaseClock clock(timing);
  auto drawn = detail::render_into_target(figure, width, height, clock);
  target_->resolve();
  clock.lap(&FigureTiming::resolve, true);
  return drawn;
}

Scene3D::Layout LiveImage::draw(const Scene3D& scene, int width, int height, FigureTiming* timing) {
  return draw_figure(scene, width, height, timing);
}

Plot2D::Layout LiveImage::draw(const Plot2D& plot, int width, int height, FigureTiming* timing) {
  return draw_figure(plot, width, height, timing);
}

unsigned LiveImage::texture() const {
  return target_->texture();
}

int LiveImage::width() const {
  return target_->width();
}

int LiveImage::height() const {
  return target_->height();
}

Image LiveImage::read() const {
  GLint read_fbo = 0;
  detail::gl.GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_fbo);
  Image img = target_->read();
  detail::gl.BindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_fbo));
  return img;
}

}  // namespace rigid::render
