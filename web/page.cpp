// The web page's side in WebAssembly: every lab live, as the explorer holds it (a
// lab::Session, the explorer's ViewState, SceneCache and Orbit), drawn by render_gl into
// the page's WebGL2 canvas. The page's script (app.js) makes the controls from each
// lab's input table and asks this for everything else through embind: a change is
// read by the one reader (Session::set_text, or session_at for the address), and what
// is shown comes back as the command line's own JSON and table rows.
#include <GLES3/gl3.h>
#include <emscripten/bind.h>
#include <emscripten/html5.h>
#include <emscripten/val.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "actions.h"
#include "common/registry.h"
#include "common/writers.h"
#include "rigid/render/context.h"
#include "rigid/render/draw.h"
#include "rigid/render/live.h"
#include "rigid/render/png.h"
#include "scene_cache.h"
#include "session_text.h"
#include "view_state.h"

namespace rigid::web {

namespace {

using lab::Json;

Json refusal_json(const lab::Refusal& r) {
  return {{"refused", r.message}, {"inputs", r.inputs}};
}

// The texts of `given` (a JSON array of [option, text] pairs) as the command line takes them.
lab::GivenTexts given_from(const std::string& text) {
  lab::GivenTexts given;
  const Json pairs = Json::parse(text, nullptr, false);
  if (!pairs.is_array()) return given;
  for (const Json& p : pairs) {
    if (p.is_array() && p.size() == 2 && p[0].is_string() && p[1].is_string())
      given.emplace_back(p[0].get<std::string>(), p[1].get<std::string>());
  }
  return given;
}

void* gl_proc(const char* name) {
  return emscripten_webgl_get_proc_address(name);
}

// Draws `image` into the canvas's rectangle (x, y from the top left, CSS pixels times
// the device's ratio), through a framebuffer that reads its texture.
class Presenter {
 public:
  void show(const render::LiveImage& image, int x, int y, int canvas_height) {
    if (read_fbo_ == 0) glGenFramebuffers(1, &read_fbo_);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, read_fbo_);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                           image.texture(), 0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    const int y0 = canvas_height - y - image.height();
    glBlitFramebuffer(0, 0, image.width(), image.height(), x, y0, x + image.width(),
                      y0 + image.height(), GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  }

 private:
  GLuint read_fbo_ = 0;
};

}  // namespace

class Page {
 public:
  Page() : labs_(lab::all_labs()) {}

  /// Every lab and what it takes (registry.h's describe()), as JSON.
  std::string labs() const {
    Json out = Json::array();
    for (const lab::LabEntry& e : labs_) out.push_back(lab::describe(e));
    return out.dump();
  }

