// The explorer's panels, as Dear ImGui builds them each frame: the inputs (the lab's
// own rules as widgets) with the export section under them, the numbers (the report
// as the command line's table has it), and the time bar (play, the time, the speed,
// which scene and plot are shown, the scene's parts). A panel reads the lab's session
// and the view's state and queues what the user does (actions.h); it changes nothing
// else but the text being typed.
#pragma once

#include <vector>

#include "actions.h"
#include "common/registry.h"
#include "view_state.h"

namespace rigid::explore {

/// What a panel reads, and where it queues what the user does.
struct PanelContext {
  const std::vector<lab::LabEntry>& labs;
  const lab::Session& session;
  ViewState& view;
  std::vector<Action>& queue;
  const std::vector<std::string>& scene_parts;  ///< the scene's legend entries
  bool recording = false;                       ///< an animation is being written
  const char* recording_path = "";
};

/// The inputs panel (with the exports under it), `width` wide and `height` tall, at the
/// window's left.
void inputs_panel(const PanelContext& c, float width, float height);
/// The numbers panel at the window's right edge.
void numbers_panel(const lab::Session& s, float x, float width, float height);
/// The time bar (and the view choices) at (x, y), w × h.
void time_panel(const PanelContext& c, float x, float y, float w, float h);
/// The keys that act while no field is typed in: space, the arrows, 1 to 9.
void keys(const PanelContext& c);

}  // namespace rigid::explore
