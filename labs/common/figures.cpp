#include "common/figures.h"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#if RIGID_HAVE_RENDER
#include "rigid/render/context.h"
#endif

namespace rigid::lab {
namespace fs = std::filesystem;

std::string FigureSet::title(const std::string& own) const {
  return lab_.scene_title(own);
}

std::string Lab::scene_title(const std::string& own) const {
  // The lab's name in text markup: '_' would start a subscript.
  std::string text;
  for (char c : name_) text += c == '_' ? std::string("\\_") : std::string(1, c);
  const std::string inputs = title_inputs();
  if (!inputs.empty()) text += ": " + inputs;
  if (!own.empty()) text += ": " + own;
  return text;
}

template <class Figure>
void FigureSet::save(const std::string& name, const std::string& caption, const Figure& figure) {
  const std::string file = lab_.figure_prefix_ + lab_.name_ + "_" + name + ".png";
  const fs::path path = fs::path(lab_.figures_dir_) / file;
  if (fs::is_directory(path)) {
    throw UsageError("--figures", "'" + path.string() + "' is a directory, not a figure");
  }
  const auto start = std::chrono::steady_clock::now();
#if RIGID_HAVE_RENDER
  // --timing: where each figure's time went (the phases wait for the GL to finish each)
  render::FigureTiming phases;
  figure.save(path.string(), lab_.figure_width_, lab_.figure_height_,
              lab_.timing_ ? &phases : nullptr);
  if (lab_.timing_) {
    lab_.figure_phases_[file] = {{"setup", phases.setup},
                                 {"layout", phases.layout},
                                 {"draw", phases.draw},
                                 {"resolve", phases.resolve},
                                 {"encode", phases.encode}};
  }
#else
  (void)figure;
  throw std::runtime_error("this build has no renderer (RIGID_BUILD_RENDER=OFF)");
#endif
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  lab_.figures_.push_back(file);
  lab_.captions_[file] = caption;
  lab_.figure_seconds_[file] = elapsed.count();
  // A figure the user made very large (past 4x the default's pixels) takes seconds
  // each: say so as each is drawn, rather than sit silent (issue 10).
  if (static_cast<double>(lab_.figure_width_) * lab_.figure_height_ > 4.0 * 1600 * 1200) {
    std::cerr << lab_.name_ << ": drew " << file << " (" << lab_.figure_width_ << "x"
              << lab_.figure_height_ << ") in " << fmt::format("{:.1f}", elapsed.count()) << " s\n";
  }
}

void FigureSet::add(const std::string& name, const std::string& caption, render::Plot2D plot) {
  plot.title = title(plot.title);
  save(name, caption, plot);
}

void FigureSet::add(const std::string& name, const std::string& caption, render::Scene3D scene) {
  scene.title = title(scene.title);
  save(name, caption, scene);
}

void Lab::figures(const std::function<void(FigureSet&)>& draw) {
  if (figures_dir_.empty()) return;
  std::error_code error;
  fs::create_directories(figures_dir_, error);
  if (error) {
    throw UsageError("--figures",
                     "cannot create directory '" + figures_dir_ + "': " + error.message());
  }
  try {
#if RIGID_HAVE_RENDER
    // The GL context is made once per process, before any figure is drawn and
    // timed (bench/ reports it on its own, like matplotlib's import).
    render::context();
#else
    throw std::runtime_error("this build has no renderer (RIGID_BUILD_RENDER=OFF)");
#endif
    FigureSet set(*this);
    draw(set);
  } catch (const UsageError&) {
    throw;
  } catch (const std::exception& e) {
    figures_failed_ = true;
    std::cerr << name_ << ": error: --figures: " << e.what() << '\n';
  }
}

}  // namespace rigid::lab