  /// Makes the canvas `selector`'s WebGL2 context the renderer's; "" or why it cannot.
  std::string attach(const std::string& selector) {
    EmscriptenWebGLContextAttributes attrs;
    emscripten_webgl_init_context_attributes(&attrs);
    attrs.majorVersion = 2;
    attrs.minorVersion = 0;
    attrs.alpha = false;
    attrs.depth = false;
    attrs.antialias = false;             // the renderer draws into its own multisampled buffers
    attrs.preserveDrawingBuffer = true;  // the canvas can be read back between frames
    const EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context =
        emscripten_webgl_create_context(selector.c_str(), &attrs);
    if (context <= 0) return "this browser gives no WebGL2 context";
    emscripten_webgl_make_context_current(context);
    try {
      render::use_current_context(reinterpret_cast<render::ProcAddress>(&gl_proc));
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  }

  /// Opens lab `name` at the textbook's inputs but for `given` (JSON [[option, text],
  /// ...]), read as the command line reads them; {} or {refused, inputs}, and then the
  /// lab is open at the textbook's inputs.
  std::string open(const std::string& name, const std::string& given) {
    const auto e = std::find_if(labs_.begin(), labs_.end(),
                                [&](const lab::LabEntry& l) { return l.name == name; });
    if (e == labs_.end()) return Json{{"refused", "lab: no lab named '" + name + "'"}}.dump();
    Json out = Json::object();
    try {
      auto made = e->make_at(given_from(given));
      if (auto* refusal = std::get_if<lab::Refusal>(&made)) {
        out = refusal_json(*refusal);
      } else {
        session_ = std::move(std::get<std::unique_ptr<lab::Session>>(made));
      }
    } catch (const std::exception& x) {
      out = Json{{"refused", x.what()}, {"inputs", Json::array()}};
    }
    if (!out.empty() || session_ == nullptr || session_->name() != name) session_ = e->make();
    view_ = explore::ViewState{};
    cache_.reset();
    scene_drawn_ = plot_drawn_ = Drawn{};  // another session counts its generations anew
    return out.dump();
  }

  /// The seconds of a computation of lab `name` at its defaults, whole (as open()
  /// computes it), `repeats` times: the bench's WebAssembly side, beside the same loop
  /// natively (import rigidlab's _compute_seconds). A browser's clock ticks in 0.1 ms,
  /// so each is the mean of a batch of at least 2 ms.
  std::string compute_seconds(const std::string& name, int repeats) const {
    const auto e = std::find_if(labs_.begin(), labs_.end(),
                                [&](const lab::LabEntry& l) { return l.name == name; });
    Json out = Json::array();
    if (e == labs_.end()) return out.dump();
    const auto batch = [&](int n) {
      const auto start = std::chrono::steady_clock::now();
      for (int k = 0; k < n; ++k) (void)e->make_at({});
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    int n = 1;
    while (batch(n) < 2e-3 && n < (1 << 16)) n *= 2;
    for (int k = 0; k < repeats; ++k) out.push_back(batch(n) / n);
    return out.dump();
  }

  /// Sets the input `flag` from its text; {} or {refused, inputs} (the state unchanged).
  std::string set(const std::string& flag, const std::string& text) {
    const std::size_t i = session_->find(flag);
    if (i == session_->input_count()) return Json{{"refused", flag + ": not an input"}}.dump();
    if (const auto refusal = session_->set_text(i, text)) return refusal_json(*refusal).dump();
    return "{}";
  }

  /// Back to the text's example.
  void reset() { session_->reset(); }

  /// Takes the whole report in (computed here, on the page's one thread, after the
  /// preview was shown); true if it came.
  bool poll() { return session_->poll(); }

  /// What is shown, as JSON: the lab, each input's value as text, the command line that
  /// reproduces it, the report (the command line's own --json), its table's rows, the
  /// views offered, and the motion's span.
  std::string state() {
    const lab::Session& s = *session_;
    Json values = Json::array();
    for (std::size_t i = 0; i < s.input_count(); ++i) {
      const lab::InputValue v = s.value(i);
      // a switch as its field reads it: on or off
      values.push_back(std::holds_alternative<bool>(v) ? (std::get<bool>(v) ? "on" : "off")
                                                       : lab::argument_text(v));
    }
    Json rows = Json::array();
    for (const lab::TableRow& r : s.report().rows()) {
      rows.push_back({{"key", r.key},
                      {"label", r.label},
                      {"value", r.value},
                      {"unit", r.unit},
                      {"textbook", r.textbook},
                      {"remark", r.remark},
                      {"heading", r.heading}});
    }
    const lab::Animation* motion = s.animation();
    return Json{{"lab", s.name()},
                {"title", s.title()},
                {"values", values},
                {"arguments", s.arguments()},
                {"command", explore::command_line(s)},
                {"at_textbook", s.at_textbook()},
                {"pending", s.pending()},
                {"whole_error", s.whole_error()},
                {"report", Json::parse(explore::shown_json_text(s))},
                {"rows", rows},
                {"scenes", explore::view_choices(s, true)},
                {"plots", explore::view_choices(s, false)},
                {"figures", figure_names()},
                {"seconds", motion != nullptr ? motion->seconds : 0.0},
                {"has_series", s.has_time_series()}}
        .dump();
  }

  /// The command line's --json for what is shown (waits for the whole report).
  std::string json() { return explore::json_text(*session_); }

  /// The command line's CSV and its CSV-on-the-Web metadata for `name` ("" if none).
  std::string csv() {
    session_->wait();
    return lab::csv_text(session_->report().time_series());
  }
  std::string csv_metadata(const std::string& csv_name) {
    session_->wait();
    return lab::csv_metadata_text(session_->report().time_series(), csv_name, RIGID_VERSION);
  }

  // The view: what is shown and how it is seen.
  void show(bool scene, int choice) { (scene ? view_.scene_choice : view_.plot_choice) = choice; }
  void seek(double time) { view_.time = std::clamp(time, 0.0, seconds()); }
  double seconds() const {
    const lab::Animation* motion = session_->animation();
    return motion != nullptr ? motion->seconds : 0.0;
  }
  void turn(double dx, double dy, double height) { view_.orbit.drag(dx, dy, height); }
  void turn_degrees(double right, double up) { view_.orbit.turn(right, up); }
  void wheel(double steps) { view_.orbit.wheel(steps); }
  void zoom(double factor) { view_.orbit.zoom_by(factor); }
  void reset_view() { view_.orbit = explore::Orbit{}; }

  /// The parts of the scene shown (its legend's entries), each with whether it is shown,
  /// and whether the legend is drawn: JSON {parts: [[name, shown], ...], legend}.
  std::string parts() {
    Json list = Json::array();
    for (const std::string& part : cache_.parts(*session_, view_)) {
      const auto& hidden = view_.hidden;
      list.push_back({part, std::find(hidden.begin(), hidden.end(), part) == hidden.end()});
    }
    return Json{{"parts", list}, {"legend", view_.legend}}.dump();
  }
  void toggle_part(const std::string& part) { view_.toggle_part(part); }
  void toggle_legend() { view_.toggle_legend(); }
  void interacting(bool held) { view_.interacting = held; }

  /// The smallest text a figure in the view is drawn with (ticks, legends), in the
  /// canvas's pixels: the page's own smallest text times the device's pixel ratio.
  void text_px(double px) { text_px_ = px; }

  /// Draws the scene into (sx, sy, sw, sh) and the plot into (px, py, pw, ph) of a
  /// canvas of canvas_width x canvas_height pixels (a rectangle of no width is left
  /// out), the time shown marked on the plot's panels against time; "" or why not.
  std::string draw(int sx, int sy, int sw, int sh, int px, int py, int pw, int ph, int canvas_width,
                   int canvas_height) {
    try {
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glViewport(0, 0, canvas_width, canvas_height);
      glClearColor(1, 1, 1, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      if (sw > 0 && sh > 0 && cache_.shown(*session_, view_) != nullptr) {
        // drawn again only when what it shows changed: not for a frame that only
        // moves the plot's time line, or a canvas laid out again at the same size
        const Drawn want = drawn(view_.scene_choice, sw, sh, view_.time);
        if (!(scene_drawn_.valid && scene_drawn_ == want)) {
          render::Scene3D scene = cache_.view_scene(*session_, view_, sw, sh);
          scene.min_text_px = text_px_;
          scene_image_.draw(scene, sw, sh);
          scene_drawn_ = want;
        }
        presenter_.show(scene_image_, sx, sy, canvas_height);
      }
      if (pw > 0 && ph > 0) draw_plot(px, py, pw, ph, canvas_height);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  }

  /// The figure `name` drawn into the canvas's top left at width x height as the
  /// command line draws it (no smallest text of the view's); "" or why not. What the
  /// tests read back from the canvas against the command line's figure.
  std::string draw_figure(const std::string& name, int width, int height, int canvas_height) {
    try {
      session_->wait();
      const lab::NamedFigure* f = explore::figure_named(*session_, name);
      if (f == nullptr) return "figure: no figure named '" + name + "'";
      render::LiveImage& image = f->is_scene() ? scene_image_ : plot_image_;
      (f->is_scene() ? scene_drawn_ : plot_drawn_) = Drawn{};  // the view draws its own again
      std::visit([&](const auto& figure) { image.draw(figure, width, height); }, f->figure);
      presenter_.show(image, 0, 0, canvas_height);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  }

  /// A figure's size from its text ("1600x1200"), read as the explorer reads it:
  /// {width, height} or {refused}.
  std::string figure_size(const std::string& text) const {
    int width = 0, height = 0;
    if (!explore::read_figure_size(text, width, height))
      return Json{{"refused", std::string(explore::kFigureSizeRule) + " (got '" + text + "')"}}
          .dump();
    return Json{{"width", width}, {"height", height}}.dump();
  }

  /// The figure `name` as a PNG, drawn as the command line draws it at width x height
  /// (by the GL rasteriser; empty if there is no such figure).
  emscripten::val figure_png(const std::string& name, int width, int height) {
    return exported([&] {
      session_->wait();
      const lab::NamedFigure* f = explore::figure_named(*session_, name);
      if (f == nullptr) throw std::invalid_argument("figure: no figure named '" + name + "'");
      std::visit([&](const auto& figure) { render::save_png(figure, kExport, width, height); },
                 f->figure);
    });
  }

  /// The scene as shown (the orbit, the time, the parts) as a PNG at width x height.
  emscripten::val view_png(int width, int height) {
    return exported([&] {
      if (cache_.shown(*session_, view_) == nullptr)
        throw std::invalid_argument("this lab draws no 3D scene");
      render::save_png(cache_.view_scene(*session_, view_, width, height), kExport, width, height);
    });
  }

  /// Why the last export gave nothing ("" if it gave its file).
  const std::string& export_error() const { return export_error_; }

 private:
  static constexpr const char* kExport = "/tmp/export.png";

  Json figure_names() const {
    Json out = Json::array();
    for (const lab::NamedFigure& f : session_->figures())
      out.push_back({{"name", f.name}, {"caption", f.caption}, {"scene", f.is_scene()}});
    return out;
  }

  using Drawn = explore::DrawnFrom;
  Drawn drawn(int choice, int width, int height, double time) const {
    return {session_->generation(), choice,   width, height, time, view_.orbit,
            view_.hidden_version,   text_px_, true};
  }

  void draw_plot(int x, int y, int width, int height, int canvas_height) {
    const lab::Animation* motion = session_->animation();
    // drawn once (the motion's strip too), the time shown laid over it as a line
    const Drawn want = drawn(view_.plot_choice, width, height, 0.0);
    if (!(plot_drawn_.valid && plot_drawn_ == want)) {
      std::optional<render::Plot2D> plot = explore::shown_plot(*session_, view_);
      plot_drawn_ = Drawn{};
      cursors_.clear();
      if (!plot) return;
      plot->min_text_px = text_px_;
      const render::Plot2D::Layout drawn = plot_image_.draw(*plot, width, height);
      if (motion != nullptr) cursors_ = explore::time_cursors(*plot, drawn);
      plot_drawn_ = want;
    }
    presenter_.show(plot_image_, x, y, canvas_height);
    // the time shown, a line across each panel against the motion's time
    const int line = std::max(2, static_cast<int>(std::lround(text_px_ / 8)));
    glEnable(GL_SCISSOR_TEST);
    glClearColor(0, 0, 0, 1);
    for (const explore::TimeCursor& c : cursors_) {
      const std::optional<double> at = c.x_at(view_.time);
      if (!at) continue;
      const int x0 = x + static_cast<int>(std::lround(*at)) - line / 2;
      const int top = y + static_cast<int>(std::lround(c.frame.y0));
      const int bottom = y + static_cast<int>(std::lround(c.frame.y1));
      glScissor(x0, canvas_height - bottom, line, bottom - top);
      glClear(GL_COLOR_BUFFER_BIT);
    }
    glDisable(GL_SCISSOR_TEST);
  }

  // The file `write` leaves at kExport, for the page to copy out at once; null, and
  // export_error() says why, if it failed.
  template <class Write>
  emscripten::val exported(Write write) {
    export_error_.clear();
    png_.clear();
    try {
      write();
    } catch (const std::exception& e) {
      export_error_ = e.what();
      std::remove(kExport);
      return emscripten::val::null();
    }
    return read_export();
  }

  emscripten::val read_export() {
    std::FILE* f = std::fopen(kExport, "rb");
    if (f == nullptr) return emscripten::val::null();
    png_.clear();
    unsigned char buffer[1 << 16];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;)
      png_.insert(png_.end(), buffer, buffer + n);
    std::fclose(f);
    std::remove(kExport);
    return emscripten::val(emscripten::typed_memory_view(png_.size(), png_.data()));
  }

  std::vector<lab::LabEntry> labs_;
  std::unique_ptr<lab::Session> session_;
  explore::ViewState view_;
  explore::SceneCache cache_;
  render::LiveImage scene_image_, plot_image_;
  Presenter presenter_;
  Drawn scene_drawn_, plot_drawn_;
  std::vector<explore::TimeCursor> cursors_;
  double text_px_ = 13;
  std::string export_error_;
  std::vector<unsigned char> png_;
};

}  // namespace rigid::web

EMSCRIPTEN_BINDINGS(rigidlab) {
  using rigid::web::Page;
  emscripten::class_<Page>("Page")
      .constructor<>()
      .function("labs", &Page::labs)
      .function("computeSeconds", &Page::compute_seconds)
      .function("attach", &Page::attach)
      .function("open", &Page::open)
      .function("set", &Page::set)
      .function("reset", &Page::reset)
      .function("poll", &Page::poll)
      .function("state", &Page::state)
      .function("json", &Page::json)
      .function("csv", &Page::csv)
      .function("csvMetadata", &Page::csv_metadata)
      .function("show", &Page::show)
      .function("seek", &Page::seek)
      .function("seconds", &Page::seconds)
      .function("turn", &Page::turn)
      .function("turnDegrees", &Page::turn_degrees)
      .function("figureSize", &Page::figure_size)
      .function("wheel", &Page::wheel)
      .function("zoom", &Page::zoom)
      .function("resetView", &Page::reset_view)
      .function("parts", &Page::parts)
      .function("togglePart", &Page::toggle_part)
      .function("toggleLegend", &Page::toggle_legend)
      .function("interacting", &Page::interacting)
      .function("draw", &Page::draw)
      .function("textPx", &Page::text_px)
      .function("drawFigure", &Page::draw_figure)
      .function("figurePng", &Page::figure_png)
      .function("viewPng", &Page::view_png)
      .function("exportError", &Page::export_error);
}
