// A figure drawn live into a window's own GL context, for a program that shows
// figures as they change (the explorer): the same drawing as draw.h's, left in a
// texture of that context for the window to show, instead of read back as an
// image. Each LiveImage keeps its own buffers, so a scene and a plot shown side by
// side are not reallocated as they alternate. Needs use_current_context()
// (context.h) first.
#pragma once

#include <memory>

#include "rigid/render/draw.h"
#include "rigid/render/image.h"
#include "rigid/render/plot2d.h"
#include "rigid/render/scene3d.h"

namespace rigid::render {

namespace detail {
class Target;
}

class LiveImage {
 public:
  LiveImage();
  ~LiveImage();
  LiveImage(const LiveImage&) = delete;
  LiveImage& operator=(const LiveImage&) = delete;

  /// Draws the figure at width × height into this image's texture. The context's
  /// framebuffer binding and viewport are as they were after. Each gives back where its
  /// title, legend and labels or panels went (as layout() would, without planning again).
  Scene3D::Layout draw(const Scene3D& scene, int width, int height, FigureTiming* timing = nullptr);
  Plot2D::Layout draw(const Plot2D& plot, int width, int height, FigureTiming* timing = nullptr);
  /// The last drawing as a GL texture name (RGBA8, first row at the bottom); 0 before any.
  unsigned texture() const;
  int width() const;
  int height() const;
  /// The last drawing's pixels (first row at the top).
  Image read() const;

 private:
  template <class Figure>
  auto draw_figure(const Figure& figure, int width, int height, FigureTiming* timing);
  std::unique_ptr<detail::Target> target_;
};

}  // namespace rigid::render
