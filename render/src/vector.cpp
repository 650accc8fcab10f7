// Plots through cairo: as SVG and PDF, drawn on a CairoCanvas (paths for lines and
// fills; text as text: in a PDF the figure's own font embedded, in an SVG <text> of
// DejaVu Sans with every glyph placed where the layout put it), a 3D scene as its
// geometry's raster image inside a page of the same size, its title, legend and labels
// drawn over it as a plot's are; and as pixels, cairo's antialiased
// rasteriser on the CPU (no multisampled buffers to clear, resolve and read back: a
// plot's fixed cost in the GL path was about 30 ms).
//
// Why libcairo is opened here and not linked: linked, it and the twenty-odd shared
// objects it needs (pixman, fontconfig, the X client libraries, ...) would load at the
// start of every process that links the renderer, drawing or not: 1.2 to 1.4 ms more,
// where the fastest lab's whole run without figures takes 2 to 3 ms
// (bench/results.md, "Start-up: what a linked library costs"). So libcairo (with the
// FreeType it uses) is opened on the first plot drawn or vector figure written, as OSMesa,
// EGL and the video encoders are, and a process that draws neither never loads it.
#include <cairo-ft.h>
#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "backends.h"
#include "canvas.h"
#include "font.h"
#include "rigid/render/atomic_file.h"
#include "rigid/render/draw.h"
#include "scene_layout.h"
#include "target.h"

namespace rigid::render {

namespace {

using detail::DashPattern;
using detail::P3;

// A pixel is 0.75 pt: a PDF page shows the figure at 96 pixels to the inch, as a browser
// shows the SVG (whose unit is the pixel).
constexpr double kPointsPerPixel = 0.75;

// libcairo's entry points, X(library, function).
#define RIGID_CAIRO_FUNCTIONS(X)                  \
  X(cairo, cairo_svg_surface_create_for_stream)   \
  X(cairo, cairo_svg_surface_set_document_unit)   \
  X(cairo, cairo_pdf_surface_create_for_stream)   \
  X(cairo, cairo_pdf_surface_set_metadata)        \
  X(cairo, cairo_surface_finish)                  \
  X(cairo, cairo_surface_status)                  \
  X(cairo, cairo_surface_destroy)                 \
  X(cairo, cairo_surface_flush)                   \
  X(cairo, cairo_surface_mark_dirty)              \
  X(cairo, cairo_image_surface_create)            \
  X(cairo, cairo_image_surface_get_data)          \
  X(cairo, cairo_image_surface_get_stride)        \
  X(cairo, cairo_create)                          \
  X(cairo, cairo_destroy)                         \
  X(cairo, cairo_status)                          \
  X(cairo, cairo_status_to_string)                \
  X(cairo, cairo_save)                            \
  X(cairo, cairo_restore)                         \
  X(cairo, cairo_scale)                           \
  X(cairo, cairo_translate)                       \
  X(cairo, cairo_rotate)                          \
  X(cairo, cairo_set_source_rgba)                 \
  X(cairo, cairo_set_source_surface)              \
  X(cairo, cairo_paint)                           \
  X(cairo, cairo_new_path)                        \
  X(cairo, cairo_move_to)                         \
  X(cairo, cairo_line_to)                         \
  X(cairo, cairo_close_path)                      \
  X(cairo, cairo_new_sub_path)                    \
  X(cairo, cairo_arc)                             \
  X(cairo, cairo_rectangle)                       \
  X(cairo, cairo_fill)                            \
  X(cairo, cairo_stroke)                          \
  X(cairo, cairo_clip)                            \
  X(cairo, cairo_reset_clip)                      \
  X(cairo, cairo_set_fill_rule)                   \
  X(cairo, cairo_set_line_width)                  \
  X(cairo, cairo_set_line_join)                   \
  X(cairo, cairo_set_line_cap)                    \
  X(cairo, cairo_set_dash)                        \
  X(cairo, cairo_ft_font_face_create_for_ft_face) \
  X(cairo, cairo_font_face_status)                \
  X(cairo, cairo_set_font_face)                   \
  X(cairo, cairo_set_font_size)                   \
  X(cairo, cairo_font_options_create)             \
  X(cairo, cairo_font_options_destroy)            \
  X(cairo, cairo_font_options_set_hint_style)     \
  X(cairo, cairo_font_options_set_hint_metrics)   \
  X(cairo, cairo_font_options_set_antialias)      \
  X(cairo, cairo_set_font_options)                \
  X(cairo, cairo_show_glyphs)                     \
  X(freetype, FT_Init_FreeType)                   \
  X(freetype, FT_New_Face)

struct CairoApi {
  RIGID_CAIRO_FUNCTIONS(RIGID_ENTRY_POINT)
  // The figure's font as a face of the FreeType libcairo itself links (a face of the
  // renderer's own FreeType would be another library's object to it).
  cairo_font_face_t* font = nullptr;
};

const CairoApi& cairo_api() {
  static const CairoApi table = [] {
    std::string error;
    void* cairo =
        detail::open_library({"libcairo.so.2"}, "libcairo (Debian package libcairo2)", error);
    void* freetype = cairo
                         ? detail::open_library({"libfreetype.so.6"},
                                                "libfreetype (Debian package libfreetype6)", error)
                         : nullptr;
    if (freetype == nullptr) throw std::runtime_error(error);
    CairoApi api;
    if (!(true RIGID_CAIRO_FUNCTIONS(RIGID_BIND_ENTRY_POINT)))
      throw std::runtime_error("libcairo is too old: it lacks an SVG, PDF or FreeType call");
    // The face lives as long as the process: every vector figure's text uses it.
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    if (api.FT_Init_FreeType(&library) != 0 ||
        api.FT_New_Face(library, RIGID_FONT_PATH, 0, &face) != 0)
      throw std::runtime_error("cannot load the font " RIGID_FONT_PATH " for a vector figure");
    api.font = api.cairo_ft_font_face_create_for_ft_face(face, 0);
    if (api.cairo_font_face_status(api.font) != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error("libcairo cannot use the font " RIGID_FONT_PATH);
    return api;
  }();
  return table;
}

// "#rrggbb" of a colour.
std::string hex(Color c) {
  auto byte = [](float v) {
    return static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255));
  };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(c.r), byte(c.g), byte(c.b));
}

