// The command's own options, as pbrt's Options struct: filled from argv by the
// command line (command_line.h), then read by the outputs (command_outputs.h) and
// the renderer (command_render.h), none of which sees argv. The lab's own inputs go
// to its Inputs, not here.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rigid/render/figure_format.h"

namespace rigid::lab {

/// What the command writes, and where.
struct CommandOptions {
  std::string lab;                    ///< the lab's name: its files' and messages' prefix
  std::vector<std::string> command;   ///< argv as given
  std::vector<std::string> warnings;  ///< the command's own (an old option name used)

  bool json = false;    ///< --json: one JSON object on stdout instead of the table
  bool quiet = false;   ///< --quiet: no table
  bool timing = false;  ///< --timing: where each figure's time went, in the JSON

  std::string figures_dir;  ///< --figures DIR ("": no figures)
  std::string figure_prefix;
  render::FigureFormat figure_format = render::FigureFormat::kPng;
  int figure_width = 1600, figure_height = 1200;

  std::string csv_path;  ///< --csv FILE ("": none)

  std::string animation_path;  ///< --animate FILE ("": none)
  double animation_fps = 30.0, animation_duration = 10.0;
  int animation_width = 1280, animation_height = 720;

  /// ".png", ".svg" or ".pdf": the figure files' ending.
  std::string figure_extension() const {
    return "." + std::string(render::figure_format_name(figure_format));
  }
  /// The file of figure `name`: <prefix><lab>_<name>.<format>.
  std::string figure_file(const std::string& name) const {
    return figure_prefix + lab + "_" + name + figure_extension();
  }
  /// The animation's frames: its duration at its rate, at least one.
  int animation_frames() const {
    return std::max(1, static_cast<int>(std::lround(animation_duration * animation_fps)));
  }
};

}  // namespace rigid::lab
