// Drawing figures: where a Plot2D's or a Scene3D's parts land at a size, the
// image they make and the file it is written to (PNG, or SVG and PDF as vectors). This header is
// the drawing library (rigid::render_gl: OpenGL, FreeType, libpng); the descriptions it draws
// (plot2d.h, scene3d.h) are the GL-free rigid::render, so a program that only describes figures
// never meets a function it cannot link.
//
// The GL context is made on the first figure drawn; a layout needs fonts only.
#pragma once

#include <string>
#include <vector>

#include "rigid/render/figure_format.h"
#include "rigid/render/image.h"
#include "rigid/render/plot2d.h"
#include "rigid/render/rect.h"
#include "rigid/render/scene3d.h"

namespace rigid::render {

/// Where one panel's parts land at a size, in pixels.
struct Plot2D::PanelLayout {
  ScreenRect frame;                     ///< the plot area inside the axes
  ScreenRect title;                     ///< the panel title (empty when none)
  ScreenRect legend;                    ///< the legend box (empty when none is drawn)
  std::vector<ScreenRect> annotations;  ///< each annotation's text, in the panel's order
  std::vector<ScreenRect> ref_labels;   ///< each labelled reference line's label, in order
  double x_lo = 0, x_hi = 1, y_lo = 0, y_hi = 1;  ///< the axis ranges drawn
  std::vector<double> x_ticks, y_ticks;           ///< the labelled ticks' values
};

/// Where the figure's parts land at a size: the title (one or two lines, maybe shrunk) and
/// every panel, row by row.
struct Plot2D::Layout {
  ScreenRect title;
  ScreenRect legend;  ///< the shared legend under the panels (empty when there is none)
  int title_lines = 0;
  double title_size = 0;  ///< the title's font size in pixels
  std::vector<PanelLayout> panels;
};

/// Where the overlay and the scene go at a size: the title (one or two lines), the legend
/// box (empty when there is none), the region the fitted scene fills, the figure style's
/// margin inside the image's edges (the scene also keeps that margin from the legend box),
/// and each label's text box (empty if its point is behind the camera).
struct Scene3D::Layout {
  ScreenRect title, legend, region;
  int title_lines = 0;
  double title_size = 0;  ///< the title's font size in pixels
  std::vector<ScreenRect> labels;
};

/// The layout draw() gives the plot at width × height (needs fonts, not a GL context).
Plot2D::Layout layout(const Plot2D& plot, int width = 1600, int height = 1200);
/// Draws the plot into an image of width × height pixels (cairo's rasteriser, no GL context
/// needed); `timing`, if given, gets where the time went.
Image draw(const Plot2D& plot, int width = 1600, int height = 1200, FigureTiming* timing = nullptr);
/// Draws the plot with OpenGL into an image, as a live view draws it in its window (draw()
/// rasterises a plot with cairo on the CPU, from the same drawing calls).
Image draw_gl(const Plot2D& plot, int width = 1600, int height = 1200);
/// Draws the plot and writes it as a PNG atomically (see png.h).
void save_png(const Plot2D& plot, const std::string& path, int width = 1600, int height = 1200,
              FigureTiming* timing = nullptr);

/// The layout draw() gives the scene at width × height (needs fonts, not a GL context).
Scene3D::Layout layout(const Scene3D& scene, int width, int height);
/// The camera draw() would use at width × height: the fit applied (Camera::fit), returned
/// with fit off, so frames of an animation can share one view.
Camera fitted_camera(const Scene3D& scene, int width, int height);
/// Draws the scene into an image of width × height pixels; `timing`, if given, gets where
/// the time went.
Image draw(const Scene3D& scene, int width = 1600, int height = 1200,
           FigureTiming* timing = nullptr);
/// Draws the scene and writes it as a PNG atomically (see png.h).
void save_png(const Scene3D& scene, const std::string& path, int width = 1600, int height = 1200,
              FigureTiming* timing = nullptr);

/// Writes the plot as a file of `format` atomically: a PNG of width × height pixels, or an
/// SVG (width × height px) or a PDF (the same at 96 px to the inch: 0.75 pt a pixel) whose
/// lines, fills and text are vectors, laid out exactly as the PNG. Throws
/// std::runtime_error if it cannot (e.g. no libcairo for a vector format).
void save_figure(const Plot2D& plot, const std::string& path, FigureFormat format, int width = 1600,
                 int height = 1200, FigureTiming* timing = nullptr);
/// Writes the scene as a file of `format`: a PNG, or an SVG or a PDF of the same size
/// holding its width × height image.
void save_figure(const Scene3D& scene, const std::string& path, FigureFormat format,
                 int width = 1600, int height = 1200, FigureTiming* timing = nullptr);

}  // namespace rigid::render
