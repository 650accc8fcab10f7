// The explorer's frame: the actions applied, the panels and views built (explorer.h).
#include "explorer.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <system_error>

#include "exports.h"
#include "panels.h"
#include "rigid/render/png.h"
#include "rigid/support/text.h"
#include "script.h"
#include "style.h"

namespace rigid::explore {

Explorer::Explorer(std::vector<LabEntry> labs, const std::string& lab, Window window)
    : labs_(std::move(labs)), window_(std::move(window)) {
  for (std::size_t k = 0; k < labs_.size(); ++k) {
    if (labs_[k].name == lab) {
      install(k, labs_[k].make());
      return;
    }
  }
  throw std::invalid_argument("no lab named '" + support::terminal_safe(lab) + "'");
}

Explorer::~Explorer() = default;

// A lab that has come: shown from its start, the export section's fields kept.
void Explorer::install(std::size_t index, std::unique_ptr<lab::Session> session) {
  if (session_) loader_.close(std::move(session_));
  queued_.clear();  // what was queued for the lab left (an export waiting for its report)
  session_ = std::move(session);
  lab_index_ = index;
  if (window_.set_title) window_.set_title("rigidlab explore: " + session_->name());
  ViewState next;
  next.export_path = view_.export_path;
  next.figure_size = view_.figure_size;
  next.hidden_version = view_.hidden_version + 1;
  next.fields.assign(session_->input_count(), Field{});
  // a script plays only when it says so
  next.playing = session_->animation() != nullptr && !script_;
  view_ = std::move(next);
  scenes_.reset();
  views_.reset();
  after_change();
}

void Explorer::after_change() {
  // every field shows the state now taken; a refusal shown was of a value not taken
  for (std::size_t i = 0; i < view_.fields.size(); ++i) {
    view_.fields[i].text = lab::argument_text(session_->value(i));
    view_.fields[i].refusal.clear();
  }
  const lab::Animation* motion = session_->animation();
  if (motion == nullptr) return;
  if (view_.time > motion->seconds) view_.time = 0.0;
  // real time, unless the motion is too long to watch so (then as fast as it goes,
  // from when it became so)
  const bool long_motion = motion->seconds > kMaxSpeed * kLongMotionPlay;
  if (long_motion && !view_.long_motion) view_.speed = fastest(*motion);
  view_.long_motion = long_motion;
  set_speed(view_.speed);
}

void Explorer::set_speed(double speed) {
  const lab::Animation* motion = session_->animation();
  view_.speed = std::clamp(speed, kMinSpeed, motion != nullptr ? fastest(*motion) : kMaxSpeed);
}

void Explorer::toggle(const std::string& part) {
  view_.toggle_part(part);
}

void Explorer::queue(Action action) {
  queued_.push_back(std::move(action));
}

void Explorer::run(std::unique_ptr<Script> script) {
  script_ = std::move(script);
  view_.playing = false;
}

bool Explorer::scripted() const {
  return script_ != nullptr && !script_->waiting();
}

bool Explorer::animating() const {
  return view_.playing || script_ != nullptr || recording_ || session_->pending() ||
         !queued_.empty() || loader_.opening();
}

void Explorer::say(const std::string& text, bool error) {
  view_.message = text;
  view_.message_error = error;
  if (script_) (error ? std::cerr : std::cout) << text << '\n';
}

std::string Explorer::json_text() {
  return explore::json_text(*session_);
}

std::string Explorer::command_line() const {
  return explore::command_line(*session_);
}

// ---- the one point a frame where the state changes ------------------------------

void Explorer::frame(double seconds) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  sync(seconds);
  const auto t1 = Clock::now();
  build_ui();
  if (!timed_) return;
  const auto t2 = Clock::now();
  phases_.actions = std::chrono::duration<double>(t1 - t0).count();
  phases_.scene = views_.scene_timing();
  phases_.widgets = std::chrono::duration<double>(t2 - t1).count() - phases_.scene.total();
}

void Explorer::sync(double seconds) {
  // what the panels queued, for the lab they showed; then a lab asked for, once it has come
  apply_queued();
  try {
    if (auto opened = loader_.take()) install(opened->index, std::move(opened->session));
  } catch (const std::exception& e) {
    say(support::terminal_safe(e.what()), true);
  }
  script_held_ = false;
  if (script_) {
    seconds = kScriptFrameSeconds;
    step_script();
  }
  // the whole report, if it has come (the numbers and plots follow it)
  session_->poll();
  const lab::Animation* motion = session_->animation();
  if (motion != nullptr && view_.playing) {
    view_.time += seconds * view_.speed;
    // a motion plays in a loop
    if (view_.time > motion->seconds) view_.time = std::fmod(view_.time, motion->seconds);
  }
  poll_recording();
}

