// What the explorer's user sees and has set, apart from the lab's own state (a
// lab::Session): the text in each field and the rule it broke, the orbit, the time,
// which scene and plot are shown and which of the scene's parts are hidden, and the
// export section's fields. Plain data: the explorer's actions (actions.h) change it at
// one point a frame, the panels read it (and write only the text being typed).
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "common/figures.h"
#include "orbit.h"

namespace rigid::explore {

// The playing speed's span, times real time. A motion longer than kLongMotionPlay s at
// the fastest (the Earth's precession takes two days) plays faster at first: in
// kLongMotionPlay seconds, and the speed reaches that far.
constexpr double kMinSpeed = 0.1, kMaxSpeed = 10.0;
constexpr double kLongMotionPlay = 10.0;
inline double fastest(const lab::Animation& motion) {
  return std::max(kMaxSpeed, motion.seconds / kLongMotionPlay);
}
/// A script's frame, and a step of the arrows: 1/30 s of the motion at speed 1, so a
/// script plays the same on any machine.
constexpr double kScriptFrameSeconds = 1.0 / 30.0;

/// What a field shows: the text as typed, and the rule it broke ("" if none).
struct Field {
  std::string text;
  std::string refusal;
};

struct ViewState {
  std::vector<Field> fields;  ///< one an input, in the table's order
  Orbit orbit;
  int scene_choice = 0;  ///< 0: the motion (if any), else a figure of the lab
  int plot_choice = 0;   ///< 0: the motion's strip (if any), else a 2D figure of the lab
  double time = 0.0;     ///< in the motion, s
  double speed = 1.0;    ///< times real time
  bool playing = false;
  bool long_motion = false;         ///< the motion shown is longer than 10 s at 10x
  bool interacting = false;         ///< an input's slider or drag is held this frame
  std::vector<std::string> hidden;  ///< the scene's parts (legend entries) not shown
  long hidden_version = 0;          ///< moves when `hidden` or `legend` does
  bool legend = true;               ///< the scene's legend drawn over it, or collapsed

  /// A part of the scene (its legend entry) hidden if shown, shown if hidden.
  void toggle_part(const std::string& part) {
    const auto at = std::find(hidden.begin(), hidden.end(), part);
    if (at == hidden.end()) {
      hidden.push_back(part);
    } else {
      hidden.erase(at);
    }
    ++hidden_version;
  }
  /// The scene's legend drawn over it, or collapsed.
  void toggle_legend() {
    legend = !legend;
    ++hidden_version;  // what is drawn changed
  }

  // the export section
  std::string export_path, figure_size = "1600x1200";
  int export_figure = 0;
  /// The export's figure as last named (shown while the lab's figures are not yet described
  /// for the current inputs: their names do not change with them).
  std::string export_figure_name;
  std::string message;  ///< the last export's or command's line
  bool message_error = false;
};

}  // namespace rigid::explore
