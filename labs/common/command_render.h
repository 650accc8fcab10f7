// What the command needs of the renderer, in one place. CMake compiles one of two
// files behind it: command_render.cpp where the renderer is built (rigid::render_gl),
// which draws the figures and encodes the animation; command_no_render.cpp where it
// is not (RIGID_BUILD_RENDER=OFF), which says so, so that the command line refuses
// --figures and --animate before any work.
#pragma once

#include <string>

#include "common/command.h"
#include "common/command_options.h"
#include "common/writers.h"

namespace rigid::lab {

/// Why this build cannot draw ("" where it can).
std::string renderer_missing();

/// Whether `path` ends in an animation format's extension (.mp4 or .webp, any case).
bool animation_format_known(const std::string& path);

/// Where the figures' time went: each file's seconds, and with --timing its phases.
struct FigureLog {
  Json seconds = Json::object();
  Json phases = Json::object();
};

/// Draws the lab's figures into options.figures_dir (which exists), one file each
/// (CommandOptions::figure_file), listing each with its caption in `outputs` and its
/// time in `log`; throws what failed (an InputError for a figure's path).
void draw_figures(const CommandOptions& options, const Computed& computed, RunOutputs& outputs,
                  FigureLog& log);

/// Encodes `motion` into options.animation_path (frames at film_time, one camera fitted
/// to the whole motion); returns what the report says of it (RunOutputs::animation).
/// Throws std::invalid_argument for what the options ask that cannot be drawn.
Json encode_animation(const CommandOptions& options, const Animation& motion, const Report& report);

}  // namespace rigid::lab