// What the panels queued, in order; an export that needs the whole report waits in the
// queue (with all after it) until the report has come.
void Explorer::apply_queued() {
  std::vector<Action> actions = std::move(queued_);
  queued_.clear();
  for (std::size_t k = 0; k < actions.size(); ++k) {
    if (needs_whole_report(actions[k]) && session_->pending()) {
      queued_.assign(std::make_move_iterator(actions.begin() + static_cast<std::ptrdiff_t>(k)),
                     std::make_move_iterator(actions.end()));
      return;
    }
    const std::string error = apply(actions[k]);
    // a field shows its own refusal; the rest is said under the exports
    if (const std::string path = written_path(actions[k]); !path.empty()) {
      say(error.empty() ? "wrote " + support::terminal_safe(path) : support::terminal_safe(error),
          !error.empty());
    } else if (!error.empty() && !std::holds_alternative<action::SetText>(actions[k]) &&
               !std::holds_alternative<action::SetValue>(actions[k])) {
      say(support::terminal_safe(error), true);
    }
  }
}

void Explorer::build_ui() {
  const ImGuiIO& io = ImGui::GetIO();
  const float W = io.DisplaySize.x, H = io.DisplaySize.y, ui = ui_scale();
  // a narrow window narrows the panels at the sides, not the scene between them
  const float sides = (kInputsWidth + kNumbersWidth) * ui;
  const float narrow = std::clamp((W - kMinSceneWidth * ui) / sides, 0.4f, 1.0f);
  const float inputs_w = std::floor(kInputsWidth * ui * narrow);
  const float numbers_w = std::floor(kNumbersWidth * ui * narrow);
  const float bar_h = kTimeBarHeight * ui;
  const float center_w = std::max(W - inputs_w - numbers_w, 160.0f);
  const float plot_h = std::floor((H - bar_h) * kPlotShare);
  const float scene_h = std::max(H - bar_h - plot_h, 80.0f);
  view_.interacting = script_held_;
  std::vector<std::string> parts;
  const PanelContext c{labs_,
                       *session_,
                       view_,
                       queued_,
                       parts,
                       recording_.has_value(),
                       recording_ ? recording_->path.c_str() : ""};
  inputs_panel(c, inputs_w, H);
  numbers_panel(*session_, W - numbers_w, numbers_w, H);
  views_.scene(*session_, view_, scenes_, {inputs_w, 0, center_w, scene_h}, queued_);
  parts = scenes_.parts(*session_, view_);
  time_panel(c, inputs_w, scene_h, center_w, bar_h);
  keys(c);
  views_.plot(*session_, view_, {inputs_w, scene_h + bar_h, center_w, plot_h});
}

// ---- a recording, a screenshot, a script -----------------------------------------

void Explorer::poll_recording() {
  if (!recording_) return;
  // the recording's stderr, and whether it has ended
  recording_->err += recording_->child.read_available();
  if (!recording_->child.poll()) return;
  recording_->err += recording_->child.read_available();
  const bool ok = recording_->child.exit_status() == 0;
  std::string err = recording_->err;
  while (!err.empty() && err.back() == '\n') err.pop_back();
  if (const auto nl = err.rfind('\n'); nl != std::string::npos) err = err.substr(nl + 1);
  const std::string path = recording_->path;
  recording_.reset();
  if (ok) {
    say("wrote " + support::terminal_safe(path));
  } else {
    failed_write("recording failed: " + support::terminal_safe(err));
  }
}

// A write that failed: the status line's, and a script's end (its one line, exit 1).
void Explorer::failed_write(const std::string& line) {
  if (!script_) return say(line, true);
  view_.message = line;
  view_.message_error = true;
  script_->abort(1, line);
  end_script(1);
}

void Explorer::after_render() {
  if (screenshot_path_.empty()) return;
  const std::string path = std::move(screenshot_path_);
  screenshot_path_.clear();
  // the path again, as it is written (the file system may have changed since it was given)
  std::string error = output_refusal(path);
  if (error.empty()) {
    try {
      render::write_png(window_.read_frame(), path);
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  if (error.empty()) {
    say("wrote " + support::terminal_safe(path));
  } else {
    failed_write("screenshot: " + support::terminal_safe(error));
  }
}

void Explorer::step_script() {
  if (script_ && !script_->step(*this)) end_script(script_->status());
}

// The script's end: the window closes, and the exit status is the first failure's.
void Explorer::end_script(int status) {
  if (!script_) return;
  if (status_ == 0) status_ = status;
  script_.reset();
  if (window_.close) window_.close();
}

}  // namespace rigid::explore
