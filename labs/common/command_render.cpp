// The command's drawing where the renderer is built (command_render.h): the figures
// as files, the motion as a film.
#include "common/command_render.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <future>
#include <iostream>
#include <memory>

#include "common/output_paths.h"
#include "rigid/render/context.h"
#include "rigid/render/draw.h"
#include "rigid/render/png.h"
#include "rigid/render/video.h"
#include "rigid/support/progress.h"
#include "rigid/support/text.h"

namespace rigid::lab {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The seconds since t0, and t0 moved to now.
double lap(Clock::time_point& t0) {
  const auto t1 = Clock::now();
  const double s = std::chrono::duration<double>(t1 - t0).count();
  t0 = t1;
  return s;
}

// ---- Figures ----------------------------------------------------------------

// The figures as files in the --figures directory. A PNG is encoded on a second thread
// while the next figure is drawn (the drawing needs the GL context, which is this
// thread's; the encoding only the pixels); finish() waits for the last and rethrows
// what failed.
class FigureFiles : public FigureSink {
 public:
  FigureFiles(const CommandOptions& options, const Report& report, RunOutputs& outputs,
              FigureLog& log)
      : options_(options), report_(report), outputs_(outputs), log_(log) {}
  FigureFiles(const FigureFiles&) = delete;
  FigureFiles& operator=(const FigureFiles&) = delete;
  ~FigureFiles() override {
    // a failure elsewhere: the encoding in flight is waited for, its own error dropped
    if (encoding_.valid()) encoding_.wait();
  }
  void add(const std::string& name, const std::string& caption, render::Plot2D plot) override {
    plot.title = report_.figure_title(plot.title);
    save(name, caption, plot);
  }
  void add(const std::string& name, const std::string& caption, render::Scene3D scene) override {
    scene.title = report_.figure_title(scene.title);
    save(name, caption, scene);
  }
  /// Waits for the last PNG; its error, if any, is thrown here.
  void finish();

 private:
  // What a figure took, its encoding's share known when that is done.
  struct Drawn {
    std::string file;
    double seconds = 0;
    render::FigureTiming phases;
  };
  template <class Figure>
  void save(const std::string& name, const std::string& caption, const Figure& figure);
  void record(const Drawn& drawn);

  const CommandOptions& options_;
  const Report& report_;
  RunOutputs& outputs_;
  FigureLog& log_;
  std::future<double> encoding_;  ///< the seconds the PNG in flight took to encode
  Drawn in_flight_;
};

template <class Figure>
void FigureFiles::save(const std::string& name, const std::string& caption, const Figure& figure) {
  const CommandOptions& o = options_;
  const std::string file = o.figure_file(name);
  const fs::path path = output_place(o.figures_dir) / file;
  if (fs::is_directory(path)) {
    throw InputError("--figures", "'" + path.string() + "' is a directory, not a figure");
  }
  outputs_.figures.push_back(file);
  outputs_.captions[file] = caption;
  const auto start = Clock::now();
  // --timing: where each figure's time went (the phases wait for the GL to finish each)
  Drawn drawn{file, 0.0, {}};
  render::FigureTiming* phases = o.timing ? &drawn.phases : nullptr;
  if (o.figure_format != render::FigureFormat::kPng) {
    render::save_figure(figure, path.string(), o.figure_format, o.figure_width, o.figure_height,
                        phases);
    drawn.seconds = seconds_since(start);
    record(drawn);
    return;
  }
  render::Image image = render::draw(figure, o.figure_width, o.figure_height, phases);
  drawn.seconds = seconds_since(start);
  finish();  // one PNG in flight at a time
  in_flight_ = std::move(drawn);
  encoding_ = std::async(std::launch::async, [image = std::move(image), path] {
    const auto t0 = Clock::now();
    render::write_png(image, path.string());
    return seconds_since(t0);
  });
}

void FigureFiles::finish() {
  if (!encoding_.valid()) return;
  const double encode = encoding_.get();
  in_flight_.seconds += encode;
  in_flight_.phases.encode = encode;
  record(in_flight_);
}

void FigureFiles::record(const Drawn& drawn) {
  const CommandOptions& o = options_;
  log_.seconds[drawn.file] = drawn.seconds;
  if (o.timing) {
    const render::FigureTiming& p = drawn.phases;
    log_.phases[drawn.file] = {{"setup", p.setup},
                               {"layout", p.layout},
                               {"draw", p.draw},
                               {"resolve", p.resolve},
                               {"encode", p.encode}};
  }
  // A figure the user made very large (past 4x the default's pixels) takes seconds
  // each: say so as each is drawn, rather than sit silent.
  if (static_cast<double>(o.figure_width) * o.figure_height > 4.0 * 1600 * 1200) {
    std::cerr << o.lab << ": drew " << drawn.file << " (" << o.figure_width << "x"
              << o.figure_height << ") in " << fmt::format("{:.1f}", drawn.seconds) << " s\n";
  }
}

// ---- Animation --------------------------------------------------------------

// Where the frames' time went (--timing): the GL phases waited for, as for figures.
struct FilmTiming {
  render::FigureTiming phases;
  double scene = 0.0, encoder_wait = 0.0, finish = 0.0;
  void add(const render::FigureTiming& f) {
    phases.setup += f.setup, phases.layout += f.layout, phases.draw += f.draw,
        phases.resolve += f.resolve;
  }
};

// What every frame of a film shares: its layout, one camera fitted to the union of
// frames spread over the motion, and one legend, of every part any frame shows.
struct Film {
  const CommandOptions& options;
  const Animation& motion;
  const Report& report;
  int frames = 0, width = 0, height = 0;
  int strip_height = 0, scene_height = 0;  // the scene above, the strip (if any) below
  render::Camera camera;
  std::shared_ptr<const render::Scene3D> legend;