// A coordinate in pixels to 1/100 px, without trailing zeros.
std::string number(double v) {
  std::string s = fmt::format("{:.2f}", v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

// Text as XML character data.
void append_escaped(std::string& out, char32_t cp) {
  if (cp == '&')
    out += "&amp;";
  else if (cp == '<')
    out += "&lt;";
  else if (cp == '>')
    out += "&gt;";
  else
    detail::append_utf8(out, cp);
}

// One font face serves every figure drawn with cairo: one figure at a time.
std::mutex& cairo_mutex() {
  static std::mutex mutex;
  return mutex;
}

// Draws on a cairo context in the figure's pixels. Fills of one colour that follow each
// other become one path, filled once: a band drawn as a quad between each pair of samples
// would otherwise show every shared edge as a seam (each antialiased on its own), where
// the raster canvas's triangles meet exactly.
//
// cairo's SVG surface writes glyphs as outlines, which no reader can select or search;
// for an SVG the canvas writes its text as <text> instead (svg_text()), to go over
// everything cairo drew (nothing a figure draws after a text covers it).
class CairoCanvas final : public detail::Canvas {
 public:
  CairoCanvas(cairo_t* cr, bool svg_text) : api_(cairo_api()), cr_(cr), svg_text_(svg_text) {
    api_.cairo_set_fill_rule(cr_, CAIRO_FILL_RULE_WINDING);
    api_.cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
    cairo_font_options_t* options = api_.cairo_font_options_create();
    // Outlines as designed, advances unrounded: the layout's own metrics (text.cpp).
    api_.cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
    api_.cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
    api_.cairo_font_options_set_antialias(options, CAIRO_ANTIALIAS_GRAY);
    api_.cairo_set_font_options(cr_, options);
    api_.cairo_font_options_destroy(options);
    api_.cairo_set_font_face(cr_, api_.font);
  }
  CairoCanvas(const CairoCanvas&) = delete;
  CairoCanvas& operator=(const CairoCanvas&) = delete;
  ~CairoCanvas() override { fill_pending(); }

  /// Fills what is pending; after it, the context holds the whole figure.
  void finish() { fill_pending(); }
  /// The SVG elements of the text, when the canvas writes text as SVG text.
  const std::string& svg_text() const { return svg_text_layer_; }

  void clip(double x0, double y0, double x1, double y1) override {
    fill_pending();
    api_.cairo_reset_clip(cr_);
    api_.cairo_rectangle(cr_, std::floor(x0), std::floor(y0), std::ceil(x1) - std::floor(x0),
                         std::ceil(y1) - std::floor(y0));
    api_.cairo_clip(cr_);
  }
  void no_clip() override {
    fill_pending();
    api_.cairo_reset_clip(cr_);
  }
  void depth_test(bool) override {}

  void triangle(const P3& a, const P3& b, const P3& c, Color color) override {
    convex({a, b, c}, color);
  }
  void rect(double x0, double y0, double x1, double y1, Color color) override {
    pending(color);
    api_.cairo_rectangle(cr_, x0, y0, x1 - x0, y1 - y0);
  }
  void rect_outline(double x0, double y0, double x1, double y1, double w, Color color) override {
    rect(x0, y0, x1, y0 + w, color);
    rect(x0, y1 - w, x1, y1, color);
    rect(x0, y0 + w, x0 + w, y1 - w, color);
    rect(x1 - w, y0 + w, x1, y1 - w, color);
  }
  void convex(const std::vector<P3>& pts, Color color) override {
    if (pts.size() < 3) return;
    pending(color);
    api_.cairo_move_to(cr_, pts[0].x(), pts[0].y());
    for (std::size_t i = 1; i < pts.size(); ++i) api_.cairo_line_to(cr_, pts[i].x(), pts[i].y());
    api_.cairo_close_path(cr_);
  }
  void disc(const P3& c, double radius, Color color) override {
    pending(color);
    api_.cairo_new_sub_path(cr_);
    api_.cairo_arc(cr_, c.x(), c.y(), radius, 0, 2 * EIGEN_PI);
    api_.cairo_close_path(cr_);
  }
  void polyline(const std::vector<P3>& pts, double width, Color color, const DashPattern& dash,
                bool round_caps) override {
    if (pts.empty()) return;
    fill_pending();
    source(color);
    api_.cairo_set_line_width(cr_, width);
    api_.cairo_set_line_cap(cr_, round_caps ? CAIRO_LINE_CAP_ROUND : CAIRO_LINE_CAP_BUTT);
    api_.cairo_set_dash(cr_, dash.data(), static_cast<int>(dash.size()), 0);
    api_.cairo_move_to(cr_, pts[0].x(), pts[0].y());
    for (std::size_t i = 1; i < pts.size(); ++i) api_.cairo_line_to(cr_, pts[i].x(), pts[i].y());
    // A single point with round caps is a dot, as on the raster canvas.
    if (pts.size() == 1) api_.cairo_line_to(cr_, pts[0].x(), pts[0].y());
    api_.cairo_stroke(cr_);
  }
  TextExtent text(std::string_view markup, double x, double y, double size, Color color, HAlign h,
                  VAlign v, bool vertical, double) override {
    fill_pending();
    const detail::TextLayout lay = detail::layout_text(markup, size);
    const Eigen::Vector2d origin = detail::text_origin(lay.extent, x, y, h, v, vertical);
    if (svg_text_) {
      add_svg_text(lay, origin, vertical, color);
      return lay.extent;
    }
    api_.cairo_save(cr_);
    api_.cairo_translate(cr_, origin.x(), origin.y());
    if (vertical) api_.cairo_rotate(cr_, -0.5 * EIGEN_PI);
    source(color);
    // The layout's glyphs by size (scripts are smaller), each run at its size; y up there.
    std::map<int, std::vector<cairo_glyph_t>> runs;
    for (const detail::PlacedGlyph& g : lay.glyphs) runs[g.size_px].push_back({g.glyph, g.x, -g.y});
    for (const auto& [px, glyphs] : runs) {
      api_.cairo_set_font_size(cr_, px);
      api_.cairo_show_glyphs(cr_, glyphs.data(), static_cast<int>(glyphs.size()));
    }
    api_.cairo_restore(cr_);
    return lay.extent;
  }

 private:
  void source(Color c) { api_.cairo_set_source_rgba(cr_, c.r, c.g, c.b, c.a); }

  // One <text> a call, a <tspan> a glyph at its place (SVG readers differ on lists of
  // positions in one tspan: librsvg 2.54 takes only the first).
  void add_svg_text(const detail::TextLayout& lay, const Eigen::Vector2d& origin, bool vertical,
                    Color color) {
    if (lay.glyphs.empty()) return;
    std::string& out = svg_text_layer_;
    const int size = lay.glyphs.front().size_px;
    out += fmt::format(
        R"(<text xml:space="preserve" transform="translate({} {}){}" font-size="{}px" fill="{}")",
        number(origin.x()), number(origin.y()), vertical ? " rotate(-90)" : "", size, hex(color));
    if (color.a < 1) out += fmt::format(R"( fill-opacity="{:.3g}")", color.a);
    out += ">";
    for (const detail::PlacedGlyph& g : lay.glyphs) {
      out += fmt::format(R"(<tspan x="{}" y="{}")", number(g.x), number(-g.y));
      if (g.size_px != size) out += fmt::format(R"( font-size="{}px")", g.size_px);
      out += ">";
      append_escaped(out, g.code);
      out += "</tspan>";
    }
    out += "</text>\n";
  }
  // Starts or continues the pending fill of colour c.
  void pending(Color c) {
    if (has_pending_ && c.r == pending_.r && c.g == pending_.g && c.b == pending_.b &&
        c.a == pending_.a)
      return;
    fill_pending();
    has_pending_ = true;
    pending_ = c;
  }
  void fill_pending() {
    if (!has_pending_) return;
    source(pending_);
    api_.cairo_fill(cr_);
    has_pending_ = false;
  }

  const CairoApi& api_;
  cairo_t* cr_;
  bool svg_text_;
  std::string svg_text_layer_;
  bool has_pending_ = false;
  Color pending_;
};

cairo_status_t append_to_string(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// SOURCE_DATE_EPOCH (seconds since 1970, UTC) as a PDF date, or "" if unset or not a number.
std::string source_date() {
  const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
  if (epoch == nullptr || *epoch == '\0') return "";
  char* end = nullptr;
  const long long seconds = std::strtoll(epoch, &end, 10);
  if (*end != '\0' || seconds < 0) return "";
  const std::time_t t = static_cast<std::time_t>(seconds);
  std::tm utc{};
  if (gmtime_r(&t, &utc) == nullptr) return "";
  char text[32];
  return std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc) > 0 ? text : "";
}

// The SVG text layer goes last, over what cairo drew, in a group of the figure's font.
std::string with_text_layer(std::string svg, const std::string& text) {
  const std::size_t end = svg.rfind("</svg>");
  if (text.empty() || end == std::string::npos) return svg;
  svg.insert(end, "<g font-family=\"DejaVu Sans, sans-serif\">\n" + text + "</g>\n");
  return svg;
}

// Writes a vector file of width × height pixels through `draw`, which draws in pixels on a
// context of that page and returns the SVG elements to add over it (text), if any.
template <class Draw>
void write_vector(const std::string& path, FigureFormat format, int width, int height,
                  const std::string& title, Draw&& draw) {
  const CairoApi& api = cairo_api();
  const std::lock_guard<std::mutex> lock(cairo_mutex());
  std::string bytes, layer;
  cairo_surface_t* surface = nullptr;
  double scale = 1;
  if (format == FigureFormat::kSvg) {
    surface = api.cairo_svg_surface_create_for_stream(append_to_string, &bytes, width, height);
    api.cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);
  } else {
    scale = kPointsPerPixel;
    surface = api.cairo_pdf_surface_create_for_stream(append_to_string, &bytes, width * scale,
                                                      height * scale);
    api.cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "rigidlab");
    // cairo dates the file now; a reproducible build's SOURCE_DATE_EPOCH dates it then,
    // so that the same figure is the same bytes
    if (const std::string date = source_date(); !date.empty())
      api.cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATE_DATE, date.c_str());
    if (!title.empty())
      api.cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, title.c_str());
  }
  cairo_t* cr = api.cairo_create(surface);
  api.cairo_scale(cr, scale, scale);
  try {
    layer = draw(cr);
  } catch (...) {
    api.cairo_destroy(cr);
    api.cairo_surface_destroy(surface);
    throw;
  }
  const cairo_status_t drawn = api.cairo_status(cr);
  api.cairo_destroy(cr);
  api.cairo_surface_finish(surface);
  const cairo_status_t written = api.cairo_surface_status(surface);
  api.cairo_surface_destroy(surface);
  if (drawn != CAIRO_STATUS_SUCCESS || written != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(
        "cannot write '" + path +
        "': cairo: " + api.cairo_status_to_string(drawn != CAIRO_STATUS_SUCCESS ? drawn : written));
  if (format == FigureFormat::kSvg) bytes = with_text_layer(std::move(bytes), layer);
  write_file_atomically(path, [&](std::FILE* file) {
    if (std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size())
      throw std::runtime_error("write failed");
  });
}

}  // namespace

