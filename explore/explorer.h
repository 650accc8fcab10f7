// The explorer: one lab live in a window. Its inputs as widgets made from the lab's
// own rules, its scene drawn by render_gl with a camera the mouse turns, the motion
// played, its report and plots recomputed on every change, and what is shown
// exported. It holds the view's state (the orbit, the time, what is shown, the
// typed text and its refusals) apart from the lab's, which is a lab::Session:
// the explorer computes nothing itself.
//
// frame() builds and draws one frame and never blocks: a desktop loop calls it
// between waiting for events, a browser's would call it from its animation frame.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/registry.h"
#include "orbit.h"
#include "rigid/render/figure_format.h"
#include "rigid/render/live.h"
#include "rigid/render/rect.h"

namespace rigid::explore {

using lab::LabEntry;

class Script;

/// The rule of an exported figure's size, and "1600x1200" read by it (false: broken).
extern const char* const kFigureSizeRule;
bool read_figure_size(const std::string& text, int& width, int& height);

/// What the window does for the explorer: its size, time, clipboard and pixels.
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
  /// Opens `lab` (a name of all_labs()) at the textbook's example; throws
  /// std::invalid_argument if there is no such lab.
  Explorer(std::vector<LabEntry> labs, const std::string& lab, Window window);
  ~Explorer();

  /// Sets a lab's input from its text (as typed in its field or given on the command
  /// line); the refusal's one line, or "" if taken.
  std::string set_text(const std::string& flag, const std::string& text);
  /// The playing speed (times real time), within 0.1 and 10, or up to playing a long
  /// motion in 10 s.
  void set_speed(double speed);
  /// Back to the text's example, refusals cleared.
  void textbook();
  /// Runs `script` (script.h) from the next frame, a step a frame.
  void run(std::unique_ptr<Script> script);

  /// Builds this frame's UI (between ImGui::NewFrame and ImGui::Render) and draws the
  /// figures it shows into their textures; `seconds` is the wall time since the last frame.
  void frame(double seconds);
  /// After the frame is drawn and before it is shown: a screenshot asked for is taken.
  void after_render();
  /// Whether the next frame must come without waiting for an event (playing, a script,
  /// a recording under way).
  bool animating() const;
  /// Whether a script runs, not waiting (its frames are not paced to the display).
  bool scripted() const;
  /// The exit status once the window has closed: 0, or what a failed script asks.
  int status() const { return status_; }

  /// The lab shown.
  lab::Session& session() { return *session_; }

 private:
  friend class Script;
  struct Field;
  void open(const std::string& name);
  void after_change();
  void inputs_panel();
  void input_widget(std::size_t i);
  void numbers_panel();
  void time_panel(float x, float y, float w, float h);
  void scene_view(float x, float y, float w, float h);
  void plot_view(float x, float y, float w, float h);
  void export_section();
  void step_script();
  void say(const std::string& text, bool error = false);

  // What is shown: the motion or a figure of the lab.
  const render::Scene3D* shown_scene() const;
  render::Camera base_camera(int width, int height);
  std::optional<render::Plot2D> shown_plot() const;
  render::Scene3D view_scene(int width, int height);
  const lab::Animation* exact_motion() const;
  /// Shows or hides a part of the scene (a legend entry's label).
  void toggle(const std::string& label);
  /// The scene's parts that can be shown or hidden: its legend's entries.
  std::vector<std::string> scene_parts() const;

  // Exports, each through the lab's own writers; "" or the error.
  std::string save_figure(const std::string& name, const std::string& path,
                          render::FigureFormat format, int w, int h);
  std::string save_view(const std::string& path, int w, int h);
  std::string export_json(const std::string& path);
  std::string export_csv(const std::string& path);
  std::string record(const std::string& path);
  std::string command_line() const;
  std::string json_text() const;

  std::vector<LabEntry> labs_;
  std::size_t lab_index_ = 0;
  std::unique_ptr<lab::Session> session_;
  Window window_;
  std::vector<Field> fields_;

  // the view
  Orbit orbit_;
  int scene_choice_ = 0;  // 0: the motion (if any), else a figure of the lab
  int plot_choice_ = 0;   // 0: the motion's strip (if any), else a 2D figure of the lab
  double time_ = 0.0, speed_ = 1.0;
  bool playing_ = false;
  bool long_motion_ = false;  // the motion shown is longer than 10 s at 10x
  // the exact motion beside an integrator's, for the inputs of exact_generation_
  mutable std::unique_ptr<lab::Session> exact_session_;
  mutable long exact_generation_ = -1;
  struct Fit {
    long generation = -1;
    int choice = -1, width = 0, height = 0;
    std::size_t lab = 0;
    render::Camera camera;
  } fit_;
  bool interacting_ = false;      // an input's slider or drag is held this frame
  bool script_dragging_ = false;  // a script's `drag` acts as one
  render::LiveImage scene_image_, plot_image_;
  struct Drawn {
    long generation = -1;
    int choice = -1, width = 0, height = 0;
    double time = -1.0;
    Orbit orbit;
    bool valid = false;
    long hidden = 0;
  } scene_drawn_, plot_drawn_;
  // the motion's scene at a time, made once a frame
  struct MotionScene {
    long generation = -1;
    double time = -1.0;
    std::size_t lab = 0;
    render::Scene3D scene;
  };
  mutable MotionScene motion_scene_;
  // the whole motion's scenes spread over it (lab::motion_envelope): what the camera is
  // fitted to; and with the exact motion's ghost, the legend every frame keeps
  struct MotionEnvelope {
    long generation = -1;
    std::size_t lab = 0;
    std::shared_ptr<const render::Scene3D> scene, legend;
  };
  mutable MotionEnvelope motion_envelope_;
  const MotionEnvelope& motion_envelope() const;
  // the plot's panels against the motion's time: where the time cursor goes
  struct Cursor {
    render::ScreenRect frame;
    double x_lo = 0, x_hi = 1;
  };
  std::vector<Cursor> cursors_;
  std::vector<std::string> hidden_;  // the scene's parts (legend entries) not shown
  long hidden_version_ = 0;
  std::string draw_error_;

  // exports
  std::string export_path_, figure_size_ = "1600x1200";
  int export_figure_ = 0;
  std::string message_;
  bool message_error_ = false;
  struct Recording;
  std::unique_ptr<Recording> recording_;

  std::string screenshot_path_;
  std::unique_ptr<Script> script_;
  int status_ = 0;
};

}  // namespace rigid::explore
