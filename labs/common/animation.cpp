// The animation layer of the labs: --animate FILE writes the lab's motion as an
// animated WebP or an H.264 MP4 (by the file's extension), --fps and --duration
// set the video's frame rate and length, --animation-size its pixels. A lab
// describes one frame as a Scene3D at a time of its motion (Lab::animate); this
// layer samples the frame times, fits one camera to the whole motion, draws the
// frames while a second thread encodes them (render/video.h), shows progress on
// stderr, and lists the file in the JSON. Nothing of it loads without --animate.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "common/lab.h"
#include "common/progress.h"
#include "rigid/render/plot2d.h"
#include "rigid/render/scene3d.h"

#if RIGID_HAVE_RENDER
#include "rigid/render/context.h"
#include "rigid/render/video.h"
#endif

namespace rigid::lab {
namespace fs = std::filesystem;

namespace {

// Frames a camera is fitted to: spread over the motion, so whatever moves stays in view.
constexpr int kFitSamples = 16;

// "1280x720" into width and height; empty if it breaks the rule.
std::string parse_size(const std::string& text, int& width, int& height) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  const int read = std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra);
  // H.264's 4:2:0 chroma needs even sizes; the figure style is laid out from 320x240 up
  if (read != 3 || (x != 'x' && x != 'X') || w < 320 || h < 240 || w > 3840 || h > 2160 ||
      w % 2 != 0 || h % 2 != 0) {
    return "must be WxH, both even, with 320 <= W <= 3840 and 240 <= H <= 2160 (got '" + text +
           "')";
  }
  width = w;
  height = h;
  return "";
}

}  // namespace

void Lab::enable_animation() {
  animation_enabled_ = true;
  app_.add_option("--animate", animation_path_,
                  "write the motion as an animation to FILE: .mp4 (H.264, for players and "
                  "slides) or .webp (animated WebP, for browsers and READMEs)")
      ->type_name("FILE");
  // a number in [lo, hi] or the rule, as the options' errors say it
  const auto in_range = [](double lo, double hi, std::string what) {
    return CLI::Validator(
        [=](std::string& text) -> std::string {
          char* end = nullptr;
          const double v = std::strtod(text.c_str(), &end);
          if (end == text.c_str() || *end != '\0' || !(v >= lo && v <= hi))
            return fmt::format("must be {} from {:g} to {:g} (got '{}')", what, lo, hi, text);
          return "";
        },
        "");
  };
  app_.add_option("--fps", animation_fps_, "frames a second of the animation, 1 to 120")
      ->type_name("NUMBER")
      ->capture_default_str()
      ->check(in_range(1.0, 120.0, "a number"));
  app_.add_option("--duration", animation_duration_,
                  "length of the animation in seconds, 0.1 to 600 (the motion to --t-end is "
                  "shown in it)")
      ->type_name("NUMBER")
      ->capture_default_str()
      ->check(in_range(0.1, 600.0, "a number of seconds"));
  app_.add_option("--animation-size", animation_size_,
                  "animation size in pixels, even, 320x240 to 3840x2160")
      ->type_name("WxH")
      ->capture_default_str()
      ->check(CLI::Validator(
          [this](std::string& text) -> std::string {
            return parse_size(text, animation_width_, animation_height_);
          },
          ""));
}

namespace {
// Frame k at k/frames of the motion (the last frame one short of its end, so a periodic
// motion loops without a repeated frame), the camera fitted at kFitSamples more.
int frame_count(double duration, double fps) {
  return std::max(1, static_cast<int>(std::lround(duration * fps)));
}
double frame_time(double motion_seconds, int k, int frames) {
  return motion_seconds * k / frames;
}
}  // namespace