Image detail::draw_plot_on_cpu(const Plot2D& plot, int width, int height, FigureTiming* timing) {
  PhaseClock clock(timing);
  const CairoApi& api = cairo_api();
  const std::lock_guard<std::mutex> lock(cairo_mutex());
  cairo_surface_t* surface = api.cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  cairo_t* cr = api.cairo_create(surface);
  clock.lap(&FigureTiming::setup);
  {
    CairoCanvas canvas(cr, false);
    api.cairo_set_source_rgba(cr, 1, 1, 1, 1);
    api.cairo_paint(cr);
    detail::draw_plot(plot, width, height, canvas, &clock);
    canvas.finish();
  }
  const cairo_status_t status = api.cairo_status(cr);
  api.cairo_destroy(cr);
  api.cairo_surface_flush(surface);
  clock.lap(&FigureTiming::draw);
  Image img;
  img.width = width;
  img.height = height;
  img.rgb.resize(static_cast<std::size_t>(width) * height * 3);
  const unsigned char* data = api.cairo_image_surface_get_data(surface);
  const int stride = api.cairo_image_surface_get_stride(surface);
  if (status != CAIRO_STATUS_SUCCESS || data == nullptr) {
    api.cairo_surface_destroy(surface);
    throw std::runtime_error(std::string("cairo: ") + api.cairo_status_to_string(status));
  }
  for (int y = 0; y < height; ++y) {
    const auto* row =
        reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    std::uint8_t* out = img.at(0, y);
    for (int x = 0; x < width; ++x, out += 3) {
      const std::uint32_t p = row[x];
      out[0] = static_cast<std::uint8_t>(p >> 16);
      out[1] = static_cast<std::uint8_t>(p >> 8);
      out[2] = static_cast<std::uint8_t>(p);
    }
  }
  api.cairo_surface_destroy(surface);
  clock.lap(&FigureTiming::resolve);
  return img;
}