  Film(const CommandOptions& o, const Animation& m, const Report& r)
      : options(o), motion(m), report(r) {
    frames = o.animation_frames();
    width = o.animation_width;
    height = o.animation_height;
    // both parts even, for H.264
    strip_height = m.strip ? 2 * static_cast<int>(std::lround(0.5 * m.strip_share * height)) : 0;
    scene_height = height - strip_height;
    render::Scene3D envelope = motion_envelope(m);
    envelope.title = r.figure_title(envelope.title);
    camera = render::fitted_camera(envelope, width, scene_height);
    legend = std::make_shared<const render::Scene3D>(envelope.legend_only());
  }
  double time(int k) const { return film_time(motion.seconds, k, frames); }

  // Frame k: the scene, with the strip below it if the motion has one.
  render::Image frame(int k, FilmTiming& timing) const {
    auto t0 = Clock::now();
    render::Scene3D scene = motion.scene(time(k));
    scene.title = report.figure_title(scene.title);
    scene.camera = camera;
    scene.legend_from = legend;
    timing.scene += lap(t0);
    render::FigureTiming f;
    render::FigureTiming* phases = options.timing ? &f : nullptr;
    render::Image image = render::draw(scene, width, scene_height, phases);
    timing.add(f);
    if (motion.strip) {
      render::Plot2D plot = motion.strip(time(k));
      plot.style_height = height;
      const render::Image below = render::draw(plot, width, strip_height, phases);
      timing.add(f);
      image.height = height;
      image.rgb.insert(image.rgb.end(), below.rgb.begin(), below.rgb.end());
    }
    return image;
  }
};

// What the report says of a film written.
Json film_record(const Film& film, std::size_t bytes, double seconds, const FilmTiming& timing) {
  const CommandOptions& o = film.options;
  Json record = {{"path", output_place(o.animation_path).string()},
                 {"caption", film.motion.caption},
                 {"frames", film.frames},
                 {"fps", o.animation_fps},
                 {"duration_s", film.frames / o.animation_fps},
                 {"motion_s", film.motion.seconds},
                 {"width", film.width},
                 {"height", film.height},
                 {"bytes", bytes},
                 {"seconds", seconds}};
  if (!film.motion.still.empty()) record["still"] = o.figure_file(film.motion.still);
  if (o.timing) {
    const render::FigureTiming& p = timing.phases;
    record["phases"] = {{"scene", timing.scene},  {"setup", p.setup},
                        {"layout", p.layout},     {"draw", p.draw},
                        {"resolve", p.resolve},   {"encoder_wait", timing.encoder_wait},
                        {"finish", timing.finish}};
  }
  return record;
}

}  // namespace

std::string renderer_missing() {
  return "";
}

bool animation_format_known(const std::string& path) {
  return render::video_format_for(path).has_value();
}

void draw_figures(const CommandOptions& options, const Computed& computed, RunOutputs& outputs,
                  FigureLog& log) {
  // The GL context is made once per process, before any figure is drawn and
  // timed (bench/ reports it on its own, like matplotlib's import).
  render::context();
  FigureFiles sink(options, *computed.report, outputs, log);
  computed.figures(sink);
  sink.finish();
}

// The frames are drawn at their own times while a second thread encodes them
// (render/video.h).
Json encode_animation(const CommandOptions& options, const Animation& motion,
                      const Report& report) {
  const auto start = Clock::now();
  render::context();
  const Film film(options, motion, report);
  const std::string& path = options.animation_path;
  render::VideoWriter writer(path, *render::video_format_for(path),
                             {film.width, film.height, options.animation_fps});
  support::Progress progress(options.lab, "animation frames", film.frames, options.quiet);
  FilmTiming timing;
  for (int k = 0; k < film.frames; ++k) {
    render::Image image = film.frame(k, timing);
    auto t0 = Clock::now();
    writer.add(std::move(image));  // waits while two frames are still being encoded
    timing.encoder_wait += lap(t0);
    progress.update(k + 1);
  }
  auto t_finish = Clock::now();
  const std::size_t bytes = writer.finish();
  timing.finish = lap(t_finish);
  const double seconds = seconds_since(start);
  progress.finish(fmt::format(
      "wrote {}: {} frames, {}x{} at {:g} fps ({:g} s of video for {:.3g} s of motion), "
      "{:.1f} MB, in {:.1f} s",
      support::terminal_safe(path), film.frames, film.width, film.height, options.animation_fps,
      film.frames / options.animation_fps, motion.seconds, bytes / 1e6, seconds));
  return film_record(film, bytes, seconds, timing);
}

}  // namespace rigid::lab
