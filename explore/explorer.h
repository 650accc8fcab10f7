// The explorer: one lab live in a window. Its inputs as widgets made from the lab's
// own rules, its scene drawn by render_gl with a camera the mouse turns, the motion
// played, its report and plots recomputed on every change, and what is shown
// exported. Three things apart, as in MuJoCo's simulate:
//  - the lab's state, a lab::Session (the explorer computes nothing itself);
//  - what the user sees and has set, a plain ViewState (view_state.h);
//  - what the scene view draws, made from both and kept (SceneCache, Views).
// The panels and the mouse queue actions (actions.h); frame() applies them at one
// point, before it builds the panels, and a script applies the same actions.
//
// frame() builds and draws one frame and never waits: another lab is opened, and the
// one left closed, off the frame's thread (LabLoader); a slow report comes on a thread
// of its own (lab::Session), and an export that needs it waits in the queue, the frames
// going on. A desktop loop calls frame() between waiting for events, a browser's would
// call it from its animation frame.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "actions.h"
#include "common/registry.h"
#include "lab_loader.h"
#include "rigid/render/image.h"
#include "rigid/support/subprocess.h"
#include "scene_cache.h"
#include "view_state.h"
#include "views.h"

namespace rigid::explore {

using lab::LabEntry;

class Script;

/// What the window does for the explorer: its clipboard, pixels, closing and title.
struct Window {
  std::function<void(const std::string&)> set_clipboard;
  /// Reads the frame just drawn (before it is shown), rows top to bottom.
  std::function<render::Image()> read_frame;
  /// Asks the window to close after this frame.
  std::function<void()> close;
  /// Names the window (the lab shown).
  std::function<void(const std::string&)> set_title;
};

class Explorer {
 public:
  /// Opens `lab` (a name of `labs`) at the textbook's example, at once; throws
  /// std::invalid_argument if there is no such lab.
  Explorer(std::vector<LabEntry> labs, const std::string& lab, Window window);
  ~Explorer();

  /// Queues `action`, applied at the start of the next frame.
  void queue(Action action);
  /// Applies `action` now, between frames (a script's step, the command line's inputs);
  /// "" or the one line that says why it was refused or failed.
  std::string apply(const Action& action);
  /// Runs `script` (script.h) from the next frame, a step a frame.
  void run(std::unique_ptr<Script> script);
  /// What an export or a recording names that the lab shown does not have (a figure, a
  /// 3D scene, a time series, a motion): "" if it has it all. Waits for the whole report
  /// where the answer is in it.
  std::string unavailable(const Action& action);

  /// Applies what was queued, then builds this frame's UI (between ImGui::NewFrame and
  /// ImGui::Render) and draws the figures it shows into their textures; `seconds` is the
  /// wall time since the last frame.
  void frame(double seconds);
  /// After the frame is drawn and before it is shown: a screenshot asked for is taken.
  void after_render();
  /// Whether the next frame must come without waiting for an event (playing, a script,
  /// a recording, a lab or a report under way, an action queued).
  bool animating() const;
  /// Whether a script runs, not waiting (its frames are not paced to the display).
  bool scripted() const;
  /// The exit status once the window has closed: 0, or what a failed script asks.
  int status() const { return status_; }

  /// The lab shown, and what the user sees of it.
  const lab::Session& session() const { return *session_; }
  const ViewState& view() const { return view_; }
  /// The views as drawn, for a test to read.
  const Views& views() const { return views_; }
  /// Where the last frame's time went, in seconds: the queued actions applied (a changed
  /// input's compute() with them), the scene's parts (Views::SceneTiming), and the rest of
  /// the window's widgets built. Kept only after timed(true), which waits for the GL at
  /// the end of each of the scene's phases.
  struct FramePhases {
    double actions = 0, widgets = 0;
    Views::SceneTiming scene;
  };
  void timed(bool on) {
    timed_ = on;
    views_.timed(on);
  }
  const FramePhases& phases() const { return phases_; }
  /// Whether a lab asked for is still opening (the one before is shown meanwhile).
  bool opening() const { return loader_.opening(); }
  /// Whether an animation is being written.
  bool recording() const { return recording_.has_value(); }
  /// The JSON the command line prints for the inputs shown (waits for the whole report).
  std::string json_text();
  /// The command line that reproduces the inputs shown.
  std::string command_line() const;

 private:
  struct Apply;
  // An animation written by the lab's own command (`LAB ... --animate FILE`) while the
  // window goes on.
  struct Recording {
    support::Subprocess child;
    std::string path, err;
  };
  void sync(double seconds);
  void apply_queued();
  void build_ui();
  void install(std::size_t index, std::unique_ptr<lab::Session> session);
  void after_change();
  void set_speed(double speed);
  void toggle(const std::string& part);
  void poll_recording();
  void step_script();
  void end_script(int status);
  void failed_write(const std::string& line);
  void say(const std::string& text, bool error = false);

  std::vector<LabEntry> labs_;
  std::size_t lab_index_ = 0;
  std::unique_ptr<lab::Session> session_;
  Window window_;
  ViewState view_;
  SceneCache scenes_;
  Views views_;
  LabLoader loader_;
  std::vector<Action> queued_;
  bool script_held_ = false;  // a script's `drag` holds its slider this frame
  bool timed_ = false;
  FramePhases phases_;
  std::optional<Recording> recording_;
  std::string screenshot_path_;
  std::unique_ptr<Script> script_;
  int status_ = 0;
};

}  // namespace rigid::explore