void save_figure(const Plot2D& plot, const std::string& path, FigureFormat format, int width,
                 int height, FigureTiming* timing) {
  if (format == FigureFormat::kPng) return save_png(plot, path, width, height, timing);
  detail::PhaseClock clock(timing);
  write_vector(path, format, width, height, plain_text(plot.title), [&](cairo_t* cr) {
    CairoCanvas canvas(cr, format == FigureFormat::kSvg);
    cairo_api().cairo_set_source_rgba(cr, 1, 1, 1, 1);
    cairo_api().cairo_paint(cr);
    detail::draw_plot(plot, width, height, canvas);
    canvas.finish();
    return canvas.svg_text();
  });
  clock.lap(&FigureTiming::encode);
}

void save_figure(const Scene3D& scene, const std::string& path, FigureFormat format, int width,
                 int height, FigureTiming* timing) {
  if (format == FigureFormat::kPng) return save_png(scene, path, width, height, timing);
  // the geometry as the PNG's pixels, its title, legend and labels as vectors over them:
  // text a reader of the slide can select and search, and that scales
  const detail::SceneParts parts = detail::draw_scene_parts(scene, width, height, timing);
  const Image& img = parts.image;
  detail::PhaseClock clock(timing);
  write_vector(path, format, width, height, plain_text(scene.title), [&](cairo_t* cr) {
    const CairoApi& api = cairo_api();
    cairo_surface_t* pixels = api.cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
    api.cairo_surface_flush(pixels);
    unsigned char* data = api.cairo_image_surface_get_data(pixels);
    const int stride = api.cairo_image_surface_get_stride(pixels);
    if (data == nullptr) {
      api.cairo_surface_destroy(pixels);
      throw std::runtime_error("cairo: cannot hold a " + std::to_string(width) + "x" +
                               std::to_string(height) + " image");
    }
    for (int y = 0; y < height; ++y) {
      auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
      for (int x = 0; x < width; ++x) {
        const std::uint8_t* p = img.at(x, y);
        row[x] = (std::uint32_t{p[0]} << 16) | (std::uint32_t{p[1]} << 8) | p[2];
      }
    }
    api.cairo_surface_mark_dirty(pixels);
    api.cairo_set_source_surface(cr, pixels, 0, 0);
    api.cairo_paint(cr);
    api.cairo_surface_destroy(pixels);
    CairoCanvas canvas(cr, format == FigureFormat::kSvg);
    detail::draw_scene_overlay(canvas, parts.labels, parts.frame);
    canvas.finish();
    return canvas.svg_text();
  });
  clock.lap(&FigureTiming::encode);
}

}  // namespace rigid::render