std::vector<double> Lab::animation_times(double motion_seconds) const {
  const int frames = frame_count(animation_duration_, animation_fps_);
  std::vector<double> times;
  for (int k = 0; k < frames; ++k) times.push_back(frame_time(motion_seconds, k, frames));
  for (int k = 0; k < kFitSamples; ++k) times.push_back(frame_time(motion_seconds, k, kFitSamples));
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

void Lab::check_animation_path() const {
  if (!animation_enabled_ || app_.count("--animate") == 0) {
    for (const char* flag : {"--fps", "--duration", "--animation-size"}) {
      if (animation_enabled_ && app_.count(flag) > 0)
        throw UsageError(flag, "sets the animation: give --animate FILE too");
    }
    return;
  }
  if (animation_path_.empty()) throw UsageError("--animate", "needs a file name");
#if RIGID_HAVE_RENDER
  if (!render::video_format_for(animation_path_)) {
    throw UsageError("--animate",
                     "the file name must end in .mp4 or .webp (got '" + animation_path_ + "')");
  }
#endif
  std::error_code ec;
  const fs::path path = fs::absolute(animation_path_, ec);
  const fs::file_status status = fs::symlink_status(path, ec);
  if (!ec && fs::exists(status) && !fs::is_regular_file(status)) {
    throw UsageError("--animate", "'" + animation_path_ + "' exists and is not a regular file");
  }
  const fs::path parent = path.parent_path();
  if (!fs::is_directory(parent, ec) || !can_create_in(parent.string())) {
    throw UsageError("--animate", "cannot write into directory '" + parent.string() + "'");
  }
}

void Lab::animate(double motion_seconds, const std::string& caption,
                  const std::function<render::Scene3D(double)>& frame, const std::string& still) {
  animate(motion_seconds, caption, frame, {}, 0.0, still);
}

void Lab::animate(double motion_seconds, const std::string& caption,
                  const std::function<render::Scene3D(double)>& frame,
                  const std::function<render::Plot2D(double)>& strip, double strip_share,
                  const std::string& still) {
  if (animation_path_.empty()) return;
  if (!(motion_seconds > 0.0) || !std::isfinite(motion_seconds)) {
    throw UsageError("--animate", "there is no motion to show (its span is not positive)");
  }
#if RIGID_HAVE_RENDER
  const auto start = std::chrono::steady_clock::now();
  const int frames = frame_count(animation_duration_, animation_fps_);
  const auto motion_time = [&](int k) { return frame_time(motion_seconds, k, frames); };
  const int w = animation_width_, h = animation_height_;
  // the scene above, the strip (if any) below: both even, for H.264
  const int h_strip = strip ? 2 * static_cast<int>(std::lround(0.5 * strip_share * h)) : 0;
  const int h_scene = h - h_strip;
  try {
    render::context();
    // one camera for every frame, fitted to the union of frames spread over the motion;
    // RIGID_ANIMATION_FIT=first fits it to the first frame alone, as its still figure is
    // fitted (for the test that the first frame is the still figure's scene)
    render::Scene3D envelope = frame(0.0);
    envelope.title = scene_title(envelope.title);
    const char* fit = std::getenv("RIGID_ANIMATION_FIT");
    const bool first_only = fit != nullptr && std::string(fit) == "first";
    for (int k = 1; k < kFitSamples && !first_only; ++k)
      envelope.merge(frame(frame_time(motion_seconds, k, kFitSamples)));
    const render::Camera camera = envelope.fitted_camera(w, h_scene);

    render::VideoWriter writer(animation_path_, *render::video_format_for(animation_path_),
                               {w, h, animation_fps_});
    Progress progress(name_, "animation frames", frames, quiet_);
    // --timing: where the frames' time went (the GL phases waited for, as for figures)
    render::FigureTiming phases;
    double build = 0.0, handover = 0.0;
    const auto lap = [](std::chrono::steady_clock::time_point& t0) {
      const auto t1 = std::chrono::steady_clock::now();
      const double s = std::chrono::duration<double>(t1 - t0).count();
      t0 = t1;
      return s;
    };
    for (int k = 0; k < frames; ++k) {
      auto t0 = std::chrono::steady_clock::now();
      render::Scene3D scene = frame(motion_time(k));
      scene.title = scene_title(scene.title);
      scene.camera = camera;
      build += lap(t0);
      render::FigureTiming f;
      render::Image image = scene.render(w, h_scene, timing_ ? &f : nullptr);
      phases.setup += f.setup, phases.layout += f.layout, phases.draw += f.draw,
          phases.resolve += f.resolve;
      if (strip) {
        render::Plot2D plot = strip(motion_time(k));
        plot.style_height = h;
        const render::Image below = plot.render(w, h_strip, timing_ ? &f : nullptr);
        phases.setup += f.setup, phases.layout += f.layout, phases.draw += f.draw,
            phases.resolve += f.resolve;
        image.height = h;
        image.rgb.insert(image.rgb.end(), below.rgb.begin(), below.rgb.end());
      }
      lap(t0);
      writer.add(std::move(image));  // waits while two frames are still being encoded
      handover += lap(t0);
      progress.update(k + 1);
    }
    auto t_finish = std::chrono::steady_clock::now();
    const std::size_t bytes = writer.finish();
    const double finishing = lap(t_finish);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::error_code ec;
    animation_ = {{"path", fs::absolute(animation_path_, ec).lexically_normal().string()},
                  {"caption", caption},
                  {"frames", frames},
                  {"fps", animation_fps_},
                  {"duration_s", frames / animation_fps_},
                  {"motion_s", motion_seconds},
                  {"width", w},
                  {"height", h},
                  {"bytes", bytes},
                  {"seconds", seconds}};
    if (!still.empty()) animation_["still"] = figure_prefix_ + name_ + "_" + still + ".png";
    if (timing_) {
      animation_["phases"] = {
          {"scene", build},      {"setup", phases.setup},     {"layout", phases.layout},
          {"draw", phases.draw}, {"resolve", phases.resolve}, {"encoder_wait", handover},
          {"finish", finishing}};
    }
    progress.finish(fmt::format(
        "wrote {}: {} frames, {}x{} at {:g} fps ({:g} s of video for {:.3g} s of motion), "
        "{:.1f} MB, in {:.1f} s",
        animation_path_, frames, w, h, animation_fps_, frames / animation_fps_, motion_seconds,
        bytes / 1e6, seconds));
  } catch (const UsageError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw UsageError("--animate", e.what());
  } catch (const std::exception& e) {
    figures_failed_ = true;
    std::cerr << name_ << ": error: --animate: " << e.what() << '\n';
  }
#else
  (void)frame;
  (void)caption;
  (void)strip;
  (void)strip_share;
  (void)still;
  figures_failed_ = true;
  std::cerr << name_ << ": error: --animate: this build has no renderer (RIGID_BUILD_RENDER=OFF)\n";
#endif
}

}  // namespace rigid::lab
